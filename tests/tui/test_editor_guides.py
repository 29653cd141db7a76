"""The editor shows the alignment guide an item sits on while it moves, and the details view
(`v`) shows the alignment measures: the real app, driven by keys."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from editor_helpers import editor, item, item_pixel_box, position, screen_of
from floatpage.model import load_project
from floatpage.physics.guides import snap_range
from floatpage.physics.snapping import ALIGN_REACH
from floatpage.tui.keymap import SMALL_STEP_MM
from floatpage.tui.page_painter import GUIDE, GUIDE_DASH

SAMPLES = Path(__file__).resolve().parents[2] / "sample_projects"


def guide_pixels(app) -> set[tuple[int, int]]:
    canvas = screen_of(app).preview.canvas
    rows, cols = (canvas.pixels == GUIDE).all(axis=2).nonzero()
    return set(zip(cols.tolist(), rows.tolist()))


async def test_a_moving_item_shows_the_guide_it_sits_on_and_a_still_page_none(
        project_path, held_until_let_go):
    async with editor(project_path, size=(100, 40)) as (app, pilot):
        assert guide_pixels(app) == set()
        screen_of(app).selected_id = "block"  # its centre is level with the photo's (85 mm)
        await pilot.pause()
        assert guide_pixels(app) == set()  # selected, but not moving: no guide
        await pilot.press("right")  # a held key: the block moves, its centre stays at 85 mm
        await pilot.pause()
        shown = guide_pixels(app)
        p = screen_of(app).preview.projection
        row = int(p.to_pixels(0, 85.0)[1])
        photo, block = item_pixel_box(app, "photo"), item_pixel_box(app, "block")
        on_row = {x for x, y in shown if y == row}
        # a dashed line across the page, through the gap between the photo and the block
        assert any(photo[2] <= x < block[0] for x in on_row)
        assert len(on_row) >= p.width // (2 * GUIDE_DASH)  # across the page, not a stub
        screen_of(app).release_held()
        await pilot.pause()
        assert guide_pixels(app) == set()  # let go and paused: the guide goes


async def test_the_details_view_shows_the_alignment_measures(project_path):
    async with editor(project_path, size=(120, 40)) as (app, pilot):
        await pilot.press("v")
        await pilot.pause()
        text = str(screen_of(app).query_one("StatusLine").render())
        assert "misses " in text and "lines " in text and "aligned " in text


async def test_the_details_view_shows_the_alignment_measures_at_80_columns(project_path):
    """At 80 columns the details line ran "... even 0.72 · balance 0.96 · misses 0.00" and
    lost the edge lines and the share aligned off its end (user-walk-2, in tmux): at rest the
    figures go first on the status's first line, which has room."""
    from textual.geometry import Region

    async with editor(project_path, size=(80, 24)) as (app, pilot):
        await pilot.press("v")
        await pilot.pause()
        status = screen_of(app).query_one("StatusLine")
        shown = " ".join(strip.text for strip in status.render_lines(
            Region(0, 0, status.size.width, status.size.height)))
        assert "misses " in shown and "lines " in shown and "aligned " in shown, shown
        assert "overlaps" in shown and "gap " in shown, shown


async def test_a_release_note_leaves_the_details_figures_on_an_80_column_line(project_path):
    """The note a move leaves on the status line ("block anchored where you put it …") came
    before the alignment figures and pushed them off an 80-column line (in tmux)."""
    from textual.geometry import Region

    async with editor(project_path, size=(80, 24)) as (app, pilot):
        await pilot.press("v", "tab", "tab", "tab", "left")
        screen_of(app).release_held()
        await pilot.pause()
        status = screen_of(app).query_one("StatusLine")
        shown = " ".join(strip.text for strip in status.render_lines(
            Region(0, 0, status.size.width, status.size.height)))
        assert "· block anch" in shown, shown  # the note follows, as far as it fits
        assert "misses " in shown and "lines " in shown and "aligned " in shown, shown


async def test_an_item_moved_off_a_guide_and_anchored_there_is_not_snapped_back(tmp_path):
    """user-walk-13: the greeting card's front text moved 6 mm right with the arrows was
    "anchored where you put it", and once the page came to rest it stood on the centre line
    again, 6 mm from its anchor: the walls pushed it 3 mm back against its spring, and the
    snap took the rest. The snap now reaches as far from an anchored item's anchor as it reaches from a free item
    (or no further than the physics left it); it may still line up within that reach."""
    card = tmp_path / "card"
    shutil.copytree(SAMPLES / "greeting-card", card)
    async with editor(card / "greeting-card.toml") as (app, pilot):
        screen, engine = screen_of(app), app.session.engine
        engine.settle()
        screen.selected_id = "front-greeting"
        await pilot.press("right", "right", "right")  # 3 x 2 mm
        screen.release_held()
        await pilot.pause()
        anchor = item(app, "front-greeting").anchor
        assert anchor.x == pytest.approx(63.5 + 3 * SMALL_STEP_MM)
        engine.reheat()
        engine.settle()
        x, _ = position(app, "front-greeting")
        reach = ALIGN_REACH * snap_range(127.0, 203.2)  # the snap's, from the anchor
        assert abs(x - anchor.x) <= reach + 1e-9, x  # was 63.5, 6 mm off
        await pilot.press("ctrl+s")
        await pilot.pause()
    saved = load_project(card / "greeting-card.toml").pages[0].item("front-greeting")
    assert abs(saved.x - anchor.x) <= reach + 0.01
