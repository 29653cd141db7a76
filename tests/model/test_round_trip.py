"""A load and save keep what the user wrote: only what changed is rewritten (issue 12)."""

from __future__ import annotations

import pytest

from floatpage.model import load_project, save_project
from floatpage.model.layout import settle_project

ITEMS = '''
[[pages.items]]
id = "a"
kind = "block"
x = 50.0
y = 50.0
w = 20.0
h = 20.0

[[pages.items]]
id = "b"
kind = "block"
x = 50.0
y = 90.0
w = 20.0
h = 20.0
anchor = {to = "a"}
'''

CASES = {
    "no physics table": 'format = 1\n\n[[pages]]\nid = "p"\n' + ITEMS,
    "short anchor": 'format = 1\n\n[[pages]]\nid = "p"\nsize = "A5"\n' + ITEMS,
    "spelled size": 'format = 1\n\n[[pages]]\nid = "p"\nsize = " a 4 "\n' + ITEMS,
    "width on a named page": 'format = 1\n\n[[pages]]\nid = "p"\nsize = "A5"\nwidth_mm = 99.0\n'
                             'height_mm = 99.0\n' + ITEMS,
    "inline pages": 'format = 1\npages = [{id = "p", size = "A5", items = [{id = "a", kind = "block", '
                    'x = 50.0, y = 50.0, w = 20.0, h = 20.0}, {id = "b", kind = "block", x = 50.0, '
                    'y = 90.0, w = 20.0, h = 20.0, anchor = {to = "a"}}]}]\n',
}


@pytest.mark.parametrize("text", CASES.values(), ids=CASES.keys())
def test_an_unchanged_project_saves_byte_identical(tmp_path, text):
    path = tmp_path / "card.toml"
    path.write_text(text)
    save_project(load_project(path))
    assert path.read_text() == text


@pytest.mark.parametrize("text", CASES.values(), ids=CASES.keys())
def test_a_moved_item_changes_only_its_own_numbers(tmp_path, text):
    path = tmp_path / "card.toml"
    path.write_text(text)
    project = load_project(path)
    project.pages[0].items[0].x = 61.25
    save_project(project)
    assert path.read_text() == text.replace("x = 50.0", "x = 61.25", 1)


def test_a_utf8_byte_order_mark_is_kept(tmp_path):
    path = tmp_path / "card.toml"
    text = 'format = 1\ntitle = "Café"\n\n[[pages]]\nid = "p"\n' + ITEMS
    path.write_bytes(b"\xef\xbb\xbf" + text.encode())
    project = load_project(path)
    save_project(project)
    assert path.read_bytes() == b"\xef\xbb\xbf" + text.encode()
    project.pages[0].items[0].y = 70.0
    save_project(project)
    assert path.read_bytes().startswith(b"\xef\xbb\xbf")
    assert load_project(path).pages[0].items[0].y == 70.0


def test_a_file_without_physics_gets_only_the_settings_that_changed(tmp_path):
    path = tmp_path / "card.toml"
    path.write_text(CASES["no physics table"])
    project = load_project(path)
    project.physics.gutter_mm = 5.0
    save_project(project)
    text = path.read_text()
    assert "[physics]\ngutter_mm = 5.0\n" in text
    assert "alpha" not in text


def test_settling_keeps_the_short_anchor_and_the_spelling(tmp_path):
    path = tmp_path / "card.toml"
    path.write_text(CASES["spelled size"])
    project = load_project(path)
    settle_project(project)
    save_project(project)
    text = path.read_text()
    assert 'size = " a 4 "' in text and 'anchor = {to = "a"}' in text


def test_an_unchanged_save_writes_nothing_and_keeps_the_backup(tmp_path):
    path = tmp_path / "card.toml"
    path.write_text(CASES["short anchor"])
    project = load_project(path)
    project.pages[0].items[0].x = 60.0
    save_project(project)
    backup = (tmp_path / "card.toml.bak").read_text()
    modified = path.stat().st_mtime_ns
    save_project(project)
    assert path.stat().st_mtime_ns == modified
    assert (tmp_path / "card.toml.bak").read_text() == backup == CASES["short anchor"]
