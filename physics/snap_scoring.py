"""How the alignment snap (physics.snapping) scores a body's moves along one axis: every
figure is read off the sorted distances from its features to the lines of the same kind near
it, by bisection (which moves to try, what each leaves, whether it misses a line now).

Apart from the snap's search because these are its units, each called tens of thousands of
times on a page of 120 items and each a few dozen small NumPy operations: a change here is
measured per call, and must leave every score as it was (benchmarks/snap_identity.py).
"""

from __future__ import annotations

import math

import numpy as np

from floatpage.physics.alignment import NEAR_MM

ALIGNED_MM = 0.05  # features this close are aligned (positions are saved to 0.01 mm)
ESCAPE_MM = NEAR_MM + 0.05  # a near miss that cannot close opens to this
ALIGN_GAIN = 0.5  # an exact alignment is worth half a near miss
MAX_CANDIDATES = 64  # moves scored per item and axis: on a crowded page, the 64 shortest
MAX_TRIES = 8  # an item tries at most its 8 best moves on an axis (each a few checks)
SORTED_IN_PYTHON = 24  # best_first: so many moves or fewer sort faster as tuples
NO_SHIFTS: tuple[float, ...] = ()
STAY = np.zeros(1)  # the shift that leaves a body where it is, always a candidate
# misses_after's four ends around a shift (a column per shift), and what each bisection there
# counts towards twice the score: d < shift + NEAR, d < shift - ALIGNED, d <= shift - NEAR,
# d <= shift + ALIGNED; twice 1 and 1 + ALIGN_GAIN, so that scores are integers
WINDOW_ENDS = np.array([[NEAR_MM], [-ALIGNED_MM], [-NEAR_MM], [ALIGNED_MM]])
SCORE_WEIGHTS = np.array([2, 3, -2, -3])


_TRUES: dict[int, np.ndarray] = {}


def trues(width: int) -> np.ndarray:
    """A kept vector of ``width`` Trues: a boolean (k, width) table @ it is each row's any(),
    in one call without the set-up of a NumPy reduction (about twice its cost here)."""
    found = _TRUES.get(width)
    if found is None:
        found = _TRUES[width] = np.ones(width, dtype=bool)
    return found


def distance_bounds(reach: float, farthest: float) -> np.ndarray:
    """The ends of the ranges of distances candidate_shifts reads, as needles for one
    np.searchsorted from the left: four lower ends (|distance| <= ``reach``, |distance| <
    ``farthest`` + ``ESCAPE_MM``, -``NEAR_MM`` < distance < -``ALIGNED_MM``, ``ALIGNED_MM`` <
    distance < ``NEAR_MM``), then their four upper ends, each found from the right: "d <= x"
    is "d < the next float after x"; then the ends of the distances whose escape moves,
    d - ``ESCAPE_MM`` and d + ``ESCAPE_MM`` as floats, are at most ``farthest`` long: the
    first distance at which each comes within it and the first at which it is past it."""
    escape = farthest + ESCAPE_MM
    escapes = [first_where(lambda d, way=way: way(d) >= -farthest, -farthest - way(0.0))
               if end == 0 else
               first_where(lambda d, way=way: way(d) > farthest, farthest - way(0.0))
               for way in (lambda d: d - ESCAPE_MM, lambda d: d + ESCAPE_MM) for end in (0, 1)]
    return np.concatenate([[-reach, escape, -ALIGNED_MM, NEAR_MM],
                           np.nextafter([reach, -escape, -NEAR_MM, ALIGNED_MM], np.inf),
                           escapes])


