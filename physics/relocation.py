"""The last resort of the no-overlap pass on a page where the gutter fits but the pushes jam:
lift a jammed item out and set it down in room elsewhere on the page.

The projection (physics.finalize) only nudges: it parts each pair along the cheaper axis, so
the items of a row that is one gutter too long for the page push each other to and fro while
a third of the page stands empty beside them.  The packed second start (physics.packing)
rebuilds such a page, but only one of free items: with a hard anchor (an obstacle the rest
must flow around) or soft ones (whose springs pull their items back into the jam) the page kept
the widest gap the pushes reached, 0.3-1.8 mm, on random pages whose items, grown by the
gutter, needed 45-75 % of the room.

So here one *unit* at a time moves: a free item, or a free item with the items that follow
it, moved as one rigid group (a photo and its caption; a group jammed against a hard anchor
overlapped it by 14 mm on a random page, where no lone item's move could help).  The unit in
the most pairs closer than the gutter (the smallest of those first) moves to the nearest place
where each of its members keeps the gutter from every other item and its walls: a place where
a member stands beside another item's edge, or against a wall, on each axis (the corners of
the room left between items are where a rectangle fits if it fits anywhere near).  A
soft-anchored unit goes to the place nearest its anchor.  Where no such place has room for
it, it goes where it crowds the others least, if less than where it is: the pushes then part
a few items where there is room to part them.  After each move the projection runs again.
Held items, hard anchors and the groups that hold one stay where they are.

Where a few such moves do not free the page (the room it needs is spread in slivers between
items), every unit is set down anew (``placed_anew``), the largest first, each in the
free place nearest where it lay (or, where that leaves one without room, nearest a corner,
in a few orders, and with the unit left without room set down first), around the items that
stay: the gutter holds by construction, and Engine then lets a gentle run spread the items
from there.  Engine also aims this at a narrower gap: the widest a page's own items leave
(physics.page_limits.widest_gap), or none on a page too full for the gutter.
"""

from __future__ import annotations

from typing import Callable, NamedTuple

import numpy as np

from floatpage.physics.bodies import Bodies
from floatpage.physics.finalize import ROUNDING_MM, pair_clearances
from floatpage.physics.geometry import RELOCATABLE_ITEMS, group_bounds

# A search is one (2n x n) by (n x 2n) product, about 1 ms at 150 items; setting every item
# down anew is n searches, 0.2 s of CPU at 150 items.
MAX_ITEMS = RELOCATABLE_ITEMS
MAX_MOVES = 6  # units lifted out before the pass gives up and keeps the widest gap
MOVES_PER_ITEM = 2  # the pushes after a move may jam the same unit again, once
TOLERANCE_MM = 1e-9
# room_for's matrix product is taken this many rows at a time: the whole one (300 x 150 x 300
# on a page of 150 items) went to OpenBLAS's threads, which spun on the shared two-core
# machine, 5x the CPU time of the same product in small blocks that one thread computes.
PRODUCT_ROWS = 8


class Unit(NamedTuple):
    """What moves as one: a free item and the items that follow it (directly or down a
    chain).  ``members`` are the rows that take room, the root first; ``offsets`` (m, 2) their
    centres from the root's; ``carried`` every row set from the root, decorations too."""
    root: int
    members: np.ndarray
    offsets: np.ndarray
    carried: np.ndarray
    carried_offsets: np.ndarray

    @classmethod
    def lone(cls, row: int) -> "Unit":
        rows, none = np.array([row]), np.zeros((1, 2))
        return cls(row, rows, none, rows, none)

    def place(self, centres: np.ndarray, spot: np.ndarray) -> None:
        centres[self.carried] = spot + self.carried_offsets


def movable_units(bodies: Bodies) -> list[Unit]:
    """Every unit that may move, by root: free roots whose group holds no held item or hard
    anchor (those never move, and a group moves whole)."""
    roots, offsets = bodies.group_roots()
    active = bodies.active
    pinned = np.zeros(bodies.count, dtype=bool)
    np.logical_or.at(pinned, roots, bodies.hard | bodies.held)
    order = np.argsort(roots, kind="stable")
    starts = np.searchsorted(roots[order], np.arange(bodies.count + 1))
    units = []
    for root in np.flatnonzero(bodies.free & active & ~pinned):
        carried = order[starts[root]:starts[root + 1]]
        carried = np.concatenate([[root], carried[carried != root]])
        members = carried[active[carried]]
        units.append(Unit(int(root), members, offsets[members], carried, offsets[carried]))
    return units


