"""The limits of free items against the room they have (physics.page_limits): ``NoRoom``, a
free unit with no place inside its walls that keeps the gutter from the items that cannot move
(physics.relocation.room_for, exact for one rectangle among fixed ones); and
``NoArrangement``, a page of a few free items that no arrangement keeps the gutter apart
(physics.arrangements, an exact search)."""

from __future__ import annotations

import numpy as np

from floatpage.physics import arrangements, unit_arrangements
from floatpage.physics.bodies import Bodies
from floatpage.physics.geometry import rooms_of
from floatpage.physics.limit_kinds import (
    CROSSING_BLOCK, LISTED, TOLERANCE_MM, WIDEST_GAP_SLACK_MM, Limit, NoArrangement, NoRoom,
    block_clearances,
)
from floatpage.physics.relocation import Unit, movable_units, room_for, unit_bounds

# NoRoom's search costs about (2 m p)^2 x (m p) for each unit of m members among p pinned
# items that does not already stand clear of them: pages beyond this budget (thousands of
# items jammed among hundreds of anchors) are not searched, so that check stays quick.
NO_ROOM_BUDGET = 2e9
GAP_STEPS = 16  # bisection steps for the widest gap a unit can keep from the pinned items


def no_room(bodies: Bodies, pinned: np.ndarray, margin_mm: float, page_w_mm: float,
            page_h_mm: float, gutter_mm: float) -> list[Limit]:
    """Free units (physics.relocation.Unit) with no place inside their walls that keeps the
    gutter from every pinned item, the others left aside: the free items can make room for
    one another, the pinned ones never move.  room_for tries every place where a member's
    edge meets a pinned item's grown edge or a wall, on each axis, and the room left around
    fixed rectangles always has a corner of that kind, so "no place" is exact."""
    if not pinned.any():
        return []
    units = movable_units(bodies)
    if not units:
        return []
    lowest, highest = unit_bounds(bodies, units, page_w_mm, page_h_mm, margin_mm)
    on_page = unit_bounds(bodies, units, page_w_mm, page_h_mm, 0.0)
    # where a unit stands is a place if it keeps the gutter there: only the others are searched
    searched = np.flatnonzero(~_standing_clear(bodies, pinned, units, lowest, highest,
                                               gutter_mm))
    obstacles = int(pinned.sum())
    cost = sum((2.0 * len(units[k].members) * obstacles) ** 2 * len(units[k].members)
               * obstacles for k in searched)
    if cost > NO_ROOM_BUDGET:
        return []
    found: list[Limit] = []
    for k in searched:
        unit = units[k]
        work = _among_pinned(bodies, pinned, unit)
        if room_for(work, unit, gutter_mm, lowest[k], highest[k], clear_only=True) is not None:
            continue
        widest = _widest_clearance(work, unit, lowest[k], highest[k], gutter_mm)
        fits_page = room_for(work, unit, 0.0, on_page[0][k], on_page[1][k],
                             clear_only=True) is not None
        found.append(NoRoom(tuple(int(row) for row in unit.members),
                            tuple(int(row) for row in np.flatnonzero(pinned)), widest, fits_page))
        if len(found) >= LISTED:
            break
    return found


def _standing_clear(bodies: Bodies, pinned: np.ndarray, units: list, lowest: np.ndarray,
                    highest: np.ndarray, gutter_mm: float) -> np.ndarray:
    """For each unit, whether it already stands inside its walls with every member the gutter
    from every pinned item: most do, and need no search.  A block of rows at a time, so a
    page of thousands of items beside thousands of anchors is measured in bounded memory."""
    roots = np.array([unit.root for unit in units])
    clear = ((bodies.centres[roots] >= lowest - TOLERANCE_MM)
             & (bodies.centres[roots] <= highest + TOLERANCE_MM)).all(axis=1)
    owner = np.concatenate([np.full(len(unit.members), k) for k, unit in enumerate(units)])
    members = np.concatenate([unit.members for unit in units])
    obstacles = np.flatnonzero(pinned)
    halves = bodies.sizes / 2
    for start in range(0, len(members), CROSSING_BLOCK):
        rows = members[start:start + CROSSING_BLOCK]
        gaps = block_clearances(bodies.centres[rows], halves[rows], bodies.centres[obstacles],
                                halves[obstacles])
        close = (gaps < gutter_mm - TOLERANCE_MM).any(axis=1)
        clear[owner[start:start + CROSSING_BLOCK][close]] = False
    return clear


