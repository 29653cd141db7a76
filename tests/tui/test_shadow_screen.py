"""The rewritten output draws exactly the screen Textual's own output draws, for fewer bytes:
checked cell by cell in a VT emulator (pyte) after every write, on random streams and on the
real editor's frames, with the cursor where Textual's output leaves it."""

from __future__ import annotations

import pyte
from hypothesis import given, settings
from hypothesis import strategies as st

from floatpage.tui.sgr_compactor import DEFAULT, apply_sgr, transition
from floatpage.tui.shadow_screen import ShadowScreen

from editor_helpers import editor, screen_of

COLUMNS, ROWS = 12, 5


def seen(cell) -> tuple:
    """What a cell shows: a blank's foreground colour shows only under a line or reversed."""
    fg_shows = cell.data != " " or cell.underscore or cell.strikethrough or cell.reverse
    return (cell.data, cell.fg if fg_shows else None, cell.bg, cell.bold, cell.italics,
            cell.underscore, cell.strikethrough, cell.reverse, cell.blink)


class Emulator:
    def __init__(self, columns: int, rows: int):
        self.columns, self.rows = columns, rows
        self.screen = pyte.Screen(columns, rows)
        self.stream = pyte.Stream(self.screen)

    def feed(self, text: str) -> None:
        self.stream.feed(text)

    def cells(self) -> list[list[tuple]]:
        buffer = self.screen.buffer
        return [[seen(buffer[row][col]) for col in range(self.columns)]
                for row in range(self.rows)]

    def cursor(self) -> tuple[int, int]:
        return self.screen.cursor.y, self.screen.cursor.x


def assert_same_screens(writes: list[str], columns: int = COLUMNS, rows: int = ROWS) -> int:
    """Feed the writes as they are and as rewritten; the same cells and cursor after each.
    Returns the bytes the rewritten writes took."""
    original, rewritten = Emulator(columns, rows), Emulator(columns, rows)
    shadow = ShadowScreen(columns, rows)
    total = 0
    for number, text in enumerate(writes):
        shorter = shadow.rewrite(text)
        total += len(shorter.encode())
        original.feed(text)
        rewritten.feed(shorter)
        assert rewritten.cells() == original.cells(), f"write {number}: {text!r} -> {shorter!r}"
        assert rewritten.cursor() == original.cursor(), f"write {number}: {text!r} -> {shorter!r}"
    return total


SGR_CODES = st.sampled_from([
    "0", "", "1", "3", "4", "7", "9", "22", "24", "27", "31", "97", "39", "42", "104", "49",
    "38;2;10;20;30", "48;2;250;0;7", "38;5;200", "48;5;17", "1;38;2;1;2;3;48;2;4;5;6",
    "0;38;2;1;2;3;48;2;4;5;6", "0;48;2;4;5;6"])
PIECES = st.one_of(
    SGR_CODES.map(lambda code: f"\x1b[{code}m"),
    st.text(alphabet="ab ▀", min_size=1, max_size=6),
    st.sampled_from(["  ", " ", "日", "e\u0301", "x日y"]),
    st.tuples(st.integers(1, ROWS), st.integers(1, COLUMNS)).map(
        lambda at: f"\x1b[{at[0]};{at[1]}H"),
    st.sampled_from(["\r", "\n", "\x1b[K", "\x1b[1K", "\x1b[2K", "\x1b[J", "\x1b[2J",
                     "\x1b[2C", "\x1b[D", "\x1b[A", "\x1b[B", "\x1b[3G", "\x1b[H",
                     "\x1b[?2026h", "\x1b[?2026l", "\x1b[?25l", "\x1b[?7l", "\x1b[?7h",
                     "\x1b[58;5;3m", "\x1b7", "\x1b8", "\x1b[6n", "\x07"]),
)
# Textual's own kind of write: positioned runs of styled text, each reset after.
FRAME_PIECES = st.tuples(
    st.integers(1, ROWS), st.integers(1, COLUMNS),
    st.lists(st.tuples(SGR_CODES, st.text(alphabet="ab ▀", min_size=1, max_size=5)),
             min_size=1, max_size=4),
).map(lambda piece: f"\x1b[{piece[0]};{piece[1]}H" + "".join(
    f"\x1b[{code}m{text}\x1b[0m" for code, text in piece[2]))


