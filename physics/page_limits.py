"""What a page's own items rule out, whatever the physics does: the reasons `check` gives when
a settled page misses one of its guarantees (zero overlap, inside the page, the print-safe
margin, the gutter).

The guarantees give way in a fixed order on a page too full for all of them (the gutter, then
the margin, then overlap; finalize.remove_overlaps), and a page can be too full in ways its
area does not show.  Two items each wider and taller than half the room cannot be parted at
all; a group anchored together can be wider than the page; two hard anchors can pin items onto
each other.  Every reason here is exact for the items it names, so a user told of it knows
that no settle will help, and what to change instead:

- ``PinnedClash``: two items that cannot move (hard anchors, held, or following one of those
  or a decoration) stand closer than the gutter, or overlap;
- ``PinnedOutside``: such an item stands past the page's edge or inside the margin, or a
  decoration (never moved either) past the page's edge;
- ``TooLarge``: a rigid group (an item and those anchored to it), or a lone item, is larger
  than the room between its walls on one axis;
- ``Crossing``: two items that can be parted neither side by side nor one above the other
  with the gutter between them inside the room;
- ``Stack``: three or more items of which no two fit side by side with the gutter, so that
  all must stand one above another, taller together than the room (or the same across);
- ``NoRoom``: a free item (with the items following it) that has no place inside its walls
  keeping the gutter from the items that cannot move (physics.relocation.room_for's search,
  exact for one rectangle among fixed ones);
- ``PinnedStack``: free items that must stand in one row (no two fit one above the other
  inside their walls), which the items that cannot move, or the row's length across several
  rooms, leave no place for (physics.pinned_rows, exact for the row);
- ``NoArrangement``: a page of a few free items (physics.arrangements: at most six) that no
  arrangement keeps the gutter apart inside the margins, where no limit above says so (an
  exact search of every way of placing each beside or above another).

A limit caps the gap of its own room only (``rooms_of``: each region, and the free items):
what the items of one region rule out says nothing of another's.

The area test (Engine.grown_cover) stays the reason for a crowd of small items.

A reason is true only for what it accounts for: ``unexplained_pairs`` lists the pairs closer
than the gutter that no limit here explains, and `check` sends those back to `settle`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Union

import numpy as np

from floatpage.physics import arrangements, pinned_rows
from floatpage.physics.bodies import Bodies
from floatpage.physics.fast_forces import candidate_pairs
from floatpage.physics.finalize import pair_clearances
from floatpage.physics.geometry import group_extents, rooms_of
from floatpage.physics.quality import sweep_candidates
from floatpage.physics.relocation import Unit, movable_units, room_for, unit_bounds

TOLERANCE_MM = 0.01  # saved positions are rounded to 0.01 mm
CROSSING_BLOCK = 512  # rows compared with all others at once: memory O(512 n)
LISTED = 1_000  # reasons of one kind kept: enough to name, bounded on a hostile file
SWEEP_BUDGET = 10_000_000  # neighbour-search candidates (about 300 MB) before blocks instead
# NoRoom's search costs about (2 m p)^2 x (m p) for each unit of m members among p pinned
# items that does not already stand clear of them: pages beyond this budget (thousands of
# items jammed among hundreds of anchors) are not searched, so that check stays quick.
NO_ROOM_BUDGET = 2e9
# A settle keeps the widest gap a page's limits leave to within two roundings of a saved
# position (Engine._relocate_to_cap aims 0.02 mm inside it): a pair this near it is explained.
WIDEST_GAP_SLACK_MM = 0.03
GAP_STEPS = 16  # bisection steps for the widest gap a unit can keep from the pinned items


@dataclass(frozen=True)
class PinnedClash:
    rows: tuple[int, int]
    gap_mm: float  # edge to edge, negative when they overlap


@dataclass(frozen=True)
class PinnedOutside:
    row: int
    past_edge_mm: float  # how far it reaches past the page's edge (0 if inside the page)
    into_margin_mm: float  # how far it reaches into its margin
    decoration: bool = False  # a decoration: keeps no margin, but never moves either


@dataclass(frozen=True)
class TooLarge:
    rows: tuple[int, ...]  # the group's members, its root first
    axis: int  # 0 across (width), 1 down (height)
    extent_mm: float
    room_mm: float  # between its walls (the margins, or its region)
    page_mm: float


@dataclass(frozen=True)
class Crossing:
    rows: tuple[int, int]
    needs_mm: tuple[float, float]  # side by side (widths + gutter), one above the other
    room_mm: tuple[float, float]  # inside the margins
    widest_gap_mm: float  # the widest gap the two can keep inside the margins (< 0: overlap)
    fits_page: bool  # whether they can be parted at all if the margins give way


@dataclass(frozen=True)
class Stack:
    rows: tuple[int, ...]  # tallest first
    axis: int  # the axis they must be stacked along: 1 one above another, 0 side by side
    needs_mm: float  # their sizes along it, and a gutter between each two
    room_mm: float  # inside the margins
    widest_gap_mm: float  # at most this gap between them inside the margins (< 0: overlap)
    fits_page: bool  # whether they can be parted at all if the margins give way


@dataclass(frozen=True)
class NoRoom:
    rows: tuple[int, ...]  # the free item, then the items following it
    pinned: tuple[int, ...]  # the items that cannot move, that leave it no room
    widest_gap_mm: float  # the widest gap from them it can keep inside the margins (< 0: overlap)
    fits_page: bool  # whether it can stand clear of them at all if the margins give way


@dataclass(frozen=True)
class PinnedStack:
    rows: tuple[int, ...]  # free items of which no two stand beside each other (or above)
    pinned: tuple[int, ...]  # the items that cannot move that one of them cannot pass
    axis: int  # the axis they must stand along: 1 one above another, 0 side by side
    room_mm: float  # inside the margins, along it
    widest_gap_mm: float  # at most this gap between them and those items (< 0: overlap)
    fits_page: bool  # whether they can be parted at all if the margins give way


@dataclass(frozen=True)
class NoArrangement:
    rows: tuple[int, ...]  # every item that takes part on the page
    room_mm: tuple[float, float]  # inside the margins
    widest_gap_mm: float  # the widest gap they can all keep inside the margins (< 0: overlap)
    fits_page: bool  # whether they can be parted at all if the margins give way


Limit = Union[PinnedClash, PinnedOutside, TooLarge, Crossing, Stack, NoRoom, PinnedStack,
              NoArrangement]
GAP_LIMITS = (Crossing, Stack, NoRoom, PinnedStack, NoArrangement)  # with a widest_gap_mm


def page_limits(bodies: Bodies, page_w_mm: float, page_h_mm: float, margin_mm: float,
                gutter_mm: float) -> list[Limit]:
    """Every reason on this page that no arrangement keeps its guarantees (see the module
    doc), most binding first within each kind.  Decorations take no part."""
    roots, offsets = bodies.group_roots()
    near, far = bodies.insets(margin_mm, page_w_mm, page_h_mm)
    pinned = _pinned(bodies, roots)
    found: list[Limit] = []
    found += _pinned_clashes(bodies, roots, pinned, gutter_mm)
    found += _standing_outside(bodies, pinned, near, far, page_w_mm, page_h_mm)
    found += _too_large(bodies, roots, offsets, pinned, near, far, page_w_mm, page_h_mm)
    found += _crossings(bodies, roots, pinned, near, far, page_w_mm, page_h_mm, gutter_mm)
    found += _stacks(bodies, roots, offsets, near, far, page_w_mm, page_h_mm, gutter_mm)
    found += _no_room(bodies, pinned, margin_mm, page_w_mm, page_h_mm, gutter_mm)
    if pinned.any() or not np.isnan(bodies.regions[:, 0]).all():
        page_walls = bodies.insets(0.0, page_w_mm, page_h_mm)
        found += _pinned_stacks(bodies, roots, offsets, pinned, (near, far), page_walls,
                                page_w_mm, page_h_mm, gutter_mm)
    found += _no_arrangement(bodies, roots, pinned, near, far, page_w_mm, page_h_mm, gutter_mm,
                             widest_gap(found))
    return found


def _no_arrangement(bodies: Bodies, roots: np.ndarray, pinned: np.ndarray, near: np.ndarray,
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


def binding(limits: list[Limit]) -> list[Limit]:
    """The limits that rule out the gutter or zero overlap: all but decorations past the
    page's edge (they take no part in either)."""
    return [limit for limit in limits
            if not (isinstance(limit, PinnedOutside) and limit.decoration)]