def relevant_distance(farthest: float) -> float:
    """A bound past every distance options reads: every end of distance_bounds lies within
    ``farthest`` + ``ESCAPE_MM`` (and a few floats), and every window misses_after counts in,
    a candidate shift (at most ``farthest`` long) plus or less ``NEAR_MM`` at most.  Distances
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


def candidate_shifts(ordered: np.ndarray,
                     bounds: np.ndarray) -> tuple[np.ndarray, bool, bool, int]:
    """Shifts that put a feature on a line at one of the sorted distances ``ordered`` from it
    within reach, or put it just out of a near miss with one (``ESCAPE_MM``) within
    ``farthest``; with 0 (staying) first.  The way out of a near miss may be long: two items
    of nearly the same width cannot line up both edges and centre, and one 1 mm from the
    other stays in near misses until it has moved 4-5 mm.  Also whether a feature misses a
    line now (a distance between ``ALIGNED_MM`` and ``NEAR_MM``), and whether one is on a
    line (a distance within ``ALIGNED_MM``), and the score of staying (as misses_after
    gives it).  Each range of distances (``bounds``, from
    distance_bounds, with the reach and the farthest move there) is a slice of the sorted
    ones, so the escape moves need no test of their length."""
    found = ordered.searchsorted(bounds).tolist()
    low, high = found[:4], found[4:8]
    # |distance| < farthest + ESCAPE_MM, and of those, the ones whose escape stays in reach
    down = ordered[max(high[1], found[8]):min(low[1], found[9])]
    up = ordered[max(high[1], found[10]):min(low[1], found[11])]
    # |distance| <= reach (reach < farthest), just out of reach of those within farthest, 0
    shifts = np.concatenate((STAY, ordered[low[0]:high[0]], down - ESCAPE_MM, up + ESCAPE_MM))
    missing = low[2] > high[2] or low[3] > high[3]
    lined_up = high[3] > low[2]  # -ALIGNED_MM <= distance <= ALIGNED_MM
    # staying's score (misses_after of 0): its four ends are among the ranges' ends
    now = 2 * low[3] + 3 * low[2] - 2 * high[2] - 3 * high[3]
    return shifts, bool(missing), bool(lined_up), now


def misses_after(ordered: np.ndarray, shifts: np.ndarray) -> np.ndarray:
    """For each shift, the near misses between a group's features and the lines of the same
    kind at the sorted distances ``ordered`` from them (one entry per pair), less
    ``ALIGN_GAIN`` per exact alignment, twice, in integers; (len(shifts),).  Counted by bisection: the (shifts,
    distances) table of gaps it replaces was a fifth of the snapping's time."""
    ends = WINDOW_ENDS + shifts  # (4, shifts)
    # d <= x is d < the next float after x: one bisection from the left for all four ends,
    # d < shift + NEAR, d < shift - ALIGNED, d <= shift - NEAR, d <= shift + ALIGNED
    np.nextafter(ends[2:], np.inf, out=ends[2:])
    # twice (near misses and alignments, less the alignments, ALIGN_GAIN more off each)
    return SCORE_WEIGHTS @ ordered.searchsorted(ends)


def nearest_shifts(distinct: np.ndarray, count: int = MAX_CANDIDATES) -> np.ndarray:
    """The ``count`` shifts of ``distinct`` (sorted, each once) nearest to 0, of two as near
    the lower first, in ascending order.  The nearest values of a sorted array are a run of
    it: the first run whose left end is no farther from 0 than the value just past its right
    end, found by bisection (a stable sort by distance from 0 chose the same shifts; on a
    column's line of 15 groups, 500 distinct candidates, it took 7 us, this 3)."""
    value = distinct.item  # a few reads: no list of them all
    low, high = 0, max(len(distinct) - count, 0)
    while low < high:
        middle = (low + high) // 2
        if abs(value(middle)) > abs(value(middle + count)):
            low = middle + 1
        else:
            high = middle
    return distinct[low:low + count]


def best_first(shifts: np.ndarray, scores: np.ndarray, now: int,
               tries: int = MAX_TRIES) -> tuple[tuple[float, ...], float]:
    """The moves that lower the score, ``shifts`` (perhaps some twice) and their ``scores``,
    ordered best first: the fewest misses, then the shortest move, then the lower; each once,
    at most ``tries``; and what the best gains over ``now``.  A few are sorted as Python
    tuples (the same keys, so the same order), which costs less than a lexsort's set-up."""
    if len(shifts) <= SORTED_IN_PYTHON:
        values = shifts.tolist()
        keyed = sorted(zip(scores.tolist(), map(abs, values), values))
        chosen: list[float] = []
        for _, _, shift in keyed:
            if not chosen or shift != chosen[-1]:
                chosen.append(shift)
                if len(chosen) == tries:
                    break
        return tuple(chosen), (now - keyed[0][0]) / 2
    order = np.lexsort((shifts, np.abs(shifts), scores)).tolist()
    chosen = []
    for shift in shifts[order].tolist():
        if not chosen or shift != chosen[-1]:  # equal shifts have equal keys: side by side
            chosen.append(shift)
            if len(chosen) == tries:
                break
    return tuple(chosen), (now - int(scores[order[0]])) / 2
