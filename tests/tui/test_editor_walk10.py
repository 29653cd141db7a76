"""Defects a user of greeting cards, calendars and flyers met in a first week with the editor
(user-walk-10), each driven through the real app with Pilot, on a real project file."""

from __future__ import annotations

from textual.widgets import TextArea

from editor_helpers import editor, item, type_text


async def test_the_edit_form_opens_with_the_cursor_after_the_words(project_path):
    """Enter on the title opened its form with the cursor before "Happy Birthday Anna": the
    words a user added to the end landed at the start.  The cursor is now after the last
    word, so typing adds to the end, and the form applies what was typed."""
    async with editor(project_path) as (app, pilot):
        app.editor.selected_id = "title"
        await pilot.pause()
        await pilot.press("enter")
        await pilot.pause()
        area = app.screen.query_one(TextArea)
        assert area.has_focus
        assert area.cursor_location == area.document.end
        await type_text(pilot, " and Ben")
        await pilot.press("ctrl+s")
        await pilot.pause()
        assert item(app, "title").text == "Happy Birthday Anna and Ben"
