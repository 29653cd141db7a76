"""Defects a user of greeting cards, calendars and flyers met in a first week with the editor
(user-walk-10), each driven through the real app with Pilot, on a real project file."""

from __future__ import annotations

import pytest
from textual.widgets import TextArea

from editor_helpers import (
    back_on_editor, dialog_shown, editor, item, keys_go_straight_in, notices, told, type_text,
    until,
)


async def test_the_edit_form_opens_with_the_cursor_after_the_words(project_path):
    """Enter on the title opened its form with the cursor before "Happy Birthday Anna": the
    words a user added to the end landed at the start.  The cursor is now after the last
    word, so typing adds to the end, and the form applies what was typed."""
    async with editor(project_path) as (app, pilot):
        app.editor.selected_id = "title"
        await pilot.pause()
        await pilot.press("enter")
        assert await dialog_shown(pilot, app, "edit-dialog")
        area = app.screen.query_one(TextArea)
        # the focus and the cursor's move to the end come a message and a refresh later
        assert await until(pilot, lambda: area.has_focus
                           and area.cursor_location == area.document.end), \
            (area.has_focus, area.cursor_location)
        await type_text(pilot, " and Ben")
        await pilot.press("ctrl+s")
        assert await until(pilot, lambda: item(app, "title").text == "Happy Birthday Anna and Ben")


def sizes(project) -> list[tuple[str, float, float]]:
    return [(page.size, page.width_mm, page.height_mm) for page in project.pages]


async def choose_size(app, pilot, name: str) -> None:
    """`S`, then the named size in the list."""
    await pilot.press("S")
    await pilot.pause()
    assert app.screen.id == "page-size-dialog"
    options = [str(option.prompt) for option in app.screen.query_one("OptionList").options]
    await pilot.press("home", *["down"] * next(
        index for index, option in enumerate(options) if option.startswith(name + " ")),
        "enter")
    # until the list's answer is through: the next question open, or the size taken
    assert await until(pilot, lambda: app.screen.id != "page-size-dialog"
                       and keys_go_straight_in(app))


async def test_a_page_size_for_every_page_is_one_undo_step_and_is_saved(project_path):
    """`S` changed the page on screen only: a card (or a calendar, an album) made A6 kept its
    other pages at A5.  With several pages `S` asks "Every page" or "This page only", the
    first highlighted where the pages are one size; every page takes it (its items moved in
    proportion, as on the page on screen), one Ctrl+Z brings every page back, Ctrl+Y does it
    again, and the file saved holds the size on every page."""
    from floatpage.model import load_project

    async with editor(project_path) as (app, pilot):
        greeting = app.session.project.pages[1].item("greeting")  # on the back
        x, y = greeting.x, greeting.y
        await choose_size(app, pilot, "A6")
        assert app.screen.id == "which-pages-dialog"
        await pilot.press("enter")  # highlighted: every page (both are A5)
        assert await back_on_editor(pilot, app)  # the answer has started the room searches
        await app.workers.wait_for_complete()
        project = app.session.project
        assert sizes(project) == [("A6", 105.0, 148.0)] * 2
        back = project.pages[1].item("greeting")
        assert (back.x, back.y) == pytest.approx((x * 105 / 148, y * 148 / 210), abs=1.5)
        await pilot.press("ctrl+z")
        assert sizes(app.session.project) == [("A5", 148.0, 210.0)] * 2
        await pilot.press("ctrl+y", "ctrl+s")
        assert not app.session.unsaved
    assert sizes(load_project(project_path)) == [("A6", 105.0, 148.0)] * 2


async def test_this_page_only_keeps_the_others_and_is_offered_first_where_sizes_differ(
        project_path):
    """"This page only": a card's inside may differ from its front.  Once the pages differ,
    the next `S` highlights "This page only"."""
    async with editor(project_path) as (app, pilot):
        await choose_size(app, pilot, "A6")
        await pilot.press("down", "enter")
        assert await back_on_editor(pilot, app)
        assert sizes(app.session.project) == [("A6", 105.0, 148.0), ("A5", 148.0, 210.0)]
        await choose_size(app, pilot, "A4")
        options = app.screen.query_one("OptionList")
        assert str(options.get_option_at_index(options.highlighted).prompt) \
            == "This page only (front)"
        await pilot.press("escape")
        assert await back_on_editor(pilot, app)
        assert sizes(app.session.project) == [("A6", 105.0, 148.0), ("A5", 148.0, 210.0)]


async def test_the_size_every_page_has_already_asks_nothing(project_path):
    """Enter on the size the pages already have (the list opens on it) asked "Every page or
    this page only?" of a change that changed nothing; it asks nothing now, and nothing
    changes (no undo step, nothing unsaved)."""
    async with editor(project_path) as (app, pilot):
        await choose_size(app, pilot, "A5")
        assert app.screen is app.editor
        assert not app.session.unsaved and not app.session.history.undo_stack


async def test_undoing_a_group_says_it_was_the_group(project_path):
    """`G` put a picture in a group, and Ctrl+Z said "undid edit photo": which edit, the
    user could not tell.  It says "undid group photo", and Ctrl+Y "redid group photo"."""
    async with editor(project_path) as (app, pilot):
        app.editor.selected_id = "photo"
        await pilot.pause()
        await pilot.press("G")
        assert app.screen.id == "group-dialog"
        await type_text(pilot, "pics")
        await pilot.press("enter")
        assert await back_on_editor(pilot, app)
        assert item(app, "photo").group == "pics"
        await pilot.press("ctrl+z")
        assert item(app, "photo").group == ""
        assert await told(pilot, app, lambda said: said[-1:] == ["undid group photo"]), \
            notices(app)
        await pilot.press("ctrl+y")
        assert await told(pilot, app, lambda said: said[-1:] == ["redid group photo"]), \
            notices(app)
