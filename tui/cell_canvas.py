"""A grid of half-block pixels plus glyphs, turned into Textual Strips.

Each cell shows two pixels, the upper as the foreground of '▀' and the lower as
its background, or one glyph (a letter of a label or text) over a background.
Runs of cells with the same style become one Segment, and a row whose content
did not change reuses last frame's Strip, so an idle frame costs little.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np
from rich.color import Color
from rich.segment import Segment
from rich.style import Style
from textual.strip import Strip

from floatpage.tui.cell_text import graphemes, width

RGB = tuple[int, int, int]
LUMA = (0.2126, 0.7152, 0.0722)  # a colour's grey, as Textual's Monochrome (NO_COLOR) takes it
UPPER_HALF = "\u2580"
CellRun = tuple[str, int, int, int, bool]  # text, cells, fg, bg (packed), bold
NARROW_SPAN = 24  # columns up to which a span's runs are found cell by cell, not with numpy
# How many (foreground, background) styles the preview keeps made, here and in the direct
# painter: thumbnails bring hundreds of new colour pairs on every page shown, and kept
# forever they took 20 MB (1.7 KB a pair) after one pass through a 27-page album of photos,
# growing with every page. A frame needs at most one a cell (3,400 at 100 x 34); past the
# limit the kept ones are dropped and made again as asked for.
STYLES_KEPT = 16_384


@lru_cache(maxsize=4096)
def text_width(grapheme: str) -> int:
    return width(grapheme)


def pack(rgb: RGB) -> int:
    return (rgb[0] << 16) | (rgb[1] << 8) | rgb[2]


def unpack(value: int) -> RGB:
    return (value >> 16) & 255, (value >> 8) & 255, value & 255


@dataclass(frozen=True)
class Glyph:
    """One character in a cell; bg None means 'whatever pixel is in the cell's upper half'."""

    char: str
    fg: RGB
    bg: RGB | None = None
    bold: bool = False


