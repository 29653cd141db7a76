"""Starting rectangles for a starter's items: a tidy first guess the physics then polishes.

The physics would spread items dropped anywhere, but a starter that begins from a sensible
grid settles in fewer steps, the same way every time, and looks right even before settling.
Rectangles are (x, y, w, h) in mm with (x, y) the centre, as in the model.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

from floatpage.model.document import Page
from floatpage.model.page_sizes import page_dimensions
from floatpage.physics.alignment import ALIGNED_MM, NEAR_MM

Rect = tuple[float, float, float, float]
ONE_HEIGHT_WITHIN = 0.15  # a row's boxes share a height if they differ by at most 15 %


@dataclass(frozen=True)
class Region:
    """An axis-aligned area of a page, by its edges in mm."""

    left: float
    top: float
    right: float
    bottom: float

    @property
    def width(self) -> float:
        return self.right - self.left

    @property
    def height(self) -> float:
        return self.bottom - self.top

    @property
    def centre(self) -> tuple[float, float]:
        return (self.left + self.right) / 2, (self.top + self.bottom) / 2


def edges_near_miss(width_a: float, width_b: float) -> bool:
    """Whether two boxes of these widths, one centred over the other, have edges a near miss
    apart (physics.alignment: more than ALIGNED_MM, less than NEAR_MM): a look no snap can
    mend, since no move closes both edges at once."""
    return ALIGNED_MM < abs(width_a - width_b) / 2 < NEAR_MM


def new_page(page_id: str, size: str, orientation: str, **kwargs) -> Page:
    """A page with its millimetre size filled in from the named size and orientation."""
    width, height = page_dimensions(size, orientation)
    return Page(id=page_id, size=size, orientation=orientation, width_mm=width, height_mm=height,
                **kwargs)


def fit(aspect: float, max_w: float, max_h: float) -> tuple[float, float]:
    """The largest (w, h) with w / h = aspect inside max_w x max_h."""
    w = min(max_w, max_h * aspect)
    return w, w / aspect


def grid(region: Region, aspects: list[float], *, fill: float = 0.85, gap: float = 6.0,
         below: float = 0.0, stagger: float = 0.0, rows_of_one_height: bool = False,
         on_a_shelf: bool = False) -> list[Rect]:
    """Place len(aspects) boxes of those shapes in a grid over `region`, biggest total area.

    Every column count is tried; each cell holds one box scaled to `fill` of the cell, leaving
    the physics room to move. `below` reserves that many mm under each box (for a caption).
    When the best grid is a single column, `stagger` (0..1) shifts the boxes alternately left
    and right by that share of their spare width, so a stack reads as a lively zigzag.
    With `rows_of_one_height`, each row's boxes share a height (see one_height_per_row), and
    the grid is chosen by the area they keep.  With `on_a_shelf`, once the grid is chosen, a
    row's boxes of near heights are cut to one (near_heights_as_one) and each row's boxes stand
    on one line, the bottom of the row's tallest box, instead of each centred in its cell:
    products of different shapes, each with its tag right under it (`below`), stand like goods
    on a shelf, and their tags line up along the row.  Centred, a square apple over a tall
    sunflower left the tags 4-9 mm apart, ragged, and no single move of the snap lines up a
    row that far out.
    """
    n = len(aspects)

    def with_columns(cols: int, rows: int, cell_w: float) -> list[Rect] | None:
        cell_h = (region.height - gap * (rows - 1)) / rows
        if cell_w <= 0 or cell_h - below <= 0:
            return None
        rects = []
        for index, aspect in enumerate(aspects):
            row, col = divmod(index, cols)
            in_row = min(cols, n - row * cols)  # centre a short last row
            offset = (cols - in_row) * (cell_w + gap) / 2
            w, h = fit(aspect, cell_w * fill, (cell_h - below) * fill)
            x = region.left + offset + col * (cell_w + gap) + cell_w / 2
            if cols == 1 and n > 1:
                x += (-1) ** (index + 1) * stagger * (cell_w - w) / 2
            y = region.top + row * (cell_h + gap) + (cell_h - below) / 2
            rects.append((x, y, w, h))
        return one_height_per_row(rects, aspects) if rows_of_one_height else rects
    best = largest_grid(region, n, gap, with_columns)
    if not on_a_shelf or not best:
        return best
    return on_shelves(near_widths_as_one(near_heights_as_one(best, aspects), aspects,
                                         keep_row_heights=False))


def largest_grid(region: Region, count: int, gap: float,
                 with_columns: Callable[[int, int, float], list[Rect] | None]) -> list[Rect]:
    """Of the grids of ``count`` boxes ``with_columns`` makes for every column count (given
    the columns, the rows and the columns' width with ``gap`` between them; None where the
    boxes do not fit), the one whose boxes cover the most area (the fewest columns among
    equals)."""
    if count == 0:
        return []
    best: tuple[float, list[Rect]] | None = None
    for cols in range(1, count + 1):
        rows = math.ceil(count / cols)
        rects = with_columns(cols, rows, (region.width - gap * (cols - 1)) / cols)
        if rects is None:
            continue
        area = sum(w * h for _, _, w, h in rects)
        if best is None or area > best[0] + 1e-9:
            best = (area, rects)
    if best is None:
        raise ValueError(f"region {region} is too small for {count} boxes")
    return best[1]


def on_shelves(rects: list[Rect]) -> list[Rect]:
    """``rects`` from ``grid``, each row's boxes moved down onto one line, the bottom of the
    row's tallest box (which stays centred in its cell, so the rows keep their places)."""
    shelf = {y: y + max(heights) / 2 for y, heights in row_heights(rects).items()}
    return [(x, shelf[y] - h / 2, w, h) for x, y, w, h in rects]


