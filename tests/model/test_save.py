"""Saving: byte-identical round trips, comments that survive, and saves a crash cannot break."""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from floatpage.model import (
    BlockItem, CalendarItem, ItemAnchor, Page, PointAnchor, Project, TextItem, dump_project,
    load_project, save_project,
)
from floatpage.model.page_sizes import page_dimensions

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = sorted((ROOT / "sample_projects").glob("**/*.toml"))

HAND_WRITTEN = textwrap.dedent("""\
    # My card. I keep notes here.
    format = 1
    title = "Birthday"   # for Ana

    [physics]
    alpha = 150 # the paper's value

    [[pages]]
    id = "front"
    size = "5x8in"

    # the big photo
    [[pages.items]]
    id = "photo"
    kind = "block"
    x = 60
    y = 70.5
    w = 80
    h = 60
    color = "#ff8800"
""")


def test_there_are_sample_projects():
    assert SAMPLES, "sample_projects/ should hold at least one project"


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.parent.name)
def test_every_sample_round_trips_byte_identical(path, tmp_path):
    copy = tmp_path / path.name
    copy.write_bytes(path.read_bytes())
    for picture_dir in path.parent.iterdir():
        if picture_dir.is_dir():
            shutil.copytree(picture_dir, tmp_path / picture_dir.name)
    save_project(load_project(copy))
    assert copy.read_bytes() == path.read_bytes()


def test_a_hand_written_file_with_comments_saves_unchanged(tmp_path):
    path = tmp_path / "card.toml"
    path.write_text(HAND_WRITTEN)
    save_project(load_project(path))
    assert path.read_text() == HAND_WRITTEN


def test_an_edit_changes_only_its_line_and_keeps_comments(tmp_path):
    path = tmp_path / "card.toml"
    path.write_text(HAND_WRITTEN)
    project = load_project(path)
    project.pages[0].items[0].x = 61.23456
    save_project(project)
    expected = HAND_WRITTEN.replace("x = 60\n", "x = 61.23\n")
    assert path.read_text() == expected


def test_adding_and_removing_items_keeps_the_rest(tmp_path):
    path = tmp_path / "card.toml"
    path.write_text(HAND_WRITTEN)
    project = load_project(path)
    project.pages[0].items.append(TextItem(id="greeting", x=60, y=150, w=100, h=30, text="Hi!"))
    save_project(project)
    text = path.read_text()
    assert "# the big photo" in text and 'id = "greeting"' in text
    project = load_project(path)
    del project.pages[0].items[0]
    save_project(project)
    reloaded = load_project(path)
    assert [item.id for item in reloaded.pages[0].items] == ["greeting"]
    assert "# My card. I keep notes here." in path.read_text()



def add_two_blocks(path, title: str | None = None) -> None:
    """What the editor does adding two items, one save each (and a new title with the first)."""
    for k, x in ((1, 30), (2, 60)):
        project = load_project(path)
        if title is not None:
            project.title = title
        project.pages[0].items.append(BlockItem(id=f"b{k}", x=x, y=150, w=10, h=10))
        save_project(project)

def test_items_added_after_the_files_last_table_are_set_apart_by_a_blank_line(tmp_path):
    """A file that ends with its only item (as every `floatpage new blank` file does) got each
    item added in the editor jammed against the one before: `color = "#ff8800"` then
    `[[pages.items]]` on the next line, item after item.  A blank line now parts them, as it
    parts the tables the file already had, and the file still ends with one newline."""
    path = tmp_path / "card.toml"
    path.write_text(HAND_WRITTEN)
    add_two_blocks(path)
    text = path.read_text()
    assert text.startswith(HAND_WRITTEN + "\n[[pages.items]]\nid = \"b1\"")
    assert text.count("\n\n[[pages.items]]\n") == 2 and "\n[[pages.items]]\nid = \"b2\"" in text
    assert text.endswith("opacity = 1.0\n")


def test_a_windows_file_keeps_crlf_on_every_line_a_save_adds(tmp_path):
    """A project written on Windows (CRLF) got each item the editor added, and each key
    changed, ended with a bare LF: a file of mixed line ends, every added line a diff."""
    path = tmp_path / "card.toml"
    path.write_bytes(HAND_WRITTEN.replace("\n", "\r\n").encode())
    add_two_blocks(path, title="Birthday, again")
    data = path.read_bytes()
    assert b'id = "b2"' in data and data.count(b"\n") == data.count(b"\r\n")
    assert load_project(path).title == "Birthday, again"
    path.write_text(HAND_WRITTEN)  # and a file with LF keeps LF
    project = load_project(path)
    project.pages[0].items.append(BlockItem(id="b1", x=30, y=150, w=10, h=10))
    save_project(project)
    assert b"\r" not in path.read_bytes()


def test_save_keeps_the_previous_version_as_backup(tmp_path):
    path = tmp_path / "card.toml"
    path.write_text(HAND_WRITTEN)
    project = load_project(path)
    project.title = "Changed"
    save_project(project)
    assert (tmp_path / "card.toml.bak").read_text() == HAND_WRITTEN
    assert 'title = "Changed"' in path.read_text()


