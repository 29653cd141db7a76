"""The floatpage editor app: thin, as in frogmouth and posting.

The App holds the editing session and returns the EditorScreen as its
default screen; everything else lives in the screen, its widgets and dialogs.
`make_app` is the one way to build it, shared by `floatpage edit` and the tests.
"""

from __future__ import annotations

import gc
import sys
from functools import partial
from pathlib import Path
from typing import Iterable

from textual import events
from textual.app import App, SystemCommand
from textual.screen import Screen

from floatpage.model.project_file import load_project
from floatpage.tui.dialogs.form import FormDialog
from floatpage.tui.editor_screen import EditorScreen
from floatpage.tui.keymap import COMMANDS, key_label
from floatpage.tui.recovery import HangupGuard, load_recovered
from floatpage.tui.session import EditSession
from floatpage.tui.terminal_driver import HangupAwareDriver
from floatpage.tui.type_ahead import TypeAhead


ANSWER_KEYS = ("enter", "escape")  # the keys that answer a dialog, and may open the next


class FloatpageApp(App):
    """Edits one project file."""

    CSS_PATH = "app.tcss"
    TITLE = "floatpage"
    cursor_blink = True  # dialogs' text cursors; snapshot tests turn it off for repeatable frames

    def __init__(self, session: EditSession, *, autostart: bool = True):
        super().__init__(driver_class=HangupAwareDriver if sys.platform.startswith("linux")
                         else None)
        self.session = session
        self.autostart = autostart
        self.type_ahead = TypeAhead(self)

    def on_mount(self) -> None:
        if not self.is_headless:  # a real terminal, which can hang up
            HangupGuard(self.session, self.exit, self.typed_in_forms).install()
            # The writer and input threads wait for the interpreter lock while a physics frame
            # runs; Python hands it over every 5 ms by default, which delayed a key's screen
            # write or the key itself by up to that much. 1 ms costs little with three threads.
            sys.setswitchinterval(0.001)
        # Everything alive now (Textual, numpy, the project) lives as long as the app: move it
        # out of the collector's sight, so a full collection during a frame is short. Without
        # this, frames at 200 items spiked to 40-50 ms once a few seconds (measured).
        gc.freeze()

    def push_screen(self, screen, *args, **kwargs):
        """Every screen opened (a dialog, help, the palette) takes the keys typed after the
        one that opened it (`tui.type_ahead`)."""
        result = super().push_screen(screen, *args, **kwargs)
        self.type_ahead.screen_pushed(self.screen)
        return result

    async def on_event(self, event: events.Event) -> None:
        if isinstance(event, events.Key) and not event.is_forwarded:
            if not self.type_ahead.holds(event):
                await self.take_key(event)
            return
        await super().on_event(event)

    async def take_key(self, event: events.Key) -> None:
        """A key, in its turn. On the editor screen its binding runs now, before the next key
        is read, so that a dialog it opens is there for that key; a key no binding takes goes
        on to the focused widget as usual (the editor's on_key says what it needs)."""
        screen = self.screen
        if screen is self.screen_stack[0] and self._focus_takes_no_keys(screen):
            if (await self._check_bindings(event.key, priority=True)
                    or await self._check_bindings(event.key)):
                return
        await super().on_event(event)
        if screen is not self.screen_stack[0] and event.key in ANSWER_KEYS:
            self.type_ahead.answer_sent(screen)

    @staticmethod
    def _focus_takes_no_keys(screen: Screen) -> bool:
        """The editor's focus is its preview, which handles no keys of its own: running the
        bindings first changes nothing but the timing."""
        from floatpage.tui.page_preview import PagePreview
        return screen.focused is None or isinstance(screen.focused, PagePreview)

    def get_default_screen(self) -> Screen:
        return EditorScreen(self.session, autostart=self.autostart)

    @property
    def editor(self) -> EditorScreen:
        """The default screen, at the bottom of the stack under any dialog."""
        return self.screen_stack[0]  # type: ignore[return-value]

    def get_system_commands(self, screen: Screen) -> Iterable[SystemCommand]:
        """Textual's own commands, then every editor command, named as in the help screen."""
        for command in super().get_system_commands(screen):
            if command.title != "Quit":
                yield command
        editor = self.editor
        for command in COMMANDS:
            # The palette reads titles as markup: "[a]", "[u]", "[i]", "[n]" were taken for
            # style tags and vanished (and "[b]" made the rest bold), so keys go in brackets
            # no markup claims.
            yield SystemCommand(f"{command.label}  ({key_label(command.keys)})", command.help,
                                partial(editor.run_action, command.action))

    def typed_in_forms(self) -> list[str]:
        """What the open forms hold that was typed and not applied, one line each, for the
        recovery file (`HangupGuard`): the form's title, the field's label and the words."""
        typed = []
        for screen in self.screen_stack:
            if isinstance(screen, FormDialog):
                for label, words in screen.typed():
                    label = " ".join(label.split())
                    typed.append(f"{screen.title_text} · {label}: {words}")
        return typed

    async def action_quit(self) -> None:
        """Ctrl+Q and the palette's Quit ask first, like q, when there are unsaved changes."""
        self.editor.action_quit()


def make_app(project_path: str | Path, *, seed: int | None = None,
             autostart: bool = True, allow_outside_files: bool = False,
             recovered: bool = False) -> FloatpageApp:
    """Load a project and build the editor for it; raises ProjectFileError on a bad file.

    `seed` seeds the physics jitter for this session (it does not change the project's own
    seed); None, the default, uses the project's `[physics] seed`, so the editor and
    `floatpage settle` lay the same file out the same way.
    `autostart=False` starts with the physics paused, so tests see repeatable frames.
    `recovered=True` opens the edits a lost terminal left in the recovery file, unsaved.
    """
    typed: list[str] = []
    base = None
    if recovered:
        project, typed, base = load_recovered(project_path,
                                              allow_outside_files=allow_outside_files)
    else:  # a picture moved away must not keep the user out of the editor: it says so
        project = load_project(project_path, allow_outside_files=allow_outside_files,
                               missing_pictures_ok=True)
    session_seed = project.physics.seed if seed is None else seed
    session = EditSession(project, seed=session_seed)
    if recovered:
        session.mark_unsaved()
        session.typed_when_lost = typed
        if base is not None:  # the file the edits were made to: Ctrl+S asks before it
            session.disk_digest = base  # replaces a version another program wrote since
    return FloatpageApp(session, autostart=autostart)