def one_height_per_row(rects: list[Rect], aspects: list[float]) -> list[Rect]:
    """``rects`` from ``grid``, each row's boxes cut to one height (the lowest in the row), as
    an album lays them out.  Boxes of two shapes side by side (a 4:3 photo beside a 3:2), each
    as big as its cell, have edges and middles 2-4 mm apart: a near miss the eye reads as a
    mistake (physics.alignment), and no move can close it.  At one height they line up along
    the row, and in a column the narrower one sits centred, its edges well clear of the wider
    one's.  A row whose heights differ by more than ``ONE_HEIGHT_WITHIN`` (a tall photo beside
    wide ones) keeps them: cut to one height, the tall one would shrink to a stamp, and edges
    that far apart are no near miss."""
    rows = row_heights(rects)
    lowest = {y: min(heights) for y, heights in rows.items()}
    highest = {y: max(heights) for y, heights in rows.items()}
    return [(x, y, aspect * lowest[y], lowest[y])
            if lowest[y] >= (1 - ONE_HEIGHT_WITHIN) * highest[y] else (x, y, w, h)
            for aspect, (x, y, w, h) in zip(aspects, rects)]


def near_widths_as_one(rects: list[Rect], aspects: list[float], *,
                       keep_row_heights: bool = True) -> list[Rect]:
    """``rects`` from ``grid``, a box cut to the width of the narrowest box of its column when
    its own is near it (within ``ONE_HEIGHT_WITHIN``).  An apple 35 mm wide over a teapot 39 mm
    wide, centred, has edges 2 mm apart on both sides: a near miss the snap could only settle by
    pushing the two 4 mm apart, which broke the column (the flyer's rows stood 4-8 mm out of
    line).  Cut to one width, the column lines up on both edges and its centre.

    Rows come first.  With aspects fixed, a grid of 3:2 and 4:3 photos cannot have both one
    height per row and one width per column (cutting both ways in turn would shrink them
    without end), so a cut never leaves a box's top a near miss (``NEAR_MM``) from another's in
    its row, and with ``keep_row_heights`` (an album's rows of one height) a box that shares
    its height with others of its row is not cut at all.  A box cut narrower is cut lower
    too, so ``on_shelves`` comes after this."""
    found = list(rects)
    changed = True
    while changed:  # a cut lowers a box: its neighbours' cuts are judged against that
        changed = False
        heights_in_row = row_heights(found)
        columns: dict[float, list[float]] = {}
        for x, _, w, _ in found:
            columns.setdefault(x, []).append(w)
        for index, (aspect, (x, y, w, h)) in enumerate(zip(aspects, found)):
            narrowest = min(other for other in columns[x]
                            if other >= (1 - ONE_HEIGHT_WITHIN) * w)
            if narrowest >= w:
                continue
            cut_h = narrowest / aspect
            others = list(heights_in_row[y])
            others.remove(h)
            if keep_row_heights and h in others:
                continue
            if any(ALIGNED_MM < abs(cut_h - other) < NEAR_MM for other in others):
                continue
            found[index] = (x, y, narrowest, cut_h)
            changed = True
            break  # the tables above are stale now
    return found


def row_heights(rects: list[Rect]) -> dict[float, list[float]]:
    """The heights of ``grid``'s boxes by row (a row's boxes share the centre line ``y``)."""
    rows: dict[float, list[float]] = {}
    for _, y, _, h in rects:
        rows.setdefault(y, []).append(h)
    return rows


def near_heights_as_one(rects: list[Rect], aspects: list[float]) -> list[Rect]:
    """``rects`` from ``grid``, the boxes of each row whose heights are near (within
    ``ONE_HEIGHT_WITHIN`` of the lowest of them) cut to that lowest height, the others kept:
    on a shelf (``on_shelves``) boxes of near heights have tops 1-4 mm apart, a near miss no
    move can close, while a tall sunflower beside three squares stands clear of them.  Unlike
    ``one_height_per_row`` a row may keep several heights."""
    cut: dict[tuple[float, float], float] = {}  # (row, height) -> the height it is cut to
    for y, row in row_heights(rects).items():
        lowest = None
        for h in sorted(row):
            if lowest is None or lowest < (1 - ONE_HEIGHT_WITHIN) * h:
                lowest = h  # too far above the last cluster's lowest: a cluster of its own
            cut[y, h] = lowest
    return [(x, y, aspect * cut[y, h], cut[y, h]) if cut[y, h] < h else (x, y, w, h)
            for aspect, (x, y, w, h) in zip(aspects, rects)]