class CellCanvas:
    """cols x rows cells = cols x (2 rows) pixels. Drawing clips to the canvas.

    Something drawn over a glyph hides it. Rather than deleting glyphs cell by cell, every fill
    stamps the cells it touches with a rising layer number (one numpy slice), and a glyph is
    shown only if it was written after the last fill of its cell.
    """

    def __init__(self, cols: int, rows: int, fill: RGB):
        self.cols, self.rows = cols, rows
        self.pixels = np.empty((2 * rows, cols, 3), dtype=np.uint8)
        self.pixels[:] = fill
        self.layers = np.zeros((rows, cols), dtype=np.int32)
        self.layer = 0
        self._glyphs: dict[tuple[int, int], tuple[Glyph, int]] = {}

    def _clip(self, x0: int, y0: int, x1: int, y1: int) -> tuple[int, int, int, int]:
        return max(x0, 0), max(y0, 0), min(x1, self.cols), min(y1, 2 * self.rows)

    def _cover(self, x0: int, y0: int, x1: int, y1: int) -> None:
        """Hide the glyphs in every cell a clipped pixel box touches."""
        self.layer += 1
        self.layers[y0 // 2:(y1 + 1) // 2, x0:x1] = self.layer

    @property
    def glyphs(self) -> dict[tuple[int, int], Glyph]:
        """The glyphs still visible, by (row, col)."""
        layers = self.layers
        return {cell: glyph for cell, (glyph, layer) in self._glyphs.items()
                if layer >= layers[cell]}

    def glyph_at(self, col: int, row: int) -> Glyph | None:
        if not (0 <= col < self.cols and 0 <= row < self.rows):
            return None
        entry = self._glyphs.get((row, col))
        if entry is None or entry[1] < self.layers[row, col]:
            return None
        return entry[0]

    def fill(self, x0: int, y0: int, x1: int, y1: int, rgb: RGB) -> None:
        cx0, cy0, cx1, cy1 = self._clip(x0, y0, x1, y1)
        if cx0 < cx1 and cy0 < cy1:
            self.pixels[cy0:cy1, cx0:cx1] = rgb
            self._cover(cx0, cy0, cx1, cy1)

    def blit(self, x0: int, y0: int, image: np.ndarray) -> None:
        """Copy an (h, w, 3) image with its top-left at pixel (x0, y0)."""
        h, w = image.shape[:2]
        cx0, cy0, cx1, cy1 = self._clip(x0, y0, x0 + w, y0 + h)
        if cx0 < cx1 and cy0 < cy1:
            self.pixels[cy0:cy1, cx0:cx1] = image[cy0 - y0:cy1 - y0, cx0 - x0:cx1 - x0]
            self._cover(cx0, cy0, cx1, cy1)

    def outline(self, x0: int, y0: int, x1: int, y1: int, rgb: RGB,
                on_light: RGB | None = None) -> None:
        """A one-pixel frame just outside the box (x0, y0, x1, y1); glyphs stay visible.
        With `on_light`, the frame's pixels over light ones (luma above half) take that
        colour instead: in greys a light frame vanishes on light paper."""
        for box in ((x0 - 1, y0 - 1, x1 + 1, y0), (x0 - 1, y1, x1 + 1, y1 + 1),
                    (x0 - 1, y0, x0, y1), (x1, y0, x1 + 1, y1)):
            cx0, cy0, cx1, cy1 = self._clip(*box)
            if cx0 < cx1 and cy0 < cy1:
                under = self.pixels[cy0:cy1, cx0:cx1]
                if on_light is None:
                    under[...] = rgb
                else:
                    light = under.astype(np.float32) @ np.array(LUMA, np.float32) > 127.5
                    under[light] = on_light
                    under[~light] = rgb

    def put(self, col: int, row: int, glyph: Glyph) -> None:
        if 0 <= col < self.cols and 0 <= row < self.rows:
            self._glyphs[(row, col)] = (glyph, self.layer)

    def write(self, col: int, row: int, text: str, fg: RGB, bg: RGB | None = None,
              bold: bool = False, end_col: int | None = None) -> None:
        """Write text from (col, row), stopping before end_col (default: the canvas edge)."""
        if not 0 <= row < self.rows:
            return
        end = self.cols if end_col is None else min(end_col, self.cols)
        layer, glyphs = self.layer, self._glyphs
        at = col
        for grapheme in graphemes(text):
            wide = width(grapheme)
            if at + wide > end:
                break
            if at >= 0:
                glyphs[(row, at)] = (Glyph(grapheme, fg, bg, bold), layer)
                if wide == 2:  # the cell the wide character spills into shows nothing itself
                    glyphs[(row, at + 1)] = (Glyph("", fg, bg, bold), layer)
            at += wide


SPAN_GAP = 8  # unchanged cells between two changes that still go in one span


def changed_spans(cached: "CachedRow | None", pair: np.ndarray, glyphs: tuple,
                  cols: int) -> tuple[tuple[int, int], ...]:
    """The (first, end) columns of a row that differ from its cached version, each one cell
    wider on either side for wide characters; the whole row when there is nothing to compare
    with. Changes more than SPAN_GAP unchanged cells apart go in spans of their own: two
    guide lines on the calendar changed columns 33 and 66 of each row they crossed, and the
    35 cells between them, digits mostly, went through the segments and the shadow screen
    on every arrow (2-4 ms of its answer; issue 11, key to screen)."""
    if cached is None or cached.pair.shape != pair.shape:
        return ((0, cols),)
    columns = set(np.flatnonzero((cached.pair != pair).any(axis=0)).tolist())
    columns.update(col for col, _glyph in set(cached.glyphs) ^ set(glyphs))
    spans: list[tuple[int, int]] = []
    for col in sorted(columns):
        first, end = max(col - 1, 0), min(col + 2, cols)
        if spans and first <= spans[-1][1] + SPAN_GAP:
            spans[-1] = (spans[-1][0], end)
        else:
            spans.append((first, end))
    return tuple(spans)


@dataclass
class CachedRow:
    """One row as last painted: its pixel pair (2, cols), its glyphs by column, and its Strip,
    built only when Textual asks for it (None until then)."""

    pair: np.ndarray
    glyphs: tuple[tuple[int, Glyph], ...]
    strip: Strip | None = None

    @cached_property
    def glyph_map(self) -> dict[int, Glyph]:
        return dict(self.glyphs)


class StripCache:
    """Turns a canvas into Strips, reusing styles and unchanged rows across frames.

    `update` tells which cells of which rows differ from the last frame, in `changed` as
    {row: ((first col, end col), ...)}: the preview repaints only those, since a moving item changes
    a few columns of its rows and the page's surround none (issue 11). A changed row's Strip
    is built when it is asked for (`strip`): when the preview's cells go straight to the
    terminal (`direct_paint`), only the changed columns are turned into segments
    (`segments`), and building whole rows was 2 ms of a key's answer on the greeting card.
    """

    def __init__(self):
        self._styles: dict[tuple[int, int, bool], Style] = {}
        self._rows: dict[int, CachedRow] = {}
        self._packed: np.ndarray | None = None  # the last frame's pixels, packed (2 x rows, cols)
        self.rows = 0
        self.cols = 0
        self.changed: dict[int, tuple[tuple[int, int], ...]] = {}

    def style(self, fg: int, bg: int, bold: bool = False) -> Style:
        key = (fg, bg, bold)
        style = self._styles.get(key)
        if style is None:
            if len(self._styles) >= STYLES_KEPT:
                self._styles.clear()
            style = Style(color=Color.from_rgb(*unpack(fg)), bgcolor=Color.from_rgb(*unpack(bg)),
                          bold=bold)
            self._styles[key] = style
        return style

    def update(self, canvas: CellCanvas) -> None:
        """Take a new frame: remember each changed row, and where it changed."""
        packed = ((canvas.pixels[..., 0].astype(np.int64) << 16)
                  | (canvas.pixels[..., 1].astype(np.int64) << 8)
                  | canvas.pixels[..., 2].astype(np.int64))
        glyph_rows: dict[int, list[tuple[int, Glyph]]] = {}
        for (row, col), glyph in canvas.glyphs.items():
            glyph_rows.setdefault(row, []).append((col, glyph))
        self.changed = {}
        if canvas.rows != self.rows or canvas.cols != self.cols:
            self._rows = {}
            self._packed = None
        self.rows, self.cols = canvas.rows, canvas.cols
        # which rows' pixels changed, in one comparison (row by row it was 0.3 ms a frame)
        if self._packed is None:
            pixels_changed = [True] * canvas.rows
        else:
            pixels_changed = (packed != self._packed).reshape(canvas.rows, -1).any(axis=1).tolist()
        self._packed = packed
        for row in range(canvas.rows):
            pair = packed[2 * row:2 * row + 2]
            glyphs = tuple(sorted(glyph_rows.get(row, ()), key=lambda entry: entry[0]))
            cached = self._rows.get(row)
            if cached is not None and cached.glyphs == glyphs and not pixels_changed[row]:
                continue
            spans = changed_spans(cached, pair, glyphs, canvas.cols)
            if spans:
                self.changed[row] = spans
            self._rows[row] = CachedRow(pair, glyphs)

    def strip(self, row: int) -> Strip:
        """The row's Strip, built now if the row changed since it was last asked for."""
        cached = self._rows[row]
        if cached.strip is None:
            cached.strip = Strip(self.segments(row, 0, self.cols)[1], self.cols)
        return cached.strip

    def strips(self, canvas: CellCanvas) -> list[Strip]:
        """Take a new frame and return all its rows' Strips."""
        self.update(canvas)
        return [self.strip(row) for row in range(self.rows)]

    def segments(self, row: int, first: int, end: int) -> tuple[int, list[Segment]]:
        """Columns first to end of a row as Segments (`runs`), and the column they start at."""
        start, runs = self.runs(row, first, end)
        style = self.style
        return start, [Segment(text, style(fg, bg, bold)) for text, _cells, fg, bg, bold in runs]

    def runs(self, row: int, first: int, end: int) -> tuple[int, list[CellRun]]:
        """Columns first to end of a row as runs of cells in one style, (text, cells, fg, bg,
        bold) with the colours packed, and the column they start at. A wide character's second
        cell is drawn by its first: at `first`, it is left out and the runs start a column
        later; at `end - 1`, the runs end a column after `end`.

        Cells between glyphs go by stretches of equal pixels, which numpy finds in a wide span
        (building whole rows was most of a key's redraw); a narrow one goes cell by cell, as
        numpy cost more than it saved there (20 us a span, and a guide line crossing the
        calendar makes 47 spans of 3 cells). No Rich styles are made here: the direct painter
        maps the colours to terminal codes itself, and `segments` makes them for Strips."""
        cached = self._rows[row]
        if end <= first:
            return first, []
        glyphs = cached.glyph_map
        top_row, bottom_row = cached.pair[0, first:end], cached.pair[1, first:end]
        if end - first <= NARROW_SPAN:
            bounds = list(range(first, end + 1))
        else:
            starts = np.empty(end - first, dtype=bool)
            starts[0] = True
            np.not_equal(top_row[1:], top_row[:-1], out=starts[1:])
            starts[1:] |= bottom_row[1:] != bottom_row[:-1]
            for col in glyphs:  # every glyph is a run of its own, and so is what follows it
                if first <= col < end:
                    starts[col - first] = True
                if first <= col + 1 < end:
                    starts[col + 1 - first] = True
            bounds = (np.flatnonzero(starts) + first).tolist() + [end]
        tops, bottoms = top_row.tolist(), bottom_row.tolist()  # from column `first`
        runs: list[CellRun] = []
        text_parts: list[str] = []
        cells = 0
        key: tuple[int, int, bool] | None = None
        start = first
        for col, run_end in zip(bounds, bounds[1:]):
            glyph = glyphs.get(col) if glyphs else None
            if glyph is not None and glyph.char:
                bg = pack(glyph.bg) if glyph.bg is not None else tops[col - first]
                cell_key, text = (pack(glyph.fg), bg, glyph.bold), glyph.char
                count = text_width(text)
                if count == 2:
                    following = glyphs.get(col + 1)
                    if following is None or following.char != "":
                        text, count = " ", 1  # its second cell was drawn over: keep the width
            elif glyph is not None and col > 0 and glyphs.get(col - 1) is not None:
                if col == first:
                    start = first + 1
                continue  # the second cell of a wide character, drawn by the first
            else:
                top, bottom = tops[col - first], bottoms[col - first]
                count = run_end - col
                cell_key, text = (top, bottom, False), \
                    (" " if top == bottom else UPPER_HALF) * count
            if cell_key != key:
                if text_parts:
                    runs.append(("".join(text_parts), cells, *key))
                text_parts, cells, key = [], 0, cell_key
            text_parts.append(text)
            cells += count
        if text_parts:
            runs.append(("".join(text_parts), cells, *key))
        return start, runs
