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
  exact search of every way of placing each beside or above another); or a few free units
  (groups too) around items that cannot move, or in regions (physics.unit_arrangements: at
  most ten members), the same search with the pinned items as bounds.

A limit caps the gap of its own room only (``rooms_of``: each region, and the free items):
what the items of one region rule out says nothing of another's.

The area test (Engine.grown_cover) stays the reason for a crowd of small items.

A reason is true only for what it accounts for: ``unexplained_pairs`` lists the pairs closer
than the gutter that no limit here explains, and `check` sends those back to `settle`.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from floatpage.physics.bodies import Bodies
from floatpage.physics.fast_forces import candidate_pairs
from floatpage.physics.finalize import pair_clearances
from floatpage.physics.geometry import group_extents, group_room, pinned_items, rooms_of
from floatpage.physics.limit_kinds import (  # the records, for the modules that read them
    CROSSING_BLOCK, GAP_LIMITS, LISTED, TOLERANCE_MM, WIDEST_GAP_SLACK_MM, Crossing, Limit,
    NoArrangement, NoRoom, PinnedClash, PinnedOutside, PinnedStack, Stack, TooLarge,
    block_clearances,
)
from floatpage.physics.quality import sweep_candidates
from floatpage.physics.room_limits import no_arrangement, no_room, no_unit_arrangement
from floatpage.physics.stack_limits import pinned_stacks, stacks

SWEEP_BUDGET = 10_000_000  # neighbour-search candidates (about 300 MB) before blocks instead


def page_limits(bodies: Bodies, page_w_mm: float, page_h_mm: float, margin_mm: float,
                gutter_mm: float) -> list[Limit]:
    """Every reason on this page that no arrangement keeps its guarantees (see the module
    doc), most binding first within each kind.  Decorations take no part."""
    roots, offsets = bodies.group_roots()
    near, far = bodies.insets(margin_mm, page_w_mm, page_h_mm)
    pinned = pinned_items(bodies, roots)
    found: list[Limit] = []
    found += _pinned_clashes(bodies, roots, pinned, gutter_mm)
    found += _standing_outside(bodies, pinned, near, far, page_w_mm, page_h_mm)
    found += _too_large(bodies, roots, offsets, pinned, near, far, page_w_mm, page_h_mm)
    found += _crossings(bodies, roots, pinned, near, far, page_w_mm, page_h_mm, gutter_mm)
    found += stacks(bodies, roots, offsets, near, far, page_w_mm, page_h_mm, gutter_mm)
    found += no_room(bodies, pinned, margin_mm, page_w_mm, page_h_mm, gutter_mm)
    if pinned.any() or not np.isnan(bodies.regions[:, 0]).all():
        page_walls = bodies.insets(0.0, page_w_mm, page_h_mm)
        found += pinned_stacks(bodies, roots, offsets, pinned, (near, far), page_walls,
                               page_w_mm, page_h_mm, gutter_mm)
    found += no_arrangement(bodies, roots, pinned, near, far, page_w_mm, page_h_mm, gutter_mm,
                            widest_gap(found))
    if not any(isinstance(limit, (NoArrangement, TooLarge)) for limit in found):
        found += no_unit_arrangement(bodies, pinned, margin_mm, page_w_mm, page_h_mm,
                                     gutter_mm, widest_gap(found))
    return found


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
    pinned = pinned_items(bodies, roots)
    count = bodies.count
    named: list[int] = []  # pairs as a * count + b, a < b
    for limit in limits:
        if isinstance(limit, Crossing):
            named.append(limit.rows[0] * count + limit.rows[1])
        elif isinstance(limit, NoArrangement) and not limit.units:
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
    """Groups (and lone items) that no shift keeps inside their walls on an axis, by the rule
    the physics holds them to (geometry.group_room): the whole group inside its root's walls,
    a confined follower inside its region as well.  A confined photo whose caption follows it
    160 mm below can never sit in an 80 mm region, though the caption itself keeps no region:
    the physics holds the caption there with it."""
    low, high = group_extents(bodies, roots, offsets)
    lowest, highest = group_room(bodies, roots, offsets, near, far, page_w_mm, page_h_mm)
    extent = np.array([page_w_mm, page_h_mm])
    active = bodies.active
    found: list[Limit] = []
    groups = np.flatnonzero(active & (roots == np.arange(bodies.count)) & ~pinned)
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


def too_large(bodies: Bodies, page_w_mm: float, page_h_mm: float, margin_mm: float
              ) -> list[Limit]:
    """Only the groups too large for their walls (``TooLarge``), which `check` names even on a
    page that keeps every guarantee as written: the next settle would squeeze such a group
    (geometry.squeezed), so the file is not a layout settle keeps."""
    roots, offsets = bodies.group_roots()
    near, far = bodies.insets(margin_mm, page_w_mm, page_h_mm)
    return _too_large(bodies, roots, offsets, pinned_items(bodies, roots), near, far,
                      page_w_mm, page_h_mm)


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
