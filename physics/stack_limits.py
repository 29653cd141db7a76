"""The limits of items that must stand in one line (physics.page_limits): ``Stack``, three or
more items of which no two fit side by side, taller together than their room; and
``PinnedStack``, free items that must stand in one row which the items that cannot move (or
the row's length across several rooms) leave no place for (physics.pinned_rows).  Both start
from the same sets: the items of which no two stand side by side (``_clashing_sets``), each
solid rigid group as one item (``solid_units``)."""

from __future__ import annotations

import numpy as np

from floatpage.physics import pinned_rows
from floatpage.physics.bodies import Bodies
from floatpage.physics.limit_kinds import TOLERANCE_MM, Limit, PinnedStack, Stack


def stacks(bodies: Bodies, roots: np.ndarray, offsets: np.ndarray, near: np.ndarray,
           far: np.ndarray, page_w_mm: float, page_h_mm: float, gutter_mm: float
           ) -> list[Limit]:
    """The tallest set of items (one per group, of the same room) of which no two fit side by
    side with the gutter, where that set is taller than the room with a gutter between each
    two; the same with the axes swapped.  Two items clash across when their widths and the
    gutter exceed the room's width, so every item wider than half of (room - gutter) clashes
    with every other such item, and a narrower one with those wide enough to make up the rest:
    the largest such set is the wide ones with at most one narrow one, found exactly by trying
    each narrow one.  Sets of two are Crossings; a set whose two tallest cannot stack either
    holds a Crossing that already explains the page, and is left out.  A rigid group that
    is solid along the stack (``solid_units``: a photo with its caption below, as wide as
    it) stands in the set as one item the size of the whole group."""
    extent = np.array([page_w_mm, page_h_mm])
    rows = np.flatnonzero(bodies.active)
    if len(rows) < 3:
        return []
    rooms = extent - near[rows] - far[rows]
    found: list[Limit] = []
    for room in np.unique(rooms.round(6), axis=0):
        mine = rows[(np.abs(rooms - room) < 1e-6).all(axis=1)]
        for across in (0, 1):
            sizes, units = solid_units(bodies, roots, offsets, mine, across, gutter_mm)
            stack = _tallest_stack(sizes, roots, units, across, room, gutter_mm)
            if stack is not None:
                found.append(_stack_limit(sizes, stack, across, room, extent, gutter_mm))
    return found


def solid_units(bodies: Bodies, roots: np.ndarray, offsets: np.ndarray, rows: np.ndarray,
                across: int, gutter_mm: float) -> tuple[np.ndarray, np.ndarray]:
    """Sizes (n, 2) with each *solid* rigid group among ``rows`` as one item the size of the
    group (at its root's row), and the rows left (a solid group's root stands for its
    members).  A group is solid when each member spans the group's whole extent along the
    stack and no gap between members across it is as wide as the shortest other item and a
    gutter on each side: no other item can stand in the group's box between two members,
    so an item the group cannot stand beside (across) must stand above or below the whole
    group (along), as for a single item.  (Taken member by member, the
    tallest for its group, four photos with captions on a postcard, that could not stand
    side by side nor two above each other, went unexplained: fresh_projects seed 19.)"""
    sizes = bodies.sizes.copy()
    along = 1 - across
    keep = np.ones(len(rows), dtype=bool)
    for root in np.unique(roots[rows]):
        members = rows[roots[rows] == root]
        if len(members) < 2 or root not in members:
            continue
        low = offsets[members] - bodies.sizes[members] / 2
        high = offsets[members] + bodies.sizes[members] / 2
        if (np.ptp(low[:, along]) > TOLERANCE_MM or np.ptp(high[:, along]) > TOLERANCE_MM):
            continue
        order = np.argsort(low[:, across], kind="stable")
        reach = np.maximum.accumulate(high[order, across])[:-1]
        gaps = low[order[1:], across] - reach
        others = rows[roots[rows] != root]
        shortest = float(bodies.sizes[others, across].min()) if len(others) else np.inf
        if gaps.size and gaps.max() >= shortest + 2 * gutter_mm - TOLERANCE_MM:
            continue
        sizes[root, along] = high[0, along] - low[0, along]
        sizes[root, across] = high[:, across].max() - low[:, across].min()
        keep &= ~np.isin(rows, members[members != root])
    return sizes, rows[keep]


def _tallest_stack(sizes: np.ndarray, roots: np.ndarray, rows: np.ndarray, across: int,
                   room: np.ndarray, gutter_mm: float) -> np.ndarray | None:
    """stacks' search on one axis: the rows of the set, or None where none is too tall."""
    along = 1 - across
    widths, heights = sizes[rows, across], sizes[rows, along]
    best, best_need = None, room[along] + TOLERANCE_MM
    for chosen in _clashing_sets(widths, room[across], gutter_mm):
        picked = _one_per_group(rows[chosen], heights[chosen], roots)
        if len(picked) < 3:
            continue
        tall = np.sort(sizes[picked, along])[::-1]
        if tall[0] + tall[1] + gutter_mm > room[along] + TOLERANCE_MM:
            continue  # its two tallest are a Crossing
        need = tall.sum() + gutter_mm * (len(picked) - 1)
        if need > best_need:
            best, best_need = picked, need
    return best


