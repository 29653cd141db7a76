"""Bytes the editor sends to its terminal, over a real pty at 100 x 32: what an SSH link
carries.  Runs `floatpage edit` on each sample as a terminal would (the pty is its controlling
terminal), selects the first item, then measures:

- one arrow press from rest: every byte until the screen has been quiet for 2 s;
- a held arrow: 30 presses a second for one second (a terminal's key repeat), then until quiet;
- idle: bytes in 3 s with nothing pressed;
- still after release: seconds from the last key to the last byte written;
- key to screen: the median time from an arrow press to the first byte of the answer.

    .venv/bin/python benchmarks/editor_bytes.py

The same measures run for a trivial Textual app (a Label that shows the last key), the peer
floor.  Compare within one run; the machine is shared.
"""

from __future__ import annotations

import fcntl
import os
import pty
import select
import statistics
import shutil
import struct
import sys
import tempfile
import termios
import textwrap
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
QUIET_S = 2.0
RIGHT = b"\x1b[C"
TRIVIAL_APP = textwrap.dedent("""
    from textual.app import App
    from textual.widgets import Label

    class Trivial(App):
        def compose(self):
            yield Label("press keys", id="last")
        def on_key(self, event):
            self.query_one("#last", Label).update(f"last key: {event.key}")
    Trivial().run()
""")


class Terminal:
    def __init__(self, argv: list[str], cwd: Path):
        self.pid, self.fd = pty.fork()
        if self.pid == 0:
            os.chdir(cwd)
            os.execvpe(argv[0], argv, {**os.environ, "TERM": "xterm-256color"})
        fcntl.ioctl(self.fd, termios.TIOCSWINSZ, struct.pack("HHHH", 32, 100, 0, 0))
        self.total = 0
        self.last_byte_at = time.monotonic()

    def pump(self, seconds: float) -> int:
        """Read for ``seconds``; the bytes read."""
        got, deadline = 0, time.monotonic() + seconds
        while time.monotonic() < deadline:
            ready, _, _ = select.select([self.fd], [], [], min(0.02, max(deadline - time.monotonic(), 0)))
            if ready:
                try:
                    data = os.read(self.fd, 1 << 16)
                except OSError:
                    break
                got += len(data)
                self.last_byte_at = time.monotonic()
        self.total += got
        return got

    def until_quiet(self, quiet_s: float = QUIET_S, limit_s: float = 60.0) -> int:
        got, start = 0, time.monotonic()
        while time.monotonic() - start < limit_s:
            got += self.pump(0.1)
            if time.monotonic() - self.last_byte_at >= quiet_s:
                break
        return got

    def send(self, data: bytes) -> None:
        os.write(self.fd, data)

    def close(self) -> None:
        try:
            os.kill(self.pid, 9)
            os.waitpid(self.pid, 0)
        except (ProcessLookupError, ChildProcessError):
            pass
        os.close(self.fd)


def measure(argv: list[str], cwd: Path, select_first: bool) -> dict[str, float]:
    term = Terminal(argv, cwd)
    try:
        term.until_quiet(limit_s=60)
        if select_first:
            term.send(b"\t")
            term.until_quiet()
        term.send(RIGHT)
        one_key = term.until_quiet()
        sent_at = time.monotonic()
        held = 0
        for _ in range(30):
            term.send(RIGHT)
            held += term.pump(1 / 30)
        last_key = time.monotonic()
        held += term.until_quiet()
        still_after = max(term.last_byte_at - last_key, 0.0)
        idle = term.pump(3.0)
        latencies = []
        for _ in range(15):  # key to the first byte of the answer, from rest each time
            term.until_quiet(quiet_s=0.3)
            term.send(RIGHT)
            sent = time.monotonic()
            ready, _, _ = select.select([term.fd], [], [], 5.0)
            if ready:
                latencies.append(time.monotonic() - sent)
                term.pump(0.05)
        return {"latency_ms": 1000 * statistics.median(latencies) if latencies else float("nan"),
                "one_key_kb": one_key / 1024, "held_1s_kb": held / 1024,
                "still_after_s": still_after, "idle_b_per_s": idle / 3.0,
                "held_rate_kb_s": held / 1024 / max(term.last_byte_at - sent_at, 1e-9)}
    finally:
        term.close()


def main() -> None:
    editor = str(ROOT / ".venv" / "bin" / "floatpage")
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        trivial = Path(scratch) / "trivial.py"
        trivial.write_text(TRIVIAL_APP)
        rows.append(("trivial Textual app", measure([sys.executable, str(trivial)], ROOT, False)))
        for sample in ("greeting-card", "shop-flyer", "calendar-2027"):
            folder = Path(scratch) / sample
            shutil.copytree(ROOT / "sample_projects" / sample, folder)
            toml = next(folder.glob("*.toml"))
            rows.append((sample, measure([editor, "edit", str(toml)], folder, True)))
    floor = rows[0][1]["latency_ms"]
    print("| at 100x32 | one arrow from rest | 1 s held arrow | motion after release | idle "
          "| key to screen (median) |")
    print("|---|---|---|---|---|---|")
    for name, m in rows:
        print(f"| {name} | {m['one_key_kb']:.1f} KB | {m['held_1s_kb']:.1f} KB "
              f"| {m['still_after_s']:.2f} s | {m['idle_b_per_s']:.0f} B/s "
              f"| {m['latency_ms']:.1f} ms ({m['latency_ms'] / floor:.1f}x) |")


if __name__ == "__main__":
    main()
