"""Defects a user of greeting cards, calendars and flyers met in a first week with the editor
(user-walk-9), each driven through the real app with Pilot, on a real project file."""

from __future__ import annotations

from pathlib import Path

import pytest

from editor_helpers import (
    BLUE, RED, back_on_editor, editor, item, item_pixel_box, pixel, screen_of, type_text, until,
)

ROOT = Path(__file__).resolve().parents[2]


def status_of(app) -> str:
    return str(screen_of(app).query_one("#status").render())


async def test_an_empty_page_says_it_has_no_items_on_the_status_line(project_path):
    """`N` made a page with nothing on it, and the status line said "no overlaps · v details"
    of it: it printed as a blank sheet. It says so now, with the keys that mend it; a page
    with items says what it said."""
    async with editor(project_path) as (app, pilot):
        assert "no items" not in status_of(app)
        await pilot.press("N")
        await pilot.pause()
        assert not app.session.page.items
        assert "no items: prints as a blank page · i inserts · D removes the page" \
            in status_of(app)
        await pilot.press("[")
        await pilot.pause()
        assert "no items" not in status_of(app)


async def test_an_anchor_taken_off_saved_and_put_back_keeps_its_line_in_the_file(tmp_path):
    """`u` on the calendar's month name, Ctrl+S, then `a` and Ctrl+S: the anchor line came
    back after `role`, where it had been before it (a diff the user did not ask for)."""
    import shutil

    folder = tmp_path / "calendar"
    shutil.copytree(ROOT / "sample_projects" / "calendar-2027", folder)
    path = folder / "calendar-2027.toml"

    def month_name_keys() -> list[str]:
        table = path.read_text().split('id = "jan-title"')[1].split("[[")[0]
        return [line.split(" =")[0] for line in table.splitlines() if " = " in line]

    assert month_name_keys()[-2:] == ["anchor", "role"]
    async with editor(path) as (app, pilot):
        await pilot.press("tab")
        await pilot.pause()
        assert app.session.selected_id == "jan-title"
        await pilot.press("u", "ctrl+s")
        await pilot.pause()
        assert "anchor" not in month_name_keys()
        await pilot.press("a", "ctrl+s")
        await pilot.pause()
        assert not app.session.unsaved
    assert month_name_keys()[-2:] == ["anchor", "role"]


def changed_elsewhere(path: Path) -> str:
    """The title's words mended as vim would, behind the editor's back; the new text."""
    text = path.read_text().replace("Happy Birthday Anna", "Happy Birthday Anna and Ben")
    path.write_text(text)
    return text


def asked(app) -> bool:
    return app.screen.id == "changed-on-disk-dialog"


async def test_a_change_another_program_makes_is_told_at_once_not_at_the_next_ctrl_s(
        project_path):
    """The file mended in vim while the editor had it open, with a nudge unsaved: nothing
    said so until Ctrl+S, maybe an hour of edits later. Now the editor asks within seconds,
    with the Ctrl+S question's choices; "Keep editing" is the one highlighted (the edits are
    not lost to an Enter typed as it opens), the question is not asked again for the same
    file, and Ctrl+S still asks before replacing it."""
    async with editor(project_path) as (app, pilot):
        await pilot.press("tab", "right")
        await pilot.pause()
        assert app.session.unsaved
        theirs = changed_elsewhere(project_path)
        assert await until(pilot, lambda: asked(app)), "no word of the change"
        dialog = app.screen
        assert [label for label, _ in dialog.choices] == [
            "Replace it with the editor's version", "Open the file as it is now",
            "Keep editing (save nothing)"]
        assert "changed card.toml just now" in dialog.message
        assert "unsaved edits" in dialog.message
        await pilot.press("enter")  # the highlighted choice: keep editing
        assert await until(pilot, lambda: app.screen is app.editor), app.screen
        assert app.session.unsaved
        assert project_path.read_text() == theirs
        assert not await until(pilot, lambda: asked(app), seconds=2.5)  # told once
        await pilot.press("ctrl+s")
        assert await until(pilot, lambda: asked(app))  # Ctrl+S still asks
        await pilot.press("home", "enter")
        assert await until(pilot, lambda: not app.session.unsaved)
        assert "and Ben" not in project_path.read_text()
        assert project_path.with_name("card.toml.bak").read_text() == theirs
        assert not await until(pilot, lambda: asked(app), seconds=2.5)  # its own save: no change


async def test_with_nothing_unsaved_the_changed_file_opens_as_it_is_now_with_one_enter(
        project_path):
    """Nothing edited in the editor, the file changed by `git checkout`: the question has
    "Open the file as it is now" highlighted, and Enter shows their version."""
    async with editor(project_path) as (app, pilot):
        changed_elsewhere(project_path)
        assert await until(pilot, lambda: asked(app))
        assert "Nothing in the editor is unsaved" in app.screen.message
        await pilot.press("enter")
        assert await back_on_editor(pilot, app)
        assert app.session.project.pages[0].item("title").text == "Happy Birthday Anna and Ben"
        assert not app.session.unsaved


async def test_a_change_made_while_a_form_is_open_waits_until_the_form_is_done(project_path):
    """Words typed into the edit form when the file changed behind the editor: the question
    must not open over the form (keys typed would answer it) nor close it; it comes once the
    form is applied, and the applied words are still the editor's to keep."""
    async with editor(project_path) as (app, pilot):
        await pilot.press("tab")
        await pilot.pause()
        assert app.session.selected_id == "title"
        await pilot.press("enter")
        await pilot.pause()
        assert app.screen.id == "edit-dialog"
        changed_elsewhere(project_path)
        await type_text(pilot, " xyz")
        assert not await until(pilot, lambda: asked(app), seconds=2.5)
        assert app.screen.id == "edit-dialog"
        await pilot.press("ctrl+s")  # the form's own Ctrl+S: apply
        await pilot.pause()
        assert await until(pilot, lambda: asked(app))
        await pilot.press("escape")
        assert await back_on_editor(pilot, app)
        assert app.session.unsaved
        assert "xyz" in app.session.project.pages[0].item("title").text