def _among_pinned(bodies: Bodies, pinned: np.ndarray, unit: Unit) -> Bodies:
    """The page as the unit alone among the pinned items: everything else takes no room."""
    alone = ~pinned
    alone[unit.members] = False
    return Bodies(centres=bodies.centres, sizes=bodies.sizes, anchors=bodies.anchors,
                  decorative=alone)


def _widest_clearance(work: Bodies, unit: Unit, lowest: np.ndarray, highest: np.ndarray,
                      gutter_mm: float) -> float:
    """The widest gap (negative: the least overlap) the unit can keep from the pinned items
    inside its walls, by bisection (to its largest side / 2**GAP_STEPS: 0.001 mm on 60 mm)."""
    low, high = -float(work.sizes[unit.members].max()), gutter_mm
    for _ in range(GAP_STEPS):
        middle = (low + high) / 2
        if room_for(work, unit, middle, lowest, highest, clear_only=True) is None:
            high = middle
        else:
            low = middle
    return low


def no_arrangement(bodies: Bodies, roots: np.ndarray, pinned: np.ndarray, near: np.ndarray,
                   far: np.ndarray, page_w_mm: float, page_h_mm: float, gutter_mm: float,
                   capped_mm: float) -> list[Limit]:
    """A NoArrangement for a page of three to arrangements.MAX_ITEMS free items (two are a
    Crossing), each alone in its group, between the same walls, that no arrangement keeps the
    gutter apart, where the other limits leave a wider gap than the search finds
    (``capped_mm``).  A search that runs out of its budget says nothing."""
    rows = np.flatnonzero(bodies.active & ~bodies.decorative)
    if not 3 <= len(rows) <= arrangements.MAX_ITEMS or pinned[rows].any() or \
            (roots[rows] != rows).any() or not np.isnan(bodies.regions[rows, 0]).all() or \
            np.ptp(near[rows], axis=0).max() > 0 or np.ptp(far[rows], axis=0).max() > 0:
        return []
    extent = np.array([page_w_mm, page_h_mm])
    room = extent - near[rows[0]] - far[rows[0]]
    sizes = bodies.sizes[rows]
    widest = arrangements.widest_gap(sizes, room, gutter_mm)
    if widest is None or widest >= min(gutter_mm, capped_mm) - WIDEST_GAP_SLACK_MM:
        return []
    try:
        fits_page = arrangements.arranges(sizes, extent, 0.0)
    except arrangements.OutOfBudget:
        return []
    return [NoArrangement(tuple(int(row) for row in rows), (float(room[0]), float(room[1])),
                          float(widest), bool(fits_page))]