def capping(limits: list[Limit]) -> list[Limit]:
    """The limits that cap the gap the items that move can keep: items that cannot be parted
    (Crossing, Stack), a unit with no room among the pinned ones (NoRoom), a group too large
    for its room.  Two pinned items on each other (PinnedClash), or one past its wall, say
    nothing of the rest of the page: the no-overlap pass leaves such a pair out, and every
    other pair can still keep the gutter."""
    return [limit for limit in limits
            if isinstance(limit, (TooLarge, *GAP_LIMITS))]


def widest_gap(limits: list[Limit]) -> float:
    """The widest gap the limits leave the page's closest pair: the page's gap can be no
    wider than any Crossing's, Stack's or NoRoom's widest; inf where none caps it."""
    return min((limit.widest_gap_mm for limit in limits
                if isinstance(limit, GAP_LIMITS)), default=np.inf)


def room_caps(bodies: Bodies, limits: list[Limit], rooms: np.ndarray | None = None
              ) -> np.ndarray:
    """The widest gap the limits leave each room (``rooms_of``), (rooms,): widest_gap of the
    Crossings, Stacks, NoRooms and PinnedStacks that name an item of it; inf where none
    does.  Three month panels that must overlap in a words region cap that region, not the
    photos region above it (fresh_projects seed 9: the page-wide cap of -6.4 mm excused any
    overlap of the photos region up to 6.4 mm deep, and stopped its relocation:
    tests/physics/rooms/rooms-7054.toml is such a page where the photos region has room)."""
    rooms = rooms_of(bodies) if rooms is None else rooms
    caps = np.full(int(rooms.max(initial=0)) + 1, np.inf)
    for limit in limits:
        if isinstance(limit, GAP_LIMITS):
            touched = np.unique(rooms[list(limit.rows)])
            caps[touched] = np.minimum(caps[touched], limit.widest_gap_mm)
    return caps


