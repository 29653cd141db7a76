"""Rows of boxes as tall as their boxes need, the height left over shared out evenly: an album
page as a designer lays it out.

``placement.grid`` gives every row one cell height.  On a page whose top row holds tall photos
and whose bottom row wide ones, the wide photos (held by the column's width) sat small in the
middle of a cell as tall as the tall photos', the page's lower third stayed empty, and the
tall photos above were held to that same cell, smaller than the page allowed.  Here each row
is as tall as its tallest box at the column's width; where the rows together need more than
the region holds, the tallest are cut to one common height (water filling), so a row of wide
photos keeps its size and gives what it does not need to the tall row.  What is left is shared
out evenly: between the rows, and above and below them (no less than the gap between rows,
the room a title keeps, or the page's margin).
"""

from __future__ import annotations

import math
from typing import Callable

from floatpage.starters.placement import Rect, Region, fit, largest_grid

Cut = Callable[[list[Rect], list[float]], list[Rect]]  # e.g. placement.one_height_per_row


def water_level(needs: list[float], room: float) -> float:
    """The largest ``level`` with ``sum(min(need, level)) <= room``: rows that need less keep
    their need, the others share the rest at one height (``inf`` when everything fits)."""
    if sum(needs) <= room:
        return math.inf
    rest, count = room, len(needs)
    for need in sorted(needs):
        if need * count > rest:
            return rest / count
        rest -= need
        count -= 1
    return rest  # not reached: the loop returns once the level is below a need


def even_spaces(free: float, least: list[float]) -> list[float]:
    """``free`` mm of height shared out over the spaces above, between and below the rows,
    each at least its ``least`` (the gap between rows, the room under a title): as evenly as
    those allow, the spaces whose least is above the even share keeping their least."""
    spaces = sorted(range(len(least)), key=lambda k: -least[k])
    rest, count, found = free, len(least), list(least)
    for k in spaces:
        if least[k] * count <= rest:
            break
        rest -= least[k]  # this one keeps its least; the others share the rest
        count -= 1
    level = max(0.0, rest / count) if count else 0.0
    return [max(low, level) for low in found]


def even_rows(region: Region, aspects: list[float], *, fill: float = 0.96, gap: float = 8.0,
              below: float = 0.0, above: float = 0.0, under: float = 0.0, cut: Cut | None = None,
              middle: tuple[float, float] | None = None) -> list[Rect]:
    """Place boxes of ``aspects`` (in order, row by row) in columns of one width over
    ``region``, each row as tall as it needs, the column count that keeps the most area.

    A box is at most ``fill`` of its column's width; the rows' heights together at most
    ``fill`` of what the region holds after the ``below`` each row reserves under its boxes
    (for captions), the gaps, and the least spaces kept over the first row (``above``: under
    a title, or the page's margin when the region reaches the page's edge) and under the last
    (``under``), so the physics keeps room to move.  ``cut`` (e.g. rows of one height) runs
    on the sized boxes before the rows are placed, so they are placed at the heights they end
    with.  A short last row is centred.

    ``middle`` = (the page's middle line, a reach): of two rows or more, a row whose middle
    the even spaces put within that reach of the page's middle is put on it, and the spaces
    above and below it are shared out each on its own (the physics' snap pulls a row that
    near onto the page's middle line, a guide, and the rows it left behind stood 7 and 19 mm
    apart instead of 11 and 11).  A page of one row keeps its even spaces: measured, the
    physics leaves those alone.  Returns (x, y, w, h) centres.
    """
    def with_columns(cols: int, rows: int, cell_w: float) -> list[Rect] | None:
        room = (region.height - rows * below - (rows - 1) * gap - above - under) * fill
        if cell_w <= 0 or room <= 0:
            return None
        rects = _sized(region, aspects, cols, rows, cell_w, gap, fill, room)
        if cut is not None:
            rects = cut(rects, aspects)
        return _placed(region, rects, rows, [above] + [gap] * (rows - 1) + [under], below,
                       middle)
    return largest_grid(region, len(aspects), gap, with_columns)


def _sized(region: Region, aspects: list[float], cols: int, rows: int, cell_w: float,
           gap: float, fill: float, room: float) -> list[Rect]:
    """Each box at its column's centre and its size, ``y`` the row's number for now."""
    n = len(aspects)
    widest = cell_w * fill
    needs = [max(widest / aspect for aspect in aspects[row * cols:(row + 1) * cols])
             for row in range(rows)]
    level = water_level(needs, room)
    rects = []
    for index, aspect in enumerate(aspects):
        row, col = divmod(index, cols)
        in_row = min(cols, n - row * cols)
        offset = (cols - in_row) * (cell_w + gap) / 2
        w, h = fit(aspect, widest, level)
        rects.append((region.left + offset + col * (cell_w + gap) + cell_w / 2, float(row), w, h))
    return rects


def _placed(region: Region, rects: list[Rect], rows: int, least: list[float], below: float,
            middle: tuple[float, float] | None = None) -> list[Rect]:
    """``rects`` with ``y`` a row number, moved to their rows: each row as tall as its tallest
    box, the boxes centred on the row's middle, the height left shared out (even_spaces); a
    row near the page's ``middle`` put on it (see even_rows)."""
    tallest = [max(h for _, y, _, h in rects if y == row) for row in range(rows)]
    spaces = even_spaces(region.height - sum(tallest) - rows * below, least)
    middles = _middles(region.top, tallest, spaces, below)
    if middle is not None and rows > 1:
        line, reach = middle
        near = [row for row in range(rows) if 0 < abs(middles[row] - line) < reach]
        if near:
            row = near[0]
            over = line - tallest[row] / 2 - region.top - sum(tallest[:row]) - row * below
            under = region.height - (over + sum(tallest) + rows * below)
            if over >= sum(least[:row + 1]) - 1e-9 and under >= sum(least[row + 1:]) - 1e-9:
                spaces = (even_spaces(over, least[:row + 1])
                          + even_spaces(under, least[row + 1:]))
                middles = _middles(region.top, tallest, spaces, below)
    return [(x, middles[int(y)], w, h) for x, y, w, h in rects]


def _middles(top: float, tallest: list[float], spaces: list[float], below: float) -> list[float]:
    """The rows' middles from the region's top, each row after its space."""
    middles, reached = [], top
    for height, space in zip(tallest, spaces):
        middles.append(reached + space + height / 2)
        reached += space + height + below
    return middles