def no_unit_arrangement(bodies: Bodies, pinned: np.ndarray, margin_mm: float, page_w_mm: float,
                        page_h_mm: float, gutter_mm: float, capped_mm: float) -> list[Limit]:
    """A NoArrangement (with the pinned items it must stand around) for a page of a few free
    units among items that cannot move, groups or regions, where ``no_arrangement`` does not
    apply: no arrangement of the units (physics.unit_arrangements, an exact search) keeps the
    gutter from one another and from the pinned items inside their walls, and the other
    limits leave a wider gap than it finds (``capped_mm``).  fresh_projects seed 7031: a
    photo with its caption, two photos and a header beside a hard-anchored photo on A5
    overlapped by 28.8 mm, each unit alone had room, and `check` sent the page back to
    settle; no arrangement keeps them less than 4.8 mm into each other.  A search that runs
    out of its budget says nothing.

    Where the page's units are too many for one search (more than MAX_MEMBERS members) or
    it runs out of its budget, the units of each room alone (``room_arrangements``); where
    it only ran out on the way to the widest gap (the limit not ``proved``), the rooms'
    limits that are proved, if any, else the page's."""
    search = unit_arrangements.search_of(bodies, pinned, margin_mm, page_w_mm, page_h_mm,
                                         gutter_mm)
    if search is not None and not pinned.any() and len(search.units) == len(search.rows) \
            and np.isnan(bodies.regions[search.rows, 0]).all():
        return []  # free items alone: no_arrangement's
    high = min(gutter_mm, capped_mm)
    found = None if search is None else _no_arrangement_of(bodies, search, margin_mm,
                                                          page_w_mm, page_h_mm, high)
    if found is not None and all(limit.proved for limit in found):
        return found
    rooms = room_arrangements(bodies, pinned, margin_mm, page_w_mm, page_h_mm, gutter_mm, high)
    if found is None:
        return rooms
    return [limit for limit in rooms if limit.proved] or found


def room_arrangements(bodies: Bodies, pinned: np.ndarray, margin_mm: float, page_w_mm: float,
                      page_h_mm: float, gutter_mm: float, high: float) -> list[Limit]:
    """A NoArrangement for each room (geometry.rooms_of: a region's units, or the units free
    to go anywhere) whose own units no arrangement keeps ``high`` apart from one another and
    from the pinned items: the page's units taken all at once were too many for the search,
    or ran out of its budget.  Sound for the whole page: leaving units out only takes
    relations away, so a gap the room's units cannot keep among the pinned items alone the
    page cannot keep with the others there too.  Seed 7067 of fresh_projects, p4: three
    texts of a words region cannot share the room a hard-anchored text leaves them with the
    4 mm gutter (2.8 mm at most), but the page's nine members ran out of the search's
    budget, and `check` sent the page back to settle."""
    rooms = rooms_of(bodies)
    found: list[Limit] = []
    for room in np.unique(rooms[bodies.active & bodies.free]):
        search = unit_arrangements.search_of(bodies, pinned, margin_mm, page_w_mm, page_h_mm,
                                             gutter_mm, taken=rooms == room)
        if search is not None:
            found += _no_arrangement_of(bodies, search, margin_mm, page_w_mm, page_h_mm,
                                        high) or []
    return found


def _no_arrangement_of(bodies: Bodies, search: unit_arrangements.Search, margin_mm: float,
                       page_w_mm: float, page_h_mm: float, high: float
                       ) -> list[Limit] | None:
    """The NoArrangement of ``search``'s units where its widest gap is below ``high``, none
    where it reaches it; None where the search cannot tell whether ``high`` fits.  Where it
    rules ``high`` out but runs out of its budget on the way to the widest gap, the widest gap
    a layout was found for, marked not ``proved`` (unit_arrangements.widest_bracket)."""
    obstacles = bodies.centres[search.obstacles], bodies.sizes[search.obstacles] / 2
    bracket = unit_arrangements.widest_bracket(search.walls, *obstacles, high)
    if bracket is None:
        return None
    widest = bracket.low
    if widest >= high - WIDEST_GAP_SLACK_MM:
        return []
    try:
        fits_page = widest >= 0 or unit_arrangements.arranges(search.page_walls, *obstacles,
                                                               0.0)
    except arrangements.OutOfBudget:
        if bracket.exact:
            return None
        fits_page = True  # not known: overlap is not taken as forced (the margin gives way first)
    room = np.array([page_w_mm, page_h_mm]) - 2 * margin_mm
    return [NoArrangement(tuple(int(row) for row in search.rows),
                          (float(room[0]), float(room[1])), float(widest), bool(fits_page),
                          tuple(int(row) for row in search.obstacles), units=True,
                          proved=bracket.exact, at_most_mm=float(bracket.high))]
