"""A scripted user at a real terminal: a pty whose master side this process reads and types
into, for the editor benchmark.

The program under test runs on the pty's slave side (for the SSH link, that program is the
`ssh -tt` client, so every byte has crossed sshd and back). `measure_session` types what a
user types and counts what the terminal receives: bytes per key, per held second, while
idle, how long motion lasts after the last key, and the delay from a key to the first byte
of its answer and to its last (`answer_times`).
"""

from __future__ import annotations

import fcntl
import os
import pty
import select
import signal
import statistics
import struct
import termios
import time
from dataclasses import dataclass

CURSOR_QUERY, CURSOR_ANSWER = b"\x1b[6n", b"\x1b[1;1R"
QUIET_S = 2.0  # "visibly still": nothing written for this long
UP, DOWN = b"\x1b[A", b"\x1b[B"
KEY_REPEAT_HZ = 30  # a terminal's key repeat while an arrow is held
FIRST_BYTE_LIMIT_S = 5.0  # a key not answered within this long is not counted
ANSWER_WINDOW_S = 0.5  # a key's whole answer is looked for this long after the key,
ANSWER_QUIET_S = 0.1  # ... or until this long without a byte


class Terminal:
    """A pty of `columns` x `rows` running `argv`; reads everything it is sent."""

    def __init__(self, argv: list[str], cwd: str, env: dict[str, str], columns: int, rows: int):
        self.columns, self.rows = columns, rows
        self.pid, self.fd = pty.fork()
        if self.pid == 0:  # the child: set the size before anything reads it, then run
            try:
                fcntl.ioctl(0, termios.TIOCSWINSZ, struct.pack("HHHH", rows, columns, 0, 0))
                os.chdir(cwd)
                os.execvpe(argv[0], argv, env)
            finally:
                os._exit(127)
        self.total = 0
        self.last_byte_at = time.monotonic()
        self.seen = bytearray()  # everything received since the last until_seen
        self.received = bytearray()  # everything received (`Screen` reads it when asked)
        self._carry = b""  # the end of the last read, for a query split between reads

    def pump(self, seconds: float) -> int:
        """Read for `seconds`; the bytes read."""
        got, deadline = 0, time.monotonic() + seconds
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                break
            ready, _, _ = select.select([self.fd], [], [], min(0.02, left))
            if ready:
                data = self.read_ready()
                if data is None:  # the program is gone
                    time.sleep(max(deadline - time.monotonic(), 0))
                    break
                if not data:
                    break
                got += len(data)
        return got

    def read_ready(self) -> bytes | None:
        """One read of what select reported ready (None: the program is gone)."""
        try:
            data = os.read(self.fd, 1 << 16)
        except OSError:
            return None
        if data:
            self.total += len(data)
            self.seen += data
            self.received += data
            self.answer_queries(data)
            self.last_byte_at = time.monotonic()
        return data

    def answer_queries(self, data: bytes) -> None:
        """Answer cursor-position queries, as a terminal emulator does once it has drawn
        everything before them (the editor paces its frames by these answers)."""
        joined = self._carry + data
        for _ in range(joined.count(CURSOR_QUERY)):
            os.write(self.fd, CURSOR_ANSWER)
        self._carry = joined[-(len(CURSOR_QUERY) - 1):] if not joined.endswith(CURSOR_QUERY) \
            else b""

    def until_quiet(self, quiet_s: float = QUIET_S, limit_s: float = 60.0) -> int:
        """Read until nothing has come for `quiet_s` (or `limit_s` passed); the bytes read."""
        got, start = 0, time.monotonic()
        while time.monotonic() - start < limit_s:
            got += self.pump(0.05)
            # quiet since the call began, too: measured from the last byte alone, a call right
            # after a key returned at once if the answer took over 50 ms (it counted 0 bytes)
            if time.monotonic() - max(self.last_byte_at, start) >= quiet_s:
                break
        return got

    def until_seen(self, text: bytes, limit_s: float = 60.0) -> None:
        """Read until `text` has been received (since the last call); then forget it."""
        start = time.monotonic()
        while text not in self.seen:
            if time.monotonic() - start > limit_s:
                raise RuntimeError(f"never saw {text!r}; the terminal shows {self.seen[-600:]!r}")
            self.pump(0.05)
        self.seen.clear()

    def send(self, data: bytes) -> None:
        os.write(self.fd, data)

    def close(self) -> None:
        """SIGKILL the program on the slave side (never left running) and close the pty."""
        try:
            os.kill(self.pid, signal.SIGKILL)
            os.waitpid(self.pid, 0)
        except (ProcessLookupError, ChildProcessError):
            pass
        os.close(self.fd)


