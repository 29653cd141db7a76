"""Paint one page onto a CellCanvas: background, decorations, items, links, labels, selection.

Painting order is the page's stacking order: the background, then decorative
items, then the others by z; anchors and links go on top so they are never
hidden, and the selected item's frame and label come last so it always stands out.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

import numpy.ma  # noqa: F401  (imported with the editor, not on the first key: see below)

from floatpage.merge.placeholders import PlaceholderError, fields_in
from floatpage.physics.guides import lines_met
from floatpage.model.document import (
    BlockItem, CalendarItem, ItemAnchor, Page, PictureItem, PointAnchor, TextItem,
)
from floatpage.model.key_specs import alignment_share
from floatpage.tui.calendar_cells import cells, month_lines, month_text
from floatpage.tui.cell_text import graphemes, visual, wrap_cells
from floatpage.tui.cell_text import width as cell_width
from floatpage.tui.cell_canvas import RGB, CellCanvas, Glyph
from floatpage.tui.mark_places import beside_text, inside, mark_cell, occupancy, touched_cells
from floatpage.tui.projection import Projection
from floatpage.tui.thumbnails import thumbnail
from floatpage.typeset.bidi import base_direction

SURROUND: RGB = (38, 38, 46)
PAPER: RGB = (250, 250, 246)
SELECTION: RGB = (255, 196, 0)
ANCHOR: RGB = (214, 40, 170)
LINK: RGB = (0, 150, 200)
GUIDE: RGB = (0, 190, 210)  # an alignment guide the moving item sits on
GUIDE_DASH = 3  # one pixel in three: a light dashed line that hides little
REGION: RGB = (120, 170, 90)  # a region's name, and (mixed with the paper) its frame: green
GROUP: RGB = (255, 140, 0)  # the frame around the selected item's whole group
MISSING_PICTURE: RGB = (150, 150, 150)
WHITE: RGB = (255, 255, 255)
TEXT_TINT = 0.12  # how much of its ink colour a text box's background takes
SHADED_DAY = 0.18  # how much ink every other day's cells take, where days touch
BLACK: RGB = (0, 0, 0)


@dataclass
class PageView:
    """Everything one frame shows. positions override the items' own x, y (live physics)."""

    page: Page
    positions: dict[str, tuple[float, float]] = field(default_factory=dict)
    selected_id: str | None = None
    base_dir: Path = Path(".")
    labels: bool = False  # every item's id; else only the selected one's (ids hid the content)
    # alignment guides the selected item sits on while it moves: (axis, mm), 0 = a vertical line
    guides: tuple[tuple[int, float], ...] = ()
    # the terminal shows greys only (NO_COLOR): the selection's amber frame turned a grey
    # of 194 beside paper's 248, so it is drawn black where what it frames is light
    greys: bool = False


GUIDE_SHOWN_MM = 0.5  # a feature this close to a guide line is on it (physics.alignment)
# numpy.ma is imported above, with the editor: `lines_met` calls np.unique, which imports
# numpy.ma on its first call (np.ma.is_masked), and that was the first arrow key's guide
# lines: 40-120 ms of its answer (issue 11: key to screen).


def shown_guides(engine, item_id: str | None, moving: bool) -> tuple[tuple[int, float], ...]:
    """The guide lines to draw for the selected item: those it sits on, while it moves (a drag
    or a held key, or the physics settling); none when the page is still."""
    if not moving or item_id is None or item_id not in engine.ids:
        return ()
    bodies = engine.bodies
    return tuple(lines_met(bodies.centres, bodies.sizes, bodies.active, bodies.group_roots()[0],
                           engine.ids.index(item_id), (engine.page_w_mm, engine.page_h_mm),
                           engine.margin_mm, GUIDE_SHOWN_MM, bodies.regions))


def hex_to_rgb(value: str | None, default: RGB = BLACK) -> RGB:
    try:
        text = value.lstrip("#")
        return int(text[0:2], 16), int(text[2:4], 16), int(text[4:6], 16)
    except (AttributeError, ValueError, IndexError):
        return default


def mix(a: RGB, b: RGB, amount_of_b: float) -> RGB:
    return tuple(round(x + (y - x) * amount_of_b) for x, y in zip(a, b))  # type: ignore[return-value]


def readable_on(bg: RGB) -> RGB:
    """Black or white, whichever reads better on bg."""
    luminance = 0.299 * bg[0] + 0.587 * bg[1] + 0.114 * bg[2]
    return BLACK if luminance > 140 else WHITE


