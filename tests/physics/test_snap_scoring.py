"""The snap's scoring (physics.snapping) is written for few NumPy calls: one bisection for all
the ends a score needs ("d <= x" as "d < the next float after x"), scores in integers, the
candidates unsorted with repeats dropped among the winners.  Each must give exactly what the
plain definition gives, on distances that sit right on the ends of the ranges too: a slip of
one float there changes which moves the snap makes."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from floatpage.physics.guides import CENTRE, HIGH, LOW, features
from floatpage.physics.alignment import NEAR_MM
from floatpage.physics.snap_scoring import (
    ALIGNED_MM, ESCAPE_MM, MAX_TRIES, best_first, candidate_shifts, distance_bounds,
    misses_after, nearest_shifts,
)
from floatpage.physics.snapping import EVERY_MOVE, MINE, THEIRS, THEIRS_COLUMNS, feature_table

REACH, FARTHEST = 4.0, 12.0


@settings(max_examples=300, deadline=None)
@given(st.lists(st.integers(-40, 40), min_size=1, max_size=120),
       st.sampled_from([0.05, 0.25, 1.0]), st.integers(1, 70))
def test_the_nearest_shifts_are_the_first_by_distance_from_zero(steps, unit, count):
    """The cut to the shifts nearest 0 (of two as near, the lower) is the one a stable sort
    by distance from 0 makes, on values with many ties (a shift and its negative, 0, -0)."""
    distinct = np.unique(np.array(steps, dtype=float) * unit + 0.0)
    by_distance = distinct[np.argsort(np.abs(distinct), kind="stable")[:count]]
    chosen = nearest_shifts(distinct, count)
    assert np.array_equal(chosen, np.sort(by_distance))


def on_the_ends(shifts: list[float], others: list[float]) -> np.ndarray:
    """Sorted distances: ``others`` and, for each shift, a distance on each end of its ranges
    (computed as the snap computes them, in floats)."""
    ends = [shift + end for shift in shifts for end in (NEAR_MM, -NEAR_MM, ALIGNED_MM, -ALIGNED_MM)]
    return np.sort(np.array(others + ends + shifts, dtype=float))


distances = st.lists(st.floats(-20.0, 20.0, allow_nan=False), max_size=40)
some_shifts = st.lists(st.floats(-12.0, 12.0, allow_nan=False), min_size=1, max_size=12)


@settings(max_examples=200, deadline=None)
@given(some_shifts, distances)
def test_scores_are_the_counts_of_their_definition(shifts, others):
    ordered = on_the_ends(shifts, others)
    scores = misses_after(ordered, np.array(shifts))
    for shift, score in zip(shifts, scores.tolist()):
        near = int(((ordered > shift - NEAR_MM) & (ordered < shift + NEAR_MM)).sum())
        aligned = int(((ordered >= shift - ALIGNED_MM) & (ordered <= shift + ALIGNED_MM)).sum())
        # near misses (the near range less the aligned), less half a miss per alignment; twice
        assert score == 2 * (near - aligned) - aligned


@settings(max_examples=200, deadline=None)
@given(distances, st.lists(st.floats(-4.0, 4.0, allow_nan=False), max_size=8))
def test_candidates_and_the_ranges_read_off_one_bisection(others, on_lines):
    # distances right on the ends of the ranges, and some candidates twice
    ordered = np.sort(np.array(others + on_lines + on_lines + [
        REACH, -REACH, ALIGNED_MM, -ALIGNED_MM, NEAR_MM, -NEAR_MM, FARTHEST + ESCAPE_MM,
        -FARTHEST - ESCAPE_MM], dtype=float))
    shifts, missing, lined_up, now = candidate_shifts(ordered, distance_bounds(REACH, FARTHEST))
    assert shifts[0] == 0.0  # staying comes first
    assert now == misses_after(ordered, np.zeros(1))[0]
    within_reach = ordered[np.abs(ordered) <= REACH]
    escaping = ordered[np.abs(ordered) < FARTHEST + ESCAPE_MM]
    away = np.concatenate([escaping - ESCAPE_MM, escaping + ESCAPE_MM])
    expected = np.unique(np.concatenate([within_reach, away[np.abs(away) <= FARTHEST], [0.0]]))
    assert np.array_equal(np.unique(shifts), expected)
    assert missing == bool(((np.abs(ordered) > ALIGNED_MM) & (np.abs(ordered) < NEAR_MM)).any())
    assert lined_up == bool((np.abs(ordered) <= ALIGNED_MM).any())


SHIFTS = [-3.0, -1.5, -0.5, 0.5, 1.5, 2.0, 3.0, 7.25]  # pairs of equal length among them


@settings(max_examples=200, deadline=None)
@given(st.lists(st.integers(-6, 3), min_size=len(SHIFTS), max_size=len(SHIFTS)),
       st.lists(st.integers(0, len(SHIFTS) - 1), min_size=1, max_size=30),
       st.sampled_from([None, 1, 3, EVERY_MOVE]))
def test_the_best_moves_come_first_each_once(score_of, named, tries):
    """Moves of equal score and length (a shift and its opposite) and moves named twice (a
    shift's score is a function of the shift); at most ``MAX_TRIES`` of them unless told
    otherwise (_Snapper.try_lesser asks for every move)."""
    shifts = np.array([SHIFTS[which] for which in named])
    scores = np.array([score_of[which] for which in named])
    now = 4
    if tries is None:
        chosen, gain = best_first(shifts, scores, now)
    else:
        chosen, gain = best_first(shifts, scores, now, tries)
    # the plain definition: each shift once, sorted by score, then length, then value
    unique = sorted({(score_of[which], abs(SHIFTS[which]), SHIFTS[which]) for which in named})
    assert list(chosen) == [shift for _, _, shift in unique][:tries or MAX_TRIES]
    assert gain == (now - unique[0][0]) / 2


def escape_ends(farthest: float) -> list[float]:
    """Distances around the four ends where an escape move, d - ESCAPE_MM or d + ESCAPE_MM
    as a float, comes within ``farthest`` or goes past it: each end and the floats beside it."""
    ends = []
    for end in (farthest + ESCAPE_MM, farthest - ESCAPE_MM, -farthest + ESCAPE_MM,
                -farthest - ESCAPE_MM):
        for steps in range(-3, 4):
            d = end
            for _ in range(abs(steps)):
                d = float(np.nextafter(d, np.inf if steps > 0 else -np.inf))
            ends.append(d)
    return ends


@settings(max_examples=100, deadline=None)
@given(distances, st.sampled_from([4.0, 1.0 / 3.0, 3.7, 12.5, 2.0 ** -3 * 7]))
def test_escape_moves_are_cut_where_their_float_leaves_the_reach(others, reach):
    """The escape moves' length is read off the bisection at ends found float by float
    (distance_bounds): the moves kept, in their order, are exactly the ones whose rounded
    d -/+ ESCAPE_MM is at most ``farthest`` long (fails with the ends taken as the plain sums
    farthest +/- ESCAPE_MM, which the rounding misses by a float on some reaches)."""
    farthest = 3 * reach
    ordered = np.sort(np.array(others + escape_ends(farthest), dtype=float))
    shifts, *_ = candidate_shifts(ordered, distance_bounds(reach, farthest))
    within_reach = ordered[np.abs(ordered) <= reach]
    escaping = ordered[np.abs(ordered) < farthest + ESCAPE_MM]
    down, up = escaping - ESCAPE_MM, escaping + ESCAPE_MM
    expected = np.concatenate([[0.0], within_reach, down[np.abs(down) <= farthest],
                               up[np.abs(up) <= farthest]])
    assert np.array_equal(shifts, expected)


@settings(max_examples=100, deadline=None)
@given(st.lists(st.tuples(st.floats(0.0, 300.0), st.floats(0.5, 80.0)), min_size=1,
                max_size=6),
       st.lists(st.floats(0.0, 300.0), max_size=5), st.lists(st.floats(0.0, 300.0),
                                                             min_size=1, max_size=2),
       st.integers(0, 1))
def test_the_page_lines_as_rows_give_the_distances_to_each_line(items, edges, middles, axis):
    """A body's distances to the page's lines, read as rows of its axis's table (a row per
    line, +inf where a pairing does not exist), are the distances to each line of its kind,
    the same floats: each edge line to its low and its high edge, each middle to its centre;
    an inactive item's lines are at +inf."""
    centres = np.array([[c, c] for c, _ in items])
    halves = np.array([[h, h] for _, h in items])
    active = np.arange(len(items)) % 3 != 2
    edges, middles = np.array(edges, dtype=float), np.array(middles, dtype=float)
    table = feature_table(centres, halves, active, axis, edges, middles)
    mine = features(centres, halves, axis)
    page_rows = table[len(items):, THEIRS_COLUMNS]
    for row in range(len(items)):
        found = (page_rows - mine[row, MINE]).ravel()
        expected = np.concatenate([edges - mine[row, LOW], edges - mine[row, HIGH],
                                   middles - mine[row, CENTRE]])
        assert np.array_equal(np.sort(found[np.isfinite(found)]), np.sort(expected))
        theirs = table[row, THEIRS_COLUMNS]
        assert np.array_equal(theirs, mine[row, THEIRS]) if active[row] else \
            np.isinf(theirs).all()
