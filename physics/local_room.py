"""Room found near each item, for a crowd too large for relocation (physics.relocation takes
at most ``MAX_ITEMS``): every unit that still overlaps another after the no-overlap pass, or
stands in its margin because the pass gave the margin up, is set down at the nearest place
around it where it touches nothing, inside its walls.

The no-overlap pass is a Jacobi projection: in a crowd of thousands it parts nearly every pair
and then stalls on a few knots, where neighbours only undo each other's moves (10,000 items
on half of A4: 25 pairs left at the margin, 7 once the margin was dropped), although the page
is half empty.  relocation.room_for finds the place exactly but compares the unit with every
other item, so it is asked about a window around the unit only: the items whose rectangles
reach into the room the unit could take there.  No item outside the window can touch a unit
placed inside it, so a place found is clear of the whole page.  Windows grow until one has
room.
"""

from __future__ import annotations

import numpy as np

from floatpage.physics.bodies import Bodies
from floatpage.physics.fast_forces import candidate_pairs
from floatpage.physics.finalize import ROUNDING_MM, pair_clearances
from floatpage.physics.geometry import RELOCATABLE_ITEMS
from floatpage.physics.relocation import Unit, movable_units, room_for, unit_bounds

# How far around a unit to look, in turn, in units of its larger side: a small item finds
# room among a few neighbours; a window grows until it holds room or too many items
WINDOWS = (0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0)
MAX_UNITS = 5_000  # units set down at most: a knot is a few dozen; this bounds a hostile file
# A window holding more items than relocation takes is not searched (nor any larger one):
# room_for's cost grows with the cube of the items it compares, and 10,000 items on 70 % of A4
# put thousands in a 48 mm window.
MAX_NEARBY = RELOCATABLE_ITEMS


def clear_locally(bodies: Bodies, page_w_mm: float, page_h_mm: float,
                  margin_mm: float) -> int:
    """Set down each unit that overlaps another or stands past its walls at ``margin_mm`` at
    the nearest clear place within a window around it (see the module doc), the smallest
    first: a small item finds room most easily, and once it has moved its partner in the
    knot is free too.  Returns how many units moved."""
    units = movable_units(bodies)
    if not units:
        return 0
    lowest, highest = unit_bounds(bodies, units, page_w_mm, page_h_mm, margin_mm)
    clearance = 2 * ROUNDING_MM  # no overlap, kept through a save's rounding
    offenders = _offenders(bodies, units, lowest, highest, clearance)
    areas = np.array([float(np.prod(bodies.sizes[units[k].members], axis=1).sum())
                      for k in offenders])
    moved = 0
    for k in offenders[np.argsort(areas, kind="stable")][:MAX_UNITS]:
        unit = units[k]
        if not _still_offends(bodies, unit, lowest[k], highest[k], clearance):
            continue  # an earlier move freed it
        low, high = _extent(bodies, unit)
        side = float((high - low).max())
        for window in WINDOWS:
            spot = _room_near(bodies, unit, lowest[k], highest[k], clearance, window * side)
            if spot is _CROWDED:
                break
            if spot is not None:
                unit.place(bodies.centres, spot)
                bodies.velocities[unit.carried] = 0.0
                moved += 1
                break
    return moved


def _offenders(bodies: Bodies, units: list[Unit], lowest: np.ndarray, highest: np.ndarray,
               clearance: float) -> np.ndarray:
    """Indices into ``units`` of those in a pair closer than ``clearance`` (the neighbour
    search, not every pair) or whose root stands past its bounds."""
    roots, _ = bodies.group_roots()
    rows = np.flatnonzero(bodies.active)
    i, j = candidate_pairs(bodies.centres, bodies.sizes / 2, rows, roots, clearance)
    close = pair_clearances(bodies.centres, bodies.sizes / 2, i, j) < clearance - ROUNDING_MM
    touched = np.zeros(bodies.count, dtype=bool)
    touched[roots[i[close]]] = True
    touched[roots[j[close]]] = True
    unit_roots = np.array([unit.root for unit in units])
    outside = _past(bodies.centres[unit_roots], lowest, highest).any(axis=-1)
    return np.flatnonzero(touched[unit_roots] | outside)


def _past(centres: np.ndarray, lowest: np.ndarray, highest: np.ndarray) -> np.ndarray:
    """Where root centres stand past their bounds, beyond a save's rounding, per axis."""
    return (centres < lowest - ROUNDING_MM) | (centres > highest + ROUNDING_MM)


def _extent(bodies: Bodies, unit: Unit) -> tuple[np.ndarray, np.ndarray]:
    """The unit's members' lowest and highest edges from its root's centre, (2,) each."""
    halves = bodies.sizes[unit.members] / 2
    return (unit.offsets - halves).min(axis=0), (unit.offsets + halves).max(axis=0)


def _still_offends(bodies: Bodies, unit: Unit, lowest: np.ndarray, highest: np.ndarray,
                   clearance: float) -> bool:
    centre = bodies.centres[unit.root]
    if _past(centre, lowest, highest).any():
        return True
    nearby = _within(bodies, unit, centre, centre, clearance)
    if not len(nearby):
        return False
    members = np.repeat(unit.members, len(nearby))
    others = np.tile(nearby, len(unit.members))
    gaps = pair_clearances(bodies.centres, bodies.sizes / 2, members, others)
    return bool((gaps < clearance - ROUNDING_MM).any())


_CROWDED = np.full(2, np.nan)  # _room_near's answer for a window too full to search


def _room_near(bodies: Bodies, unit: Unit, lowest: np.ndarray, highest: np.ndarray,
               clearance: float, window_mm: float) -> np.ndarray | None:
    """The nearest clear place for the unit's root within ``window_mm`` of where it stands
    (and inside its bounds), found among the items that reach into that room only; None
    where there is none, ``_CROWDED`` where the window holds more than MAX_NEARBY items."""
    centre = bodies.centres[unit.root]
    low = np.maximum(lowest, centre - window_mm)
    high = np.minimum(highest, centre + window_mm)
    if (low > high).any():
        return None
    nearby = _within(bodies, unit, low, high, clearance)
    if len(nearby) > MAX_NEARBY:
        return _CROWDED
    alone = np.ones(bodies.count, dtype=bool)  # all but the unit and its neighbours left out
    alone[nearby] = False
    alone[unit.members] = False
    work = Bodies(centres=bodies.centres, sizes=bodies.sizes, anchors=bodies.anchors,
                  decorative=alone)
    return room_for(work, unit, clearance, low, high, clear_only=True,
                    goal=centre.copy())


def _within(bodies: Bodies, unit: Unit, low: np.ndarray, high: np.ndarray,
            clearance: float) -> np.ndarray:
    """Active rows, not the unit's, whose rectangles come within ``clearance`` of the room
    the unit's members take with its root anywhere from ``low`` to ``high``."""
    extent_low, extent_high = _extent(bodies, unit)
    reach_low = low + extent_low - clearance
    reach_high = high + extent_high + clearance
    their_low = bodies.centres - bodies.sizes / 2
    their_high = bodies.centres + bodies.sizes / 2
    near = bodies.active & ((their_high > reach_low) & (their_low < reach_high)).all(axis=1)
    near[unit.members] = False
    return np.flatnonzero(near)
