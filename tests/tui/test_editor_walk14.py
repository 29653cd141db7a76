"""Defects found by walk-14: the editor on other terminals, long sessions, large pages."""

from __future__ import annotations

import shutil
import sys
import time
from pathlib import Path

import pyte
from textual.color import Color

from floatpage.tui.page_painter import PagePainter

from editor_helpers import editor, until
from terminal_probe import DOWN, Terminal, hold_arrow

ROOT = Path(__file__).resolve().parents[2]
COLUMNS, ROWS = 100, 32


def copy_sample(tmp_path: Path, sample: str) -> Path:
    folder = tmp_path / sample
    shutil.copytree(ROOT / "sample_projects" / sample, folder)
    return folder / f"{sample}.toml"


async def test_no_color_opens_the_editor_and_draws_the_page(tmp_path, monkeypatch):
    """With NO_COLOR set (no-color.org, a convention many users keep in their shell's
    profile), `floatpage edit` died at start with a traceback: Textual's Monochrome filter
    reads every segment's style, and the preview's rows not yet painted (its first render,
    before the page is projected) were blank strips with none.  Now the editor opens, the
    page is drawn, an item moves."""
    monkeypatch.setenv("NO_COLOR", "1")
    path = copy_sample(tmp_path, "shop-flyer")
    async with editor(path) as (app, pilot):
        assert app.no_color
        preview = app.editor.query_one("#preview")
        await pilot.press("tab", "down", "down")
        assert await until(pilot, lambda: app.session.unsaved)
        assert "Corner Shop" in "\n".join(preview.text_lines())
        app.save_screenshot(str(tmp_path / "screen.svg"))  # the whole screen renders


def colours_of(screen: pyte.Screen) -> set[str]:
    """Every colour a cell of the screen shows, foreground of non-blank cells and
    background, as pyte names them (a hex string for an RGB colour)."""
    found = set()
    for row in range(screen.lines):
        for col in range(screen.columns):
            char = screen.buffer[row][col]
            found.add(char.bg)
            if char.data.strip():
                found.add(char.fg)
    return found


def test_no_color_keeps_the_moving_item_grey_too(tmp_path):
    """With NO_COLOR, Textual draws the screen in greys, but the preview's changed cells,
    which go to the terminal past Textual's compositor (tui/direct_paint.py), went out in
    full colour: a photo moved on the greeting card showed in colour on a grey page.  Over a
    real pty, in truecolour: after the photo is moved (single keys and a held arrow), every
    colour on the screen is a grey."""
    path = copy_sample(tmp_path, "greeting-card")
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "LANG": "C.UTF-8",
           "TERM": "xterm-256color", "COLORTERM": "truecolor", "NO_COLOR": "1"}
    term = Terminal([sys.executable, "-m", "floatpage.cli.main", "edit", str(path)],
                    str(path.parent), env, COLUMNS, ROWS)
    screen = pyte.Screen(COLUMNS, ROWS)
    stream = pyte.ByteStream(screen)
    try:
        deadline = time.monotonic() + 60
        while b"items" not in term.seen:
            assert time.monotonic() < deadline, bytes(term.seen[-400:])
            term.pump(0.05)
        for keys in (b"\t", DOWN, DOWN, DOWN):
            term.send(keys)
            term.until_quiet(quiet_s=1.0)
        hold_arrow(term, 0.5, DOWN)
        term.until_quiet(quiet_s=1.5)
        stream.feed(bytes(term.seen))
    finally:
        term.close()
    assert " mm" in screen.display[0], "\n".join(screen.display)  # the photo selected, moved
    coloured = sorted(colour for colour in colours_of(screen)
                      if len(colour) == 6 and len(set((colour[:2], colour[2:4], colour[4:]))) > 1)
    assert not coloured, coloured


def grey(rgb) -> float:
    """The grey Textual's Monochrome filter shows for a colour (textual.color.Color.monochrome)."""
    return Color(*(int(channel) for channel in rgb)).monochrome.r


async def test_no_color_shows_the_selection_frame_apart_from_the_paper(tmp_path, monkeypatch):
    """Under NO_COLOR the selected picture's amber frame showed as a grey of 194 on the
    flyer's cream paper's 248: a frame a user had to look for.  In greys the frame is black
    where what it frames is light (and stays light on the dark header).  The preview's pixels
    are read as the terminal shows them, through the grey Textual makes of each colour."""
    monkeypatch.setenv("NO_COLOR", "1")
    path = copy_sample(tmp_path, "shop-flyer")
    async with editor(path) as (app, pilot):
        await pilot.press(*["tab"] * 6)  # a product photo, on the cream paper
        assert await until(pilot, lambda: (app.session.selected_id or "").startswith("product"))
        preview = app.editor.query_one("#preview")
        preview.redraw()
        item = app.session.page.item(app.session.selected_id)
        x0, y0, x1, y1 = PagePainter(preview.projection)._box(item, preview.view)
        pixels = preview.canvas.pixels
        frame = [grey(pixels[y0 - 1, x]) for x in range(x0 + 1, x1 - 1)]  # its top line
        paper = [grey(pixels[y0 - 3, x]) for x in range(x0 + 1, x1 - 1)]  # two pixels above
    assert max(paper) - max(frame) > 120, (frame, paper)