@lru_cache(maxsize=4096)
def printable(text: str) -> str:
    """Graphemes at their width, control characters as '?' (see tui.cell_text)."""
    return "".join(graphemes(text))


def text_cells(text: str) -> int:
    """How many cells ``text`` takes (cell_text.width is one grapheme's)."""
    return sum(cell_width(grapheme) for grapheme in graphemes(text))


@lru_cache(maxsize=1024)
def wrapped(text: str, width: int) -> tuple[str, ...]:
    """Greedy line breaks of a paragraph by cells, in visual order (cached: texts rarely
    change)."""
    return tuple(wrap_cells(text, width))


def picture_stand_in(path: str, exists: bool = False) -> str:
    """What a picture the preview cannot show says instead: a merge template's picture,
    named by its fields ("pictures/{photo}"), is filled in per record, and is not missing; a
    file that is there but does not decode (a JPEG cut short, which render prints grey or
    cut off, with a warning) is unreadable, not missing."""
    try:
        if fields_in(path):
            return f"one per record: {path}"
    except PlaceholderError:
        pass
    return f"unreadable {path}" if exists else f"missing {path}"


@lru_cache(maxsize=1024)
def cut_short(line: str, cells: int, rtl: bool = False) -> str:
    """The line with "…" at its end, in at most ``cells`` cells: at 80x24 the flyer's
    captions read "Sunfl" and "Coffe", as if that were all of them.  A right-to-left line
    (in visual order) ends at its left: the "…" goes there, and a cut keeps its right, where
    it begins (the first letters of a Hebrew or Arabic line were cut instead)."""
    parts = graphemes(line.strip() if rtl else line.rstrip())
    kept: list[str] = []
    used = 0
    for grapheme in reversed(parts) if rtl else parts:
        if used + cell_width(grapheme) > cells - 1:
            break
        kept.append(grapheme)
        used += cell_width(grapheme)
    return "\u2026" + "".join(reversed(kept)).lstrip() if rtl else "".join(kept) + "\u2026"