def unit_bounds(bodies: Bodies, units: list[Unit], page_w_mm: float, page_h_mm: float,
                margin_mm: float) -> tuple[np.ndarray, np.ndarray]:
    """Lowest and highest root centre, (len(units), 2) each, that keeps each unit inside its
    members' walls (geometry.group_bounds)."""
    roots, offsets = bodies.group_roots()
    near, far = bodies.insets(margin_mm, page_w_mm, page_h_mm)
    rows = np.array([unit.root for unit in units], dtype=int)
    return group_bounds(bodies, rows, roots, offsets, near, far, page_w_mm, page_h_mm)


def relocate_jammed(bodies: Bodies, page_w_mm: float, page_h_mm: float, gutter_mm: float,
                    margin_mm: float, project: Callable[[], bool]) -> bool:
    """Move jammed units into room, running ``project`` (the no-overlap pass, True when it
    keeps the gutter) after each move; whether the page keeps the gutter in the end.  Leaves
    the page as the last attempt left it: the caller restores what it had if this fails."""
    clearance = gutter_mm + 2 * ROUNDING_MM
    units = movable_units(bodies)
    if not units:
        return False
    lowest, highest = unit_bounds(bodies, units, page_w_mm, page_h_mm, margin_mm)
    moves = np.zeros(len(units), int)
    for _ in range(MAX_MOVES):
        for k in jammed_units(bodies, clearance, units):
            if moves[k] >= MOVES_PER_ITEM:
                continue
            moves[k] += 1
            spot = room_for(bodies, units[k], clearance, lowest[k], highest[k])
            if spot is not None:
                units[k].place(bodies.centres, spot)
                bodies.velocities[units[k].carried] = 0.0
                break
        else:
            return False
        if project():
            return True
    return False


def jammed_units(bodies: Bodies, clearance: float, units: list[Unit]) -> list[int]:
    """Indices into ``units`` of those in pairs closer than ``clearance``: the most such
    pairs first, then the smallest (the easiest to set down elsewhere)."""
    rows = np.flatnonzero(bodies.active)
    i, j = np.triu_indices(len(rows), 1)
    i, j = rows[i], rows[j]
    roots, _ = bodies.group_roots()
    close = pair_clearances(bodies.centres, bodies.sizes / 2, i, j) < clearance - ROUNDING_MM
    close &= roots[i] != roots[j]  # a group's own members keep their offsets
    counts = np.bincount(np.concatenate([i[close], j[close]]), minlength=bodies.count)
    areas = bodies.sizes[:, 0] * bodies.sizes[:, 1]
    unit_counts = np.array([counts[unit.members].sum() for unit in units])
    unit_areas = np.array([areas[unit.members].sum() for unit in units])
    unit_roots = np.array([unit.root for unit in units])
    jammed = np.flatnonzero(unit_counts > 0)
    order = np.lexsort((unit_roots[jammed], unit_areas[jammed], -unit_counts[jammed]))
    return [int(k) for k in jammed[order]]


# placed_anew's tries, in turn until one sets every unit down: the order units go in (the
# largest area first, or the longest side first), and where each goes (nearest where it lay
# or its anchor, or nearest a corner of its room, as a printer fills a sheet).  The first is
# the page as it was, moved least; the corners pack tighter where it left a unit no room.
PLACEMENT_TRIES = (("area", "own"), ("area", (0, 0)), ("side", (0, 0)), ("area", (1, 0)),
                   ("area", (0, 1)), ("area", (1, 1)), ("side", (1, 1)))