def test_a_save_killed_midway_leaves_the_old_file_intact(tmp_path):
    """A subprocess starts saving a large project, writes half, and is killed with SIGKILL."""
    path = tmp_path / "big.toml"
    project = Project(pages=[Page(id="p", items=[
        TextItem(id=f"t{i}", x=10.0 + i % 100, y=20.0, w=5.0, h=5.0, text="x" * 2000) for i in range(300)
    ])])
    save_project(project, path)
    original = path.read_bytes()
    script = textwrap.dedent(f"""
        import sys, time
        import floatpage.model.atomic_file as save
        from floatpage.model import load_project, save_project
        project = load_project({str(path)!r})
        project.title = "half-written"
        def slow_write(handle, data, chunk=1 << 12):
            handle.write(data[: len(data) // 2])
            handle.flush()
            print("half", flush=True)
            time.sleep(60)
        save.write_chunks = slow_write
        save_project(project)
    """)
    process = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True,
                               cwd=ROOT)
    try:
        assert process.stdout.readline().strip() == "half"
        os.kill(process.pid, signal.SIGKILL)
    finally:
        process.wait(timeout=30)
    assert process.returncode == -signal.SIGKILL
    assert path.read_bytes() == original
    assert len(load_project(path).pages[0].items) == 300


def test_saving_into_a_missing_folder_is_a_clear_error(tmp_path):
    from floatpage.model import FloatpageError

    project = Project(pages=[Page(id="p")])
    with pytest.raises(FloatpageError, match="could not save"):
        save_project(project, tmp_path / "no" / "such" / "dir.toml")


ids = st.from_regex(r"[a-z][a-z0-9-]{0,8}", fullmatch=True)
coords = st.floats(min_value=-500, max_value=500, allow_nan=False)
sizes = st.floats(min_value=0.5, max_value=400, allow_nan=False)


@st.composite
def projects(draw):
    item_ids = draw(st.lists(ids, min_size=1, max_size=6, unique=True))
    items = []
    for index, item_id in enumerate(item_ids):
        kind = draw(st.sampled_from(["text", "block", "calendar"]))
        common = dict(id=item_id, x=draw(coords), y=draw(coords), w=draw(sizes), h=draw(sizes),
                      z=draw(st.integers(-5, 5)), decorative=draw(st.booleans()))
        if kind == "text":
            item = TextItem(**common, text=draw(st.text(max_size=40)), bold=draw(st.booleans()))
        elif kind == "block":
            item = BlockItem(**common, opacity=draw(st.floats(0, 1)))
        else:
            item = CalendarItem(**common, year=draw(st.integers(1, 9999)), month=draw(st.integers(1, 12)))
        if index and draw(st.booleans()):
            item.anchor = ItemAnchor(to=item_ids[0], dx=draw(coords), dy=draw(coords))
        elif draw(st.booleans()):
            item.anchor = PointAnchor(x=draw(coords), y=draw(coords), gamma=draw(st.floats(0, 1)))
        items.append(item)
    size, orientation = draw(st.sampled_from(["A4", "A5", "5x8in", "Letter"])), draw(
        st.sampled_from(["portrait", "landscape"]))
    width, height = page_dimensions(size, orientation)
    return Project(title=draw(st.text(max_size=20)), pages=[
        Page(id="p1", size=size, orientation=orientation, width_mm=width, height_mm=height, items=items)])


@settings(max_examples=60, deadline=None)
@given(projects())
def test_any_project_survives_dump_load_dump(tmp_path_factory, project):
    path = tmp_path_factory.mktemp("rt") / "p.toml"
    first = dump_project(project)
    path.write_text(first)
    loaded = load_project(path)
    assert dump_project(loaded) == first
    for before, after in zip(project.pages[0].items, loaded.pages[0].items):
        # half a hundredth, plus the float error of the saved decimal (0.375 saves as 0.38,
        # 0.0050000000000000044 away)
        assert abs(before.x - after.x) <= 0.005 + 1e-12
        assert abs(before.w - after.w) <= 0.005 + 1e-12
        assert type(before) is type(after) and before.id == after.id


def test_a_new_file_gets_the_usual_permissions_not_mkstemps_0600(tmp_path):
    old = os.umask(0o022)
    try:
        path = save_project(Project(pages=[Page(id="p")]), tmp_path / "new.toml")
    finally:
        os.umask(old)
    assert path.stat().st_mode & 0o777 == 0o644