class PagePainter:
    """Paints page views; holds nothing between frames but the projection it was given."""

    def __init__(self, projection: Projection):
        self.projection = projection

    def paint(self, view: PageView) -> CellCanvas:
        p = self.projection
        canvas = CellCanvas(p.cols, p.rows, SURROUND)
        self._background(canvas, view)
        names = self._regions(canvas, view)
        # as the PDF prints them (typeset.placed.paint_order): at one z, words over pictures
        items = sorted(view.page.items, key=lambda item: (
            not item.decorative, item.z, item.kind in ("text", "calendar")))
        boxes = {item.id: self._box(item, view) for item in view.page.items}
        for item in items:
            self._item(canvas, view, item, boxes[item.id])
        centres = {item.id: self._centre(item, view) for item in view.page.items}
        cells = {item_id: touched_cells(box) for item_id, box in boxes.items()}
        taken = occupancy((cells[item.id] for item in view.page.items if not item.decorative),
                          canvas.cols, canvas.rows)
        for item in view.page.items:
            self._anchor(canvas, item, centres, cells, taken)
        self._guides(canvas, view.guides)
        selected = next((item for item in view.page.items if item.id == view.selected_id), None)
        if selected is not None and selected.group:
            members = [boxes[item.id] for item in view.page.group_members(selected.group)]
            frame = (min(b[0] for b in members), min(b[1] for b in members),
                     max(b[2] for b in members), max(b[3] for b in members))
            self._dashed_frame(canvas, (frame[0] - 2, frame[1] - 2, frame[2] + 2, frame[3] + 2),
                               GROUP)
            col0, row = max(frame[0] - 1, 0), (frame[1] - 2) // 2
            text = printable(f"group {selected.group}")
            canvas.write(col0, row, text, BLACK, GROUP, bold=True)
            names.append((row, col0, col0 + text_cells(text), ""))  # kept clear for the label
        if selected is not None:
            canvas.outline(*boxes[selected.id], SELECTION, on_light=BLACK if view.greys else None)
            self._frame_label(canvas, selected, boxes[selected.id], names)
        for row, col, end, text in names:  # last: no item, label or link hides a name
            canvas.write(col, row, text, REGION, PAPER, bold=True, end_col=end)
        return canvas

    # -- geometry ----------------------------------------------------------------------------

    def _centre(self, item, view: PageView) -> tuple[float, float]:
        return view.positions.get(item.id, (item.x, item.y))

    def _box(self, item, view: PageView) -> tuple[int, int, int, int]:
        x, y = self._centre(item, view)
        return self.projection.rect(x, y, item.w, item.h)

    @staticmethod
    def _cells(box: tuple[int, int, int, int]) -> tuple[int, int, int, int]:
        """Columns and rows of the cells wholly inside a pixel box: (col0, row0, col1, row1)."""
        x0, y0, x1, y1 = box
        return x0, (y0 + 1) // 2, x1, y1 // 2

    # -- layers ------------------------------------------------------------------------------

    def _background(self, canvas: CellCanvas, view: PageView) -> None:
        p = self.projection
        box = (p.left, p.top, p.left + p.width, p.top + p.height)
        background = view.page.background
        canvas.fill(*box, PAPER)
        if background is None:
            return
        if background.picture:
            image = thumbnail(view.base_dir / background.picture, p.width, p.height)
            if image is not None:
                canvas.blit(p.left, p.top, image)
            else:
                canvas.fill(*box, mix(PAPER, MISSING_PICTURE, 0.3))
        elif background.color:
            canvas.fill(*box, hex_to_rgb(background.color, PAPER))

    def _regions(self, canvas: CellCanvas, view: PageView) -> list[tuple[int, int, int, str]]:
        """Each region as a dashed green frame, under the items: the walls of the items
        confined to it.  Its name goes on the frame's top line, as a titled border, and is
        written last of all (``paint``): drawn inside and first, it hid under the items and
        labels at the region's top, the very items confined to it (user-walk-6).  Returns
        the names' places, (row, first column, end column, text)."""
        names = []
        for region in view.page.regions:
            left, top, right, bottom = region.box
            x0, y0 = self.projection.to_pixels(left, top)
            x1, y1 = self.projection.to_pixels(right, bottom)
            box = (int(x0), int(y0), max(int(x1) - 1, int(x0)), max(int(y1) - 1, int(y0)))
            self._dashed_frame(canvas, box, mix(PAPER, REGION, 0.7), step=GUIDE_DASH)
            text = printable(region.id)
            col = max(box[0] + 1, 0)
            end = min(box[2], col + text_cells(text))
            if end > col:
                names.append((max(box[1] // 2, 0), col, end, text))
        return names

    @staticmethod
    def _dashed_frame(canvas: CellCanvas, box, colour: RGB, step: int = 2) -> None:
        """A one-pixel dashed rectangle on the pixels (x0, y0)-(x1, y1), ends included, one
        pixel in ``step`` drawn."""
        height, width = canvas.pixels.shape[:2]
        x0, y0, x1, y1 = box
        for x in range(max(x0, 0), min(x1 + 1, width), step):
            for y in (y0, y1):
                if 0 <= y < height:
                    canvas.pixels[y, x] = colour
        for y in range(max(y0, 0), min(y1 + 1, height), step):
            for x in (x0, x1):
                if 0 <= x < width:
                    canvas.pixels[y, x] = colour

    def _item(self, canvas: CellCanvas, view: PageView, item, box) -> None:
        x0, y0, x1, y1 = box
        if isinstance(item, PictureItem):
            image = thumbnail(view.base_dir / item.path, x1 - x0, y1 - y0)
            if image is None:
                canvas.fill(*box, MISSING_PICTURE)
                there = (view.base_dir / item.path).is_file()
                self._body(canvas, box, [picture_stand_in(item.path, there)], BLACK,
                           MISSING_PICTURE)
            else:
                canvas.blit(x0, y0, image)
            if view.labels and item.id != view.selected_id:  # its id is on its frame
                self._label(canvas, item, box, WHITE, BLACK)
            return
        under = tuple(int(v) for v in canvas.pixels[
            min(max((y0 + y1) // 2, 0), canvas.pixels.shape[0] - 1),
            min(max((x0 + x1) // 2, 0), canvas.cols - 1)])
        if isinstance(item, BlockItem):
            fill = mix(under, hex_to_rgb(item.color, MISSING_PICTURE), item.opacity)
            canvas.fill(*box, fill)
            if view.labels and item.id != view.selected_id:
                self._label(canvas, item, box, readable_on(fill), fill)
            return
        # Text is printed straight on the page, so its box is only a faint tint of what lies
        # under it, and the text keeps the contrast it will have on paper.
        ink = hex_to_rgb(getattr(item, "color", None))
        fill = mix(under, ink, TEXT_TINT)
        canvas.fill(*box, fill)
        # the selected one's id is on its frame (_frame_label), not over its first row
        labelled = view.labels and item.id != view.selected_id
        if labelled:
            self._label(canvas, item, box, mix(readable_on(fill), fill, 0.45), fill)
        if isinstance(item, TextItem):
            self._body(canvas, box, item.text.split("\n"), ink, fill, bold=item.bold,
                       below_label=labelled, align=item.align)
        elif isinstance(item, CalendarItem):
            self._calendar(canvas, box, item, ink, fill, below_label=labelled)

    def _label(self, canvas: CellCanvas, item, box, fg: RGB, bg: RGB) -> None:
        """The item's id on its first full row (or the row holding its top, if it is thin)."""
        col0, row0, col1, row1 = self._cells(box)
        row = row0 if row1 > row0 else box[1] // 2
        text = printable(("~" if item.decorative else "") + item.id)
        width = max(col1 - col0, 1)
        canvas.write(col0, row, text[:width], fg, bg, bold=True, end_col=col0 + width)

    def _frame_label(self, canvas: CellCanvas, item, box, kept_clear) -> None:
        """The selected item's id on the row above the rows its text may use (its frame's top
        line) or the row below them, so that it covers none of the item: inside the box it
        hid the first row of a text's words (user-walk-6).  Of those, the first that covers
        no other item's words, region name or group label (``kept_clear``: (row, column, end
        column, text)), or else its own first row where no words are (a picture's top: over
        the caption below it, the album's label hid the caption); else the first clear of
        those names; only where none is, inside, as `n`'s labels go."""
        col0, _, col1, _ = self._cells(box)
        _, first, _, end = self._text_area(box, below_label=False)
        text = printable(("~" if item.decorative else "") + item.id)
        width = max(col1 - col0, 1)
        text = text[:width]
        span = text_cells(text)
        places = []
        for row in (first - 1, end, first):  # inside last: over a picture's top, not words
            if not 0 <= row < canvas.rows:
                continue
            col = max(col0, 0)
            for taken_row, start, stop, _ in sorted(kept_clear, key=lambda place: place[1]):
                if taken_row == row and start < col + span and col < stop:
                    col = stop + 1  # after the name, if the label still fits above the box
            if col + span <= col0 + width and col + span <= canvas.cols:
                places.append((any(canvas.glyph_at(c, row) is not None and
                                   canvas.glyph_at(c, row).char.strip()
                                   for c in range(col, col + span)), row, col))
        if places:
            _, row, col = min(places, key=lambda place: place[0])  # the first free of words
            canvas.write(col, row, text, BLACK, SELECTION, bold=True, end_col=col + span)
            return
        self._label(canvas, item, box, BLACK, SELECTION)

    def _text_area(self, box, below_label: bool) -> tuple[int, int, int, int]:
        """The cells a box's text may use, (col0, first row, col1, end row): its full cells,
        under the label row if any. A box with no full row (a caption a cell tall that
        straddles two rows, as most do at some height) gets the row holding its top, as the
        label does: the album's captions, the flyer's and the multilingual card's lines
        showed as bare half-blocks."""
        col0, row0, col1, row1 = self._cells(box)
        if row1 <= row0 and box[3] > box[1]:
            row0, row1 = box[1] // 2, box[1] // 2 + 1
        return col0, row0 + (1 if below_label else 0), col1, row1

    def _body(self, canvas: CellCanvas, box, paragraphs: list[str], fg: RGB, bg: RGB,
              *, bold: bool = False, below_label: bool = True, align: str = "start") -> None:
        """As much of the text as fits the item's cells, word-wrapped, each line where the
        box's ``align`` sets it in the PDF."""
        col0, first, col1, row1 = self._text_area(box, below_label)
        width = col1 - col0
        if width < 1 or first >= row1:
            return
        lines, directions = [], []
        for paragraph in paragraphs:
            shown = wrapped(paragraph, width)
            lines.extend(shown)
            directions.extend([base_direction(paragraph)] * len(shown))
        rows = row1 - first
        if len(lines) > rows:  # the last line shown ends in "…": the text goes on
            lines = lines[:rows - 1] + [cut_short(lines[rows - 1], width,
                                                  directions[rows - 1] == "R")]
        share = alignment_share(align, base_direction("".join(paragraphs)))
        for row, line in zip(range(first, row1), lines):
            spare = max(width - sum(cell_width(g) for g in graphemes(line)), 0)
            canvas.write(col0 + int(spare * share), row, line, fg, bg, bold=bold, end_col=col1)

    def _calendar(self, canvas: CellCanvas, box, item: CalendarItem, fg: RGB, bg: RGB,
                  *, below_label: bool) -> None:
        """Every day of the month, in the richest layout its cells hold (`calendar_cells`);
        every other day shaded where the days stand with no space between."""
        col0, first, col1, row1 = self._text_area(box, below_label)
        if col1 <= col0 or first >= row1:
            return
        month = month_text(item.year, item.month, item.first_weekday, item.language)
        if month is None:
            canvas.write(col0, first, f"calendar {item.year}-{item.month}", fg, bg, end_col=col1)
            return
        shade = mix(bg, fg, SHADED_DAY)
        lines, _whole = month_lines(month, col1 - col0, row1 - first)
        for row, line in zip(range(first, row1), lines):
            col = col0
            for text, shaded in line:
                canvas.write(col, row, visual(printable(text)), fg, shade if shaded else bg,
                             end_col=col1)
                col += cells(text)

    def _guides(self, canvas: CellCanvas, guides) -> None:
        """Dashed one-pixel lines across the page, on the pixels no text covers: the guides
        the moving item has snapped to (design tools' smart guides)."""
        p = self.projection
        height, width = canvas.pixels.shape[:2]
        for axis, mm in guides:
            if axis == 0:
                x = min(int(p.to_pixels(mm, 0)[0]), p.left + p.width - 1)
                if 0 <= x < width:
                    for y in range(max(p.top, 0), min(p.top + p.height, height), GUIDE_DASH):
                        if canvas.glyph_at(x, y // 2) is None:
                            canvas.pixels[y, x] = GUIDE
            else:
                y = min(int(p.to_pixels(0, mm)[1]), p.top + p.height - 1)
                if 0 <= y < height:
                    for x in range(max(p.left, 0), min(p.left + p.width, width), GUIDE_DASH):
                        if canvas.glyph_at(x, y // 2) is None:
                            canvas.pixels[y, x] = GUIDE

    def _anchor(self, canvas: CellCanvas, item, centres, cells, taken) -> None:
        """The item's anchor mark, or its follow link's two ends, where they read as marks
        and hide nothing (`mark_places`), joined to the item by a dotted line."""
        own = cells[item.id]
        if isinstance(item.anchor, PointAnchor):
            point = self.projection.cell_of(item.anchor.x, item.anchor.y)
            under = canvas.glyph_at(*point)
            if under is not None and under.char.strip() and inside(own, *point):
                # a letter of its own text stays readable, on the anchor colour
                canvas.put(*point, Glyph(under.char, WHITE, ANCHOR, bold=True))
                return
            end = mark_cell(canvas, own, point, taken)
            if end is None:
                return
            canvas.put(*end, Glyph("#" if item.anchor.hard else "+", WHITE, ANCHOR, bold=True))
            self._dots(canvas, self.projection.cell_of(*centres[item.id]), end, ANCHOR, [own])
        elif isinstance(item.anchor, ItemAnchor) and item.anchor.to in centres:
            followed = item.anchor.to
            ends = []
            for marked, toward in ((item.id, followed), (followed, item.id)):
                end = mark_cell(canvas, cells[marked], self.projection.cell_of(*centres[toward]),
                                taken)
                if end is not None:
                    canvas.put(*end, Glyph("o", WHITE, LINK, bold=True))
                ends.append(end or self.projection.cell_of(*centres[marked]))
            self._dots(canvas, ends[0], ends[1], LINK, [own, cells[followed]])

    @staticmethod
    def _dots(canvas: CellCanvas, start, end, colour: RGB, skipped) -> None:
        """A dotted line of cells from start to end (Bresenham), ends excluded, on no cell of
        the `skipped` boxes (the items it joins) and beside no letter."""
        (c0, r0), (c1, r1) = start, end
        steps = max(abs(c1 - c0), abs(r1 - r0))
        for i in range(1, steps):
            col = round(c0 + (c1 - c0) * i / steps)
            row = round(r0 + (r1 - r0) * i / steps)
            if 0 <= row < canvas.rows and 0 <= col < canvas.cols \
                    and canvas.glyph_at(col, row) is None and not beside_text(canvas, col, row) \
                    and not any(inside(box, col, row) for box in skipped):
                canvas.put(col, row, Glyph("\u00b7", colour, None, bold=True))