# A try that leaves a unit without room is tried again with that unit set down first, this
# many times, before the next try: the units set down before it took the room only it needs
# (random page 7054: a photo and its caption, 147 mm wide together, fit only across the page
# above a hard anchor, where a tall pair of items set down first, being larger, had stood).
# Twice was too few: eight units around a hard anchor kept 2.9 mm of a 4 mm gutter that a
# third promotion keeps (fresh_projects seed 50, tests/cli/fresh_projects/gutter-promotions-50).
PROMOTIONS = 8
# After those, this many orders drawn at random (a fixed seed: the same page gives the same
# centres), each nearest a corner or where the units lay in turn.  A largest-first order is a
# good guess, not a search: six photos, groups and a block around two hard-anchored texts in
# a photos region (fresh_projects seed 9, tests/cli/fresh_projects/limit-margin-rows-9) kept
# overlaps of 12 mm where an order drawn at random sets every unit down with the margin given
# up (17 of the 3,600 orders and goals do).  A try that fails costs about a
# millisecond at ten units.
RANDOM_TRIES = 16
RANDOM_TRIES_UNITS = 24  # at most this many units: a try on 150 costs a fifth of a second
RANDOM_GOALS = ((0, 0), (1, 0), (0, 1), (1, 1), "own")


def placed_anew(bodies: Bodies, page_w_mm: float, page_h_mm: float, gutter_mm: float,
                margin_mm: float) -> np.ndarray | None:
    """Centres (n, 2) for a page the moves above could not free: the items that do not move
    stay, and the units are set down anew one by one (PLACEMENT_TRIES, PROMOTIONS), each in
    the place nearest its goal that keeps the gutter from every item set down before it.  The
    gutter holds by construction, around hard anchors too, where the packed second start
    (physics.packing) knows no obstacles; None if every try left a unit without room.
    Deterministic: the same page gives the same centres."""
    if int(bodies.active.sum()) > MAX_ITEMS:
        return None
    units = movable_units(bodies)
    if not units:
        return None
    lowest, highest = unit_bounds(bodies, units, page_w_mm, page_h_mm, margin_mm)
    roots = np.array([unit.root for unit in units])
    tries = [([int(k) for k in np.lexsort((roots, -_unit_sizes(bodies, units, order)))], goal)
             for order, goal in PLACEMENT_TRIES]
    if len(units) <= RANDOM_TRIES_UNITS:
        rng = np.random.default_rng(len(units))
        tries += [([int(k) for k in rng.permutation(len(units))],
                   RANDOM_GOALS[index % len(RANDOM_GOALS)]) for index in range(RANDOM_TRIES)]
    for sequence, goal in tries:
        for _ in range(PROMOTIONS + 1):
            centres = _placed_anew(bodies, units, lowest, highest, gutter_mm, sequence, goal)
            if isinstance(centres, np.ndarray):
                return centres
            sequence.remove(centres)  # the unit left without room goes first (PROMOTIONS)
            sequence.insert(0, centres)
    return None


def _placed_anew(bodies: Bodies, units: list[Unit], lowest: np.ndarray, highest: np.ndarray,
                 gutter_mm: float, sequence: list[int], goal) -> np.ndarray | int:
    """placed_anew's one try (see PLACEMENT_TRIES): the units set down in ``sequence`` (indices
    into ``units``), each nearest ``goal``: "own", or a corner of the room as (0 left / 1
    right, 0 top / 1 bottom).  The centres, or the index of the first unit left without
    room."""
    clearance = gutter_mm + 2 * ROUNDING_MM
    placed = bodies.active.copy()
    for unit in units:
        placed[unit.members] = False
    centres = bodies.centres.copy()
    work = Bodies(centres=centres, sizes=bodies.sizes, anchors=bodies.anchors,
                  decorative=~placed)
    for k in sequence:
        unit = units[k]
        work.decorative = ~placed  # what is not yet set down takes no room
        work.decorative[unit.members] = False
        corner = None if goal == "own" else np.where(goal, highest[k], lowest[k])
        spot = room_for(work, unit, clearance, lowest[k], highest[k], clear_only=True,
                        goal=corner)
        if spot is None:
            return k
        unit.place(centres, spot)
        placed[unit.members] = True
    return centres


