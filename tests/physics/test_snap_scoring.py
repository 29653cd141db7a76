"""The snap's scoring (physics.snapping) is written for few NumPy calls: one bisection for all
the ends a score needs ("d <= x" as "d < the next float after x"), scores in integers, the
candidates unsorted with repeats dropped among the winners.  Each must give exactly what the
plain definition gives, on distances that sit right on the ends of the ranges too: a slip of
one float there changes which moves the snap makes."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from floatpage.physics.snapping import (
    ALIGNED_MM, ESCAPE_MM, EVERY_MOVE, MAX_TRIES, NEAR_MM, best_first, candidate_shifts,
    distance_bounds, misses_after,
)

REACH, FARTHEST = 4.0, 12.0


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
    shifts, missing, lined_up = candidate_shifts(ordered, distance_bounds(REACH, FARTHEST),
                                                 FARTHEST)
    assert shifts[0] == 0.0  # staying comes first
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
