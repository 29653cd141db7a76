"""Textual's Linux driver, with one change: end of input is a hang-up, not a busy loop.

When the terminal goes away, Textual's input thread finds its file descriptor readable with
nothing to read and goes round again at once, forever: the editor stayed alive at 50-70 % CPU
after its tmux session was killed.  Here an empty read, or EIO, sends this process SIGHUP, and
`recovery.HangupGuard` saves unsaved edits and leaves.
"""

from __future__ import annotations

import os
import selectors
import signal
from codecs import getincrementaldecoder

from textual._parser import ParseError
from textual._xterm_parser import XTermParser
from textual.drivers.linux_driver import LinuxDriver


class HangupAwareDriver(LinuxDriver):
    def run_input_thread(self) -> None:
        """Textual's loop (textual/drivers/linux_driver.py), stopping at end of input."""
        selector = selectors.SelectSelector()
        selector.register(self.fileno, selectors.EVENT_READ)
        parser = XTermParser(self._debug)
        decode = getincrementaldecoder("utf-8")().decode
        try:
            while not self.exit_event.is_set():
                for _key, mask in selector.select(0.1):
                    if not mask & selectors.EVENT_READ:
                        continue
                    try:
                        data = os.read(self.fileno, 1024 * 4)
                    except OSError:  # EIO: the terminal hung up
                        data = b""
                    if not data:
                        os.kill(os.getpid(), signal.SIGHUP)
                        return
                    for event in parser.feed(decode(data)):
                        self.process_message(event)
                for event in parser.tick():
                    self.process_message(event)
        finally:
            selector.close()
            try:
                for _event in parser.feed(""):
                    pass
            except (EOFError, ParseError):
                pass
