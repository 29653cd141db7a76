"""The widest gap one choice of relations keeps: with each pair of a layout held to the side it
stands on (this unit left of that one, that member below the pinned photo), how far apart can
every pair stand?  Without a search.

physics.unit_arrangements decides whether *some* choice of relations keeps a gap, a search
exponential in the pairs; near the widest gap each answer costs tens of thousands of steps, and
a bisection asked eight of them (3 s of CPU to check a 5 x 7 in card).  Once a layout is found,
though, the choice it makes fixes a linear problem: per axis, difference constraints
``x_v - x_u >= c + gap`` between units, bounds ``x_u >= a + gap`` or ``x_u <= b - gap`` beside
pinned items, and each unit's walls.  Whether they hold for a gap is a longest-path question
(Bellman-Ford: a cycle that pushes a unit past itself, or a chain past a wall, rules it out),
and it is monotone in the gap, so a bisection of cheap tests finds the widest gap that choice
keeps.  The search is then asked only whether any choice keeps a little more.
"""

from __future__ import annotations

import numpy as np

STEPS = 30  # bisection steps of the cheap test (a millionth of a millimetre on 100 mm)
EPSILON = 1e-9


def held_relations(units, obstacle_centres: np.ndarray, obstacle_halves: np.ndarray,
                   roots: np.ndarray) -> list[tuple]:
    """The relation each pair keeps in the layout ``roots`` (u, 2): for two members of
    different units, or a member and a pinned item, the side on which they stand furthest
    apart.  ``("edge", axis, first, second, c)``: unit ``second`` stands at least ``c`` + gap
    after ``first`` on ``axis``; ``("lower" | "upper", axis, unit, value)``: the unit's root at
    least ``value`` + gap, or at most ``value`` - gap."""
    centres = roots[units.owner] + units.offsets
    relations: list[tuple] = []
    members = len(units.owner)
    for i in range(members):
        for j in range(i + 1, members):
            u, v = int(units.owner[i]), int(units.owner[j])
            if u == v:
                continue
            reach = units.halves[i] + units.halves[j]
            axis, after = _side(centres[j] - centres[i], reach)
            if after:  # j after i
                relations.append(("edge", axis, u, v, float(
                    units.offsets[i, axis] - units.offsets[j, axis] + reach[axis])))
            else:
                relations.append(("edge", axis, v, u, float(
                    units.offsets[j, axis] - units.offsets[i, axis] + reach[axis])))
        for p in range(len(obstacle_centres)):
            u = int(units.owner[i])
            reach = units.halves[i] + obstacle_halves[p]
            axis, after = _side(centres[i] - obstacle_centres[p], reach)
            if after:
                relations.append(("lower", axis, u, float(
                    obstacle_centres[p, axis] + reach[axis] - units.offsets[i, axis])))
            else:
                relations.append(("upper", axis, u, float(
                    obstacle_centres[p, axis] - reach[axis] - units.offsets[i, axis])))
    return relations


def _side(apart: np.ndarray, reach: np.ndarray) -> tuple[int, bool]:
    """The axis on which two boxes ``apart`` (centre to centre, (2,)) with half sizes summing to
    ``reach`` stand furthest apart, and whether the second stands after the first on it."""
    axis = int(np.argmax(np.abs(apart) - reach))
    return axis, bool(apart[axis] >= 0)


def relation_layout(units, relations: list[tuple], gap: float) -> np.ndarray | None:
    """Root positions (u, 2) midway between the least and the greatest the relations allow at
    ``gap`` (a layout spread over its room, not packed into a corner), or None where
    they allow none."""
    count = len(units.lowest)
    least = np.empty((count, 2))
    greatest = np.empty((count, 2))
    for axis in (0, 1):
        lows = units.lowest[:, axis].astype(float).tolist()
        ups = units.highest[:, axis].astype(float).tolist()
        edges = []
        for relation in relations:
            if relation[1] != axis:
                continue
            if relation[0] == "edge":
                edges.append((relation[2], relation[3], relation[4] + gap))
            elif relation[0] == "lower":
                lows[relation[2]] = max(lows[relation[2]], relation[3] + gap)
            else:
                ups[relation[2]] = min(ups[relation[2]], relation[3] - gap)
        falls = [-up for up in ups]
        if not (_longest(lows, edges, count)
                and _longest(falls, [(second, first, c) for first, second, c in edges], count)):
            return None
        ups = [-fall for fall in falls]
        if any(low > up + EPSILON for low, up in zip(lows, ups)):
            return None
        least[:, axis], greatest[:, axis] = lows, np.maximum(ups, lows)
    return (least + greatest) / 2


def _longest(lows: list[float], edges: list[tuple], count: int) -> bool:
    """Raise ``lows`` along every edge (first, second, c): x_second >= x_first + c, until none
    moves; False where they still move after ``count`` rounds (a cycle that pushes a unit past
    itself).  The greatest positions are the same push on the negated upper bounds along the
    reversed edges (x_first <= x_second - c is -x_first >= -x_second + c)."""
    for _ in range(count + 1):
        moved = False
        for first, second, c in edges:
            if lows[first] + c > lows[second] + 1e-12:
                lows[second] = lows[first] + c
                moved = True
        if not moved:
            return True
    return False


def widest_for_relations(units, relations: list[tuple], low: float, high: float
                         ) -> tuple[float, np.ndarray]:
    """The widest gap in [``low``, ``high``] the relations keep, to STEPS halvings, and its
    layout (relation_layout); the relations must keep ``low``."""
    layout = relation_layout(units, relations, low)
    if layout is None:
        raise ValueError("the relations do not keep the gap they were read at")
    if high > low:
        at_high = relation_layout(units, relations, high)
        if at_high is not None:
            return high, at_high
        for _ in range(STEPS):
            middle = (low + high) / 2
            found = relation_layout(units, relations, middle)
            if found is None:
                high = middle
            else:
                low, layout = middle, found
    return low, layout
