"""Defects a user of greeting cards, calendars and flyers met in a first week with the editor
(user-walk-9), each driven through the real app with Pilot, on a real project file."""

from __future__ import annotations

from pathlib import Path

from editor_helpers import editor, screen_of

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
