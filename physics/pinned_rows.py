"""Whether items that must stand in one row can pass the items that cannot move: the search
behind physics.page_limits' ``PinnedStack``.

Items of which no two fit one above the other in their room (each taller than the room less
the other and the gap) must stand side by side: each takes its own stretch of the room's
width.  An item that cannot move stands in that row too, for each of them that cannot pass
above or below it.  So the row is a one-dimensional packing: each free item gets a stretch
inside the room, a gap from each other's, and a gap from each pinned item's stretch it cannot
pass.  Set down from the left, each item as far left as it goes, the right end of a set of
items is least for some order of them, and the least over all orders follows from the least
of each smaller set (``fits``): exact, in 2^m steps for m items.  (The axes swap for items
that must stand one above another.)  On a banner 300 x 100 mm, five items that must stand in
one row between two hard-anchored photos overlap by at least 8.7 mm wherever they go, and
check found no reason for their 18.8 mm (fresh_projects seed 51; a text beside the row,
9.1 mm into one of it, is still not explained); on a postcard, three did beside a hard
block and a hard photo (seed 17), where dropping the margin parts them.
"""

from __future__ import annotations

import numpy as np

MAX_MEMBERS = 8  # 3^8 steps at most for every set of the free items (rows_fit)
GAP_STEPS = 16  # bisection steps for the widest gap (to the largest size / 2**16)
SEARCH_BUDGET = 200_000  # blockers x items x 2^items: one search of that many steps


def is_row(widths: np.ndarray, rooms: np.ndarray, gap_mm: float) -> bool:
    """Whether no two of the items (``widths`` across the row, the side on which they would
    stand above each other; ``rooms`` (m, 4) each one's walls, as in ``fits``) fit one above
    the other with ``gap_mm``: from the near wall of one to the far wall of the other, in the
    better order (page_limits._spans)."""
    if len(widths) < 2:
        return True
    span = np.maximum(rooms[None, :, 3] - rooms[:, None, 2], rooms[:, None, 3] - rooms[None, :, 2])
    pairs = widths[:, None] + widths[None, :] + gap_mm > span
    np.fill_diagonal(pairs, True)
    return bool(pairs.all())


def fits(lengths: np.ndarray, widths: np.ndarray, rooms: np.ndarray, blockers: np.ndarray,
         gap_mm: float) -> bool:
    """Whether the items (``lengths`` along the row, ``widths`` across it) fit side by side,
    each inside its walls (``rooms`` (m, 4): low and high along, low and high across; a
    region's, or the page's inside the margins), each ``gap_mm`` from the next and from each
    blocker (k, 4, the same columns) it cannot pass above or below.  False only where no
    placement exists; True too where they need not stand in one row at all (``is_row``)."""
    if not is_row(widths, rooms, gap_mm):
        return True
    count = len(lengths)
    banned = []  # each item's stretches it may not start in: the blockers it cannot pass
    for k in range(count):
        above = blockers[:, 2] - gap_mm - rooms[k, 2]
        below = rooms[k, 3] - blockers[:, 3] - gap_mm
        blocking = (widths[k] > above) & (widths[k] > below)
        starts = blockers[blocking, 0] - gap_mm - lengths[k]
        ends = blockers[blocking, 1] + gap_mm
        order = np.argsort(starts)
        banned.append(list(zip(starts[order].tolist(), ends[order].tolist())))
    first = rooms[:, 0].tolist()
    last = (rooms[:, 1] - lengths).tolist()

    def earliest(k: int, start: float) -> float:
        start = max(start, first[k])
        moved = True
        while moved:
            moved = False
            for begin, end in banned[k]:
                if begin < start < end:
                    start, moved = end, True
        return start if start <= last[k] + 1e-9 else np.inf

    ends = np.full(1 << count, np.inf)
    ends[0] = -np.inf
    for mask in range(1, 1 << count):
        best = np.inf
        for k in range(count):
            bit = 1 << k
            if mask & bit and ends[mask ^ bit] < np.inf:
                start = earliest(k, ends[mask ^ bit] + gap_mm)
                best = min(best, start + float(lengths[k]))
        ends[mask] = best
    return bool(ends[-1] < np.inf)


def rows_fit(lengths: np.ndarray, widths: np.ndarray, rooms: np.ndarray, blockers: np.ndarray,
             gap_mm: float) -> bool:
    """``fits`` for every set of two or more of the items that stand in one row at this gap:
    at a narrower gap two of them may fit one above the other (so the whole set need not
    stand in one row), but the rest still must.  Only the largest such sets are searched (a
    set's subsets fit where it does).  Three photos on a postcard beside a hard block: the
    two shorter fit above each other with 0.2 mm, but the tallest and either of them must
    still stand side by side, and do not fit beside the block even overlapping (seed 17)."""
    count = len(lengths)
    searched: list[int] = []
    for mask in sorted(range(3, 1 << count), key=lambda m: -bin(m).count("1")):
        if bin(mask).count("1") < 2 or any(mask & done == mask for done in searched):
            continue
        chosen = np.array([k for k in range(count) if mask >> k & 1])
        if not is_row(widths[chosen], rooms[chosen], gap_mm):
            continue
        searched.append(mask)
        if not fits(lengths[chosen], widths[chosen], rooms[chosen], blockers, gap_mm):
            return False
    return True


def in_the_way(widths: np.ndarray, rooms: np.ndarray, blockers: np.ndarray,
               gap_mm: float) -> np.ndarray:
    """Which blockers (k,) some item cannot pass above or below with ``gap_mm``, inside the
    reach of its walls along the row."""
    above = blockers[None, :, 2] - gap_mm - rooms[:, None, 2]
    below = rooms[:, None, 3] - blockers[None, :, 3] - gap_mm
    reach = ((blockers[None, :, 0] < rooms[:, None, 1] + gap_mm)
             & (blockers[None, :, 1] > rooms[:, None, 0] - gap_mm))
    return ((widths[:, None] > above) & (widths[:, None] > below) & reach).any(axis=0)


def widest_gap(lengths: np.ndarray, widths: np.ndarray, rooms: np.ndarray, blockers: np.ndarray,
               gutter_mm: float) -> float | None:
    """The widest gap (negative: the least overlap) at which the items may still fit in
    their rows (``rows_fit``), by bisection: an upper bound on the gap any layout keeps
    between them and the blockers.  None where they fit with the gutter, or are too many to
    search."""
    if len(lengths) > MAX_MEMBERS:
        return None
    # only blockers some item cannot pass at the gutter matter (at a narrower gap, fewer)
    blockers = blockers[in_the_way(widths, rooms, blockers, gutter_mm)]
    if len(blockers) * len(lengths) << len(lengths) > SEARCH_BUDGET:
        return None  # a hostile page of thousands of anchors: not searched, check stays quick
    if rows_fit(lengths, widths, rooms, blockers, gutter_mm):
        return None
    low = -float(max(lengths.max(), widths.max()))
    high = gutter_mm
    for _ in range(GAP_STEPS):
        middle = (low + high) / 2
        if rows_fit(lengths, widths, rooms, blockers, middle):
            low = middle
        else:
            high = middle
    return high
