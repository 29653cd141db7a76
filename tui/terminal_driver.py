"""Textual's Linux driver, with five changes: its size is the terminal's, whatever $COLUMNS
says; end of input is a hang-up, not a busy loop;
the output sends only the cells the terminal does not already show, and colour codes only
where the colour changes (`shadow_screen`); it measures its link for the frame pacer
(`frame_pacer.LinkMeter`: cursor-position queries after physics frames, whose answers it
takes out of the input, and output not yet flushed); and cells painted past Textual (a key's
answer) are written at once from the app's thread when the terminal takes them without
waiting (`write_prompt`).

When the terminal goes away, Textual's input thread finds its file descriptor readable with
nothing to read and goes round again at once, forever: the editor stayed alive at 50-70 % CPU
after its tmux session was killed.  Here an empty read, or EIO, sends this process SIGHUP, and
`recovery.HangupGuard` saves unsaved edits and leaves.
"""

from __future__ import annotations

import os
import selectors
import signal
import sys
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
        self.writes = self.flushed_writes = 0  # writes taken from the thread's queue, flushed

    def write(self, text: str | bytes) -> int:
        """Text, or the bytes a prompt write (`HangupAwareDriver.write_prompt`) left over."""
        self.writes += 1
        self._unflushed += len(text)
        if isinstance(text, bytes):
            self._file.flush()  # what the text layer holds goes first
            return self._file.buffer.write(text)
        return self._file.write(text)

    def flush(self) -> None:
        writes = self.writes
        self._file.flush()
        flushed, self._unflushed = self._unflushed, 0
        self._link.flushed(flushed)
        self.flushed_writes = writes

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
        self._handed = 0  # writes handed to the writer thread
        self._prompt_fd: int | None = None  # the terminal, opened again without blocking

    def _get_terminal_size(self) -> tuple[int, int]:
        """The terminal's own size, asked of it (TIOCGWINSZ), before $COLUMNS and $LINES:
        Textual's driver takes `shutil.get_terminal_size`, which reads those first, so an
        exported COLUMNS (a shell's rc file, a parent program such as pytest-xdist's workers,
        which export 80 x 24) laid the editor out for the wrong size, and a resize never
        changed it. They still count where the terminal cannot say (a size of 0)."""
        for stream in (self._file, sys.__stdin__, sys.__stdout__):
            try:
                size = os.get_terminal_size(stream.fileno())
            except (AttributeError, OSError, ValueError):
                continue
            if size.columns and size.lines:
                return size.columns, size.lines
        return super()._get_terminal_size()

    def write(self, data: str) -> None:
        """The same screen for fewer bytes (over SSH each byte counts, issue 11), and after a
        physics frame a query whose answer tells when the terminal has drawn it."""
        with self._write_lock:
            if self._screen_stale:
                self._screen_stale = False
                self.shadow.reset(*self._get_terminal_size())
            data = self.shadow.rewrite(data) + self.link.probe()
            self.link.queued(len(data), len(data.encode("utf-8", "replace")))
            self._handed += 1
            super().write(data)

    def paint_cells(self, runs) -> bool:
        """Cells that do not go through Textual (`direct_paint`), written in place against the
        shadow; False, and nothing written, while the shadow does not follow the screen."""
        with self._write_lock:
            if self._screen_stale or self._writer_thread is None or not self.shadow.can_paint():
                return False
            data = self.shadow.paint(runs) + self.link.probe()
            if data:
                self.write_prompt(data)
        return True

    def write_prompt(self, data: str) -> None:
        """Write now, from this thread, what the terminal takes without waiting; the rest goes
        to the writer thread. Only while that thread has nothing of its own to write, so the
        order stays. A key's answer waited 1-4 ms in the writer thread's queue: the thread
        gets the interpreter lock only once the app's loop, busy with Textual's update after
        the key, hands it over (every millisecond at best, `sys.setswitchinterval`).
        Needs `_write_lock`."""
        encoded = data.encode("utf-8", "replace")
        written = 0
        if self._prompt_fd is not None and self._file.flushed_writes == self._handed:
            try:
                written = os.write(self._prompt_fd, encoded)
            except OSError:  # full (BlockingIOError), or gone: the writer thread finds out
                written = 0
        self.link.queued(0, written)
        if written < len(encoded):
            rest = encoded[written:]
            self.link.queued(len(rest), len(rest))
            self._handed += 1
            super().write(rest)

    def open_prompt_fd(self) -> None:
        """The terminal opened a second time, without blocking: a write through it never holds
        up the app's loop (the writer thread's own file blocks, on a terminal that does not
        read). A new open file description, so the input side's stays as Textual set it."""
        self.close_prompt_fd()
        try:
            if os.isatty(self._file.fileno()):
                self._prompt_fd = os.open(os.ttyname(self._file.fileno()),
                                          os.O_WRONLY | os.O_NONBLOCK | os.O_NOCTTY)
        except OSError:
            self._prompt_fd = None

    def close_prompt_fd(self) -> None:
        if self._prompt_fd is not None:
            try:
                os.close(self._prompt_fd)
            except OSError:
                pass
            self._prompt_fd = None

    def stop_application_mode(self) -> None:
        self.close_prompt_fd()
        super().stop_application_mode()

    def start_application_mode(self) -> None:
        """Textual's, and a resize makes the shadow screen start again: a terminal may reflow
        what it shows, and the cells it holds are no longer the ones remembered."""
        super().start_application_mode()
        self.open_prompt_fd()
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
