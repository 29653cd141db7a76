"""Snapshots of the editor with the physics frozen: paused (autostart=False), fixed seed, and
the page at rest as saved, so frames repeat whatever the physics' tuning.

Review a changed snapshot in the report before running `pytest --snapshot-update`.
"""

from __future__ import annotations

from floatpage.tui.app import make_app
from floatpage.tui.page_preview import PagePreview

from editor_helpers import dialog_shown, until


def frozen_app(project_path):
    app = make_app(project_path, seed=0, autostart=False)
    app.cursor_blink = False
    return app


async def select(pilot, item_id: str) -> None:
    """Select an item once the editor's preview is mounted: a snapshot's pilot may start
    before the default screen's children are (the event loop's order shuffled showed it,
    tools/shuffled_loop.py), and a selection redraws the preview."""
    assert await until(pilot, lambda: pilot.app.editor.query(PagePreview))
    pilot.app.editor.selected_id = item_id
    await pilot.pause()


def opened(key: str, dialog_id: str, typed: str = ""):
    """A snapshot's ``run_before``: ``key`` opens ``dialog_id``, and ``typed`` goes into its
    focused field; taken once the dialog is mounted and has the words. The snapshot's own
    ``press`` looks once, after a pause, which the keys typed ahead of a dialog (held until
    it is mounted) can outlast on a loaded machine."""
    async def run_before(pilot) -> None:
        app = pilot.app
        await pilot.press(key, *typed)
        assert await dialog_shown(pilot, app, dialog_id)
        if typed:
            assert await until(pilot, lambda: getattr(app.screen.focused, "text", "") == typed)

    return run_before


def test_main_screen(project_path, snap_compare):
    """The front page of the test card, A5 portrait, centred on a dark surround: a faintly
    pink box with 'Happy Birthday Anna' in dark red, the photo thumbnail (red over blue) and
    its grey caption 'Summer' right under it, each with a blue 'o' beside it (the caption
    follows the photo; the marks sit beside them, hiding neither), a green block framed in
    yellow and labelled 'block' (selected: only the selected item shows its id), and the
    decorative yellow band behind the March 2027 grid (title and five weeks: every day),
    whose anchor shows as a magenta digit.
    The top bar names the selected block, its size and where it is ('at 115, 85 mm'); the
    status lines speak words ('paused · Space resumes', 'no overlaps · gaps kept · v details'); the footer fits 100 columns: Help,
    Save, Export and Quit first, then the item commands while they fit."""
    async def run_before(pilot) -> None:
        await select(pilot, "block")

    assert snap_compare(frozen_app(project_path), terminal_size=(100, 34), run_before=run_before)


def test_main_screen_80x24(project_path, snap_compare):
    """The same page in the smallest supported terminal: the whole page still fits, and the
    calendar shows every day of March in its 4 rows, two cells a day, every other day on a
    darker shade (1-8, 9-16, 17-24, 25-31); the link's 'o' marks sit left of the photo and
    of its caption; nothing is selected, so the footer starts
    with the page commands: '? Help', 'tab Next', 'itpbcg Insert', '][NDSo Page', Pause."""
    assert snap_compare(frozen_app(project_path), terminal_size=(80, 24))


def test_help_screen(project_path, snap_compare):
    """The help dialog over the editor: 'floatpage keys', then groups (Select, Move and resize,
    Insert, ...) listing each key and what it does."""
    assert snap_compare(frozen_app(project_path), run_before=opened("question_mark", "help"),
                        terminal_size=(100, 34))


def test_insert_dialog(project_path, snap_compare):
    """The Insert dialog over the editor: Text box (highlighted), Picture…, Colour block,
    Calendar month, Background…, with 'Enter chooses · Esc cancels' under the list."""
    assert snap_compare(frozen_app(project_path), run_before=opened("i", "insert-dialog"),
                        terminal_size=(100, 34))


def test_insert_text_dialog(project_path, snap_compare):
    """The text box form: a 'Text' area holding 'Hello', an empty error line, the hint and
    OK / Cancel buttons."""
    assert snap_compare(frozen_app(project_path),
                        run_before=opened("t", "text-dialog", typed="Hello"),
                        terminal_size=(100, 34))


def test_insert_dialog_at_40x12(project_path, snap_compare):
    """The Insert dialog on a 40 x 12 terminal: no padding and no top or bottom border, the
    title 'Insert', all five choices (Text box highlighted, Picture…, Colour block, Calendar
    month, Background…) with no frame around the list, and 'Enter chooses · Esc cancels' on
    the line under them; the page's top bar above and the footer below still show."""
    assert snap_compare(frozen_app(project_path), run_before=opened("i", "insert-dialog"),
                        terminal_size=(40, 12))


def test_edit_form_at_20x6(project_path, snap_compare):
    """The title's edit form on a 20 x 6 terminal: 'Edit title (text)', then the field's
    last two rows, 'Birthday' and 'Anna', with the cursor after its last a (the form opens
    with the cursor after the words, scrolled past the 'Text' label to show it; a scroll bar
    at the right; user-walk-10),
    'Esc cancels' alone as the hint, and the OK and Cancel buttons on the last row."""
    async def run_before(pilot) -> None:
        await select(pilot, "title")
        await pilot.press("enter")
        assert await dialog_shown(pilot, pilot.app, "edit-dialog")
        fields = pilot.app.screen.query_one(".form-fields")
        # the form scrolls to the cursor once its words are wrapped
        assert await until(pilot, lambda: fields.scroll_y > 0)

    assert snap_compare(frozen_app(project_path), run_before=run_before, terminal_size=(20, 6))


def test_dialog_below_20x6(project_path, snap_compare):
    """The Insert dialog on an 18 x 5 terminal: in its place, on red, 'Terminal too small:
    make it 20 × 6 or more (now 18 × 5). Esc cancels.', wrapped over the width."""
    assert snap_compare(frozen_app(project_path), run_before=opened("i", "insert-dialog"),
                        terminal_size=(18, 5))