def unexplained_pairs(bodies: Bodies, limits: list[Limit], gutter_mm: float
                      ) -> list[tuple[int, int, float]]:
    """Pairs (a, b, clearance) of active items of different groups closer than the gutter
    that the limits do not account for: not two pinned items (PinnedClash), not a pair a
    Crossing, Stack or NoRoom names, and closer than the widest gap the limits leave their
    room (room_caps; a settle that cannot keep the gutter keeps the widest gap that fits, on
    every pair of the room; a pair of two rooms, the wider of the gaps of the rooms of its
    items that move: an item that can leave the crowded room need not crowd it, and one
    beside a hard-anchored header of another room keeps its own room's gap,
    fresh_projects seed 1080).  A reason `check` gives is true only for
    the pairs it explains: a page with two hard anchors on each other had a free item
    28.6 mm into one of them, and the clash was given as the reason.  Closest first, at most
    LISTED."""
    roots, _ = bodies.group_roots()
    pinned = _pinned(bodies, roots)
    count = bodies.count
    named: list[int] = []  # pairs as a * count + b, a < b
    for limit in limits:
        if isinstance(limit, Crossing):
            named.append(limit.rows[0] * count + limit.rows[1])
        elif isinstance(limit, NoArrangement):
            named += [a * count + b for a in limit.rows for b in limit.rows if a < b]
        elif isinstance(limit, Stack):  # a solid group stands in it by its root
            members = np.flatnonzero(np.isin(roots, limit.rows))
            named += [a * count + b for a in members for b in members
                      if a < b and roots[a] != roots[b]]
        elif isinstance(limit, NoRoom):
            named += [min(a, b) * count + max(a, b) for a in limit.rows for b in limit.pinned]
        elif isinstance(limit, PinnedStack):  # its groups, with each other and the pinned
            members = np.flatnonzero(np.isin(roots, roots[list(limit.rows)]))
            named += [min(a, b) * count + max(a, b) for a in members
                      for b in np.concatenate([members, np.array(limit.pinned, dtype=int)])
                      if a != b and roots[a] != roots[b]]
    named_keys = np.array(named, dtype=np.int64)
    rooms = rooms_of(bodies)
    caps = room_caps(bodies, limits, rooms) - WIDEST_GAP_SLACK_MM

    def unexplained(a: np.ndarray, b: np.ndarray, gaps: np.ndarray) -> np.ndarray:
        keys = np.minimum(a, b).astype(np.int64) * count + np.maximum(a, b)
        # a pair of two rooms keeps the wider cap of the rooms of the items that move: an
        # item beside a pinned one is held to its own room's cap (the relocation of that room
        # aims there); one that can leave a crowded room need not crowd it
        cap = np.maximum(np.where(pinned[a], -np.inf, caps[rooms[a]]),
                         np.where(pinned[b], -np.inf, caps[rooms[b]]))
        return ~(pinned[a] & pinned[b]) & (gaps < cap) & ~np.isin(keys, named_keys)
    return close_pairs(bodies, np.flatnonzero(bodies.active), roots, gutter_mm, unexplained)


