"""The compacted output draws exactly the screen Textual's own output draws, for fewer bytes:
checked cell by cell in a VT emulator (pyte), on random streams and on a real preview frame."""

from __future__ import annotations

import pyte
from hypothesis import given, settings
from hypothesis import strategies as st
from rich.console import Console

from floatpage.model import load_project
from floatpage.tui.cell_canvas import StripCache
from floatpage.tui.page_painter import PagePainter, PageView
from floatpage.tui.projection import Projection
from floatpage.tui.sgr_compactor import (
    DEFAULT, TOKEN, SgrCompactor, Style, apply_sgr, transition,
)

COLUMNS, ROWS = 40, 6


def seen(cell) -> tuple:
    """What a cell shows: a blank's foreground colour shows only under a line or reversed."""
    fg_shows = cell.data != " " or cell.underscore or cell.strikethrough or cell.reverse
    return (cell.data, cell.fg if fg_shows else None, cell.bg, cell.bold, cell.italics,
            cell.underscore, cell.strikethrough, cell.reverse, cell.blink)


def screen_after(*writes: str) -> list[list[tuple]]:
    screen = pyte.Screen(COLUMNS, ROWS)
    stream = pyte.Stream(screen)
    for text in writes:
        stream.feed(text)
    return [[seen(screen.buffer[row][col]) for col in range(COLUMNS)] for row in range(ROWS)]


def styles_of_text(writes: list[str]) -> list[tuple[str, Style | None]]:
    """Each printed character with the style in force when it was printed (this module's
    own model, which follows dim, overline and the rest that pyte ignores)."""
    style: Style | None = DEFAULT
    shown = []
    for text in writes:
        index = 0
        while index < len(text):
            match = TOKEN.match(text, index)
            if match:
                if match.group(1) is not None:
                    style = apply_sgr(style, match.group(1))
                index = match.end()
            else:
                shown.append((text[index], style))
                index += 1
    return shown


SGR_CODES = st.sampled_from([
    "0", "", "1", "2", "3", "4", "7", "9", "21", "53", "22", "23", "24", "27", "29", "55",
    "31", "97", "39", "42", "104", "49", "38;2;10;20;30", "48;2;250;0;7", "38;5;200",
    "48;5;17", "1;38;2;1;2;3;48;2;4;5;6"])
PIECES = st.one_of(
    SGR_CODES.map(lambda code: f"\x1b[{code}m"),
    st.text(alphabet="ab ▀", min_size=1, max_size=4),
    st.sampled_from(["  ", " "]),
    st.tuples(st.integers(1, ROWS), st.integers(1, COLUMNS)).map(
        lambda at: f"\x1b[{at[0]};{at[1]}H"),
    st.sampled_from(["\r", "\x1b[K"]),
)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.lists(PIECES, max_size=30).map("".join), min_size=1, max_size=4))
def test_random_streams_draw_the_same_screen(writes):
    compactor = SgrCompactor()
    compacted = [compactor.compact(text) for text in writes]
    assert screen_after(*compacted) == screen_after(*writes)
    original, shorter = styles_of_text(writes), styles_of_text(compacted)
    assert [char for char, _ in shorter] == [char for char, _ in original]
    for (char, want), (_, have) in zip(original, shorter):
        if char != " ":  # blanks keep whatever foreground the terminal has
            assert have == want
        else:
            assert have is not None and want is not None and have.bg == want.bg


def test_codes_it_does_not_follow_pass_through_unchanged():
    text = "\x1b[1;38;2;1;2;3mA\x1b[4:3mB\x1b[58;5;3mC\x1b[0mD"
    assert screen_after(SgrCompactor().compact(text)) == screen_after(text)
    assert "\x1b[4:3m" in SgrCompactor().compact(text)


def test_transition_turns_off_only_what_must_go():
    have = Style(frozenset({"bold", "dim"}), "31", "42")
    want = Style(frozenset({"dim"}), "31", "44")
    assert transition(have, want) == "\x1b[22;2;44m"
    assert transition(want, want) == ""
    assert transition(None, want) == "\x1b[0;2;31;44m"


def test_a_real_preview_frame_draws_the_same_for_far_fewer_bytes(project_path):
    """A frame of the test card's preview, rendered by Textual's own Strip rendering (one full
    style and a reset per run of cells), as the driver would send it."""
    global COLUMNS, ROWS
    page = load_project(project_path).pages[0]
    projection = Projection.fit(40, 20, page.width_mm, page.height_mm)
    canvas = PagePainter(projection).paint(PageView(page=page, base_dir=project_path.parent))
    console = Console(color_system="truecolor", width=canvas.cols)
    frame = "".join(f"\x1b[{row + 1};1H" + strip.render(console)
                    for row, strip in enumerate(StripCache().strips(canvas)))
    compacted = SgrCompactor().compact(frame)
    saved_size = COLUMNS, ROWS
    COLUMNS, ROWS = canvas.cols, canvas.rows
    try:
        assert screen_after(compacted) == screen_after(frame)
    finally:
        COLUMNS, ROWS = saved_size
    assert len(compacted.encode()) < 0.6 * len(frame.encode())
