"""Textual's Linux driver, with three changes: end of input is a hang-up, not a busy loop;
the output sends only the cells the terminal does not already show, and colour codes only
where the colour changes (`shadow_screen`); and it measures its link for the frame pacer
(`frame_pacer.LinkMeter`: cursor-position queries after physics frames, whose answers it
takes out of the input, and output not yet flushed).

When the terminal goes away, Textual's input thread finds its file descriptor readable with
nothing to read and goes round again at once, forever: the editor stayed alive at 50-70 % CPU
after its tmux session was killed.  Here an empty read, or EIO, sends this process SIGHUP, and
`recovery.HangupGuard` saves unsaved edits and leaves.
"""

from __future__ import annotations

import os
import selectors
import signal
import threading
from codecs import getincrementaldecoder

from textual import events
from textual._parser import ParseError
from textual._xterm_parser import XTermParser
from textual.drivers.linux_driver import LinuxDriver

from floatpage.tui.frame_pacer import LinkMeter
from floatpage.tui.shadow_screen import ShadowScreen


class MeteredFile:
    """The terminal's output file as the writer thread sees it, telling the meter what was
    flushed: output the thread cannot flush is output the terminal is not reading."""

    def __init__(self, file, link: LinkMeter):
        self._file, self._link, self._unflushed = file, link, 0

    def write(self, text: str) -> int:
        self._unflushed += len(text)
        return self._file.write(text)

    def flush(self) -> None:
        self._file.flush()
        flushed, self._unflushed = self._unflushed, 0
        self._link.flushed(flushed)

    def fileno(self) -> int:
        return self._file.fileno()

    def isatty(self) -> bool:
        return self._file.isatty()

    def __getattr__(self, name):
        return getattr(self._file, name)


class HangupAwareDriver(LinuxDriver):
    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.shadow = ShadowScreen(80, 24)
        self._screen_stale = True  # resized (or not yet sized): the shadow starts again
        # Textual writes from its input thread too (answers to its start-up queries turn on
        # in-band resizes and pixel mouse reports): each write is rewritten against the shadow
        # and queued in one piece, or the terminal would get them in another order than the
        # shadow followed.
        self._write_lock = threading.Lock()
        self.link = LinkMeter()
        self._file = MeteredFile(self._file, self.link)

    def write(self, data: str) -> None:
        """The same screen for fewer bytes (over SSH each byte counts, issue 11), and after a
        physics frame a query whose answer tells when the terminal has drawn it."""
        with self._write_lock:
            if self._screen_stale:
                self._screen_stale = False
                self.shadow.reset(*self._get_terminal_size())
            data = self.shadow.rewrite(data) + self.link.probe()
            self.link.queued(len(data), len(data.encode("utf-8", "replace")))
            super().write(data)

    def paint_cells(self, runs) -> bool:
        """Cells that do not go through Textual (`direct_paint`), written in place against the
        shadow; False, and nothing written, while the shadow does not follow the screen."""
        with self._write_lock:
            if self._screen_stale or self._writer_thread is None or not self.shadow.can_paint():
                return False
            data = self.shadow.paint(runs) + self.link.probe()
            if data:
                self.link.queued(len(data), len(data.encode("utf-8", "replace")))
                super().write(data)
        return True

    def start_application_mode(self) -> None:
        """Textual's, and a resize makes the shadow screen start again: a terminal may reflow
        what it shows, and the cells it holds are no longer the ones remembered."""
        super().start_application_mode()
        textual_handler = signal.getsignal(signal.SIGWINCH)

        def on_resize(signum, frame) -> None:
            self._screen_stale = True
            if callable(textual_handler):
                textual_handler(signum, frame)

        if callable(textual_handler):
            signal.signal(signal.SIGWINCH, on_resize)

    def process_message(self, message) -> None:
        if isinstance(message, events.Resize):  # an in-band resize report
            self._screen_stale = True
        super().process_message(message)

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
                        if isinstance(event, events.CursorPosition):
                            self.link.answered()  # our query's answer, not the app's
                            continue
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