def _pinned(bodies: Bodies, roots: np.ndarray) -> np.ndarray:
    """Rows that no push moves: hard anchors and held items, and everything following one or
    following a decoration (a decoration is never moved, so neither is a caption set beside
    it: on a random page one stood past the page's edge, another 6.5 mm into a hard anchor)."""
    fixed = bodies.hard | bodies.held | bodies.decorative
    return bodies.active & (fixed | fixed[roots])


def _pinned_clashes(bodies: Bodies, roots: np.ndarray, pinned: np.ndarray,
                    gutter_mm: float) -> list[Limit]:
    """Pairs of pinned items of different groups closer than the gutter, closest first, at
    most ``LISTED``."""
    return [PinnedClash((a, b), gap) for a, b, gap in
            close_pairs(bodies, np.flatnonzero(pinned), roots, gutter_mm)]


def close_pairs(bodies: Bodies, rows: np.ndarray, roots: np.ndarray, gutter_mm: float,
                keep: Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray] | None = None
                ) -> list[tuple[int, int, float]]:
    """Pairs (a, b, clearance), a < b, of ``rows`` in different groups closer than the gutter
    and, if given, that ``keep`` (rows a, rows b, clearances -> bool mask) keeps: closest
    first, at most ``LISTED``.  Compared a block of rows at a time where the neighbour search
    would meet too many candidates, so that a file of thousands of items piled on one spot
    is measured in bounded memory."""
    centres, halves = bodies.centres[rows], bodies.sizes[rows] / 2
    if len(rows) < 2:
        return []
    if sweep_candidates(centres, halves, gutter_mm) <= SWEEP_BUDGET:
        # the physics' neighbour search: on a page of thousands of pinned items, a few
        # milliseconds where comparing every pair took 20 s
        i, j = candidate_pairs(bodies.centres, bodies.sizes / 2, rows, roots, gutter_mm)
        gaps = pair_clearances(bodies.centres, bodies.sizes / 2, i, j)
        close = gaps < gutter_mm - TOLERANCE_MM
        if keep is not None:
            close[close] = keep(i[close], j[close], gaps[close])
        i, j, gaps = np.minimum(i, j)[close], np.maximum(i, j)[close], gaps[close]
        order = np.lexsort((j, i, gaps))[:LISTED]
        return [(int(a), int(b), float(g)) for a, b, g in zip(i[order], j[order], gaps[order])]
    found: list[tuple[float, int, int]] = []
    for start in range(0, len(rows), CROSSING_BLOCK):  # a pile: a block of rows at a time
        block = np.arange(start, min(start + CROSSING_BLOCK, len(rows)))
        gaps = block_clearances(centres[block], halves[block], centres, halves)
        later = np.arange(len(rows))[None, :] > block[:, None]
        close = ((gaps < gutter_mm - TOLERANCE_MM) & later
                 & (roots[rows][block][:, None] != roots[rows][None, :]))
        x, y = np.nonzero(close)
        a, b, values = rows[block[x]], rows[y], gaps[x, y]
        if keep is not None:
            kept = keep(a, b, values)
            a, b, values = a[kept], b[kept], values[kept]
        if len(values) > LISTED:  # a pile: keep the closest, not millions of tuples
            part = np.argpartition(values, LISTED)[:LISTED]
            a, b, values = a[part], b[part], values[part]
        found = sorted(found + [(float(g), int(min(p, q)), int(max(p, q)))
                                for g, p, q in zip(values, a, b)])[:LISTED]
    return [(a, b, gap) for gap, a, b in sorted(found)[:LISTED]]