@dataclass
class SessionFigures:
    one_key_kb: float  # one arrow from rest, every byte until QUIET_S of quiet
    held_kb: float  # a 1 s held arrow, every byte until quiet
    steady_kb_s: float  # bytes a second while the arrow is held (steady motion)
    still_after_s: float  # last key of the held second to the last byte
    idle_b_s: float  # bytes a second with nothing pressed
    latency_ms: float  # median, key to the first byte of the answer, from rest
    latency_p90_ms: float
    whole_ms: float  # median, key to the whole answer on the screen (`answer_times`)
    whole_p90_ms: float


def hold_arrow(term: Terminal, seconds: float, key: bytes) -> tuple[int, float]:
    """Press `key` KEY_REPEAT_HZ times a second for `seconds`; (bytes read meanwhile, time)."""
    got, start = 0, time.monotonic()
    for press in range(round(seconds * KEY_REPEAT_HZ)):
        term.send(key)
        got += term.pump(start + (press + 1) / KEY_REPEAT_HZ - time.monotonic())
    return got, time.monotonic() - start


class Screen:
    """What the terminal shows, read by pyte from everything received, when asked: reading it
    as the bytes come (pure Python, milliseconds a frame) would delay the answers to the
    editor's cursor queries, and so its frame pacing and its bytes."""

    def __init__(self, term: Terminal, columns: int, rows: int):
        import pyte

        self.term = term
        self.screen = pyte.Screen(columns, rows)
        self.stream = pyte.ByteStream(self.screen)
        self.read_up_to = 0

    def catch_up(self) -> None:
        self.stream.feed(bytes(self.term.received[self.read_up_to:]))
        self.read_up_to = len(self.term.received)

    def top_line(self) -> str:
        return self.screen.display[0]


def answer_times(term: Terminal, sent: float, screen: Screen) -> tuple[float, float] | None:
    """(first byte, whole answer) for a key sent at `sent`, in seconds after it; None when
    nothing came within FIRST_BYTE_LIMIT_S. `screen` has caught up with all before the key.

    The whole answer is on the screen once its top line has changed too: both apps show a
    key's effect there (the trivial app's label, the editor's top bar with the selected
    item's position, "at 96, 175 mm", which every arrow changes), and the editor's other
    part of the answer, the moved item's cells, comes before it or in the same write. So:
    the later of the first byte and the last read that changed the top line within
    ANSWER_WINDOW_S of the key (a line half drawn by one read and finished by the next counts
    to the next; the first byte alone when the line never changes, as when an item cannot
    move).
    The reads are timed as select reports them, as the first byte always was, and read by
    pyte only after the answer's time is over (ANSWER_WINDOW_S, or ANSWER_QUIET_S without a
    byte), so that reading them costs no time in the figure."""
    before = screen.top_line()
    reads: list[tuple[float, int]] = []  # (when, end of the read in term.received)
    while True:
        now = time.monotonic()
        if reads:
            wait = min(sent + ANSWER_WINDOW_S, reads[-1][0] + ANSWER_QUIET_S) - now
        else:
            wait = sent + FIRST_BYTE_LIMIT_S - now
        if wait <= 0:
            break
        ready, _, _ = select.select([term.fd], [], [], wait)
        if not ready:
            break
        at = time.monotonic()
        try:
            data = os.read(term.fd, 1 << 16)
        except OSError:
            break
        if not data:
            break
        term.total += len(data)
        term.seen += data
        term.received += data
        term.answer_queries(data)
        term.last_byte_at = at
        reads.append((at, len(term.received)))
    if not reads:
        return None
    whole, shown = reads[0][0], before
    for at, end in reads:  # the top line's last change in the window
        screen.stream.feed(bytes(term.received[screen.read_up_to:end]))
        screen.read_up_to = end
        if screen.top_line() != shown:
            whole, shown = at, screen.top_line()
    screen.catch_up()
    return reads[0][0] - sent, whole - sent


