"""The preview's cells go straight to the terminal (`tui/direct_paint.py`), past Textual's
compositor, only when nothing else can be on them; and the terminal then shows what Textual
itself would have drawn.

The screen check runs `floatpage edit` on the greeting card (a photo) and the calendar (text
among blank cells, which go in the text's style) over a real pty, in truecolour,
read by pyte: after keys that move the photo (one at a time and held) and toggle the labels,
the screen is compared with Textual's own full repaint of the same state, which a resize
forces (the driver forgets what the terminal shows, and Textual redraws every cell)."""

from __future__ import annotations

import fcntl
import shutil
import struct
import sys
import termios
import time
from pathlib import Path

import pyte
import pytest

from floatpage.tui.direct_paint import DirectPainter
from floatpage.tui.app import make_app

import editor_key_trace
from editor_helpers import screen_of, until
from test_shadow_screen import seen
from terminal_probe import DOWN, UP, Terminal, hold_arrow

ROOT = Path(__file__).resolve().parents[2]
CARD = ROOT / "sample_projects" / "greeting-card" / "greeting-card.toml"
COLUMNS, ROWS = 100, 32


def cells(screen: pyte.Screen) -> list[list[tuple]]:
    """What each cell shows (a blank's foreground colour does not show)."""
    return [[seen(screen.buffer[row][col]) for col in range(screen.columns)]
            for row in range(screen.lines)]


def resize(term: Terminal, columns: int, rows: int) -> None:
    fcntl.ioctl(term.fd, termios.TIOCSWINSZ, struct.pack("HHHH", rows, columns, 0, 0))


@pytest.mark.parametrize("sample", ["greeting-card", "calendar-2027"])
def test_the_screen_is_the_one_textual_draws_itself(tmp_path, sample):
    folder = tmp_path / sample
    shutil.copytree(ROOT / "sample_projects" / sample, folder)
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "LANG": "C.UTF-8",
           "TERM": "xterm-256color", "COLORTERM": "truecolor"}
    term = Terminal([sys.executable, "-m", "floatpage.cli.main", "edit",
                     str(folder / f"{sample}.toml")], str(folder), env, COLUMNS, ROWS)
    screen = pyte.Screen(COLUMNS, ROWS)
    stream = pyte.ByteStream(screen)

    def read_until_quiet() -> None:
        term.until_quiet(quiet_s=1.5)
        stream.feed(bytes(term.seen))
        term.seen.clear()

    try:
        deadline = time.monotonic() + 60
        while b"items" not in term.seen:
            assert time.monotonic() < deadline, bytes(term.seen[-400:])
            term.pump(0.05)
        read_until_quiet()
        for keys in (b"\t", DOWN, UP, DOWN, b"n"):
            term.send(keys)
            read_until_quiet()
        hold_arrow(term, 0.5, DOWN)
        read_until_quiet()
        drawn = cells(screen)
        assert " mm" in screen.display[0], "\n".join(screen.display)  # an item selected

        resize(term, COLUMNS - 10, ROWS - 4)
        screen.resize(ROWS - 4, COLUMNS - 10)
        read_until_quiet()
        resize(term, COLUMNS, ROWS)
        screen.resize(ROWS, COLUMNS)
        read_until_quiet()
    finally:
        term.close()
    repainted = cells(screen)
    for row in range(ROWS):
        assert drawn[row] == repainted[row], f"row {row}: {screen.display[row]!r}"


async def test_cells_go_past_textual_only_when_nothing_else_is_on_them():
    """On the editor screen the preview is its cells' sole owner; under a notification or a
    dialog it is not, and Textual draws its changes."""
    app = make_app(CARD, autostart=False)
    async with app.run_test(size=(COLUMNS, ROWS), notifications=True) as pilot:
        await pilot.pause()
        preview = screen_of(app).preview

        def sole_owner() -> bool:
            return DirectPainter.sole_owner(preview, preview._cache.cols, preview._cache.rows)

        # each of these shows a few messages and a screen update later: waited for, not paused
        assert await until(pilot, sole_owner)
        app.editor.notify("a notice over the preview", timeout=30)
        assert await until(pilot, lambda: not sole_owner())
        app.clear_notifications()
        assert await until(pilot, sole_owner)
        await pilot.press("question_mark")  # help
        assert await until(pilot, lambda: not sole_owner())


def test_a_keys_whole_answer_is_one_write(tmp_path):
    """An arrow's answer, the moved photo and the top bar's new position ("at 96, 175 mm"),
    reaches the terminal in one write, written at once: the top bar used to follow 3-4 ms later
    in a write of its own, through Textual's next screen update, which now does not run at
    all. The editor runs over a real pty in the
    key trace's child (benchmarks/editor_key_trace.py), which logs every write that carries
    bytes; each key is counted until the physics frame it wakes."""
    folder = tmp_path / "greeting-card"
    shutil.copytree(ROOT / "sample_projects" / "greeting-card", folder)
    log = tmp_path / "trace.log"
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "LANG": "C.UTF-8",
           "TERM": "xterm-256color", "COLORTERM": "truecolor"}
    term = Terminal([sys.executable, str(ROOT / "benchmarks" / "editor_key_trace.py"),
                     "--traced", str(folder / "greeting-card.toml"), str(log)], str(folder), env,
                    COLUMNS, ROWS)
    presses = 4
    try:
        answers = editor_key_trace.type_keys(term, presses)
    finally:
        term.close()
    assert len(answers) == presses
    times = editor_key_trace.stage_times(log, presses)
    assert times["writes flushed (count)"] == [1] * presses
    # and written at once from the app's thread, the terminal taking it all: through the
    # writer thread it waited for the interpreter lock, 1-4 ms after the key's work was done
    assert times["of which written at once (count)"] == [1] * presses
    # and Textual has nothing left to draw: its screen update for the top bar found the line
    # on the terminal already, and cost 1.3-1.5 ms of CPU while the answer was on its way
    assert "Textual's screen update, in all" not in times
