"""The exact search of physics.unit_arrangements, asked of a few units around a page's closest
pair, each kept inside a window around where they stand, with every other item an obstacle
where it stands.

Relocation sets the whole page's units down by that search where they are few enough
(MAX_MEMBERS), and each room's where the room's are (RoomRelocation._arrange_rooms).  A page
whose rooms are each too many is left with what the pushes reached: on fresh_projects seed
9630, p2 (Letter, seventeen items, a region of eleven), two photos 0.1 mm apart and a
calendar 0.1 mm from a block, where its items grown by the 2 mm gutter need well under
the room.  The pair is taken with the units nearest it, up to NEAR_MEMBERS members, and
what lies outside their window cannot reach them, so the search stays small; any layout it
finds keeps every pair the units are not in as it was, and those they are in at least the
gap it finds, so setting them down where that beats their closest pair is sound.
"""

from __future__ import annotations

import numpy as np

from floatpage.physics.unit_arrangements import MAX_OBSTACLES, Search, Units

NEAR_MEMBERS = 8  # members of the units searched around a pair, at most
WINDOW_TRIES = 3  # the window's growth halved, each time too many obstacles lie inside it


def near_search(bodies, units: list, pair: tuple[int, int], margin_mm: float,
                page_w_mm: float, page_h_mm: float, gutter_mm: float) -> Search | None:
    """The search of the units (relocation.Unit, of movable_units) holding ``pair``'s rows
    and those nearest them, up to NEAR_MEMBERS members, each inside a window (the box around
    their members grown by half the largest member's side), with every other item near the
    window an obstacle; None where a unit of the pair is too large for it or no window holds
    MAX_OBSTACLES obstacles or fewer."""
    from floatpage.physics.relocation import unit_bounds  # relocation imports this module's users
    owner_of = {int(row): k for k, unit in enumerate(units) for row in unit.members}
    chosen = sorted({owner_of[row] for row in pair if row in owner_of})
    if not chosen:
        return None
    halves = bodies.sizes / 2

    def members(ks: list[int]) -> np.ndarray:
        return np.concatenate([units[k].members for k in ks])
    if len(members(chosen)) > NEAR_MEMBERS:
        return None
    box_low = (bodies.centres[members(chosen)] - halves[members(chosen)]).min(axis=0)
    box_high = (bodies.centres[members(chosen)] + halves[members(chosen)]).max(axis=0)
    # the units nearest the pair's box, while the members stay few
    nearest = np.argsort(_distance(bodies, units, box_low, box_high), kind="stable")
    for k in nearest:
        k = int(k)
        if k in chosen:
            continue
        if len(members(chosen)) + len(units[k].members) > NEAR_MEMBERS:
            break
        chosen.append(k)
    chosen.sort()
    rows = members(chosen)
    box_low = (bodies.centres[rows] - halves[rows]).min(axis=0)
    box_high = (bodies.centres[rows] + halves[rows]).max(axis=0)
    picked = [units[k] for k in chosen]
    lowest, highest = unit_bounds(bodies, picked, page_w_mm, page_h_mm, margin_mm)
    page_lowest, page_highest = unit_bounds(bodies, picked, page_w_mm, page_h_mm, 0.0)
    owner = np.concatenate([np.full(len(unit.members), k) for k, unit in enumerate(picked)])
    offsets = np.concatenate([unit.offsets for unit in picked])
    member_halves = halves[rows]
    others = bodies.active.copy()
    others[rows] = False
    others = np.flatnonzero(others)
    grow = member_halves.max(axis=0)
    for _ in range(WINDOW_TRIES):
        win_low = np.maximum(box_low - grow, 0.0)
        win_high = np.minimum(box_high + grow, [page_w_mm, page_h_mm])
        # each root where every member of its unit stays inside the window
        inside_low = np.full((len(picked), 2), -np.inf)
        inside_high = np.full((len(picked), 2), np.inf)
        np.maximum.at(inside_low, owner, win_low - offsets + member_halves)
        np.minimum.at(inside_high, owner, win_high - offsets - member_halves)
        near = ((bodies.centres[others] + halves[others] > win_low - gutter_mm)
                & (bodies.centres[others] - halves[others] < win_high + gutter_mm)).all(axis=1)
        obstacles = others[near]
        if len(obstacles) <= MAX_OBSTACLES:
            break
        grow = grow / 2
    else:
        return None
    walls = Units(owner, offsets, member_halves, np.maximum(lowest, inside_low),
                  np.minimum(highest, inside_high))
    page_walls = Units(owner, offsets, member_halves, np.maximum(page_lowest, inside_low),
                       np.minimum(page_highest, inside_high))
    return Search(picked, walls, page_walls, rows, obstacles)


def _distance(bodies, units: list, low: np.ndarray, high: np.ndarray) -> np.ndarray:
    """How far each unit's nearest member stands from the box ``low``-``high``, (u,): the
    larger of the two axes' gaps (negative where it reaches into the box)."""
    halves = bodies.sizes / 2
    found = np.empty(len(units))
    for k, unit in enumerate(units):
        centres, member_halves = bodies.centres[unit.members], halves[unit.members]
        gaps = np.maximum(low - (centres + member_halves), (centres - member_halves) - high)
        found[k] = gaps.max(axis=1).min()
    return found
