"""What one arrow press costs on the wire: `floatpage edit` on the greeting card over a real
pty of 100 x 32, in truecolour (every colour in full, the costliest case), as issue 11's
benchmark measures it (benchmarks/editor.py, which adds sshd). The terminal answers the
editor's cursor-position queries, as an emulator does, and shows what it read in pyte.

The card's first item is a 93 x 124 mm photo. One arrow sent 21 KB: the photo was scaled
again whenever its rounded edges moved apart or together, and every changed row was written
from the preview's left edge, unchanged cells and all. The goal is at most 10 KB."""

from __future__ import annotations

import re
import shutil
import sys
import time
from pathlib import Path

import pyte

from terminal_probe import DOWN, Terminal

ROOT = Path(__file__).resolve().parents[2]
COLUMNS, ROWS = 100, 32


def test_one_arrow_on_the_greeting_card_sends_at_most_10_kb(tmp_path):
    folder = tmp_path / "greeting-card"
    shutil.copytree(ROOT / "sample_projects" / "greeting-card", folder)
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "LANG": "C.UTF-8",
           "TERM": "xterm-256color", "COLORTERM": "truecolor"}
    term = Terminal([sys.executable, "-m", "floatpage.cli.main", "edit",
                     str(folder / "greeting-card.toml")], str(folder), env, COLUMNS, ROWS)
    screen = pyte.Screen(COLUMNS, ROWS)
    stream = pyte.ByteStream(screen)
    try:
        deadline = time.monotonic() + 60
        while b"items" not in term.seen:
            assert time.monotonic() < deadline, bytes(term.seen[-400:])
            term.pump(0.05)
        term.until_quiet(quiet_s=1.0)
        term.send(b"\t")
        term.until_quiet(quiet_s=1.0)
        stream.feed(bytes(term.seen))
        before = where(screen)
        term.seen.clear()
        term.send(DOWN)
        sent = term.until_quiet()  # every byte until 2 s of quiet, as the benchmark counts
        stream.feed(bytes(term.seen))
    finally:
        term.close()
    assert where(screen) > before, screen.display[0]  # the photo went down
    assert sent <= 10 * 1024, f"one arrow sent {sent} bytes"


def where(screen: pyte.Screen) -> int:
    """The selected photo's height on the page, in mm, as the top bar shows it."""
    shown = re.search(r"front-picture .* at \d+, (\d+) mm", screen.display[0])
    assert shown, "\n".join(screen.display)
    return int(shown.group(1))
