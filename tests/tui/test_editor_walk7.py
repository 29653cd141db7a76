"""Defects a demanding user met over SSH (user-walk-7), each driven through the real app:
keys typed ahead of a dialog, a new page's name, and a template's placeholder in a narrow box."""

from __future__ import annotations

import shutil
from pathlib import Path

from textual import events

from floatpage.model import load_project, save_project
from floatpage.model.document import Page, Project

from editor_helpers import editor, position, screen_of

ROOT = Path(__file__).resolve().parents[2]


def type_ahead(app, *keys: str) -> None:
    """Send keys to the app the way a fast typist over SSH does: all of them in the driver's
    queue at once, none waiting for the screen the one before opens."""
    for key in keys:
        event = events.Key(key, {"space": " "}.get(key, key if len(key) == 1 else None))
        event.set_sender(app)
        app._driver.send_message(event)


async def test_keys_typed_ahead_of_a_dialog_go_to_the_dialog(project_path):
    """`p` then `l` at once moved the selected item right, instead of typing `l` into the
    picture dialog (its tree has the focus: `l` is no key there, so nothing at all moves)."""
    async with editor(project_path) as (app, pilot):
        await pilot.press("tab")
        await pilot.pause()
        chosen = screen_of(app).selected_id
        before = position(app, chosen)
        type_ahead(app, "p", "l")
        await pilot.pause(0.3)
        assert app.screen.id == "picture-dialog"
        assert position(app, chosen) == before


async def test_words_typed_ahead_of_a_form_are_typed_into_it_in_order(project_path):
    """`t` then the first letters: they came back to an App whose form was not yet mounted
    and were lost (or, `h` and `l`, moved the selected item)."""
    async with editor(project_path) as (app, pilot):
        await pilot.press("tab")
        await pilot.pause()
        chosen = screen_of(app).selected_id
        before = position(app, chosen)
        type_ahead(app, "t", "H", "e", "l", "l", "o", "space", "h", "i")
        await pilot.pause(0.3)
        assert app.screen.id == "text-dialog"
        assert app.screen.focused.text == "Hello hi"
        assert position(app, chosen) == before


async def test_a_choice_typed_ahead_reaches_the_dialog_the_one_before_opened(project_path):
    """`i` (insert), Enter (its first choice, a text box) and the words, at once: each key goes
    to the screen the key before it opened, through two dialogs."""
    async with editor(project_path) as (app, pilot):
        type_ahead(app, "i", "enter", "O", "k")
        await pilot.pause(0.3)
        assert app.screen.id == "text-dialog"
        assert app.screen.focused.text == "Ok"