def _clashing_sets(widths: np.ndarray, room_mm: float, gutter_mm: float) -> list[np.ndarray]:
    """Masks of the largest sets of items of ``widths`` of which no two fit side by side in
    ``room_mm`` with the gutter (two clash when their widths and the gutter exceed it): every
    item wider than half of (room - gutter) clashes with every other such item, and a narrower
    one with those wide enough to make up the rest, so the candidates are the wide ones, and
    the wide ones with each narrow one that clashes with the widest (stacks' and
    pinned_stacks' candidates alike)."""
    spare = room_mm - gutter_mm + TOLERANCE_MM
    wide = widths > spare / 2
    return [wide] + [wide & (widths > spare - widths[k]) | (np.arange(len(widths)) == k)
                     for k in np.flatnonzero(~wide & (widths > spare - widths.max()))]


def _one_per_group(rows: np.ndarray, heights: np.ndarray, roots: np.ndarray) -> np.ndarray:
    """The tallest row of each rigid group among ``rows``: members of one group keep their
    own offsets and may overlap, so only one of them counts towards a stack."""
    order = np.argsort(-heights, kind="stable")
    _, first = np.unique(roots[rows[order]], return_index=True)
    return rows[order[np.sort(first)]]


def _stack_limit(sizes: np.ndarray, stack: np.ndarray, across: int, room: np.ndarray,
                 extent: np.ndarray, gutter_mm: float) -> Stack:
    along = 1 - across
    tall = np.sort(sizes[stack, along])[::-1]
    narrow = np.sort(sizes[stack, across])
    count = len(stack)

    def widest(span: np.ndarray) -> float:  # stacked, or the two narrowest side by side
        return max((span[along] - tall.sum()) / (count - 1), span[across] - narrow[0] - narrow[1])
    return Stack(tuple(int(row) for row in stack[np.argsort(-sizes[stack, along],
                                                                 kind="stable")]),
                 along, float(tall.sum() + gutter_mm * (count - 1)), float(room[along]),
                 float(widest(room)), bool(widest(extent) >= 0))


def pinned_stacks(bodies: Bodies, roots: np.ndarray, offsets: np.ndarray,
                  pinned: np.ndarray, walls: tuple[np.ndarray, np.ndarray],
                  page_walls: tuple[np.ndarray, np.ndarray], page_w_mm: float,
                  page_h_mm: float, gutter_mm: float) -> list[Limit]:
    """Free items that must stand in one row (no two fit one above the other inside their
    walls) and cannot all find a stretch of it beside each other and the items that cannot
    move (physics.pinned_rows): for each room and axis the set ``_stacks`` would try, where
    the pinned items matter (without them the row fits, or a Stack already says it does
    not); and for each axis the items of several rooms (regions and the free items) wide in
    their own, which no Stack looks at (fresh_projects seed 118: a words region's text, a
    free text and two photos of the photos region, on a banner, each too tall to stand above
    another, 0.07 mm too wide for one row with the gutter)."""
    extent = np.array([page_w_mm, page_h_mm])
    near, far = walls
    rows = np.flatnonzero(bodies.active)
    rooms = np.concatenate([near[rows], far[rows]], axis=1).round(6)
    halves = bodies.sizes / 2
    obstacles = np.flatnonzero(pinned)
    free_rows = rows[~pinned[rows]]
    found: list[Limit] = []
    for across in (0, 1):
        along = 1 - across
        boxes = np.stack([bodies.centres[obstacles, along] - halves[obstacles, along],
                          bodies.centres[obstacles, along] + halves[obstacles, along],
                          bodies.centres[obstacles, across] - halves[obstacles, across],
                          bodies.centres[obstacles, across] + halves[obstacles, across]], axis=1)

        def walls_of(picked: np.ndarray, low: np.ndarray, high: np.ndarray) -> np.ndarray:
            return np.stack([low[picked, along], extent[along] - high[picked, along],
                             low[picked, across], extent[across] - high[picked, across]],
                            axis=1)

        candidates = []
        for room in np.unique(rooms, axis=0):
            mine = rows[(np.abs(rooms - room) < 1e-6).all(axis=1)]
            free = mine[~pinned[mine]]
            if len(free) >= 2:
                sizes, units = solid_units(bodies, roots, offsets, free, across, gutter_mm)
                picked = _row_candidate(sizes, roots, units, across,
                                        extent - room[:2] - room[2:], gutter_mm)
                if picked is not None:
                    candidates.append((sizes, picked, False, False))
        if len(free_rows) >= 2:
            sizes, units = solid_units(bodies, roots, offsets, free_rows, across, gutter_mm)
            own = extent[across] - near[units, across] - far[units, across]
            wide_in_own = units[sizes[units, across] > (own - gutter_mm) / 2]
            wide = _one_per_group(wide_in_own, sizes[wide_in_own, along], roots)
            wide = wide[np.argsort(-sizes[wide, along], kind="stable")][:pinned_rows.MAX_MEMBERS]
            if len(np.unique(rooms[np.searchsorted(rows, wide)], axis=0)) >= 2:
                candidates.append((sizes, np.sort(wide), True, False))
            clashing = _clashing(sizes, roots, units, walls_of(units, near, far), across,
                                 gutter_mm)
            if (len(np.unique(rooms[np.searchsorted(rows, clashing)], axis=0)) >= 2
                    and not any(np.array_equal(np.sort(clashing), picked)
                                for _, picked, _, _ in candidates)):
                candidates.append((sizes, np.sort(clashing), True, True))
        for sizes, picked, mixed, least in candidates:
            lengths, widths = sizes[picked, along], sizes[picked, across]
            box = walls_of(picked, near, far)
            widest = pinned_rows.widest_gap(lengths, widths, box, boxes, gutter_mm)
            if widest is not None and least:  # only the items that make the gap that narrow
                picked = _least_set(picked, lengths, widths, box, boxes, gutter_mm, widest)
                if len(np.unique(rooms[np.searchsorted(rows, picked)], axis=0)) < 2:
                    continue  # one room's: its own candidate, or a Stack, names them
                lengths, widths = sizes[picked, along], sizes[picked, across]
                box = walls_of(picked, near, far)
            if widest is None or not mixed and not pinned_rows.rows_fit(
                    lengths, widths, box, boxes[:0], gutter_mm):
                continue  # they fit, or do not even without the pinned items (a Stack)
            page_box = walls_of(picked, *page_walls)
            in_way = pinned_rows.in_the_way(widths, box, boxes, gutter_mm)
            found.append(PinnedStack(
                tuple(int(r) for r in picked[np.argsort(-lengths, kind="stable")]),
                tuple(int(r) for r in obstacles[in_way]), along,
                float(box[:, 1].max() - box[:, 0].min()), float(widest),
                pinned_rows.rows_fit(lengths, widths, page_box, boxes, 0.0)))
    return found


