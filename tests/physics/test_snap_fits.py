"""The snap's test of whether a move fits (snap_fit_kernel.fitting_shifts, compiled) reads only the
neighbours a move could bring within the clearance, and of those only the pairs not already
apart across.  It must keep exactly the moves the plain definition keeps: every member inside
its margins (or no further out than it is), and no pair of a member and another item closer
than the clearance, or than it is now, after the move (for moves at most the longest long)."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from floatpage.physics.snap_fit_kernel import fitting_shifts
from floatpage.physics.snapping import TOLERANCE_MM, feature_table

PAGE = 120.0


def plain_fits(members: list[int], axis: int, shifts: tuple[float, ...], centres: np.ndarray,
               halves: np.ndarray, lowest: np.ndarray, highest: np.ndarray, active: np.ndarray,
               clearance: float) -> list[float]:
    """Every shift tested against every other active item, in plain Python floats."""
    across_axis = 1 - axis
    kept = []
    for shift in shifts:
        fits = all(min(lowest[m, axis], centres[m, axis]) - TOLERANCE_MM
                   <= centres[m, axis] + shift
                   <= max(highest[m, axis], centres[m, axis]) + TOLERANCE_MM for m in members)
        for other in range(len(centres)):
            if not fits or not active[other] or other in members:
                continue
            for m in members:
                across = (abs(centres[other, across_axis] - centres[m, across_axis])
                          - halves[other, across_axis] - halves[m, across_axis])
                reach = halves[other, axis] + halves[m, axis]
                now = abs(centres[other, axis] - centres[m, axis]) - reach
                after = abs(centres[other, axis] - (centres[m, axis] + shift)) - reach
                needed = min(max(now, across), clearance) - TOLERANCE_MM
                fits = fits and max(after, across) >= needed
        if fits:
            kept.append(shift)
    return kept


@settings(max_examples=300, deadline=None)
@given(st.integers(2, 30), st.integers(0, 2 ** 32 - 1), st.sampled_from([0.05, 0.25, None]),
       st.integers(1, 4), st.sampled_from([(3.05, 12.0), (0.5, 4.0), (6.0, 12.0)]))
def test_the_kernel_keeps_the_moves_of_the_plain_definition(count, seed, grid, body, limits):
    """Random crowded pages (items overlapping, touching, a gap apart; on a grid of 0.05 or
    0.25 mm many gaps are exactly the clearance), inactive rows, margins some items are
    already past, a body of 1-4 rows, moves up to the longest each way."""
    rng = np.random.default_rng(seed)
    clearance, farthest = limits
    if grid is None:
        centres, halves = rng.uniform(0.0, PAGE, (count, 2)), rng.uniform(0.5, 25.0, (count, 2))
        shifts = rng.uniform(-farthest, farthest, 12)
    else:
        centres = rng.integers(0, int(PAGE / grid), (count, 2)) * grid
        halves = rng.integers(1, int(25 / grid), (count, 2)) * grid
        shifts = rng.integers(-int(farthest / grid), int(farthest / grid) + 1, 12) * grid
    active = rng.random(count) < 0.9
    margin = rng.uniform(0.0, 10.0)
    lowest, highest = halves + margin, PAGE - halves - margin
    members = rng.choice(count, size=min(body, count - 1), replace=False)
    active[members] = True
    tables = tuple(feature_table(centres, halves, active, axis, np.array([margin]),
                                 np.array([PAGE / 2])) for axis in (0, 1))
    shifts = tuple(shifts.tolist())
    for axis in (0, 1):
        found = fitting_shifts(members, axis, shifts, centres, halves, lowest, highest, tables,
                               np.array([clearance, farthest, TOLERANCE_MM]))
        assert found == plain_fits(members.tolist(), axis, shifts, centres, halves, lowest,
                                   highest, active, clearance)
