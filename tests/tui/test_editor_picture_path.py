"""A picture's file path can be mended in the editor (user walk 5).

A user who moved their photo could not point the picture at its new place without a text
editor: the edit form had no field for it.  It has one now; a path that names no file, a
folder or a file that is not a picture is a sentence naming the file and what to do, and the
form stays open.
"""

from __future__ import annotations

import shutil

from textual.widgets import Input, Label

from floatpage.model import load_project
from editor_helpers import answer_form, dialog_shown, editor, item, paint_picture, screen_of, until


async def open_path_field(app, pilot, item_id: str) -> Input:
    screen_of(app).selected_id = item_id
    await pilot.press("enter")
    assert await dialog_shown(pilot, app, "edit-dialog")
    field = app.screen.query_one("#field-path", Input)
    field.value = ""
    field.focus()  # given by a message: Enter pressed before it went to another field
    assert await until(pilot, lambda: field.has_focus)
    return field


def form_error(app) -> str:
    return str(app.screen.query_one("#form-error", Label).render())


async def test_a_moved_photo_is_found_again_by_its_new_path(project_path):
    folder = project_path.parent
    (folder / "moved").mkdir()
    shutil.move(folder / "pictures" / "photo.png", folder / "moved" / "photo.png")
    async with editor(project_path) as (app, pilot):
        assert app.session.project.missing_pictures  # opened all the same
        field = await open_path_field(app, pilot, "photo")
        field.value = "moved/photo.png"
        await answer_form(pilot, app, "enter")
        assert app.screen is screen_of(app)
        assert item(app, "photo").path == "moved/photo.png"
        await pilot.press("ctrl+s")
        await pilot.pause()
    project = load_project(project_path)  # no longer refused for a missing picture
    assert project.pages[0].item("photo").path == "moved/photo.png"


async def test_another_photo_keeps_its_own_shape(project_path):
    paint_picture(project_path.parent / "pictures" / "tall.png", size=(20, 60))
    async with editor(project_path) as (app, pilot):
        before = item(app, "photo")
        area = before.w * before.h
        field = await open_path_field(app, pilot, "photo")
        field.value = "pictures/tall.png"
        await answer_form(pilot, app, "enter")
        after = item(app, "photo")
        assert abs(after.h / after.w - 3.0) < 1e-6
        assert abs(after.w * after.h - area) < 1e-6 * area
        await pilot.press("ctrl+z")
        await pilot.pause()
        assert item(app, "photo").path == "pictures/photo.png"


async def test_a_path_to_nothing_names_the_file_and_what_to_do(project_path):
    async with editor(project_path) as (app, pilot):
        field = await open_path_field(app, pilot, "photo")
        field.value = "pictures/gone.jpg"
        await answer_form(pilot, app, "enter")
        assert app.screen.id == "edit-dialog"  # stays open, with the reason
        words = form_error(app)
        assert str(project_path.parent / "pictures" / "gone.jpg") in words
        assert "not found" in words and "copy the file there" in words
        assert item(app, "photo").path == "pictures/photo.png"


async def test_a_text_file_or_a_folder_is_refused_in_words(project_path):
    notes = project_path.parent / "notes.jpg"
    notes.write_text("not a picture at all")
    async with editor(project_path) as (app, pilot):
        field = await open_path_field(app, pilot, "photo")
        field.value = "notes.jpg"
        await answer_form(pilot, app, "enter")
        words = form_error(app)
        assert str(notes) in words and "is not a picture floatpage can read" in words
        assert "use " in words  # which formats to use instead
        field.value = "pictures"
        await answer_form(pilot, app, "enter")
        assert "is a folder" in form_error(app)
        field.value = ""
        await answer_form(pilot, app, "enter")
        assert "type the picture's file path" in form_error(app)
        assert item(app, "photo").path == "pictures/photo.png"


async def test_a_missing_picture_keeps_its_other_fields_editable(project_path):
    (project_path.parent / "pictures" / "photo.png").unlink()
    async with editor(project_path) as (app, pilot):
        screen_of(app).selected_id = "photo"
        await pilot.press("enter")
        assert await dialog_shown(pilot, app, "edit-dialog")
        app.screen.query_one("#field-group", Input).value = "top"
        await answer_form(pilot, app, "ctrl+s")
        assert app.screen is screen_of(app)
        assert item(app, "photo").group == "top"


async def test_the_refusal_names_the_full_path_when_the_project_was_opened_by_a_relative_one(
        project_path, monkeypatch):
    """`floatpage edit card.toml` in its folder: "many/p5.jpg not found" named the file only
    as typed; the full path says where it was looked for."""
    monkeypatch.chdir(project_path.parent)
    from floatpage.tui.app import make_app

    app = make_app("card.toml", autostart=False)
    async with app.run_test(size=(100, 40)) as pilot:
        await pilot.pause()
        field = await open_path_field(app, pilot, "photo")
        field.value = "moved/photo.png"
        await answer_form(pilot, app, "enter")
        assert str(project_path.parent / "moved" / "photo.png") in form_error(app)


async def test_a_project_whose_picture_is_no_picture_opens_to_be_mended(project_path):
    """A photo overwritten by a text file kept the user out of the editor ("is not a picture
    floatpage can read"), as a missing one once did; it opens, names the file and what is
    wrong, shows a stand-in, and the path field mends it."""
    import pytest

    (project_path.parent / "pictures" / "photo.png").write_text("oops")
    with pytest.raises(Exception, match="is not a picture"):
        load_project(project_path)  # every other command still refuses it
    async with editor(project_path) as (app, pilot):
        shown = [n for n in app._notifications if n.title == "Pictures that cannot be used"]
        assert shown and 'item "photo": picture file "pictures/photo.png" is not a picture' \
            in shown[0].message
        text = "\n".join(screen_of(app).preview.text_lines())
        assert "unreadable" in text
        field = await open_path_field(app, pilot, "photo")
        field.value = "pictures/second.png"
        await answer_form(pilot, app, "enter")
        await pilot.press("ctrl+s")
        await pilot.pause()
    assert load_project(project_path).pages[0].item("photo").path == "pictures/second.png"


def test_a_picture_the_loader_refuses_is_never_decoded_for_a_thumbnail(tmp_path):
    """The editor opens such a project; its thumbnails must not decode what the loader
    refuses (a 200-megapixel PNG would take gigabytes)."""
    from PIL import Image

    from floatpage.model.picture_files import MAX_PIXELS
    from floatpage.tui import thumbnails

    path = tmp_path / "huge.png"
    side = int(MAX_PIXELS ** 0.5) + 100
    Image.new("1", (side, side)).save(path)  # one bit a pixel: a small file that claims much
    before = thumbnails._working_copy.cache_info().misses
    assert thumbnails.thumbnail(path, 10, 10) is None
    assert thumbnails._working_copy.cache_info().misses == before + 1
    assert thumbnails.thumbnail(path, 12, 12) is None  # remembered, not read again
    assert thumbnails._working_copy.cache_info().misses == before + 1


async def test_a_merge_template_picture_takes_a_placeholder_path(project_path):
    """A merge template names its picture by a data column (`pictures/{photo}`), a path no
    file has until `merge` fills it: the loader takes it, and so does the form."""
    async with editor(project_path) as (app, pilot):
        field = await open_path_field(app, pilot, "photo")
        field.value = "pictures/{photo}"
        await answer_form(pilot, app, "enter")
        assert app.screen is screen_of(app)
        assert item(app, "photo").path == "pictures/{photo}"
        await pilot.press("ctrl+s")
        await pilot.pause()
    assert load_project(project_path).pages[0].item("photo").path == "pictures/{photo}"
