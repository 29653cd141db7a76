"""Defects a user of greeting cards, calendars and flyers met in a first week with the editor
(user-walk-9), each driven through the real app with Pilot, on a real project file."""

from __future__ import annotations

from editor_helpers import editor, screen_of


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
