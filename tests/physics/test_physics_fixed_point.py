"""A settled file is a fixed point: `settle` of what `settle` wrote changes no byte, and what it
wrote keeps the guarantees `check --strict` tests (inside the page, no overlap) after rounding.

Random pages with point anchors (soft and hard), items following other items, and decorations,
in both modes; the same code path as `floatpage settle` (load, settle_project, save).
"""

from __future__ import annotations

import tempfile
from pathlib import Path

from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from floatpage.model import load_project, save_project
from floatpage.model.document import (
    BlockItem, ItemAnchor, Page, PhysicsSettings, PointAnchor, Project, TextItem,
)
from floatpage.model.layout import engine_for_page, safe_round, settle_page, settle_project

FEW = settings(max_examples=10, deadline=None, derandomize=True, database=None, print_blob=True,
               phases=[Phase.explicit, Phase.generate],
               suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


@st.composite
def projects(draw) -> Project:
    page_w, page_h = round(draw(st.floats(90, 300)), 2), round(draw(st.floats(90, 300)), 2)
    count = draw(st.integers(2, 14))
    items = []
    for k in range(count):
        w = draw(st.floats(0.05, 0.3)) * page_w
        h = draw(st.floats(0.05, 0.3)) * page_h
        x, y = draw(st.floats(0, 1)) * page_w, draw(st.floats(0, 1)) * page_h
        kind = draw(st.sampled_from(["block", "text", "decoration"]))
        item = (TextItem(id=f"t{k}", x=x, y=y, w=w, h=h, text="hello") if kind == "text"
                else BlockItem(id=f"b{k}", x=x, y=y, w=w, h=h, decorative=kind == "decoration",
                               z=-1 if kind == "decoration" else 0))
        anchor = draw(st.sampled_from(["none", "none", "soft", "hard", "follow"]))
        if anchor == "soft":
            item.anchor = PointAnchor(x=x, y=y, gamma=draw(st.floats(0.1, 1.0)))
        elif anchor == "hard" and not item.decorative:
            # The user's own hard anchor, inside the page once written to 0.01 mm.
            item.anchor = PointAnchor(x=round(min(max(x, w / 2 + 0.01), page_w - w / 2 - 0.01), 2),
                                      y=round(min(max(y, h / 2 + 0.01), page_h - h / 2 - 0.01), 2),
                                      hard=True)
        elif anchor == "follow" and items and not item.decorative:
            target = items[draw(st.integers(0, len(items) - 1))]
            if target.anchor is None:
                item.anchor = ItemAnchor(to=target.id, dx=0.0, dy=(target.h + h) / 2 + 4)
        items.append(item)
    mode = draw(st.sampled_from(["fast", "fast", "paper"]))
    physics = PhysicsSettings(mode=mode, seed=draw(st.integers(0, 1000)),
                              heat_decay=0.01 if mode == "fast" else 0.05)
    page = Page(id="p", size="custom", width_mm=page_w, height_mm=page_h, items=items)
    return Project(title="random", physics=physics, pages=[page])


def settle_file(path: Path) -> None:
    project = load_project(path)
    settle_project(project, max_steps=20_000)
    save_project(project)


def placed_by_user(item, page: Page) -> bool:
    by_id = {other.id: other for other in page.items}
    seen = set()
    while isinstance(item.anchor, ItemAnchor) and item.id not in seen:
        seen.add(item.id)
        item = by_id[item.anchor.to]
    return item.decorative


@FEW
@given(projects())
def test_settling_a_settled_file_changes_no_byte(project):
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "page.toml"
        save_project(project, path)
        settle_file(path)
        settled = path.read_bytes()
        settle_file(path)
        assert path.read_bytes() == settled


@FEW
@given(projects())
def test_what_settle_saves_stays_inside_the_page_after_rounding(project):
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "page.toml"
        save_project(project, path)
        settle_file(path)
        reloaded = load_project(path)
    for page in reloaded.pages:
        quality = engine_for_page(page, reloaded.physics).quality()
        # Decorations stay where the user put them (the physics does not move them), and so
        # do items that follow a decoration: their place is the user's, off the page or not.
        fitting = [k for k, item in enumerate(page.items) if not placed_by_user(item, page)
                   and item.w <= page.width_mm and item.h <= page.height_mm]
        assert not set(quality.off_page) & set(fitting)


def test_rounding_keeps_an_item_flush_with_an_edge_inside():
    # A 30.0 mm item flush with the left edge at 0.004999: nearest rounding gives 15.0 -> fine;
    # flush at the right edge of a 100.005 mm page: nearest would stick out by 0.005 mm.
    assert safe_round(15.0 + 0.004, 15.0, 100.0) == 15.0
    centre = safe_round(100.005 - 15.0, 15.0, 100.005)
    assert centre + 15.0 <= 100.005
    assert safe_round(14.996, 15.0, 100.0) >= 15.0  # the left edge would be at -0.004


ALBUM = Path(__file__).resolve().parents[2] / "sample_projects" / "photo-album" / "photo-album.toml"


def test_a_settled_page_nudged_by_hand_stays_the_layout_it_was():
    """A settled file with one photo moved 2 mm by hand, still sound: settle keeps the layout
    near where it was (model.layout's near-rest path) rather than laying the page out anew,
    which moved photos 12-25 mm on this page."""
    project = load_project(ALBUM)
    page = project.pages[0]
    before = {item.id: (item.x, item.y) for item in page.items}
    nudged = next(item for item in page.items if item.id == "p1-photo-3")
    nudged.x += 2.0
    report = settle_page(page, project.physics)
    assert report.fixed_point and report.fits
    moved = max(abs(item.x - before[item.id][0]) + abs(item.y - before[item.id][1])
                for item in page.items)
    assert moved <= 4.0, f"settle moved an item {moved:.2f} mm after a 2 mm nudge"
