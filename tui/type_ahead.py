"""Keys typed ahead of a screen reach that screen, in the order they were typed.

Over SSH a user types faster than the screen answers: `p` then `l` arrive together. Textual
hands a key to the focused widget and runs its binding only once the key has come back up to
the App, a turn of the event loop later; a priority binding (the arrows and h/j/k/l, which
move the selected item) runs at once. So `l` moved the item before `p` had even opened the
picture dialog, and keys that are no binding (the first letters of a text box's words) came
back to an App whose dialog was not yet mounted and were dropped.

`TypeAhead` puts the App's key handling in one line: on the editor screen, a key's binding
runs as the key arrives (so the dialog it opens is on the stack before the next key is read);
while a screen just pushed is not yet mounted and focused, later keys wait in a queue and go
to that screen, in order, once it is.
"""

from __future__ import annotations

import asyncio
import time
from collections import deque

from textual import events
from textual.app import App
from textual.screen import Screen

ANSWER_WAIT_S = 0.5  # the longest keys wait for a dialog's answer (they never stay stuck)
MOUNT_WAIT_S = 5.0  # ... and for a screen to mount


class TypeAhead:
    """The App's queue of keys that arrived while a screen was opening."""

    def __init__(self, app: App):
        self.app = app
        self.waiting: deque[events.Key] = deque()
        self.opening: Screen | None = None  # pushed, not yet mounted and focused
        self.answering = False  # an Enter or Esc went to a dialog, which may close or open one

    def screen_pushed(self, screen: Screen) -> None:
        """Hold keys from now until `screen` is mounted and has given its focus."""
        self.opening = screen
        self.app.run_worker(self.wait_for(screen), exclusive=False, group="type-ahead")

    async def wait_for(self, screen: Screen) -> None:
        try:  # a screen that fails to mount must not keep the keys for ever
            await asyncio.wait_for(screen._mounted_event.wait(), MOUNT_WAIT_S)
        except asyncio.TimeoutError:
            self.opened(screen)
            return
        # Its on_mount has run: a dialog gives its first field the focus there, by a message
        # to the App. A message of ours posted to the App now is handled after it, and the
        # screen's refresh after that applies the auto focus of a screen that names none
        # (the refresh alone came first now and then on a loaded machine: flake-hunt).
        self.app.call_later(screen.call_after_refresh, self.opened, screen)

    def opened(self, screen: Screen) -> None:
        """``screen`` is mounted: its keys go to it once the focus its on_mount asked for is
        given.  A widget's focus() is a message at the back of the App's queue, so the keys
        wait behind it there (``let_keys_in``), still held: on a loaded machine a drain
        already queued ran before that focus and handed the "Ok" typed ahead through the
        insert and text dialogs to the form's scroll container, which dropped it."""
        if self.opening is screen:
            self.app.call_later(self.let_keys_in, screen)

    async def let_keys_in(self, screen: Screen) -> None:
        if self.opening is screen:
            self.opening = None
            await self.drain()

    def holds(self, event: events.Key) -> bool:
        """Queue `event` if a screen is opening or keys before it still wait; True if queued."""
        if self.opening is not None and self.opening not in self.app.screen_stack:
            self.opening = None  # closed before it ever opened
        if self.opening is None and not self.answering and not self.waiting:
            return False
        self.waiting.append(event)
        return True

    def answer_sent(self, screen: Screen) -> None:
        """An Enter or Esc went to the dialog `screen`: it may close it and open the next
        (Enter on "Text box" opens the text form), some messages later (the list's choice,
        the dialog's answer, its callback). Hold the keys after it until that is done."""
        self.answering = True
        self.app.run_worker(self.wait_for_answer(screen), exclusive=False, group="type-ahead")

    async def wait_for_answer(self, screen: Screen) -> None:
        """Until the dialog is gone, or it and the App have two turns running with no message
        left to handle (the key changed a field, or was no key there); at most ANSWER_WAIT_S."""
        quiet_turns = 0
        deadline = time.monotonic() + ANSWER_WAIT_S
        while quiet_turns < 2 and time.monotonic() < deadline:
            await asyncio.sleep(0.002)
            if screen not in self.app.screen_stack:
                break  # answered: a screen it opened is `opening` by now, and holds the keys
            pumps = [self.app, *self.app.screen_stack, *screen.walk_children()]
            busy = any(not pump._message_queue.empty() for pump in pumps)
            quiet_turns = 0 if busy else quiet_turns + 1
        self.answering = False
        self.app.call_next(self.drain)

    async def drain(self) -> None:
        """Hand the waiting keys on, one by one, until one of them opens another screen."""
        while self.waiting and self.opening is None and not self.answering:
            await self.app.take_key(self.waiting.popleft())
