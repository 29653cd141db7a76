"""Frames only as fast as the link takes them.

The physics runs at 30 frames a second; a link that cannot carry 30 drawn frames a second
would queue them (in the writer thread, the pty, sshd, the network) and the screen would lag
further and further behind the keys. So the editor asks the terminal itself how far behind
it is: after a frame it sends a cursor-position query (`ESC[6n`), which a terminal answers
only once it has drawn everything before it. `LinkMeter` keeps the queries in flight; the
age of the oldest unanswered one is the link's backlog, the quickest answer its bare delay.
`FramePacer` skips drawing (the physics goes on) while the backlog exceeds the bare delay
by more than a couple of frames, and draws again as soon as the answers catch up: the drawn
frame rate falls to what the link carries and rises back when it drains. Nothing is lost:
the next frame drawn shows the latest state, and the last frame is owed until it is drawn.

Whatever the link, drawn frames stay within BYTES_PER_S a second (goal: motion at most
100 KB/s): a page whose every frame repaints pictures draws fewer of them.

A terminal that never answers (none within NO_ANSWER_S of the first query) is not asked
again; then the only sign left is output the writer thread could not hand to the terminal
(`pending`, bytes written but not yet flushed), which also holds frames back.
"""

from __future__ import annotations

import threading
import time
from collections import deque

PROBE = "\x1b[6n"  # "where is the cursor?": answered in order, after all output before it
MAX_IN_FLIGHT = 16
NO_ANSWER_S = 2.0
SLACK_S = 0.07  # about two frames beyond the link's bare delay
RECENT_ANSWERS = 32
STUCK_WRITE_S = 0.05  # output not flushed for this long: the terminal is not reading
BYTES_PER_S = 80_000  # drawn frames' budget; keys' answers are never held back
BUDGET_WINDOW_S = 1.0


class LinkMeter:
    """What the driver knows about its link: queries in flight and unflushed output.

    Written by three threads (the app's loop, the writer, the input reader), hence the lock.
    """

    def __init__(self, clock=time.monotonic):
        self.clock = clock
        self._lock = threading.Lock()
        self._in_flight: deque[float] = deque()
        self._delays: deque[float] = deque(maxlen=RECENT_ANSWERS)
        self.answered_any = False
        self.supported = True
        self.pending = 0  # characters handed to the writer thread, not yet flushed
        self._pending_since: float | None = None
        self.armed = False  # a drawn frame is on its way: follow it with a query
        self.bytes_written = 0  # everything handed to the terminal, in UTF-8 bytes

    def arm(self) -> None:
        """The next write carries a drawn frame: ask after it. That is a physics frame, or a
        key's answer while the physics runs (`EditorScreen.after_edit` asks `may_draw`
        before drawing it, and an arrow from rest has reheated the page by then), so such an
        answer is followed by a query too. Nothing else is: not a key's answer on a page at
        rest (a decoration nudged on a still page), a dialog, or anything once the physics
        rests."""
        self.armed = True

    # -- queries ------------------------------------------------------------------------

    def probe(self) -> str:
        """PROBE, to append to a write, or "" when enough are in flight or none are answered."""
        now = self.clock()
        with self._lock:
            if not self.armed or not self.supported:
                return ""
            self.armed = False
            if self._in_flight and not self.answered_any \
                    and now - self._in_flight[0] > NO_ANSWER_S:
                self.supported = False  # this terminal does not answer: stop asking
                self._in_flight.clear()
                return ""
            if len(self._in_flight) >= MAX_IN_FLIGHT:
                return ""
            self._in_flight.append(now)
            return PROBE

    def answered(self) -> None:
        """A cursor position report arrived: the oldest query has been drawn."""
        now = self.clock()
        with self._lock:
            if self._in_flight:
                self._delays.append(now - self._in_flight.popleft())
                self.answered_any = True

    def backlog_s(self) -> float:
        """How long the oldest unanswered query has waited (0 when none is, or before the
        terminal has shown that it answers at all)."""
        with self._lock:
            if not self._in_flight or not self.supported or not self.answered_any:
                return 0.0
            return self.clock() - self._in_flight[0]

    def bare_delay_s(self) -> float:
        """The quickest recent answer: the link's delay with nothing queued."""
        with self._lock:
            return min(self._delays) if self._delays else 0.0

    # -- output the writer thread holds ---------------------------------------------------

    def queued(self, characters: int, size_bytes: int = 0) -> None:
        """`characters` handed to the writer thread (0: `size_bytes` written at once)."""
        with self._lock:
            self.bytes_written += size_bytes
            if not characters:
                return
            if self.pending == 0:
                self._pending_since = self.clock()
            self.pending += characters

    def flushed(self, characters: int) -> None:
        with self._lock:
            self.pending = max(self.pending - characters, 0)
            self._pending_since = self.clock() if self.pending else None

    def write_stuck(self) -> bool:
        with self._lock:
            since = self._pending_since
        return since is not None and self.clock() - since > STUCK_WRITE_S


class FramePacer:
    """Decides at each physics tick whether to draw it, and at each edit made while the
    physics runs whether to draw its answer now or leave it to the next frame (a held key
    that outruns the link). `link` is None without a terminal."""

    def __init__(self, link: LinkMeter | None, clock=time.monotonic):
        self.link = link
        self.clock = clock
        self.skipped = 0  # frames not drawn since the last one that was
        self._written: deque[tuple[float, int]] = deque()  # (time, bytes written) per tick

    def over_budget(self, link: LinkMeter) -> bool:
        """More than BYTES_PER_S written in the last BUDGET_WINDOW_S."""
        now, total = self.clock(), link.bytes_written
        self._written.append((now, total))
        while len(self._written) > 1 and now - self._written[1][0] >= BUDGET_WINDOW_S:
            self._written.popleft()
        return total - self._written[0][1] > BYTES_PER_S * BUDGET_WINDOW_S

    def may_draw(self) -> bool:
        """True when the link has caught up and the byte budget allows; then the frame about
        to be drawn is followed by a query."""
        link = self.link
        if link is None:
            return True
        behind = (link.backlog_s() > link.bare_delay_s() + SLACK_S or link.write_stuck()
                  or self.over_budget(link))
        self.skipped = self.skipped + 1 if behind else 0
        if not behind:
            link.arm()
        return not behind