@settings(max_examples=400, deadline=None)
@given(st.lists(st.lists(PIECES, max_size=25).map("".join), min_size=1, max_size=5))
def test_random_streams_draw_the_same_screen(writes):
    assert_same_screens(writes)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.lists(FRAME_PIECES, min_size=1, max_size=8).map("".join),
                min_size=2, max_size=6))
def test_frames_like_textuals_draw_the_same_screen(writes):
    assert_same_screens(writes)


def test_unchanged_cells_are_not_sent_again():
    """The second frame changes one cell in the middle of a row Textual sends whole."""
    row = "\x1b[2;1H\x1b[48;2;38;38;46m" + "ab" * 5 + "\x1b[0m"
    changed = row.replace("ababa", "ababX", 1)
    shadow = ShadowScreen(COLUMNS, ROWS)
    shadow.rewrite(row)
    again = shadow.rewrite(changed)
    assert "X" in again and "a" not in again and "b" not in again
    assert shadow.rewrite(changed) == ""  # the same frame again: nothing to send
    assert_same_screens([row, changed, changed])


def test_a_resize_forgets_the_screen():
    row = "\x1b[1;1Habc"
    shadow = ShadowScreen(COLUMNS, ROWS)
    shadow.rewrite(row)
    shadow.reset(COLUMNS + 2, ROWS)
    assert "abc" in shadow.rewrite(row)


async def test_the_editors_real_frames_draw_the_same_screen(project_path):
    """The editor's own full-screen renders, one after each step of a session (select, move,
    physics, labels, a dialog), rewritten as diffs against the last: the same screen each time,
    for a fraction of the bytes."""
    columns, rows = 100, 34
    async with editor(project_path, size=(columns, rows)) as (app, pilot):
        frames = []

        def capture() -> None:
            update = app.screen._compositor.render_update(full=True)
            frames.append("\x1b[?2026h" + update.render_segments(app.console) + "\x1b[1;1H"
                          + "\x1b[?2026l")

        capture()
        for keys in (["tab"], ["tab"], ["down"], ["down", "down"], ["n"], ["n"], ["right"],
                     ["v"], ["i"], ["escape"], ["bracketright"]):
            await pilot.press(*keys)
            screen_of(app).step_physics(5)
            await pilot.pause()
            capture()
        sent = assert_same_screens(frames, columns, rows)
        assert sent < 0.5 * sum(len(frame.encode()) for frame in frames)


# A whole write of Textual's: runs, then the cursor put where the app wants it.
TEXTUAL_WRITES = st.tuples(
    st.lists(FRAME_PIECES, min_size=1, max_size=6).map("".join),
    st.integers(1, ROWS), st.integers(1, COLUMNS),
).map(lambda write: f"{write[0]}\x1b[{write[1]};{write[2]}H")
PAINT_RUNS = st.lists(st.tuples(
    st.integers(0, ROWS - 1), st.integers(0, COLUMNS - 1), SGR_CODES,
    st.text(alphabet="ab ▀", min_size=1, max_size=5) | st.just("日")), min_size=1, max_size=6)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.one_of(TEXTUAL_WRITES, PAINT_RUNS), min_size=2, max_size=8))
def test_cells_painted_outside_the_stream_draw_the_same_screen(writes):
    """`paint` (the preview's cells, past Textual) among Textual-like frames: the same cells
    as writing each run in place and putting the cursor and style back (DECSC/DECRC), and
    the stream goes on from where it was. (Textual ends each write with a cursor move, so
    the cursor never waits to wrap when cells are painted.)"""
    original, rewritten = Emulator(COLUMNS, ROWS), Emulator(COLUMNS, ROWS)
    shadow = ShadowScreen(COLUMNS, ROWS)
    for number, write in enumerate(writes):
        if isinstance(write, str):
            original.feed(write)
            rewritten.feed(shadow.rewrite(write))
        else:
            runs = [(row, col, style, text[:COLUMNS - col - (text == "日")])
                    for row, col, code, text in write
                    if (style := apply_sgr(DEFAULT, code)) is not None]
            runs = [(row, col, text, style) for row, col, style, text in runs if text]
            if not shadow.can_paint():
                continue  # the driver leaves these to Textual
            original.feed("\x1b7" + "".join(f"\x1b[{row + 1};{col + 1}H{transition(None, style)}{text}"
                                             for row, col, text, style in runs) + "\x1b8")
            rewritten.feed(shadow.paint(runs))
        assert rewritten.cells() == original.cells(), f"write {number}: {write!r}"
        assert rewritten.cursor() == original.cursor(), f"write {number}: {write!r}"