def _least_set(picked: np.ndarray, lengths: np.ndarray, widths: np.ndarray, box: np.ndarray,
               blockers: np.ndarray, gutter_mm: float, widest: float) -> np.ndarray:
    """``picked`` less each item without which the others still leave no wider gap than
    ``widest`` (pinned_rows.widest_gap): a PinnedStack names every pair of its items, and
    a photo of a region above three panels that must overlap in theirs is in no such pair
    (tests/physics/test_rooms_and_rows.py, stacked_regions)."""
    keep = np.ones(len(picked), dtype=bool)
    for k in range(len(picked)):
        keep[k] = False
        rest = pinned_rows.widest_gap(lengths[keep], widths[keep], box[keep], blockers,
                                      gutter_mm) if keep.sum() >= 2 else None
        keep[k] = rest is None or rest > widest + TOLERANCE_MM
    return picked[keep]


def _clashing(sizes: np.ndarray, roots: np.ndarray, units: np.ndarray, box: np.ndarray,
              across: int, gutter_mm: float) -> np.ndarray:
    """The longest free units (one per group, at most pinned_rows.MAX_MEMBERS) of which each
    cannot stand above or below at least one other inside their walls (``box``, as
    pinned_rows takes them), whatever their rooms: pinned_stacks' mixed candidate takes
    only items wide in their own room, and missed a free text 126 mm wide on A3 that can
    stand beside no item of the photos region, each 175-190 mm of its 200, though it is
    narrow for the page (fresh_projects seed 7114: three such items 454 mm tall together on
    a page 420 mm tall overlapped by 45 mm, and check sent the page back to settle)."""
    widths = sizes[units, across]
    span = np.maximum(box[None, :, 3] - box[:, None, 2], box[:, None, 3] - box[None, :, 2])
    clash = widths[:, None] + widths[None, :] + gutter_mm > span + TOLERANCE_MM
    np.fill_diagonal(clash, False)
    picked = units[clash.any(axis=1)]
    picked = _one_per_group(picked, sizes[picked, 1 - across], roots)
    return picked[np.argsort(-sizes[picked, 1 - across], kind="stable")][:pinned_rows.MAX_MEMBERS]


def _row_candidate(sizes: np.ndarray, roots: np.ndarray, rows: np.ndarray, across: int,
                   room: np.ndarray, gutter_mm: float) -> np.ndarray | None:
    """The largest set of ``rows`` (one per group) of which no two fit one above the other
    across the room with the gutter (the sets ``_tallest_stack`` tries), or None if none has
    two."""
    widths, heights = sizes[rows, across], sizes[rows, 1 - across]
    best = None
    for chosen in _clashing_sets(widths, room[across], gutter_mm):
        picked = _one_per_group(rows[chosen], heights[chosen], roots)
        if len(picked) >= 2 and (best is None or len(picked) > len(best)):
            best = picked
    return best
