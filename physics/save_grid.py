"""The grid a save writes positions on: centres to 0.01 mm (model.layout.write_back), each
rounded towards the inside of the page where the nearest step would put an item past its edge
(model.layout.safe_round).

The alignment snap (physics.snapping) works on that grid: before its first move it puts every
group it may move onto it (where the move fits: _Snapper.onto_grid), and every move it scores
is a whole number of steps (snap_scoring_core.h, SAVE_STEPS_PER_MM), so the layout it leaves is
the layout saved.  Rounded only afterwards, features the snap had left 0.043-0.048 mm apart
(aligned: within snap_scoring.ALIGNED_MM) came back from the file 0.051-0.056 mm apart, near
misses, and the snap of the next probe moved items 2-10 mm to close them: the probe found the
page not at rest, and a settle took one probe more (benchmarks/guide_cost.py's fresh seeds
3027 and 4026, and 6 of the 11 pages that needed one on seeds 2000-4029).
"""

from __future__ import annotations

import numpy as np

from floatpage.physics.fast_forces import GRID_FROM_ITEMS, candidate_pairs
from floatpage.physics.snap_setup_kernel import sweep_pairs

STEPS_PER_MM = 100  # 0.01 mm: model.layout.POSITION_DECIMALS (tests/physics/test_save_grid.py)


def on_save_grid(centres: np.ndarray, halves: np.ndarray, page_mm: float) -> np.ndarray:
    """``centres`` along one axis rounded as a save rounds them (model.layout.safe_round): to
    the nearest step, but an item inside the page that the nearest step would put past an edge
    goes to the nearest step inside.  A new array."""
    step = 1.0 / STEPS_PER_MM
    centres = np.asarray(centres, float)
    halves = np.asarray(halves, float)
    nearest = np.floor(centres * STEPS_PER_MM + 0.5) / STEPS_PER_MM
    inside = ((centres - halves >= -1e-9) & (centres + halves <= page_mm + 1e-9)
              & (2 * halves <= page_mm))
    low = inside & (nearest - halves < 0)
    nearest[low] = np.ceil(np.round(halves[low] / step, 6)) / STEPS_PER_MM
    high = inside & (nearest + halves > page_mm)
    nearest[high] = np.floor(np.round((page_mm - halves[high]) / step, 6)) / STEPS_PER_MM
    return nearest + 0.0


def fitting_grid_shifts(centres: np.ndarray, halves: np.ndarray, rows: np.ndarray,
                        roots: np.ndarray, shifts: np.ndarray, axis: int, lowest: np.ndarray,
                        highest: np.ndarray, clearance: float, tolerance: float) -> np.ndarray:
    """``shifts`` (per row of the page, along ``axis``, each at most a step long: a
    group's rows share its root's; 0 for rows that stay) less those of the groups they do not
    fit for, made all at once: a group keeps its shift only if, with every other kept shift
    made too, each of its rows stays inside its margins (or no further out than it is:
    ``lowest``, ``highest`` per row and axis) and keeps every pair with another group's row
    (of ``rows``, the active ones) at least the clearance apart, or as far apart as it is
    now: snapping._Snapper.fits' test, for every group at once.  A group that fails drops
    its shift and the rest are tested again, until none fails (each round drops at least
    one, so it ends).  Only pairs within the clearance and three steps on both axes can fail
    (each row moves at most a step): found by the physics' sweep.  A new array."""
    kept = shifts.copy()
    if len(rows) < GRID_FROM_ITEMS:
        ends = np.frombuffer(sweep_pairs(centres, halves, _active(rows, len(centres)), roots,
                                         clearance + 3.0 / STEPS_PER_MM),
                             dtype=np.int64).reshape(-1, 2)
        i, j = ends[:, 0], ends[:, 1]
    else:
        i, j = candidate_pairs(centres, halves, rows, roots, clearance + 3.0 / STEPS_PER_MM)
    across = 1 - axis
    gap_across = (np.abs(centres[i, across] - centres[j, across]) - halves[i, across]
                  - halves[j, across])
    reach = halves[i, axis] + halves[j, axis]
    along = centres[i, axis] - centres[j, axis]
    needed = np.minimum(np.maximum(np.abs(along) - reach, gap_across), clearance) - tolerance
    tested = ~(gap_across >= needed)  # else no shift along this axis brings them closer
    i, j = i[tested], j[tested]
    along, reach, gap_across, needed = (along[tested], reach[tested], gap_across[tested],
                                        needed[tested])
    at = centres[rows, axis]
    low = np.minimum(lowest[rows, axis], at) - tolerance
    high = np.maximum(highest[rows, axis], at) + tolerance
    while True:
        after = at + kept[rows]
        failing = rows[(after < low) | (after > high)]
        gap = np.maximum(np.abs(along + kept[i] - kept[j]) - reach, gap_across)
        close = gap < needed
        failing = np.concatenate([failing, i[close], j[close]])
        failing = failing[kept[failing] != 0]
        if not len(failing):
            return kept
        kept[np.isin(roots, roots[failing])] = 0.0


def _active(rows: np.ndarray, count: int) -> np.ndarray:
    active = np.zeros(count, dtype=bool)
    active[rows] = True
    return active