def test_the_preview_keeps_a_bounded_number_of_colour_styles():
    """The preview's Rich styles (StripCache) and the direct painter's terminal styles were
    kept for every (foreground, background) pair ever shown: a photo's thumbnail brings
    hundreds of new pairs, and one pass through a 27-page album of photos left 12,400 of
    them, 20 MB (benchmarks/editor_long_session.py), growing with every new page.  After
    50,000 pairs, at most 20,000 are kept, and a pair made again gives the same codes."""
    from rich.color import ColorSystem

    from floatpage.tui.cell_canvas import StripCache
    from floatpage.tui.direct_paint import DirectPainter, LineLooks

    cache, painter = StripCache(), DirectPainter()
    looks = LineLooks((), Color(0, 0, 0))
    first = painter.cell_style(cache, 0x123456, 0xabcdef, False, ColorSystem.TRUECOLOR, looks)
    for pair in range(50_000):
        painter.cell_style(cache, (pair * 7919) & 0xFFFFFF, (pair * 104729) & 0xFFFFFF,
                           bool(pair & 1), ColorSystem.TRUECOLOR, looks)
    assert len(cache._styles) <= 20_000
    assert len(painter._cell_styles) <= 20_000 and len(painter._styles) <= 20_000
    again = painter.cell_style(cache, 0x123456, 0xabcdef, False, ColorSystem.TRUECOLOR, looks)
    assert again == first == DirectPainter().cell_style(
        StripCache(), 0x123456, 0xabcdef, False, ColorSystem.TRUECOLOR, looks)


async def test_undo_says_when_older_edits_are_past_its_reach(tmp_path):
    """After 220 edits on the card, 200 Ctrl+Z took it back as far as undo keeps (200
    snapshots), and the next said "nothing to undo" while the project was still unsaved and
    20 edits away from the file: a user took it to mean the page was back as it began.  Now
    it says how far undo reaches and how many edits came before."""
    path = copy_sample(tmp_path, "greeting-card")
    async with editor(path) as (app, pilot):
        await pilot.press("tab")
        for _ in range(110):
            await pilot.press("plus", "minus")
        assert await until(pilot, lambda: len(app.session.history.undo_stack) == 200)
        for _ in range(200):
            await pilot.press("ctrl+z")
        assert await until(pilot, lambda: not app.session.history.undo_stack)
        await pilot.press("ctrl+z")
        said = lambda: [str(note.message) for note in app._notifications]  # noqa: E731
        assert await until(pilot, lambda: any("nothing more to undo" in words
                                              for words in said())), said()
        assert any("the last 200 edits, and 20 came before them" in words for words in said())
        assert app.session.unsaved


async def test_no_color_shows_whether_a_checkbox_is_ticked(tmp_path, monkeypatch):
    """Under NO_COLOR the edit form's Bold and Italic boxes both showed "X" in the same
    grey (Textual tells on from off by colour alone): the flyer's subtitle, italic and not
    bold, looked both.  Now an unticked box is empty, and Space ticks it."""
    monkeypatch.setenv("NO_COLOR", "1")
    path = copy_sample(tmp_path, "shop-flyer")
    async with editor(path) as (app, pilot):
        app.session.select("shop-subtitle")
        await pilot.press("enter")
        assert await until(pilot, lambda: app.screen.query("#field-bold"))
        bold, italic = app.screen.query_one("#field-bold"), app.screen.query_one("#field-italic")
        assert (bold.value, italic.value) == (False, True)
        assert "X" in italic.render().plain and "X" not in bold.render().plain
        bold.focus()
        await pilot.press("space")
        assert await until(pilot, lambda: "X" in bold.render().plain)


def test_a_terminal_that_is_not_utf8_is_told_so_not_drawn_in_escapes(tmp_path):
    """Under an ISO-8859-1 locale (here PYTHONIOENCODING, as the machine has no such locale
    built), every half block of the preview went out as the six characters "\\u2580": a
    screen of escapes, each row pushed past the edge.  Over a real pty, the editor now says
    before taking the screen that it needs UTF-8, and how to get it, and ends with exit 1."""
    import os

    path = copy_sample(tmp_path, "shop-flyer")
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "LANG": "C.UTF-8",
           "TERM": "xterm-256color", "COLORTERM": "truecolor", "PYTHONIOENCODING": "latin-1"}
    term = Terminal([sys.executable, "-m", "floatpage.cli.main", "edit", str(path)],
                    str(path.parent), env, COLUMNS, ROWS)
    try:
        deadline = time.monotonic() + 60
        status = 0
        while time.monotonic() < deadline:
            term.pump(0.1)
            pid, status = os.waitpid(term.pid, os.WNOHANG)
            if pid:
                break
        term.pump(0.3)
        said = bytes(term.received).decode("latin-1")
    finally:
        term.close()
    assert os.waitstatus_to_exitcode(status) == 1, said[-400:]
    assert "needs a UTF-8 terminal" in said and "iso8859-1" in said, said[-400:]
    assert "LANG=C.UTF-8" in said and "\\u2580" not in said and "\x1b[?1049h" not in said
