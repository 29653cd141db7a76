"""Shared helpers for driving the editor with Pilot and reading its preview."""

from __future__ import annotations

from contextlib import asynccontextmanager
from pathlib import Path

from PIL import Image

from floatpage.tui.app import FloatpageApp, make_app
from floatpage.tui.editor_screen import EditorScreen

SIZE = (100, 40)
RED = (220, 30, 30)
BLUE = (30, 60, 220)


def paint_picture(path: Path, size=(40, 30)) -> Path:
    """A 4:3 picture, red on top and blue below, so a thumbnail is easy to recognise."""
    image = Image.new("RGB", size, BLUE)
    image.paste(RED, (0, 0, size[0], size[1] // 2))
    path.parent.mkdir(parents=True, exist_ok=True)
    image.save(path)
    return path


@asynccontextmanager
async def editor(path: Path, size: tuple[int, int] = SIZE, *, autostart: bool = False):
    """The real app on a project file, physics paused unless autostart; yields (app, pilot)."""
    app = make_app(path, autostart=autostart)
    async with app.run_test(size=size) as pilot:
        await pilot.pause()
        yield app, pilot


DEADLINE_S = 60.0  # how long a wait gives a condition: minutes on no machine we know of


async def until(pilot, condition, seconds: float = DEADLINE_S) -> bool:
    """Wait, a tenth of a second at a time, until ``condition()`` holds, at most ``seconds``:
    a fixed pause that suits an idle machine is too short on a loaded CI runner. The deadline
    is generous (a lost key or a broken feature still fails, only later); a test that wants
    "never" passes a short one of its own."""
    for _ in range(int(seconds / 0.1)):
        if condition():
            return True
        await pilot.pause(0.1)
    return condition()


def keys_go_straight_in(app: FloatpageApp) -> bool:
    """No key is held back by the App's type-ahead (`tui.type_ahead`): no screen is still
    opening and no dialog's answer is still on its way, so a key pressed now is handled in
    its turn. After an Enter or Esc that answers a dialog, the keys typed next wait until
    the answer is through, several turns of the loop later. A dialog's answer reaches the
    editor by a callback the App runs after the dialog is off the stack (Textual's
    `call_next`), so nothing may be left pending on the App either."""
    waiting = app.type_ahead
    return (waiting.opening is None and not waiting.answering and not waiting.waiting
            and not app._next_callbacks and app._message_queue.empty())


async def back_on_editor(pilot, app: FloatpageApp, seconds: float = DEADLINE_S) -> bool:
    """Until every dialog is closed, its answer handled and the keys typed meanwhile handed
    on: a dialog closes by a chain of messages (the key to its list, the list's choice, the
    dialog's answer, the callback on the App), which one pause does not wait out on a
    loaded machine."""
    return await until(pilot, lambda: app.screen is app.editor and keys_go_straight_in(app),
                       seconds)


async def every_page_resized_and_saved(app: FloatpageApp, pilot, size: str) -> None:
    """`S`, the size whose name starts with ``size`` ("A6 "), every page; then, once the room
    searches have answered, Ctrl+S, and wait until it is saved (the editor must run: a save
    settles)."""
    await pilot.press("S")
    assert await until(pilot, lambda: app.screen.id == "page-size-dialog")
    options = [str(option.prompt) for option in app.screen.query_one("OptionList").options]
    await pilot.press("home", *["down"] * next(
        index for index, option in enumerate(options) if option.startswith(size)), "enter")
    assert await until(pilot, lambda: app.screen.id == "which-pages-dialog")
    await pilot.press("enter")  # every page
    assert await back_on_editor(pilot, app)
    assert await until(pilot, lambda: not app.session.room_wanted
                       and not app.editor.room_searches, 240)
    await app.workers.wait_for_complete()
    await pilot.press("ctrl+s")
    assert await until(pilot, lambda: not app.session.unsaved, 120)


async def dialog_shown(pilot, app: FloatpageApp, dialog_id: str,
                       seconds: float = DEADLINE_S) -> bool:
    """Until the dialog ``dialog_id`` is on top, mounted, and takes the keys typed to it (the
    keys typed while it opened are handed to it first)."""
    return await until(pilot, lambda: app.screen.id == dialog_id and app.screen.is_mounted
                       and keys_go_straight_in(app), seconds)


async def answer_form(pilot, app: FloatpageApp, *keys: str, error: str = "#form-error") -> None:
    """Press ``keys`` (Enter, or Ctrl+S) in a form, until its answer is through: the form
    closed and its answer handled (`back_on_editor`'s test), or the form's error line says
    something new. Either comes a few messages after the key; one pause read the form
    still open, or the old error, on a loaded machine."""
    before = words_in(app, error)
    form = app.screen

    def answered() -> bool:
        if app.screen is app.editor:
            return keys_go_straight_in(app)
        return app.screen is form and words_in(app, error) != before

    await pilot.press(*keys)
    assert await until(pilot, answered), (app.screen.id, words_in(app, error))


async def press_then_quit(pilot, *keys: str, seconds: float = DEADLINE_S) -> bool:
    """Press ``keys``, the last of which quits the editor, and wait until the App exits.
    Pilot's own ``press`` then waits for the screen to handle every message it has queued;
    a screen the exit closes never does, and Pilot gave up after 30 s with its
    WaitForScreenTimeout (seen under `tools/shuffled_loop.py`). So the last key is sent as
    Pilot sends it, and the wait is for the exit alone, by the loop's clock."""
    import asyncio

    app = pilot.app
    *first, last = keys
    if first:
        await pilot.press(*first)
    await app._press_keys([last])
    for _ in range(int(seconds / 0.1)):
        if app._exit:
            return True
        await asyncio.sleep(0.1)
    return bool(app._exit)


def notices(app: FloatpageApp) -> list[str]:
    """The words of the notices the App holds, oldest first."""
    return [notification.message for notification in app._notifications]


async def told(pilot, app: FloatpageApp, check, seconds: float = DEADLINE_S) -> bool:
    """Until ``check(notices(app))`` holds: a notice is a message (Textual's ``notify`` posts
    it to the App), handled a turn after the key that gave it, which may be after the key's
    ``press`` has returned."""
    return await until(pilot, lambda: check(notices(app)), seconds)


def words_in(app: FloatpageApp, selector: str) -> str:
    """What the widget ``selector`` on the top screen shows ("" while there is none): for
    waiting on a form's error, which comes a few messages after the Enter that asked."""
    from textual.css.query import NoMatches
    try:
        return str(app.screen.query_one(selector).render())
    except NoMatches:
        return ""


def screen_of(app: FloatpageApp) -> EditorScreen:
    return app.editor


def item(app: FloatpageApp, item_id: str):
    """The model's item, with the engine's live position written back."""
    session = app.session
    session.sync_positions()
    return session.page.item(item_id)


def position(app: FloatpageApp, item_id: str) -> tuple[float, float]:
    return app.session.engine.positions()[item_id]


async def type_text(pilot, text: str) -> None:
    await pilot.press(*[{" ": "space"}.get(char, char) for char in text])


def preview_text(app: FloatpageApp) -> str:
    return "\n".join(screen_of(app).preview.text_lines())


def pixel(app: FloatpageApp, col: int, pixel_row: int) -> tuple[int, int, int]:
    canvas = screen_of(app).preview.canvas
    return tuple(int(v) for v in canvas.pixels[pixel_row, col])


def item_pixel_box(app: FloatpageApp, item_id: str) -> tuple[int, int, int, int]:
    preview = screen_of(app).preview
    x, y = position(app, item_id)
    it = app.session.page.item(item_id)
    return preview.projection.rect(x, y, it.w, it.h)
