"""Defects found by user-walk-12a: the editor over SSH, and the last walk's leftovers."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from editor_helpers import editor, paint_picture, screen_of, type_text, until
from test_editor_walk11 import every_page_a6, hold_room_searches, overlaps_in, three_months

ROOT = Path(__file__).resolve().parents[2]


async def test_a_save_right_after_a_new_page_size_waits_for_the_room(tmp_path):
    """Ctrl+S pressed right after `S` to A6 on every page saved the months with their photos
    piled on the titles and grids (the room searches not done); the searches' answers came
    after and marked the project unsaved again, and a user who saved and closed the link had
    a file with 5, 4 and 4 overlaps.  Ctrl+S waits for the room, as Ctrl+E does, says so on
    the status line, then saves the pages as the searches leave them."""
    path = three_months(tmp_path)
    async with editor(path, autostart=True) as (app, pilot):
        gate = hold_room_searches(app)
        await every_page_a6(app, pilot)
        assert app.editor.room_searches
        await pilot.press("ctrl+s")
        assert await until(pilot, lambda: "save once room is found" in app.editor.state_word())
        assert app.session.unsaved
        gate.set()
        assert await until(pilot, lambda: not app.editor.room_searches
                           and not app.session.unsaved, 240)
    assert overlaps_in(path) == {"jan": 0, "may": 0, "jul": 0}


def flyer(tmp_path):
    folder = tmp_path / "flyer"
    shutil.copytree(ROOT / "sample_projects" / "shop-flyer", folder)
    return folder / "shop-flyer.toml"


async def insert_text(app, pilot, words: str):
    await pilot.press("t")
    await until(pilot, lambda: app.screen.id == "text-dialog")
    await type_text(pilot, words)
    await pilot.press("tab", "enter")
    await until(pilot, lambda: app.screen is app.editor)
    return app.session.page.item(app.session.selected_id)


async def test_a_new_text_takes_the_look_of_the_selected_text_or_of_the_pages_texts(tmp_path):
    """A text inserted on the flyer came in as a 94 x 31 mm box of black serif among 36 x 14
    mm price tags in red bold sans (user-walk-11's leftover).  With nothing selected it takes
    the look and box most of the page's texts share (six of its eight are price tags); with
    the title selected, the title's.  Never the role: a longer text in the price role would
    shrink every price.  Saved as shown."""
    from floatpage.model import load_project

    path = flyer(tmp_path)
    async with editor(path) as (app, pilot):
        gate = hold_room_searches(app)  # the items read as the insert made them
        price = app.session.page.item("product-1-price")
        new = await insert_text(app, pilot, "Open Sundays")
        assert (new.font, new.color, new.bold, new.w, new.h) == (
            price.font, price.color, price.bold, price.w, price.h) == ("sans", "#c0392b", True,
                                                                        36.0, 14.0)
        assert new.role == "" and price.role == "price"
        screen_of(app).selected_id = "shop-title"
        await pilot.pause()
        title = app.session.page.item("shop-title")
        second = await insert_text(app, pilot, "Summer sale")
        assert (second.font, second.color, second.bold, second.w, second.h) == (
            "display", title.color, True, title.w, title.h)
        gate.set()
        await pilot.press("ctrl+s")
        assert await until(pilot, lambda: not app.session.unsaved, 60)
    saved = load_project(path).pages[0]
    assert (saved.item(new.id).font, saved.item(new.id).color) == ("sans", "#c0392b")
    assert saved.item(second.id).font == "display"


async def test_a_new_picture_is_as_large_as_the_selected_one_in_its_own_shape(tmp_path):
    """A photo put into the flyer came in 84 mm wide among 35 mm ones.  It takes the area of
    the selected picture (or the page's median), in its own file's shape: a portrait photo
    beside square ones is as large, not as wide."""
    path = flyer(tmp_path)
    paint_picture(path.parent / "pictures" / "tall.png", (30, 60))
    async with editor(path) as (app, pilot):
        gate = hold_room_searches(app)  # the picture read as the insert made it
        screen_of(app).selected_id = "product-1"
        await pilot.pause()
        apples = app.session.page.item("product-1")
        await pilot.press("p")
        await until(pilot, lambda: app.screen.id == "picture-dialog")
        await pilot.press("tab", *"pictures/tall.png", "enter")
        await until(pilot, lambda: app.screen is app.editor)
        new = app.session.page.item(app.session.selected_id)
        assert new.path == "pictures/tall.png"
        assert new.h == pytest.approx(2 * new.w)
        assert new.w * new.h == pytest.approx(apples.w * apples.h)
        gate.set()


async def test_a_new_block_offers_the_colour_of_the_selected_block(tmp_path):
    """The colour block's form showed the default grey, and what the form shows is what the
    block takes: the selected block's colour is offered, and taken with its size."""
    path = flyer(tmp_path)
    async with editor(path) as (app, pilot):
        gate = hold_room_searches(app)  # the block read as the insert made it
        band = app.session.page.item("header-stripe")
        screen_of(app).selected_id = band.id
        await pilot.pause()
        await pilot.press("b")
        await until(pilot, lambda: app.screen.id == "block-dialog")
        assert app.screen.query_one("Input").value == band.color
        await pilot.press("enter")
        await until(pilot, lambda: app.screen is app.editor)
        new = app.session.page.item(app.session.selected_id)
        assert (new.kind, new.color, new.w, new.h) == ("block", band.color, band.w, band.h)
        gate.set()


async def test_a_region_with_no_item_in_it_can_be_changed_and_removed(tmp_path):
    """`R` with nothing selected made a new region every time: a region holding no item (made
    by a stray `R`, or kept empty) could be neither changed nor removed in the editor, only
    undone at once, and after a save only in a text editor.  With nothing selected on a page
    that has regions, `R` asks: a new one, or one of the page's; an empty name removes it."""
    from floatpage.model import load_project

    folder = tmp_path / "card"
    shutil.copytree(ROOT / "sample_projects" / "greeting-card", folder)
    path = folder / "greeting-card.toml"
    async with editor(path) as (app, pilot):
        await pilot.press("R")
        await until(pilot, lambda: app.screen.id == "region-dialog")
        await pilot.press("enter")  # the page's top two-thirds, as offered
        await until(pilot, lambda: app.screen is app.editor)
        assert [region.id for region in app.session.page.regions] == ["region-1"]
        await pilot.press("ctrl+s")
        assert await until(pilot, lambda: not app.session.unsaved, 60)
    async with editor(path) as (app, pilot):  # reopened: no undo to take it away
        await pilot.press("R")
        assert await until(pilot, lambda: app.screen.id == "which-region-dialog"), app.screen.id
        await pilot.press("down", "enter")  # region-1
        await until(pilot, lambda: app.screen.id == "region-dialog")
        name = app.screen.query_one("Input")
        assert name.value == "region-1" and name.has_focus
        await pilot.press(*["backspace"] * len(name.value), "enter")  # an empty name removes it
        await until(pilot, lambda: app.screen is app.editor)
        assert app.session.page.regions == []
        await pilot.press("ctrl+s")
        assert await until(pilot, lambda: not app.session.unsaved, 60)
    assert load_project(path).pages[0].regions == []


async def group_two_photos(app, pilot) -> None:
    for photo in ("p1-photo-1", "p1-photo-2"):
        screen_of(app).selected_id = photo
        await pilot.pause()
        await pilot.press("G")
        await until(pilot, lambda: app.screen.id == "group-dialog")
        await type_text(pilot, "toprow")
        await pilot.press("enter")
        await until(pilot, lambda: app.screen is app.editor)
    assert [item.id for item in app.session.page.group_members("toprow")] == [
        "p1-photo-1", "p1-photo-2"]


def form_words(app) -> str:
    return " ".join(str(label.render()) for label in app.screen.query("Label"))


async def region_form(app, pilot, *numbers: str) -> None:
    """`R` on the selected item, the region's left, top, width and height typed."""
    await pilot.press("R")
    await until(pilot, lambda: app.screen.id == "region-dialog")
    for typed in numbers:
        await pilot.press("tab", *typed)
    await pilot.press("enter")


async def test_a_group_member_put_in_a_region_takes_its_group_along(tmp_path):
    """Two album photos grouped, the first then kept inside a new region at the page's foot
    with `R`: the first photo (and its caption) jumped into the region and the second stayed
    at the top, so the group, one body, was 220 mm tall for a region of 97, and `check` said
    no settle could fit it (2 overlaps).  The group (with its captions) goes into the region
    together, keeping its shape; a region that leaves the group no place (the photo inside
    it, its caption and the other photo inside the margins) is refused in the form, with the
    group named and what to do."""
    folder = tmp_path / "album"
    shutil.copytree(ROOT / "sample_projects" / "photo-album", folder)
    async with editor(folder / "photo-album.toml", autostart=True) as (app, pilot):
        await group_two_photos(app, pilot)
        screen_of(app).selected_id = "p1-photo-1"
        await pilot.pause()
        page = app.session.page
        app.session.sync_positions()
        apart = page.item("p1-photo-2").x - page.item("p1-photo-1").x
        # at the page's foot, 60 mm: the photo's caption would fall past the bottom margin
        await region_form(app, pilot, "0", "237", "210", "60")
        assert await until(pilot, lambda: "moves as one" in form_words(app)), form_words(app)
        assert app.screen.id == "region-dialog"  # refused: the form stays open
        assert 'group "toprow"' in form_words(app), form_words(app)
        assert "no place on the page" in form_words(app)
        await pilot.press("escape")
        await until(pilot, lambda: app.screen is app.editor)
        await region_form(app, pilot, "0", "200", "210", "97")
        assert await until(pilot, lambda: app.screen is app.editor)
        app.session.sync_positions()
        body = [page.item(name) for name in ("p1-photo-1", "p1-photo-2", "p1-photo-1-caption",
                                             "p1-photo-2-caption")]
        assert all(item.y - item.h / 2 >= 200 - 0.01 and item.y + item.h / 2 <= 297.01
                   for item in body), [(item.id, item.y) for item in body]
        assert page.item("p1-photo-2").x - page.item("p1-photo-1").x == pytest.approx(apart)
        assert await until(pilot, lambda: app.editor.at_rest, 120)  # the photo below makes way
        quality = app.session.engine.quality()
        assert quality.overlapping_pairs == (), quality.summary()


async def test_a_group_member_is_not_kept_in_a_region_its_group_cannot_fit_from_the_form(tmp_path):
    """The same through `Enter`'s "Keep inside region": a grouped photo was confined to a
    region 60 mm tall that its group (68 mm with the captions) could never fit, without a
    word; `check` then found no settle that fits it.  The form says why and stays open."""
    from textual.widgets import Select

    folder = tmp_path / "album"
    shutil.copytree(ROOT / "sample_projects" / "photo-album", folder)
    async with editor(folder / "photo-album.toml") as (app, pilot):
        await pilot.press("R")  # nothing selected: a new region, typed
        await until(pilot, lambda: app.screen.id == "region-dialog")
        for typed in ("0", "230", "210", "60"):
            await pilot.press("tab", *typed)
        await pilot.press("enter")
        assert await until(pilot, lambda: app.screen is app.editor)
        await group_two_photos(app, pilot)
        screen_of(app).selected_id = "p1-photo-1"
        await pilot.pause()
        await pilot.press("enter")
        await until(pilot, lambda: app.screen.id == "edit-dialog")
        app.screen.query_one(Select).value = "region-1"
        await pilot.press("ctrl+s")
        assert await until(pilot, lambda: app.screen is app.editor)
        told = [n.message for n in app._notifications if "moves as one" in n.message]
        assert told and 'group "toprow"' in told[0] and 'region "region-1"' in told[0], told
        assert app.session.page.item("p1-photo-1").region == ""


async def test_a_turned_page_fits_a_confined_photo_with_its_caption_in_its_region(tmp_path):
    """An album photo kept in a region around it with its caption, the page then turned with
    `o`: the region, scaled with the page, came out 62 mm tall, and the photo alone was fitted
    to it, its caption left below, outside: the status line said the photo was too large for
    its room, and `check` that no settle could fit them.  The photo and its caption shrink
    together until they fit the region."""
    from floatpage.model import load_project
    from floatpage.model.layout import engine_for_page

    folder = tmp_path / "album"
    shutil.copytree(ROOT / "sample_projects" / "photo-album", folder)
    path = folder / "photo-album.toml"
    async with editor(path, autostart=True) as (app, pilot):
        screen_of(app).selected_id = "p1-photo-5"
        await pilot.pause()
        await pilot.press("R")
        await until(pilot, lambda: app.screen.id == "region-dialog")
        await pilot.press("enter")  # around the photo and its caption, the photo kept inside
        assert await until(pilot, lambda: app.screen is app.editor)
        assert app.session.page.item("p1-photo-5").region == "region-1"
        await pilot.press("o")
        await until(pilot, lambda: app.screen.id == "which-pages-dialog")
        await pilot.press("enter")  # every page
        await until(pilot, lambda: app.screen is app.editor)
        assert await until(pilot, lambda: not app.editor.room_searches and app.editor.at_rest,
                           120)
        await pilot.press("ctrl+s")
        assert await until(pilot, lambda: not app.session.unsaved, 120)
    project = load_project(path)
    page = project.pages[0]
    assert page.orientation == "landscape"
    quality = engine_for_page(page, project.physics).quality()
    assert quality.outside_region == () and quality.overlapping_pairs == (), quality.summary()


def test_the_details_view_keeps_the_alignment_figures_at_80_columns_while_settling():
    """At 80 columns, while the page settled, the details view's quality line ended
    "balance 0.99 · misses 3.60…": the edge lines and the share aligned fell off its end
    (in tmux, the flyer reheated with `r`; the settling lasts under a second, too short to
    catch in a Pilot test, so the lines are built here as the screen builds them, with the
    flyer's own measures).  The figures go first on the first line, as at rest, and the
    frame figures give way to them."""
    from floatpage.model import load_project
    from floatpage.model.layout import engine_for_page
    from floatpage.tui.status_line import Status, fitted, status_text

    project = load_project(ROOT / "sample_projects" / "shop-flyer" / "shop-flyer.toml")
    engine = engine_for_page(project.pages[0], project.physics)
    status = Status(state="settling", energy=10.2, fps=28.9, steps_per_s=2890.0,
                    quality=engine.quality().summary(), frame_ms=21.3, details=True,
                    alignment=engine.alignment().short())
    width = 80 - 2  # the status line's padding
    lines = [fitted(line, width) for line in status_text(status).split("\n")]
    assert all(len(line) <= width for line in lines), lines
    shown = " ".join(lines)
    assert "misses " in shown and "lines " in shown and "aligned " in shown, lines
    assert "balance " in shown and "energy " in shown, lines


async def test_a_new_text_does_not_copy_a_pages_only_text(tmp_path):
    """One text is no style a page repeats: on a calendar month, whose only text is its
    186 x 24 mm month name, a note typed with nothing selected took the month name's box and
    display face (the look "most of the page's texts" share, with one text).  It comes at the
    defaults; selected, the month name still gives its look."""
    path = three_months(tmp_path)
    async with editor(path) as (app, pilot):
        gate = hold_room_searches(app)  # the items read as the insert made them
        month_name = next(item for item in app.session.page.items if item.kind == "text")
        note = await insert_text(app, pilot, "Holiday")
        assert (note.font, note.w) != (month_name.font, month_name.w)
        assert note.font == "serif"
        screen_of(app).selected_id = month_name.id
        await pilot.pause()
        copy = await insert_text(app, pilot, "Enero")
        assert (copy.font, copy.color, copy.w) == (month_name.font, month_name.color,
                                                   month_name.w)
        gate.set()
