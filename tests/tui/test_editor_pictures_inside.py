"""A picture picked in the editor from outside the project's folder is copied into its
`pictures/`, so the saved project loads without --allow-outside-files (issue 12)."""

from __future__ import annotations

from pathlib import Path

from PIL import Image

from floatpage.model import Page, Project, load_project, save_project
from floatpage.tui.session import EditSession


def session_in(folder: Path, *, allow_outside: bool = False) -> EditSession:
    folder.mkdir()
    path = folder / "card.toml"
    save_project(Project(pages=[Page(id="p")]), path)
    project = load_project(path)
    project.allow_outside_files = allow_outside
    return EditSession(project)


def test_an_outside_picture_is_copied_in_and_the_project_still_loads(tmp_path):
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    Image.new("RGB", (40, 30), "red").save(elsewhere / "photo.png")
    session = session_in(tmp_path / "project")
    written = session.relative_picture_path(elsewhere / "photo.png")
    assert written == "pictures/photo.png"
    assert (tmp_path / "project" / written).read_bytes() == (elsewhere / "photo.png").read_bytes()
    assert session.relative_picture_path(elsewhere / "photo.png") == written, "no second copy"

    other = tmp_path / "other"
    other.mkdir()
    Image.new("RGB", (40, 30), "blue").save(other / "photo.png")
    assert session.relative_picture_path(other / "photo.png") == "pictures/photo-2.png"

    session.insert_item(session.make_item("picture", path=written))
    session.save()
    assert load_project(tmp_path / "project" / "card.toml").pages[0].items[0].path == written


def test_a_picture_inside_stays_where_it_is_and_an_allowing_project_keeps_outside_paths(tmp_path):
    session = session_in(tmp_path / "project")
    (tmp_path / "project" / "art").mkdir()
    Image.new("RGB", (4, 3)).save(tmp_path / "project" / "art" / "a.png")
    assert session.relative_picture_path(tmp_path / "project" / "art" / "a.png") == "art/a.png"

    Image.new("RGB", (4, 3)).save(tmp_path / "b.png")
    allowing = session_in(tmp_path / "allowing", allow_outside=True)
    assert allowing.relative_picture_path(tmp_path / "b.png") == str(tmp_path / "b.png")
