"""Fewer bytes per frame: send only the cells the terminal does not already show.

Textual repaints a changed widget line from the widget's left edge to its last changed cell
(`ChopsUpdate.render_segments` crops a line only at its end), so every changed row of the
page preview carried its unchanged surround, and a guide line vanishing in the middle of a
photo resent the photo's left half on every row it crossed: 3.5 KB for a dashed line.

`ShadowScreen.rewrite` keeps a copy of what the terminal shows, cell by cell (character and
style), as curses does. It follows Textual's output (cursor moves, colour codes, text) and
sends only the cells that differ, reaching them with cursor moves; short gaps of unchanged
cells are resent when that is cheaper than the move. Colour codes go only where the colour
changes (`sgr_compactor.transition`), and a blank keeps the terminal's foreground, which it
does not show.

Whatever it cannot follow it passes on as it came and forgets what it knew: an unknown
sequence, an erase, a character that is not one cell wide (its width is the terminal's
business), a switch of screens. A forgotten cell is always sent again. A resize forgets
everything (`reset`). At the end of each write the terminal's cursor and style are where
Textual's own output would have left them.
"""

from __future__ import annotations

import re
from functools import lru_cache
from typing import Iterable

from rich.cells import cell_len

from floatpage.tui.sgr_compactor import DEFAULT, SHOWN_ON_BLANKS, Style, apply_sgr, transition

TOKEN = re.compile(
    r"\x1b\[([?<>=]?)([0-9;:]*)([ -/]*)([@-~])"  # CSI: private mark, parameters, final
    r"|\x1b\][^\x07\x1b]*(?:\x07|\x1b\\)"  # OSC (title, clipboard): paints nothing
    r"|\x1b[PX^_][^\x1b]*\x1b\\"  # DCS, SOS, PM, APC strings
    r"|\x1b[ -/]*[0-~]"  # other escapes
    r"|[\x00-\x1f\x7f]")  # C0 controls, one at a time (a lone ESC among them)

# Modes whose switching changes no cell: cursor shown, mouse and focus reports, paste,
# synchronized output, in-band resize, line wrap (text past the last column is not followed).
HARMLESS_MODES = frozenset({"7", "12", "25", "1000", "1002", "1003", "1004", "1005", "1006",
                            "1015", "1016", "2004", "2026", "2048"})
MOVES = frozenset("ABCDEFGHdf")
REWRITE_GAP = 6  # unchanged cells between changes: resent if cheaper than a cursor move


@lru_cache(maxsize=4096)
def blank_key(style: Style) -> Style:
    """What a blank cell shows of a style: its foreground only under a line or reversed."""
    if style.fg is None or style.flags & SHOWN_ON_BLANKS:
        return style
    return Style(style.flags, None, style.bg)


_narrow: dict[str, bool] = {}


def is_narrow(char: str) -> bool:
    """One cell wide for certain: where the terminal and Rich agree."""
    narrow = _narrow.get(char)
    if narrow is None:
        narrow = _narrow[char] = char.isascii() or cell_len(char) == 1
    return narrow


