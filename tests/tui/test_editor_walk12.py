"""Defects found by user-walk-12a: the editor over SSH, and the last walk's leftovers."""

from __future__ import annotations

from editor_helpers import editor, until
from test_editor_walk11 import every_page_a6, hold_room_searches, overlaps_in, three_months


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
