"""A second start for a page the physics jammed: the items packed, then spread evenly.

The physics only ever nudges what it is given, so the order in which items end up is the order
the start suggested.  On a page with a few large items that order can be a dead end: three
photos each wider than half of an A4 page (inside its 5 mm margins) stacked one above another,
with two small ones left over, need 288 mm of the 287 the margins leave, while the same items
in another order (the small ones beside the first photo) need 255 mm.  No push can swap a
photo with the row above it, so the gutter was lost on a page whose items, each grown by the
gutter, cover 57 % of it.

``packed_layout`` builds another order directly, as a printer fills a sheet: each item, grown
by the gutter, goes where its top ends lowest on the skyline of those placed before it
(bottom-left best fit), or where it traps the least room beneath it.  It tries both rules on
the items ordered by height, area, width and longest side, across the page and down it, and
keeps the first packing that fits.  Then every centre is spread
away from the room's corner as far as the room allows, one axis at a time: spreading centres
apart never narrows a gap, so the page starts even and keeps the gutter.  Deterministic: the
same items give the same start.
"""

from __future__ import annotations

from itertools import product

import numpy as np

from floatpage.physics.maxrects import MAX_ITEMS as MAXRECTS_ITEMS, RULES, maxrects_pack

MAX_ITEMS = 500  # the skyline costs O(n^2) in Python: beyond this the physics is on its own


def packed_layout(sizes: np.ndarray, room_low: np.ndarray, room_high: np.ndarray,
                  gutter_mm: float) -> np.ndarray | None:
    """Centres (n, 2) for items of ``sizes`` inside the rectangle ``room_low``-``room_high``
    (mm: left/top, right/bottom), every pair at least ``gutter_mm`` apart, spread over the
    room; None if no packing tried fits (or there are too many items to try).  The skyline
    first; where it finds nothing, maximal free rectangles (physics.maxrects)."""
    if len(sizes) > MAX_ITEMS:
        return None
    packers = [lambda boxes, w, h, waste=waste: skyline_pack(boxes, w, h, waste)
               for waste in (False, True)]
    found = packed_by(packers, sizes, room_low, room_high, gutter_mm)
    if found is None and len(sizes) <= MAXRECTS_ITEMS:
        packers = [lambda boxes, w, h, rule=rule: maxrects_pack(boxes, w, h, rule)
                   for rule in RULES]
        found = packed_by(packers, sizes, room_low, room_high, gutter_mm)
    return found


def packed_by(packers: list, sizes: np.ndarray, room_low: np.ndarray, room_high: np.ndarray,
              gutter_mm: float) -> np.ndarray | None:
    """packed_layout with these packers (each: grown sizes in order, the room's width and
    height, grown too -> top-left corners or None), each tried on the items ordered by height,
    area, width and longest side, across the page and down it; the first that fits, spread."""
    room = np.asarray(room_high, float) - np.asarray(room_low, float)
    grown = sizes + gutter_mm
    for axes in ((0, 1), (1, 0)):  # rows across the page first, then columns down it
        flipped = grown[:, axes]
        width, height = room[list(axes)] + gutter_mm
        keys = (flipped[:, 1], flipped.prod(axis=1), flipped[:, 0], flipped.max(axis=1))
        for key, pack in product(keys, packers):
            order = np.lexsort((np.arange(len(sizes)), -key))
            corners = pack(flipped[order], width, height)
            if corners is None:
                continue
            centres = np.empty_like(sizes, dtype=float)
            centres[order] = (corners + flipped[order] / 2)[:, axes]
            centres = np.asarray(room_low, float) + centres - gutter_mm / 2
            return spread(centres, sizes, np.asarray(room_low, float),
                          np.asarray(room_high, float))
    return None


def skyline_pack(sizes: np.ndarray, width: float, height: float, least_waste: bool = False
                 ) -> np.ndarray | None:
    """Top-left corners (n, 2) for rectangles placed in this order into a ``width`` x
    ``height`` box, each where its far edge ends nearest the box's near edge (ties: leftmost),
    or, ``least_waste``, where it leaves the least area trapped beneath it; None if one does
    not fit.  The skyline is a list of (x, y, length) steps."""
    skyline = [(0.0, 0.0, width)]
    corners = np.empty((len(sizes), 2))
    for k, (w, h) in enumerate(sizes):
        best = None  # (score, top, x, y)
        for first, (x, _, _) in enumerate(skyline):
            if x + w > width + 1e-9:
                break
            y, reach, step = 0.0, x + w, first
            while step < len(skyline) and skyline[step][0] < reach - 1e-9:
                y = max(y, skyline[step][1])
                step += 1
            if y + h > height + 1e-9:
                continue
            waste = 0.0
            if least_waste:
                for start, level, length in skyline[first:step]:
                    waste += (y - level) * (min(start + length, reach) - start)
            score = (waste, y + h, x) if least_waste else (y + h, x)
            if best is None or score < best[0]:
                best = (score, y + h, x, y)
        if best is None:
            return None
        _, top, x, y = best
        corners[k] = (x, y)
        skyline = raise_skyline(skyline, x, w, top)
    return corners


def raise_skyline(skyline: list[tuple[float, float, float]], x: float, w: float, top: float
                  ) -> list[tuple[float, float, float]]:
    """The skyline with the span [x, x + w] raised to ``top``, neighbours of one height merged."""
    raised: list[tuple[float, float, float]] = [(x, top, w)]
    end = x + w
    for start, y, length in skyline:
        stop = start + length
        if stop <= x + 1e-9 or start >= end - 1e-9:
            raised.append((start, y, length))
            continue
        if start < x - 1e-9:
            raised.append((start, y, x - start))
        if stop > end + 1e-9:
            raised.append((end, y, stop - end))
    raised.sort()
    merged: list[tuple[float, float, float]] = []
    for start, y, length in raised:
        if merged and abs(merged[-1][1] - y) < 1e-12:
            merged[-1] = (merged[-1][0], y, merged[-1][2] + length)
        else:
            merged.append((start, y, length))
    return merged


def spread(centres: np.ndarray, sizes: np.ndarray, room_low: np.ndarray,
           room_high: np.ndarray) -> np.ndarray:
    """Centres moved away from the room's near corner, each axis scaled by the largest factor
    that keeps every item inside the room.  Scaling centre distances by a factor of at least
    one widens every gap along that axis, so a packing that keeps the gutter still does."""
    halves = sizes / 2
    offsets = centres - halves - room_low  # near edges from the room's corner, all >= 0
    slack = room_high - room_low - (offsets + sizes)  # room beyond each far edge, >= 0
    spread_out = centres.copy()
    for axis in (0, 1):
        moving = offsets[:, axis] > 1e-9
        if not moving.any():
            continue
        factor = 1.0 + float((slack[moving, axis] / offsets[moving, axis]).min())
        spread_out[:, axis] = room_low[axis] + offsets[:, axis] * factor + halves[:, axis]
    return spread_out