def block_clearances(centres_a: np.ndarray, halves_a: np.ndarray, centres_b: np.ndarray,
                     halves_b: np.ndarray) -> np.ndarray:
    """finalize.pair_clearances for every a (k rows) against every b (m rows), (k, m), in the
    same arithmetic, so that a pair gets the same clearance either way."""
    return (np.abs(centres_a[:, None] - centres_b[None]) - halves_a[:, None]
            - halves_b[None]).max(axis=2)


def _standing_outside(bodies: Bodies, pinned: np.ndarray, near: np.ndarray, far: np.ndarray,
                      page_w_mm: float, page_h_mm: float) -> list[Limit]:
    """Items that never move, standing outside their room: pinned ones past their walls (the
    margin, or a region), decorations past the page's edge (they keep no margin, but count as
    off the page)."""
    extent = np.array([page_w_mm, page_h_mm])
    low = bodies.centres - bodies.sizes / 2
    high = bodies.centres + bodies.sizes / 2
    past = np.maximum(-low, high - extent).max(axis=1).clip(0.0)
    into = np.maximum(near - low, high - (extent - far)).max(axis=1).clip(0.0)
    decoration = bodies.decorative
    into = np.where(decoration, past, into)
    rows = np.flatnonzero((pinned | decoration) & (into > TOLERANCE_MM))
    return [PinnedOutside(int(row), float(past[row]), float(into[row]), bool(decoration[row]))
            for row in rows]


def _too_large(bodies: Bodies, roots: np.ndarray, offsets: np.ndarray, pinned: np.ndarray,
               near: np.ndarray, far: np.ndarray, page_w_mm: float, page_h_mm: float
               ) -> list[Limit]:
    """Groups (and lone items) that no shift keeps inside their walls on an axis: the walls
    of every member count, as each keeps its own (a bleed member none, a confined one its
    region's)."""
    low, high = group_extents(bodies, roots, offsets)
    extent = np.array([page_w_mm, page_h_mm])
    member_low = offsets - bodies.sizes / 2  # each row's edges relative to its root's centre
    member_high = offsets + bodies.sizes / 2
    count = bodies.count
    # The shift of the root's centre each member's walls allow: from lowest to highest.
    lowest = np.full((count, 2), -np.inf)
    highest = np.full((count, 2), np.inf)
    active = bodies.active
    np.maximum.at(lowest, roots[active], near[active] - member_low[active])
    np.minimum.at(highest, roots[active], extent - far[active] - member_high[active])
    found: list[Limit] = []
    groups = np.flatnonzero(active & (roots == np.arange(count)) & ~pinned)
    for axis in (0, 1):
        short = groups[lowest[groups, axis] > highest[groups, axis] + TOLERANCE_MM]
        for root in short:
            members = np.flatnonzero(active & (roots == root))
            members = np.concatenate([[root], members[members != root]])
            size = float(high[root, axis] - low[root, axis])
            room = size - float(lowest[root, axis] - highest[root, axis])
            found.append(TooLarge(tuple(int(m) for m in members), axis, size, room,
                                  float(extent[axis])))
    return found