async def test_a_file_only_touched_is_no_change_and_a_removed_one_is_told(project_path):
    """`touch`, or a checkout that writes the same bytes, changes nothing: no question. A
    file removed (or renamed away) is told once, and Ctrl+S writes it again."""
    import os

    async with editor(project_path) as (app, pilot):
        os.utime(project_path, (1e9, 1e9))
        assert not await until(pilot, lambda: asked(app), seconds=2.5)
        project_path.rename(project_path.with_name("moved.toml"))
        told = lambda: any("removed or renamed" in n.message for n in app._notifications)
        assert await until(pilot, told)
        assert app.screen is app.editor
        await pilot.press("ctrl+s")
        await pilot.pause()
        assert project_path.exists()


def phone_photo(path: Path) -> Path:
    """A portrait photo as a phone stores it: 30 x 40 pixels upright (red above, blue
    below), saved turned a quarter (40 x 30) with the EXIF tag that turns it back."""
    from PIL import Image

    upright = Image.new("RGB", (30, 40), BLUE)
    upright.paste(RED, (0, 0, 30, 20))
    exif = Image.Exif()
    exif[0x0112] = 6  # "turn 90° clockwise to show"
    upright.transpose(Image.Transpose.ROTATE_90).save(path, exif=exif.tobytes(), quality=95)
    return path


async def test_a_phones_portrait_photo_is_inserted_upright_in_a_portrait_box(project_path):
    """A phone's portrait photo (stored sideways, with an EXIF turn) got a landscape box and
    showed sideways in the preview; the PDF, which turns it upright, then cut its top and
    bottom off to fill the box. The box is portrait now, and the preview shows it upright."""
    phone_photo(project_path.parent / "pictures" / "phone.jpg")
    async with editor(project_path) as (app, pilot):
        await insert_picture(pilot, "pictures/phone.jpg")
        new = item(app, "picture-1")
        assert new.h / new.w == pytest.approx(40 / 30)
        left, top, right, bottom = item_pixel_box(app, "picture-1")
        middle = (left + right) // 2
        assert near(pixel(app, middle, top + 1), RED) and near(pixel(app, middle, bottom - 2), BLUE)


async def insert_picture(pilot, path: str) -> None:
    """Insert a picture the way a user does: `p`, then its path in the form."""
    await pilot.press("p", "tab")
    await type_text(pilot, path)
    await pilot.press("enter")
    app = pilot.app
    assert await until(pilot, lambda: "picture-1" in app.session.page.item_ids())


def near(colour, wanted, tolerance: int = 60) -> bool:
    return all(abs(a - b) <= tolerance for a, b in zip(colour, wanted))


async def test_a_pdf_logo_gets_its_own_shape_and_is_drawn_in_the_preview(project_path):
    """A shop's logo as a PDF (4:1) got the default 4:3 box, and the preview said
    "unreadable pictures/logo.pdf" in it, as if the file were broken, while the PDF printed
    it. The box takes the PDF page's shape, and the preview draws its first page."""
    from PIL import Image

    logo = Image.new("RGB", (400, 100), BLUE)
    logo.paste(RED, (0, 0, 100, 100))  # a red square at its left end
    logo.save(project_path.parent / "pictures" / "logo.pdf", resolution=100)
    async with editor(project_path) as (app, pilot):
        await insert_picture(pilot, "pictures/logo.pdf")
        new = item(app, "picture-1")
        assert new.h / new.w == pytest.approx(0.25, abs=0.01)
        left, top, right, bottom = item_pixel_box(app, "picture-1")
        middle = (top + bottom) // 2
        assert near(pixel(app, left + 2, middle), RED)
        assert near(pixel(app, (left + right) // 2, middle), BLUE)


async def test_a_price_changed_on_the_flyer_moves_nothing(tmp_path):
    """A price typed anew on the shop flyer ("€2.40" to "€1.99", the same box): the edit
    reheated the page, and Ctrl+S saved every item moved, up to 9 mm, though `floatpage
    settle` of the file with the new price moves nothing. Words, colours and fonts change no
    body the physics moves: nothing is reheated, and the save changes the price alone."""
    import shutil

    folder = tmp_path / "flyer"
    shutil.copytree(ROOT / "sample_projects" / "shop-flyer", folder)
    path = folder / "shop-flyer.toml"
    before = path.read_text()
    async with editor(path, autostart=True) as (app, pilot):
        price = next(i for i in app.session.page.items if "€" in getattr(i, "text", ""))
        app.editor.selected_id = price.id
        await pilot.pause()
        old = price.text
        new = old.replace(old.split("€")[1].split()[0], "1.99")
        await pilot.press("enter")
        await pilot.pause()
        assert app.screen.id == "edit-dialog"
        app.screen.query_one("#field-text").text = new
        await pilot.press("ctrl+s")  # apply the form
        assert await back_on_editor(pilot, app)
        assert app.session.unsaved
        assert await until(pilot, lambda: app.editor.at_rest)
        await pilot.press("ctrl+s")
        await pilot.pause()
        assert not app.session.unsaved
    after = path.read_text()
    assert after == before.replace(toml_string(old), toml_string(new))


def toml_string(text: str) -> str:
    import json

    return json.dumps(text, ensure_ascii=False)