def quiet_all(terms: list[Terminal], quiet_s: float = QUIET_S, limit_s: float = 60.0) -> None:
    """Read every terminal until none has written for `quiet_s` (or `limit_s` passed): all
    of them read, so that none waits on a full pty or an unanswered cursor query."""
    start = time.monotonic()
    fds = {term.fd: term for term in terms}
    while time.monotonic() - start < limit_s:
        ready, _, _ = select.select(list(fds), [], [], 0.05)
        for fd in ready:
            if not fds[fd].read_ready():
                del fds[fd]  # gone: nothing more to wait for
        last = max([term.last_byte_at for term in fds.values()] + [start])
        if not fds or time.monotonic() - last >= quiet_s:
            return


def interleaved_answers(terms: list[Terminal], presses: int = 21
                        ) -> list[tuple[list[float], list[float]]]:
    """Per terminal, the ms from a key to the first byte of its answer and to the whole of it
    (`answer_times`), the terminals taking turns key by key, each key after QUIET_S of quiet
    on all of them: every app meets the same load, where one app's keys after another's met
    whatever the shared machine did in that minute (ratios between apps moved by up to 1.5x
    between runs, the trivial app's own median from 4.4 to 12.9 ms). Up and Down in turns,
    as `measure_session` sends them; the order of the terminals turns by one each round."""
    screens = [Screen(term, term.columns, term.rows) for term in terms]
    answers: list[tuple[list[float], list[float]]] = [([], []) for _ in terms]
    for press in range(presses):
        for turn in range(len(terms)):
            index = (turn + press) % len(terms)
            term, screen = terms[index], screens[index]
            quiet_all(terms)
            screen.catch_up()
            term.send(DOWN if press % 2 else UP)
            times = answer_times(term, time.monotonic(), screen)
            if times is not None:
                answers[index][0].append(1000 * times[0])
                answers[index][1].append(1000 * times[1])
    quiet_all(terms, QUIET_S / 2)
    return answers


def median_p90(values: list[float]) -> tuple[float, float]:
    ordered = sorted(values) or [float("nan")]
    return statistics.median(ordered), ordered[int(0.9 * (len(ordered) - 1))]


def measure_session(term: Terminal, *, ready: bytes, select_first: bool,
                    presses: int = 21) -> SessionFigures:
    """The user's session: wait for `ready` on the screen, select an item, then the measures
    (`presses=0`: no latency figures here, NaN; `interleaved_answers` measures them)."""
    screen = Screen(term, term.columns, term.rows)
    term.until_seen(ready)
    term.until_quiet()
    if select_first:
        term.send(b"\t")
        term.until_quiet()
    term.send(DOWN)  # down, not sideways: a band as wide as the page cannot move sideways
    one_key = term.until_quiet()
    held, held_s = hold_arrow(term, 1.0, DOWN)
    last_key = time.monotonic()
    after = term.until_quiet()
    still_after = max(term.last_byte_at - last_key, 0.0)
    idle_s = 3.0
    idle = term.pump(idle_s)
    firsts, lasts = [], []
    for press in range(presses):
        # from rest each time: QUIET_S of quiet, as "still" is counted above (with 1 s, a late
        # write of the last key's rest now and then came right after the next key, and was
        # counted as its answer: 1-4 of 21 answers quicker than any key could be answered)
        term.until_quiet(quiet_s=QUIET_S)
        screen.catch_up()
        term.send(DOWN if press % 2 else UP)
        times = answer_times(term, time.monotonic(), screen)
        if times is not None:
            firsts.append(1000 * times[0])
            lasts.append(1000 * times[1])
    term.until_quiet(quiet_s=QUIET_S / 2)
    (first, first_p90), (whole, whole_p90) = median_p90(firsts), median_p90(lasts)
    return SessionFigures(
        one_key_kb=one_key / 1024, held_kb=(held + after) / 1024,
        steady_kb_s=held / 1024 / held_s, still_after_s=still_after, idle_b_s=idle / idle_s,
        latency_ms=first, latency_p90_ms=first_p90, whole_ms=whole, whole_p90_ms=whole_p90)
