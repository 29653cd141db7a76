"""A settle's save patches only the moved numbers into the text read, and writes the very
bytes the full save (tomlkit) would."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from floatpage.model import load_project, save_project
from floatpage.model.layout import settle_project
from floatpage.model.position_patch import Positions, patched_text, save_settled

HAND_WRITTEN = """\
# My card. I keep notes here.
format = 1
title = "Birthday"   # for Ana

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

[[pages.items]]
id = "note"
kind = "block"
x = 30
y = 150
w = 20
h = 20
"""

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = sorted((ROOT / "sample_projects").glob("*/*.toml"))


def copy_project(path: Path, into: Path) -> Path:
    into.mkdir()
    for entry in path.parent.iterdir():
        if entry.is_dir():
            shutil.copytree(entry, into / entry.name)
    copy = into / path.name
    copy.write_bytes(path.read_bytes())
    return copy


def nudged(path: Path) -> None:
    """Move every item of the file 7.5 mm right and 4.25 mm down, in the text: a settle then
    has work to do on every page."""
    project = load_project(path)
    for page in project.pages:
        for item in page.items:
            item.x, item.y = item.x + 7.5, item.y + 4.25
    save_project(project)


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.parent.name)
def test_a_settle_saves_the_bytes_the_full_save_writes(path, tmp_path):
    patched_file = copy_project(path, tmp_path / "patched")
    full_file = copy_project(path, tmp_path / "full")
    nudged(patched_file)
    nudged(full_file)
    project = load_project(patched_file)
    read = Positions.of(project)
    settle_project(project)
    assert patched_text(project, read) is not None, "the samples' layout is the patchable one"
    save_settled(project, read)
    full = load_project(full_file)
    settle_project(full)
    save_project(full)
    assert patched_file.read_bytes() == full_file.read_bytes()


def test_comments_line_endings_and_a_bom_survive_and_only_moved_numbers_change(tmp_path):
    text = HAND_WRITTEN.replace("x = 60\n", "x = 60   # from the left\n")
    path = tmp_path / "card.toml"
    path.write_bytes(b"\xef\xbb\xbf" + text.replace("\n", "\r\n").encode())
    project = load_project(path)
    read = Positions.of(project)
    project.pages[0].items[0].x = 71.25
    save_settled(project, read)
    expected = text.replace("x = 60   #", "x = 71.25   #").replace("\n", "\r\n")
    assert path.read_bytes() == b"\xef\xbb\xbf" + expected.encode()


def test_an_inline_item_table_takes_the_full_save(tmp_path):
    path = tmp_path / "inline.toml"
    path.write_text('format = 1\n\n[[pages]]\nid = "p"\nsize = "A5"\n'
                    'items = [{id = "a", kind = "block", x = 20, y = 20, w = 10, h = 10}]\n')
    project = load_project(path)
    read = Positions.of(project)
    project.pages[0].items[0].x = 30.5
    assert patched_text(project, read) is None
    save_settled(project, read)
    assert load_project(path).pages[0].items[0].x == 30.5


def test_a_project_changed_beyond_positions_takes_the_full_save(tmp_path):
    path = tmp_path / "card.toml"
    path.write_text(HAND_WRITTEN)
    project = load_project(path)
    read = Positions.of(project)
    project.pages[0].items.pop()
    assert patched_text(project, read) is None


def test_a_multi_line_string_that_looks_like_keys_takes_the_full_save(tmp_path):
    path = tmp_path / "card.toml"
    path.write_text(HAND_WRITTEN.replace(
        'id = "note"\nkind = "block"\n',
        'id = "note"\nkind = "text"\ntext = """\nx = 30\n[[pages.items]]\n"""\n'))
    project = load_project(path)
    read = Positions.of(project)
    project.pages[0].items[1].x = 44.5
    assert patched_text(project, read) is None
    save_settled(project, read)
    saved = load_project(path).pages[0].items[1]
    assert (saved.x, saved.text) == (44.5, "x = 30\n[[pages.items]]\n")


@pytest.mark.parametrize("value", [0.0, -0.0, 1.0, 12.5, 107.25, 0.01, 1e-05, 123456789.01,
                                   -3.14, 1e16, 2.675, 0.1 + 0.2])
def test_a_patched_number_is_written_as_tomlkit_writes_it(value):
    """The patch writes floats itself, without importing tomlkit: the same text."""
    import tomlkit

    from floatpage.model.position_patch import rewritten

    assert rewritten("x = 1.0\n", "x", 1.0, value) == f"x = {tomlkit.item(value).as_string()}\n"