def test_a_key_added_and_a_first_region_keep_the_files_blank_lines(tmp_path):
    """The editor joined an item to a group and made the page's first region: the save wrote
    `group = "g"` after the blank line that ends the item's table, and the new
    `[[pages.regions]]` table jammed against the next `[[pages]]` (user walk 5)."""
    from floatpage.model.document import Region

    path = tmp_path / "card.toml"
    path.write_text(HAND_WRITTEN + "\n[[pages]]\nid = \"back\"\nsize = \"5x8in\"\n")
    project = load_project(path)
    project.pages[0].items[0].group = "g"
    project.pages[0].regions.append(Region("top", 0.0, 0.0, 100.0, 100.0))
    save_project(project)
    text = path.read_text()
    assert 'color = "#ff8800"\ngroup = "g"\n\n[[pages.regions]]\n' in text, text
    assert "h = 100.0\n\n[[pages]]\nid = \"back\"" in text, text
    assert load_project(path).pages[0].region("top").w == 100.0
    path.write_text(HAND_WRITTEN + '\ngroup = "g"\n[[pages]]\nid = "back"\nsize = "5x8in"\n')
    project = load_project(path)  # as an older save left it: the group after the blank line
    project.pages[0].regions.append(Region("top", 0.0, 0.0, 100.0, 100.0))
    save_project(project)
    assert "h = 100.0\n\n[[pages]]\nid = \"back\"" in path.read_text(), path.read_text()
    path.write_text(HAND_WRITTEN)  # the file's only page: the region after a blank line
    project = load_project(path)
    project.pages[0].regions.append(Region("top", 0.0, 0.0, 100.0, 100.0))
    save_project(project)
    text = path.read_text()
    assert 'color = "#ff8800"\n\n[[pages.regions]]\n' in text and text.endswith("h = 100.0\n")


def test_a_key_a_save_added_can_be_changed_and_taken_out_by_the_next_save(tmp_path):
    """The editor keeps the document it saved into: a group or region key added before an
    item's closing blank line, then taken out by an undo and saved again, failed with
    "KeyError: 'region'" (user-walk-8: a long session, undone all the way back, could not be
    saved)."""
    from floatpage.model.document import Region

    folder = tmp_path / "album"
    shutil.copytree(ROOT / "sample_projects" / "photo-album", folder)
    path = folder / "photo-album.toml"
    project = load_project(path)
    page = project.pages[0]
    item = page.items[1]  # an item between two others: its table ends with a blank line
    page.regions.append(Region("top", 0.0, 0.0, 200.0, 200.0))
    for group, region in (("g", ""), ("h", "top"), ("", "top"), ("g", ""), ("", "")):
        item.group, item.region = group, region
        save_project(project)
        again = load_project(path).pages[0].items[1]
        assert (again.group, again.region) == (group, region)
        text = path.read_text()
        assert text.count("group =") == (1 if group else 0)
        assert text.count('region = "top"') == (1 if region else 0)


def test_tomlkit_is_bounded_to_the_releases_a_save_was_checked_against():
    """tomlkit 0.15.0 and 0.15.1 write a control character in a title as `\\e` (TOML 1.1),
    which the loader (tomllib, TOML 1.0) refuses: a project saved with them no longer opened
    (`test_any_project_survives_dump_load_dump` fails there); 0.13-0.15.1 also wrote a blank
    line too many before a page's first region, and `add_key` uses tomlkit's internal
    `Container._insert_at`. `>=0.13` let pip pick any of those, and any later release."""
    import tomllib
    from importlib.metadata import version

    from packaging.requirements import Requirement
    from packaging.version import Version

    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    spec = next(Requirement(line) for line in project["dependencies"]
                if Requirement(line).name == "tomlkit").specifier
    assert Version(version("tomlkit")) in spec
    for refused in ("0.13.2", "0.14.0", "0.15.0", "0.15.1", "0.16.0", "1.0.0"):
        assert Version(refused) not in spec, refused
    from tomlkit.container import Container

    assert hasattr(Container, "_insert_at")  # what add_key relies on, within the bound


def test_an_anchor_taken_off_saved_and_put_back_keeps_its_place_in_the_file(tmp_path):
    """The calendar's month names have `anchor` before `role`: taken off (the editor's `u`),
    saved, then put back (`a`, or an undo) and saved again, the anchor came after `role`, a
    diff nobody asked for (user-walk-8). Now it goes back where it was, and the file saved
    with it back is the file as read."""
    folder = tmp_path / "calendar"
    shutil.copytree(ROOT / "sample_projects" / "calendar-2027", folder)
    path = folder / "calendar-2027.toml"
    original = path.read_text()
    project = load_project(path)
    month = project.pages[0].items[0]
    assert month.anchor is not None and month.role
    anchor = month.anchor
    month.anchor = None
    save_project(project)
    assert path.read_text().count("anchor =") == original.count("anchor =") - 1
    month.anchor = anchor
    save_project(project)
    assert path.read_text() == original
    # a key taken out twice, and one whose follower went too, still come back whole
    month.anchor, month.role = None, ""
    save_project(project)
    month.anchor, month.role = anchor, "month-name"
    save_project(project)
    again = load_project(path).pages[0].items[0]
    assert (again.anchor, again.role) == (anchor, "month-name")
    assert path.read_text() == original
