"""The last resort of the no-overlap pass on a page where the gutter fits but the pushes jam:
lift a jammed item out and set it down in room elsewhere on the page.

The projection (physics.finalize) only nudges: it parts each pair along the cheaper axis, so
the items of a row that is one gutter too long for the page push each other to and fro while
a third of the page stands empty beside them.  The packed second start (physics.packing)
rebuilds such a page, but only one of free items: with a hard anchor (an obstacle the rest
must flow around) or soft ones (whose springs pull their items back into the jam) the page kept
the widest gap the pushes reached, 0.3-1.8 mm, on random pages whose items, grown by the
gutter, needed 45-75 % of the room.

So here one item at a time, the lone free item in the most pairs closer than the gutter (the
smallest of those first), moves to the nearest place where it keeps the gutter from every
other item and its walls: a place beside another item's edge, or against a wall, on each axis
(the corners of the room left between items are where a rectangle fits if it fits anywhere
near).  A soft-anchored item goes to the place nearest its anchor.  Where no such place has
room for it, it goes where it crowds the others least, if less than where it is: the pushes
then part a few items where there is room to part them.  After each move the projection runs
again.  Items in a group, held or anchored hard stay where they are.

Where a few such moves do not free the page (the room it needs is spread in slivers between
items), every free item is set down anew (``placed_anew``), the largest first, each in the
free place nearest where it lay, around the items that stay: the gutter holds by
construction, and Engine then lets a gentle run spread the items from there.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from floatpage.physics.bodies import Bodies
from floatpage.physics.finalize import ROUNDING_MM, pair_clearances
from floatpage.physics.geometry import item_bounds

MAX_ITEMS = 150  # the search is O(n^3) in NumPy: 0.1 s a move at 150 items
PLACE_MAX_ITEMS = 60  # setting every item down anew is n searches: 0.3 s at 60 items
MAX_MOVES = 6  # items lifted out before the pass gives up and keeps the widest gap
MOVES_PER_ITEM = 2  # the pushes after a move may jam the same item again, once
TOLERANCE_MM = 1e-9


def relocate_jammed(bodies: Bodies, page_w_mm: float, page_h_mm: float, gutter_mm: float,
                    margin_mm: float, project: Callable[[], bool]) -> bool:
    """Move jammed items into room, running ``project`` (the no-overlap pass, True when it
    keeps the gutter) after each move; whether the page keeps the gutter in the end.  Leaves
    the page as the last attempt left it: the caller restores what it had if this fails."""
    clearance = gutter_mm + 2 * ROUNDING_MM
    lowest, highest = item_bounds(bodies, page_w_mm, page_h_mm, margin_mm)
    movable = _movable(bodies)
    moves = np.zeros(bodies.count, int)
    for _ in range(MAX_MOVES):
        for row in jammed_rows(bodies, clearance, movable):
            if moves[row] >= MOVES_PER_ITEM:
                continue
            moves[row] += 1
            spot = room_for(bodies, row, clearance, lowest[row], highest[row])
            if spot is not None:
                bodies.centres[row] = spot
                bodies.velocities[row] = 0.0
                break
        else:
            return False
        if project():
            return True
    return False


def jammed_rows(bodies: Bodies, clearance: float, movable: np.ndarray) -> list[int]:
    """Movable rows in pairs closer than ``clearance``: the most such pairs first, then the
    smallest item (the easiest to set down elsewhere)."""
    rows = np.flatnonzero(bodies.active)
    i, j = np.triu_indices(len(rows), 1)
    i, j = rows[i], rows[j]
    close = pair_clearances(bodies.centres, bodies.sizes / 2, i, j) < clearance - ROUNDING_MM
    counts = np.bincount(np.concatenate([i[close], j[close]]), minlength=bodies.count)
    jammed = np.flatnonzero((counts > 0) & movable)
    areas = bodies.sizes[jammed, 0] * bodies.sizes[jammed, 1]
    return [int(row) for row in jammed[np.lexsort((jammed, areas, -counts[jammed]))]]


def placed_anew(bodies: Bodies, page_w_mm: float, page_h_mm: float, gutter_mm: float,
                margin_mm: float) -> np.ndarray | None:
    """Centres (n, 2) for a page the moves above could not free: the items that do not move
    stay, and the free lone items are set down anew one by one, the largest first, each in
    the place nearest its anchor (or where it lay) that keeps the gutter from every item set
    down before it.  The gutter holds by construction, around hard anchors too, where the
    packed second start (physics.packing) knows no obstacles; None if an item finds no room.
    Deterministic: the same page gives the same centres."""
    if int(bodies.active.sum()) > PLACE_MAX_ITEMS:
        return None
    for into_corner in (False, True):
        centres = _placed_anew(bodies, page_w_mm, page_h_mm, gutter_mm, margin_mm, into_corner)
        if centres is not None:
            return centres
    return None


def _placed_anew(bodies: Bodies, page_w_mm: float, page_h_mm: float, gutter_mm: float,
                 margin_mm: float, into_corner: bool) -> np.ndarray | None:
    """placed_anew's one try: each item nearest where it was, or (``into_corner``) nearest
    the room's top left corner, as a printer fills a sheet, where the first try left an item
    without room."""
    clearance = gutter_mm + 2 * ROUNDING_MM
    lowest, highest = item_bounds(bodies, page_w_mm, page_h_mm, margin_mm)
    movable = _movable(bodies)
    placed = bodies.active & ~movable
    centres = bodies.centres.copy()
    work = Bodies(centres=centres, sizes=bodies.sizes, anchors=bodies.anchors,
                  decorative=~placed)
    rows = np.flatnonzero(movable)
    areas = bodies.sizes[rows, 0] * bodies.sizes[rows, 1]
    for row in rows[np.lexsort((rows, -areas))]:
        work.decorative = ~placed  # what is not yet set down takes no room
        work.decorative[row] = False
        spot = room_for(work, int(row), clearance, lowest[row], highest[row], clear_only=True,
                        goal=lowest[row] if into_corner else None)
        if spot is None:
            return None
        centres[row] = spot
        placed[row] = True
    return centres


def _movable(bodies: Bodies) -> np.ndarray:
    """Free lone items: not held, anchored hard, following or followed."""
    movable = bodies.free & bodies.active
    movable[bodies.targets[bodies.followers]] = False
    return movable


def room_for(bodies: Bodies, row: int, clearance: float, lowest: np.ndarray,
             highest: np.ndarray, clear_only: bool = False,
             goal: np.ndarray | None = None) -> np.ndarray | None:
    """Where the row should go: a centre within ``lowest``-``highest`` at which it keeps
    ``clearance`` from every other active item, the one nearest its anchor (or where it is);
    where no place tried has such room, the place where it crowds the others least (the area
    by which it, grown by the clearance, covers them), if that is less than where it is: the
    pass then has less to part, and room to part it (not if ``clear_only``).  None if there
    is no such place."""
    if (lowest > highest + TOLERANCE_MM).any():
        return None
    others = np.flatnonzero(bodies.active)
    others = others[others != row]
    centres, sizes = bodies.centres[others], bodies.sizes[others]
    reach = (sizes + bodies.sizes[row]) / 2 + clearance  # centre distance that clears a pair
    if goal is None:
        anchor = bodies.anchors[row]
        goal = anchor if not np.isnan(anchor).any() else bodies.centres[row]
    spots = []
    for axis in (0, 1):
        line = np.concatenate([centres[:, axis] - reach[:, axis],
                               centres[:, axis] + reach[:, axis],
                               [lowest[axis], highest[axis], goal[axis]]])
        inside = (line >= lowest[axis] - TOLERANCE_MM) & (line <= highest[axis] + TOLERANCE_MM)
        spots.append(np.unique(np.clip(line[inside], lowest[axis], highest[axis])))
    xs, ys = spots
    now = crowding(bodies.centres[row][None, :], centres, reach)[0]
    best, best_key = None, None
    depth_y = np.clip(reach[None, :, 1] - np.abs(ys[:, None] - centres[None, :, 1]), 0.0, None)
    for x in xs:
        depth_x = np.clip(reach[:, 0] - np.abs(x - centres[:, 0]), 0.0, None)  # (others,)
        crowd = (depth_y * depth_x[None, :]).sum(axis=1)  # (ys,)
        distance = (x - goal[0]) ** 2 + (ys - goal[1]) ** 2
        k = int(np.lexsort((distance, crowd))[0])
        key = (float(crowd[k]), float(distance[k]))
        if clear_only and key[0] > TOLERANCE_MM:
            continue
        if (clear_only or key[0] < now - TOLERANCE_MM) and (best_key is None or key < best_key):
            best, best_key = np.array([x, ys[k]]), key
    return best


def crowding(spots: np.ndarray, centres: np.ndarray, reach: np.ndarray) -> np.ndarray:
    """For each spot (m, 2), the area by which an item there, grown by the clearance, covers
    the others (their centres, and the centre distances that clear each pair)."""
    depth = np.clip(reach[None] - np.abs(spots[:, None, :] - centres[None]), 0.0, None)
    return (depth[:, :, 0] * depth[:, :, 1]).sum(axis=1)
