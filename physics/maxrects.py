"""A second packer for packing.packed_layout: maximal free rectangles (Jylänki's MaxRects).

The skyline packer keeps one "roof" over what it has placed, so room under an overhang is lost
for good; near the issue's 85 % cover that loss decides.  A page of 41 items on A5, covering
84.98 % grown by the gutter, found no skyline packing at the gutter and settled with a 0.64 mm
gap; this packer fits it at 3.2 mm (benchmarks/gutter_fits.py --seed 77, page 23).  It keeps
every maximal empty rectangle of the box and puts each item, in the order given, into one of
them (best short side fit, lowest top, or best area fit), then splits the rectangles it
overlaps and drops those inside another.  The rectangles can grow to O(n^2), so it is kept for
pages of at most ``MAX_ITEMS`` items, tried after the skyline, which stays the first choice:
a page the skyline packs keeps its layout.
"""

from __future__ import annotations

import numpy as np

MAX_ITEMS = 150  # each placement compares every pair of free rectangles
RULES = ("short side", "lowest top", "area")
EPS = 1e-9


def maxrects_pack(sizes: np.ndarray, width: float, height: float, rule: str = "short side"
                  ) -> np.ndarray | None:
    """Top-left corners (n, 2) for rectangles of ``sizes`` placed in this order into a
    ``width`` x ``height`` box without overlap, each into the free rectangle ``rule`` picks;
    None if one does not fit anywhere."""
    free = np.array([[0.0, 0.0, width, height]])  # rows: left, top, right, bottom
    corners = np.empty((len(sizes), 2))
    for k, (w, h) in enumerate(sizes.tolist()):
        spare_w, spare_h = free[:, 2] - free[:, 0] - w, free[:, 3] - free[:, 1] - h
        fitting = np.flatnonzero((spare_w >= -EPS) & (spare_h >= -EPS))
        if not len(fitting):
            return None
        left, top = free[fitting, 0], free[fitting, 1]
        if rule == "short side":
            short = np.minimum(spare_w[fitting], spare_h[fitting])
            long = np.maximum(spare_w[fitting], spare_h[fitting])
            order = np.lexsort((left, top, long, short))
        elif rule == "lowest top":
            order = np.lexsort((left, top))
        else:  # the least area left over, then the shorter leftover side
            area = (spare_w[fitting] + w) * (spare_h[fitting] + h) - w * h
            order = np.lexsort((left, top, np.minimum(spare_w[fitting], spare_h[fitting]), area))
        x, y = float(left[order[0]]), float(top[order[0]])
        corners[k] = (x, y)
        free = split_free(free, x, y, x + w, y + h)
    return corners


def split_free(free: np.ndarray, left: float, top: float, right: float, bottom: float
               ) -> np.ndarray:
    """The free rectangles once the rectangle ``left, top, right, bottom`` is taken: each one
    it overlaps replaced by its up to four maximal parts around it, then every rectangle that
    lies inside another dropped (of two equal ones, the later)."""
    hit = ((free[:, 0] < right - EPS) & (free[:, 2] > left + EPS)
           & (free[:, 1] < bottom - EPS) & (free[:, 3] > top + EPS))
    parts = [free[~hit]]
    for x0, y0, x1, y1 in free[hit].tolist():
        pieces = [(x0, y0, left, y1) if left > x0 + EPS else None,
                  (right, y0, x1, y1) if right < x1 - EPS else None,
                  (x0, y0, x1, top) if top > y0 + EPS else None,
                  (x0, bottom, x1, y1) if bottom < y1 - EPS else None]
        kept = [piece for piece in pieces if piece is not None]
        if kept:
            parts.append(np.array(kept))
    rects = np.concatenate(parts)
    inside = ((rects[:, None, 0] >= rects[None, :, 0] - EPS)
              & (rects[:, None, 1] >= rects[None, :, 1] - EPS)
              & (rects[:, None, 2] <= rects[None, :, 2] + EPS)
              & (rects[:, None, 3] <= rects[None, :, 3] + EPS))  # [i, j]: i inside j
    np.fill_diagonal(inside, False)
    equal = inside & inside.T
    drop = (inside & ~equal).any(axis=1) | np.tril(equal, -1).any(axis=1)
    return rects[~drop]
