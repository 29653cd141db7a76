"""How the alignment snap (physics.snapping) scores a body's moves along one axis: every
figure is read off the sorted distances from its features to the lines of the same kind near
it, by bisection (which moves to try, what each leaves, whether it misses a line now).

The scoring itself is compiled (physics/snap_scoring_kernel.c, score_moves): called tens of
thousands of times on a page of 120 items, it was a few dozen small NumPy operations a call, and
their set-up was most of the snap's time.  What is here is worked out once per page: the constants
and the ends of the distance ranges, handed to the kernel as one array (scoring_ranges).  A
change here or there must leave every score as it was (benchmarks/snap_identity.py).
"""

from __future__ import annotations

import math

import numpy as np

from floatpage.physics.alignment import NEAR_MM

# features this close are aligned (positions are saved to 0.01 mm); and a millionth more: on
# the save's grid (physics.save_grid) two centres are often exactly 0.05 apart, which the
# snap's floats (a sum of moves) put at 0.04999999999995 and the file's at 0.05000000000001,
# a near miss the next probe's snap closed by moving an item 4.2 mm (fresh seed 2003)
ALIGNED_MM = 0.05 + 1e-6
ESCAPE_MM = NEAR_MM + 0.05  # a near miss that cannot close opens to this
ALIGN_GAIN = 0.5  # an exact alignment is worth half a near miss
MAX_CANDIDATES = 64  # moves scored per item and axis: on a crowded page, the 64 shortest
MAX_TRIES = 8  # an item tries at most its 8 best moves on an axis (each a few checks)
NO_SHIFTS: tuple[float, ...] = ()
# the kernel's four ends around a shift, each added to it: d < shift + NEAR, d < shift -
# ALIGNED, d <= shift - NEAR, d <= shift + ALIGNED (the kernel counts them twice 1 and
# 1 + ALIGN_GAIN, so that scores are integers: weights 2, 3, -2, -3)
WINDOW_ENDS = (NEAR_MM, -ALIGNED_MM, -NEAR_MM, ALIGNED_MM)


_TRUES: dict[int, np.ndarray] = {}


def trues(width: int) -> np.ndarray:
    """A kept vector of ``width`` Trues: a boolean (k, width) table @ it is each row's any(),
    in one call without the set-up of a NumPy reduction (about twice its cost here)."""
    found = _TRUES.get(width)
    if found is None:
        found = _TRUES[width] = np.ones(width, dtype=bool)
    return found


def distance_bounds(reach: float, farthest: float) -> np.ndarray:
    """The ends of the ranges of distances the kernel's candidate_shifts reads, as needles for
    one bisection from the left (np.searchsorted's): four lower ends (|distance| <= ``reach``,
    |distance| < ``farthest`` + ``ESCAPE_MM``, -``NEAR_MM`` < distance < -``ALIGNED_MM``,
    ``ALIGNED_MM`` < distance < ``NEAR_MM``), then their four upper ends, each found from the
    right: "d <= x" is "d < the next float after x"; then the ends of the distances whose
    escape moves, d - ``ESCAPE_MM`` and d + ``ESCAPE_MM`` as floats, are at most ``farthest``
    long: the first distance at which each comes within it and the first past it."""
    escape = farthest + ESCAPE_MM
    escapes = [first_where(lambda d, way=way: way(d) >= -farthest, -farthest - way(0.0))
               if end == 0 else
               first_where(lambda d, way=way: way(d) > farthest, farthest - way(0.0))
               for way in (lambda d: d - ESCAPE_MM, lambda d: d + ESCAPE_MM) for end in (0, 1)]
    return np.concatenate([[-reach, escape, -ALIGNED_MM, NEAR_MM],
                           np.nextafter([reach, -escape, -NEAR_MM, ALIGNED_MM], np.inf),
                           escapes])


def scoring_ranges(reach: float, farthest: float, window: float,
                   relevant: float | None = None, grid: float = 0.0) -> np.ndarray:
    """What the kernel's scoring (snap_scoring_kernel.score_moves) reads besides the table, worked
    out once per page, as the one array of 20 floats it takes: the twelve needles of
    distance_bounds (moves onto lines within ``reach``, escape moves at most ``farthest``
    long), WINDOW_ENDS, ``ESCAPE_MM``, the ``window`` around a body within which lines are
    near it, the distance past which none is read (relevant_distance, unless given) and the
    ``grid`` every candidate shift is rounded onto, in steps per mm (on_grid; 0: none; the snap
    passes physics.save_grid.STEPS_PER_MM).  Which distances make candidates is decided before
    the rounding, on the floats."""
    if relevant is None:
        relevant = relevant_distance(farthest)
    key = (reach, farthest, window, relevant, grid)
    found = _RANGES.get(key)
    if found is None:  # a page size's ranges, worked out once (first_where's float walks)
        found = np.concatenate([distance_bounds(reach, farthest), WINDOW_ENDS,
                                [ESCAPE_MM, window, relevant, grid]])
        found.flags.writeable = False  # kept and shared: the kernels only read it
        if len(_RANGES) < 64:
            _RANGES[key] = found
    return found


_RANGES: dict[tuple[float, float, float, float, float], np.ndarray] = {}


def on_grid(shift: float, grid: float) -> float:
    """A candidate shift rounded onto ``grid`` steps per mm, as the kernel rounds it (0: as it
    is): shift * grid to the nearest whole number (ties to even), times 1 / grid; monotone, so
    the sorted candidates stay sorted.  (Candidate shifts are at most a few centimetres.)"""
    return round(shift * grid) * (1.0 / grid) if grid > 0 else shift


def relevant_distance(farthest: float) -> float:
    """A bound past every distance the scoring reads: every end of distance_bounds lies within
    ``farthest`` + ``ESCAPE_MM`` (and a few floats), and every window a score counts in, a
    candidate shift (at most ``farthest`` long) plus or less ``NEAR_MM`` at most.  Distances
    beyond it (on a line of a dozen groups, three in four) only move every bisection's index by
    the same count, which every range and score takes as a difference: dropping them before
    the sort changes no range, no candidate and no score, and sorts a quarter as many."""
    return farthest + max(ESCAPE_MM, NEAR_MM) + 1.0


def first_where(holds, guess: float) -> float:
    """The least float d for which ``holds(d)``, a test that holds from some float on (a
    comparison of a rounded sum that grows with d), searched a few floats either side of
    ``guess``: the exact end of a range the rounding of the sum blurs."""
    if not math.isfinite(guess):  # no page makes one, but never loop on an infinity
        return guess
    d = guess
    while holds(d):
        d = math.nextafter(d, -math.inf)
    while not holds(d):
        d = math.nextafter(d, math.inf)
    return d
