"""Issue 11: a keyboard-only flow fits in 80x24.  From a blank project, by keys alone: insert a
text and a colour block through their dialogs, move and grow the text, anchor it, undo and
redo, add a page, save, export a real PDF and quit, with every dialog and the footer's
essentials on screen at 80 columns by 24 rows."""

from __future__ import annotations

import pdfplumber

from floatpage.model import Page, Project, load_project, save_project
from floatpage.tui.key_bar import KeyBar
from editor_helpers import back_on_editor, editor, press_then_quit, screen_of, type_text, until

SIZE = (80, 24)


def fits(app) -> None:
    """The open dialog's frame lies within 80 x 24 (a long text inside it scrolls), and the
    footer keeps its essentials."""
    for dialog in app.screen.query(".dialog"):
        region = dialog.region
        assert region.width and region.height
        assert region.right <= SIZE[0] and region.bottom <= SIZE[1], (dialog, region)
    bar = screen_of(app).query_one(KeyBar)
    assert {"help", "save", "export_pdf", "quit"} <= set(bar.actions)


async def test_a_whole_keyboard_flow_at_80x24(tmp_path):
    path = tmp_path / "flow.toml"
    save_project(Project(title="Flow", pages=[Page(id="p1", size="A5", width_mm=148.0,
                                                   height_mm=210.0)]), path)
    async with editor(path, size=SIZE) as (app, pilot):
        await pilot.press("t")
        await pilot.pause()
        assert app.screen.id == "text-dialog"
        fits(app)
        await type_text(pilot, "Hello from the keyboard")
        await pilot.press("ctrl+s")  # applies the form
        assert await back_on_editor(pilot, app)
        assert len(app.session.page.items) == 1
        await pilot.press("b")
        await pilot.pause()
        assert app.screen.id == "block-dialog"
        fits(app)
        await pilot.press("enter")
        assert await back_on_editor(pilot, app)  # Tab, next, goes to the editor at once
        assert len(app.session.page.items) == 2
        text = next(item for item in app.session.page.items if item.kind == "text")
        screen_of(app).selected_id = None
        while app.session.selected_id != text.id:
            await pilot.press("tab")
        await pilot.press("right", "right", "plus", "a")
        await pilot.pause()
        screen_of(app).release_held()
        assert app.session.page.item(text.id).anchor is not None
        await pilot.press("ctrl+z", "ctrl+y")
        await pilot.press("N")  # a second page
        await pilot.pause()
        assert len(app.session.project.pages) == 2
        fits(app)
        await pilot.press("question_mark")
        await pilot.pause()
        assert app.screen.id == "help"
        fits(app)
        await pilot.press("escape")
        assert await back_on_editor(pilot, app)
        await pilot.press("ctrl+s")
        assert not app.session.unsaved
        await pilot.press("ctrl+e")
        await app.workers.wait_for_complete()
        if app.session.unsaved:  # the export's pass moved an item (an edit): `q` asks
            await pilot.press("q")
            assert app.screen.id == "quit-dialog"
        else:
            assert await press_then_quit(pilot, "q")
    saved = load_project(path)
    assert [len(page.items) for page in saved.pages] == [2, 0]
    with pdfplumber.open(path.with_suffix(".pdf")) as pdf:
        assert len(pdf.pages) == 2
        words = pdf.pages[0].extract_text()
    assert "Hello" in words and "keyboard" in words