def _unit_sizes(bodies: Bodies, units: list[Unit], order: str) -> np.ndarray:
    """How large each unit is for placed_anew's order: its members' area, or the longest
    side of the box around them."""
    if order == "area":
        return np.array([(bodies.sizes[unit.members, 0] * bodies.sizes[unit.members, 1]).sum()
                         for unit in units])
    halves = bodies.sizes / 2
    return np.array([((unit.offsets + halves[unit.members]).max(axis=0)
                      - (unit.offsets - halves[unit.members]).min(axis=0)).max()
                     for unit in units])


def room_for(bodies: Bodies, unit: Unit, clearance: float, lowest: np.ndarray,
             highest: np.ndarray, clear_only: bool = False,
             goal: np.ndarray | None = None) -> np.ndarray | None:
    """Where the unit's root should go: a centre within ``lowest``-``highest`` at which each
    member keeps ``clearance`` from every other active item, the one nearest the root's
    anchor (or where it is); where no place tried has such room, the place where it crowds
    the others least (the area by which its members, grown by the clearance, cover them), if
    that is less than where it is: the pass then has less to part, and room to part it (not
    if ``clear_only``).  None if there is no such place."""
    if (lowest > highest + TOLERANCE_MM).any():
        return None
    row, offsets = unit.root, unit.offsets
    others = np.flatnonzero(bodies.active)
    others = others[~np.isin(others, unit.members)]
    centres, sizes = bodies.centres[others], bodies.sizes[others]
    # centre distance that clears each member (m) from each other item (o): (m, o, 2)
    reach = (sizes[None] + bodies.sizes[unit.members][:, None]) / 2 + clearance
    if goal is None:
        anchor = bodies.anchors[row]
        goal = anchor if not np.isnan(anchor).any() else bodies.centres[row]
    # where each other item sits as seen from the root: (m, o, 2)
    seen = centres[None] - offsets[:, None]
    spots = []
    for axis in (0, 1):
        line = np.concatenate([(seen[..., axis] - reach[..., axis]).ravel(),
                               (seen[..., axis] + reach[..., axis]).ravel(),
                               [lowest[axis], highest[axis], goal[axis]]])
        inside = (line >= lowest[axis] - TOLERANCE_MM) & (line <= highest[axis] + TOLERANCE_MM)
        spots.append(np.unique(np.clip(line[inside], lowest[axis], highest[axis])))
    xs, ys = spots
    now = crowding(bodies.centres[row][None, :], seen, reach)[0]
    # The area each spot's members cover the others by, every spot at once: the overlap of
    # two rectangles is the product of their overlaps on each axis, so the sum over the pairs
    # is a matrix product, (xs, pairs) by (pairs, ys).
    depth_x = np.clip(reach[..., 0].ravel() - np.abs(xs[:, None] - seen[..., 0].ravel()), 0.0,
                      None)
    depth_y = np.clip(reach[..., 1].ravel() - np.abs(ys[:, None] - seen[..., 1].ravel()), 0.0,
                      None)
    crowd = np.concatenate([depth_x[start:start + PRODUCT_ROWS] @ depth_y.T
                            for start in range(0, len(xs), PRODUCT_ROWS)]).ravel()  # x by x
    distance = ((xs[:, None] - goal[0]) ** 2 + (ys[None, :] - goal[1]) ** 2).ravel()
    least = np.flatnonzero(crowd == crowd.min())
    best = int(least[np.argmin(distance[least])])  # the least crowded, then the nearest
    if crowd[best] > (TOLERANCE_MM if clear_only else now - TOLERANCE_MM):
        return None
    return np.array([xs[best // len(ys)], ys[best % len(ys)]])


def crowding(spots: np.ndarray, seen: np.ndarray, reach: np.ndarray) -> np.ndarray:
    """For each root spot (k, 2), the area by which the unit's members there, grown by the
    clearance, cover the others: ``seen`` (m, o, 2) is where each other item sits from the
    root for each member, ``reach`` (m, o, 2) the centre distances that clear each pair."""
    depth = np.clip(reach[None] - np.abs(spots[:, None, None, :] - seen[None]), 0.0, None)
    return (depth[..., 0] * depth[..., 1]).sum(axis=(1, 2))