def _crossings(bodies: Bodies, roots: np.ndarray, pinned: np.ndarray, near: np.ndarray,
               far: np.ndarray, page_w_mm: float, page_h_mm: float, gutter_mm: float
               ) -> list[Limit]:
    """Pairs of items of different groups that cannot keep the gutter inside the room, at
    least one of them free (two pinned ones are clashes).  Such a pair holds an item wider
    than half the room less the gutter, so only those are compared with the rest."""
    extent = np.array([page_w_mm, page_h_mm])
    rows = np.flatnonzero(bodies.active)
    if len(rows) < 2:
        return []
    sizes = bodies.sizes[rows]
    low, high = near[rows], extent - far[rows]  # each item's walls, (m, 2)
    room = high - low
    # A pair needs an item wider than half its own room less the gutter (its span, below, is
    # at least the mean of the two rooms), so only those are compared with the rest.
    wide = np.flatnonzero(sizes[:, 0] > (room[:, 0] - gutter_mm) / 2)
    found: list[Limit] = []
    for start in range(0, len(wide), CROSSING_BLOCK):
        first = wide[start:start + CROSSING_BLOCK]
        shared = _spans(low[first], high[first], low, high)  # (k, m, 2)
        needs = sizes[first][:, None, :] + sizes[None, :, :]
        spare = (shared - needs).max(axis=2)  # the widest gap inside the margins
        spare_page = (extent - needs).max(axis=2)
        a, b = np.meshgrid(first, np.arange(len(rows)), indexing="ij")
        ra, rb = rows[a], rows[b]
        hit = ((spare < gutter_mm - TOLERANCE_MM) & (ra != rb) & (roots[ra] != roots[rb])
               & ~(pinned[ra] & pinned[rb])
               # a pair of two wide items is found from both: keep it once
               & ~((b < a) & np.isin(b, wide)))
        for k, m in zip(*np.nonzero(hit)):
            x, y = int(ra[k, m]), int(rb[k, m])
            found.append(Crossing((min(x, y), max(x, y)),
                                  tuple(float(v) + gutter_mm for v in needs[k, m]),
                                  tuple(float(v) for v in shared[k, m]),
                                  float(spare[k, m]), bool(spare_page[k, m] >= 0)))
    found.sort(key=lambda limit: limit.widest_gap_mm)
    return found


def _spans(low_a: np.ndarray, high_a: np.ndarray, low_b: np.ndarray, high_b: np.ndarray
           ) -> np.ndarray:
    """The room each pair (k of a by m of b) has to stand side by side in, along each axis,
    (k, m, 2): from the near wall of the one to the far wall of the other, in the better of
    the two orders.  Two items of one room have that room; two of different regions have the
    span the two regions cover together.  (Taken as the smaller of the two rooms, a calendar
    in a words region and a photo in the photos region above it "could not be parted" where
    the split between the regions parts them: fresh_projects seed 9.)"""
    return np.maximum(high_b[None, :, :] - low_a[:, None, :],
                      high_a[:, None, :] - low_b[None, :, :])


def _stacks(bodies: Bodies, roots: np.ndarray, offsets: np.ndarray, near: np.ndarray,
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
    """_stacks' search on one axis: the rows of the set, or None where none is too tall."""
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
    the wide ones with each narrow one that clashes with the widest (_stacks' and
    _pinned_stacks' candidates alike)."""
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


def _pinned_stacks(bodies: Bodies, roots: np.ndarray, offsets: np.ndarray,
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
    pinned_rows takes them), whatever their rooms: _pinned_stacks' mixed candidate takes
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


def _no_room(bodies: Bodies, pinned: np.ndarray, margin_mm: float, page_w_mm: float,
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