class ShadowScreen:
    """Rewrites one terminal's output stream, write by write, against a copy of its screen."""

    def __init__(self, cols: int, rows: int):
        self.wanted: Style | None = DEFAULT  # the style the stream has asked for
        self.raw_pending = ""  # style codes passed on as they came while `wanted` is unknown
        self.style: Style | None = None  # the terminal's style (None: unknown)
        self.reset(cols, rows)

    def reset(self, cols: int, rows: int) -> None:
        """Forget the screen (a resize, which some terminals answer by reflowing it)."""
        self.cols, self.rows = max(cols, 1), max(rows, 1)
        self.chars = [[" "] * self.cols for _ in range(self.rows)]
        self.keys: list[list[Style | None]] = [[None] * self.cols for _ in range(self.rows)]
        # The cursor of the original stream, and the terminal's as this stream left it. A
        # column of `cols` is the last column with a wrap pending. When the original's is
        # unknown (None), everything passes as it came, so the terminal's is the same.
        self.row: int | None = None
        self.col: int | None = None
        self.at: tuple[int, int] | None = None
        self.line_feeds: tuple[int, int, int] | None = None  # deferred: (row, col, count)
        # With the row known and the column not: the columns the cursor may be between.
        self.lost_span = (0, 0)

    # -- the stream -------------------------------------------------------------------------

    def rewrite(self, text: str) -> str:
        out: list[str] = []
        position = 0
        for match in TOKEN.finditer(text):
            start = match.start()
            if start > position:
                self._text(out, text[position:start])
            if match.group(4) == "m" and not match.group(1) and not match.group(3):
                self._sgr(out, match.group(0), match.group(2))
            else:
                self._token(out, match)
            position = match.end()
        if position < len(text):
            self._text(out, text[position:])
        self._flush_line_feeds(out)
        if self.col is not None:
            self._goto(out, self.row, self.col)
        self._settle(out, "x")
        return "".join(out)

    def can_paint(self) -> bool:
        """The stream's cursor and style are known, so `paint` can put them back."""
        return self.row is not None and self.col is not None and self.line_feeds is None \
            and self.wanted is not None and not self.raw_pending

    def paint(self, runs: Iterable[tuple[int, int, str, Style]]) -> str:
        """Cells from outside the stream (`direct_paint`: the page preview's, which never go
        through Textual): each run's text at (row, column) in its style, sent only where the
        terminal shows something else. Then the terminal's cursor and style go back to where
        the stream left them, so the stream goes on as if nothing had come between.
        Needs `can_paint()`."""
        out: list[str] = []
        row, col, wanted = self.row, self.col, self.wanted
        for run_row, run_col, text, style in runs:
            if 0 <= run_row < self.rows and 0 <= run_col < self.cols:
                self.row, self.col, self.wanted = run_row, run_col, style
                self._text(out, text)
        self.row, self.col, self.wanted = row, col, wanted
        if out:
            self._goto(out, row, col)
            self._settle(out, "x")
        return "".join(out)

    def _token(self, out: list[str], match: re.Match) -> None:
        whole = match.group(0)
        final = match.group(4)
        if final is not None:
            private, params, between = match.group(1), match.group(2), match.group(3)
            if final == "m" and not private and not between:
                self._sgr(out, whole, params)
            elif final in MOVES and not private and not between:
                self._move(out, whole, final, params)
            elif final in "JK" and not private and not between:
                self._erase(out, whole, final, params)
            elif final in "hl" and private == "?" and not between:
                if set(params.split(";")) <= HARMLESS_MODES:
                    out.append(whole)
                else:  # another screen, origin mode and the like
                    self._pass_and_forget(out, whole)
            elif self._harmless_csi(private, between, final):
                out.append(whole)
            else:
                self._pass_and_forget(out, whole)
        elif whole == "\r":
            if self.row is None:
                out.append(whole)  # the terminal moves with the stream
            else:  # a known place again: line feeds deferred before it are moot
                self.line_feeds = None
                self.col = 0
        elif whole == "\n":
            self._line_feed(out)
        elif whole == "\x07" or whole in ("\x1b=", "\x1b>"):  # bell, keypad modes
            out.append(whole)
        elif whole.startswith("\x1b]"):  # OSC: a title, the clipboard
            out.append(whole)
        else:
            self._pass_and_forget(out, whole)

    @staticmethod
    def _harmless_csi(private: str, between: str, final: str) -> bool:
        """Queries and settings that paint nothing: reports (n, c), mode queries ($p), the
        cursor's shape ( q), the version query (>q) and the kitty keyboard protocol (u)."""
        return (final in "nc" and not between) or (final == "p" and between == "$") \
            or (final == "q" and (between == " " or private == ">")) \
            or (final == "u" and private in ("<", ">", "=", "?"))

    # -- styles -----------------------------------------------------------------------------

    def _sgr(self, out: list[str], whole: str, params: str) -> None:
        """Follow the style asked for; `_settle` sends it only before what shows it."""
        wanted = apply_sgr(self.wanted, params)
        if wanted is None:  # a code not followed: pass it on as it came, over the style
            if self.wanted is not None:  # it was meant to change
                self._settle(out, "x")
            self.raw_pending += whole
        elif self.wanted is None:  # a reset ends the unknown stretch
            self.raw_pending = ""
            self.style = None
        self.wanted = wanted

    def _settle(self, out: list[str], shown: str, want: Style | None = None) -> None:
        """Bring the terminal to `want` (default: the wanted style) before `shown` is written;
        before blanks the terminal keeps its own foreground."""
        if want is None:
            want = self.wanted
            if want is None:
                if self.raw_pending:
                    out.append(self.raw_pending)
                    self.raw_pending = ""
                self.style = None
                return
        style = self.style
        if style is want:
            return
        if style is not None and want.fg != style.fg and not shown.strip(" ") \
                and not (want.flags | style.flags) & SHOWN_ON_BLANKS:
            want = Style(want.flags, style.fg, want.bg)
        out.append(transition(style, want))
        self.style = want

    # -- the cursor -------------------------------------------------------------------------

    def _goto(self, out: list[str], row: int, col: int) -> None:
        """Put the terminal's cursor where the stream's is (a column of `cols`: on the last
        column with a wrap pending, reached by writing that cell again)."""
        if self.at == (row, col):
            return
        if col >= self.cols:
            last = self.cols - 1
            key = self.keys[row][last]
            self._goto(out, row, last)
            if key is not None:
                char = self.chars[row][last]
                self._settle(out, char, key)
                out.append(char)
                self.at = (row, self.cols)
            return
        at = self.at
        if at is not None and at[0] == row:
            step = col - min(at[1], self.cols - 1)
            if step > 0:
                out.append("\x1b[C" if step == 1 else f"\x1b[{step}C")
            elif step < 0:
                out.append("\x1b[D" if step == -1 else f"\x1b[{-step}D")
            else:  # from a pending wrap on the last column to that column
                out.append(f"\x1b[{row + 1};{col + 1}H")
        else:
            out.append(f"\x1b[{row + 1};{col + 1}H")
        self.at = (row, col)

    def _move(self, out: list[str], whole: str, final: str, params: str) -> None:
        """A cursor move paints nothing: follow it, and move the terminal's only when a cell
        is to be written."""
        numbers = [int(part) if part.isdigit() else 0 for part in params.split(";")]
        if final in "Hf":
            self.line_feeds = None
            row = numbers[0] if numbers else 0
            col = numbers[1] if len(numbers) > 1 else 0
            self.row = min(max(row, 1), self.rows) - 1
            self.col = min(max(col, 1), self.cols) - 1
            return
        self._flush_line_feeds(out)
        if self.row is None or self.col is None:
            out.append(whole)  # relative to a place unknown: the terminal moves with the stream
            count = max(numbers[0], 1) if numbers else 1
            if final == "G" and self.row is not None:
                self.col = min(count, self.cols) - 1
            elif final == "C" and self.row is not None:
                low, high = self.lost_span
                self.lost_span = (min(low + count, self.cols - 1), min(high + count, self.cols - 1))
            elif final == "D" and self.row is not None:
                low, high = self.lost_span
                self.lost_span = (max(low - count, 0), max(high - count, 0))
            else:
                self.row = None  # the row is lost too
            return
        if self.col >= self.cols:  # from a pending wrap emulators differ: pass it on as it is
            self._goto(out, self.row, self.col)
            out.append(whole)
            self._forget_all()
            self.row = self.col = self.at = None
            return
        count = max(numbers[0], 1) if numbers else 1
        row, col = self.row, self.col
        if final == "A":
            row -= count
        elif final == "B":
            row += count
        elif final == "C":
            col += count
        elif final == "D":
            col -= count
        elif final == "E":
            row, col = row + count, 0
        elif final == "F":
            row, col = row - count, 0
        elif final == "G":
            col = count - 1
        elif final == "d":
            row = count - 1
        self.row = min(max(row, 0), self.rows - 1)
        self.col = min(max(col, 0), self.cols - 1)

    def _line_feed(self, out: list[str]) -> None:
        """A line feed moves the cursor down (and to the left edge, if the pty adds a carriage
        return); at the bottom it scrolls. Textual follows each with a cursor position, which
        makes it moot: it is deferred, and sent only if something is written before a cursor
        position comes."""
        deferred = self.line_feeds is not None
        if not deferred and (self.row is None or self.col is None):
            out.append("\n")  # in step with the stream
            if self.row is not None and self.row < self.rows - 1:
                self.row += 1
                self.lost_span = (0, self.lost_span[1])  # a carriage return, if the pty adds it
            else:
                self._forget_all()
            return
        if self.row >= self.rows - 1:  # a scroll: everything moves up a row
            self._flush_line_feeds(out)
            if self.col is not None:
                self._goto(out, self.row, self.col)
            out.append("\n")
            self._forget_all()
            self.col, self.at = None, None
            return
        if not deferred:
            self.line_feeds = (self.row, self.col, 0)
        row, col, count = self.line_feeds
        self.line_feeds = (row, col, count + 1)
        self.row += 1
        self.col = None  # unknown until sent, or made moot by a cursor position

    def _flush_line_feeds(self, out: list[str]) -> None:
        """Send the deferred line feeds from where they were written."""
        if self.line_feeds is None:
            return
        row, col, count = self.line_feeds
        self.line_feeds = None
        self._goto(out, row, col)
        out.append("\n" * count)
        self.at = None  # in step with the stream, whose column is not known
        self.lost_span = (0, min(col, self.cols - 1))

    # -- cells ------------------------------------------------------------------------------

    def _text(self, out: list[str], text: str) -> None:
        self._flush_line_feeds(out)
        row, col = self.row, self.col
        if row is None or col is None:
            self._settle(out, text)
            out.append(text)
            if row is not None:
                low, high = self.lost_span
                high += 2 * len(text)  # at most two cells a character
                if high < self.cols:
                    self._forget(row, max(low - 1, 0), self.cols)
                    self.lost_span = (low, high)
                    return
            self._forget_all()  # it may have wrapped
            self.row = None
            return
        wanted = self.wanted
        chars, keys, cols = self.chars[row], self.keys[row], self.cols
        if wanted is None:
            key = blank = None  # cells in a style not followed: written, and not remembered
        else:
            key, blank = wanted, blank_key(wanted)
        limit = len(text)
        if not text.isascii():
            limit = next((index for index, char in enumerate(text) if not is_narrow(char)), limit)
            if 0 < limit < len(text) and cell_len(text[limit]) == 0:
                limit -= 1  # a combining mark goes with the character it marks
        limit = min(limit, cols - col)
        index = 0
        while index < limit:  # runs of cells the terminal does not show yet
            if key is not None:
                char = text[index]
                shown = blank if char == " " else key
                known = keys[col + index]
                if chars[col + index] == char and (known is shown or known == shown):
                    index += 1
                    continue
            start = index
            index += 1
            while index < limit:
                if key is not None:
                    char = text[index]
                    shown = blank if char == " " else key
                    known = keys[col + index]
                    if chars[col + index] == char and (known is shown or known == shown):
                        break
                index += 1
            run = text[start:index]
            if self.at != (row, col + start):
                self._reach(out, row, col + start, run)
            self._settle(out, run)
            out.append(run)
            chars[col + start:col + index] = run
            keys[col + start:col + index] = [blank if char == " " else key for char in run]
            self.at = (row, col + index)
        col += limit
        if limit < len(text):
            # past the row's end, or a width that is the terminal's business: pass the rest
            # as it came, from the right place, and forget what it covers
            self._goto(out, row, col)
            rest = text[limit:]
            self._settle(out, rest)
            out.append(rest)
            if col + 2 * len(rest) >= cols:  # it may wrap, with the terminal's widths
                self._forget_all()
                self.row = None
            else:  # a combining mark at its start joins the cell before
                self._forget(row, max(col - 1, 0), cols)
                self.lost_span = (col, col + 2 * len(rest))
            self.col = None
            self.at = None
            return
        self.col = col

    def _reach(self, out: list[str], row: int, col: int, run: str) -> None:
        """Move to (row, col) before writing `run`: by resending a short gap of unchanged
        cells, when that takes fewer bytes than moving over them."""
        at = self.at
        if at is not None and at[0] == row and 0 < col - at[1] <= REWRITE_GAP \
                and self.wanted is not None:
            keys, chars = self.keys[row], self.chars[row]
            gap = range(at[1], col)
            if all(keys[index] is not None for index in gap):
                saved, parts = self.style, []
                for index in gap:
                    self._settle(parts, chars[index], keys[index])
                    parts.append(chars[index])
                self._settle(parts, run)
                resent = "".join(parts)
                after_gap = self.style
                self.style = saved
                moved: list[str] = []
                step = col - at[1]
                moved.append("\x1b[C" if step == 1 else f"\x1b[{step}C")
                self._settle(moved, run)
                if len(resent.encode()) < len("".join(moved).encode()):
                    out.append(resent)
                    self.style = after_gap
                    self.at = (row, col)
                    return
                self.style = saved
        self._goto(out, row, col)

    def _erase(self, out: list[str], whole: str, final: str, params: str) -> None:
        """An erase paints blanks in the current background: sent from the right place and
        style, and the cells it touches forgotten."""
        self._flush_line_feeds(out)
        if self.row is not None and self.col is not None:
            self._goto(out, self.row, self.col)
        self._settle(out, " ")
        out.append(whole)
        row, col = self.row, self.col
        kind = params or "0"
        if row is None or col is None:
            if row is not None and final == "K":
                self._forget(row, 0, self.cols)
            else:
                self._forget_all()
            return
        col = min(col, self.cols - 1)
        if final == "K":
            start, end = {"0": (col, self.cols), "1": (0, col + 1)}.get(kind, (0, self.cols))
            self._forget(row, start, end)
        elif kind == "0":
            self._forget(row, col, self.cols)
            for below in range(row + 1, self.rows):
                self._forget(below, 0, self.cols)
        elif kind == "1":
            self._forget(row, 0, col + 1)
            for above in range(row):
                self._forget(above, 0, self.cols)
        else:
            self._forget_all()

    def _forget(self, row: int, start: int, end: int) -> None:
        self.keys[row][start:end] = [None] * (end - start)

    def _forget_all(self) -> None:
        for keys in self.keys:
            keys[:] = [None] * self.cols

    def _pass_and_forget(self, out: list[str], whole: str) -> None:
        """Something not followed: send it as it came, from where the stream's cursor is, then
        know nothing of the screen, the cursor or the style until told again."""
        self._flush_line_feeds(out)
        if self.row is not None and self.col is not None:
            self._goto(out, self.row, self.col)
        self._settle(out, "x")
        out.append(whole)
        self._forget_all()
        self.row = self.col = None
        self.at = None
        self.style = None  # a restored cursor brings its style back: in step, not known
        self.wanted, self.raw_pending = None, ""
