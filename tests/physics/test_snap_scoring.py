"""The snap's scoring (physics/snap_scoring_kernel.c) is compiled and written for speed:
bisections for all the ends a score needs ("d <= x" as "d < the next float after x"), scores in
integers, the candidates merged from their runs, the far distances dropped before the sort.
Each must give exactly what the plain definition gives, on distances that sit right on the ends
of the ranges too: a slip of one float there changes which moves the snap makes.  The whole
scoring is held to a plain, slow reference written here (plain_scoring), on random tables made
the snap's way."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from floatpage.physics.guides import CENTRE, HIGH, LOW, features
from floatpage.physics.alignment import NEAR_MM
from floatpage.physics.save_grid import STEPS_PER_MM
from floatpage.physics.snap_scoring_kernel import line_of, score_moves, scored_candidates
from floatpage.physics.snap_scoring import (
    ALIGNED_MM, ESCAPE_MM, MAX_CANDIDATES, MAX_TRIES, on_grid, scoring_ranges,
)
from floatpage.physics.snapping import (
    EVERY_MOVE, HIGHS_COLUMN, LOWS_COLUMN, MINE, MINE_COLUMNS, THEIRS, THEIRS_COLUMNS,
    feature_table,
)

REACH, FARTHEST = 4.0, 12.0
RANGES = scoring_ranges(REACH, FARTHEST, window=16.0)


def candidates_of(ordered: np.ndarray, reach: float = REACH, farthest: float = FARTHEST):
    """The kernel's candidates, their scores, whether it misses / is on a line, staying's score."""
    shifts, scores, missing, lined_up, now = scored_candidates(
        ordered, scoring_ranges(reach, farthest, window=16.0))
    return np.array(shifts), scores, missing, lined_up, now


def on_the_ends(shifts: list[float], others: list[float]) -> np.ndarray:
    """Sorted distances: ``others`` and, for each shift, a distance on each end of its ranges
    (computed as the snap computes them, in floats)."""
    ends = [shift + end for shift in shifts for end in (NEAR_MM, -NEAR_MM, ALIGNED_MM, -ALIGNED_MM)]
    return np.sort(np.array(others + ends + shifts, dtype=float))


distances = st.lists(st.floats(-20.0, 20.0, allow_nan=False), max_size=40)
some_shifts = st.lists(st.floats(-REACH, REACH, allow_nan=False), min_size=1, max_size=12)


@settings(max_examples=200, deadline=None)
@given(some_shifts, distances)
def test_scores_are_the_counts_of_their_definition(shifts, others):
    """Every candidate's score (among them each of ``shifts``: a distance within reach), with
    distances right on the ends of its windows."""
    ordered = on_the_ends(shifts, others)
    candidates, scores, *_ = candidates_of(ordered)
    assert set(shifts) <= set(candidates.tolist())
    for shift, score in zip(candidates.tolist(), scores):
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
    shifts, scores, missing, lined_up, now = candidates_of(ordered)
    assert now == scores[shifts.tolist().index(0.0)]  # staying is a candidate, scoring now
    within_reach = ordered[np.abs(ordered) <= REACH]
    escaping = ordered[np.abs(ordered) < FARTHEST + ESCAPE_MM]
    away = np.concatenate([escaping - ESCAPE_MM, escaping + ESCAPE_MM])
    expected = np.unique(np.concatenate([within_reach, away[np.abs(away) <= FARTHEST], [0.0]]))
    assert np.array_equal(np.unique(shifts), expected)
    assert missing == bool(((np.abs(ordered) > ALIGNED_MM) & (np.abs(ordered) < NEAR_MM)).any())
    assert lined_up == bool((np.abs(ordered) <= ALIGNED_MM).any())


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
    (distance_bounds): the moves kept are exactly the ones whose rounded
    d -/+ ESCAPE_MM is at most ``farthest`` long (fails with the ends taken as the plain sums
    farthest +/- ESCAPE_MM, which the rounding misses by a float on some reaches)."""
    farthest = 3 * reach
    ordered = np.sort(np.array(others + escape_ends(farthest), dtype=float))
    shifts, *_ = candidates_of(ordered, reach, farthest)
    within_reach = ordered[np.abs(ordered) <= reach]
    escaping = ordered[np.abs(ordered) < farthest + ESCAPE_MM]
    down, up = escaping - ESCAPE_MM, escaping + ESCAPE_MM
    expected = np.unique(np.concatenate([[0.0], within_reach, down[np.abs(down) <= farthest],
                                         up[np.abs(up) <= farthest]]))
    assert np.array_equal(shifts, expected)  # sorted, each once


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


def plain_scoring(table: np.ndarray, members: list[int], reach: float, farthest: float,
                  window: float, tries: int, grid: float = 0.0) -> tuple:
    """What the snap's scoring of the rigid body ``members`` means, in plain Python floats:
    every distance from a feature of a member to a line of the same kind of a row near the
    body (reaching into its extent widened by ``window``) that is not its own; the moves onto
    a line within ``reach`` and out of a near miss at most ``farthest`` long, and staying; of
    more than MAX_CANDIDATES of them (each rounded onto ``grid`` steps per mm first, if
    any: to the nearest whole number of steps, ties to even, times the step), the distinct
    ones nearest 0 (of two as near, the lower);
    each scored as twice its near misses less three times its alignments; those scoring below
    staying, by score, length, value, each once, at most ``tries``."""
    rows = table.tolist()
    mine = [rows[member] for member in members]
    low = min(row[0] for row in mine) - window
    high = max(row[2] for row in mine) + window
    lines = [row for k, row in enumerate(rows)
             if k not in members and row[LOWS_COLUMN] < high and row[HIGHS_COLUMN] > low]
    theirs, paired = range(*THEIRS_COLUMNS.indices(15)), range(*MINE_COLUMNS.indices(15))
    distances = sorted(line[their] - member[my] for member in mine for line in lines
                       for their, my in zip(theirs, paired))

    def score(shift: float) -> int:
        near = sum(shift - NEAR_MM < d < shift + NEAR_MM for d in distances)
        aligned = sum(shift - ALIGNED_MM <= d <= shift + ALIGNED_MM for d in distances)
        return 2 * near - 3 * aligned

    escaping = [d for d in distances if abs(d) < farthest + ESCAPE_MM]
    shifts = ([0.0] + [d for d in distances if abs(d) <= reach]
              + [d - ESCAPE_MM for d in escaping if abs(d - ESCAPE_MM) <= farthest]
              + [d + ESCAPE_MM for d in escaping if abs(d + ESCAPE_MM) <= farthest])
    if grid:
        shifts = [on_grid(shift, grid) for shift in shifts]
    if len(shifts) > MAX_CANDIDATES:
        shifts = sorted(sorted(set(shifts), key=lambda v: (abs(v), v))[:MAX_CANDIDATES])
    now = score(0.0)
    better = sorted({(score(shift), abs(shift), shift) for shift in shifts if score(shift) < now})
    chosen = tuple(shift for _, _, shift in better[:tries])
    gain = (now - better[0][0]) / 2 if better else 0.0
    missing = any(ALIGNED_MM < abs(d) < NEAR_MM for d in distances)
    lined_up = any(abs(d) <= ALIGNED_MM for d in distances)
    return chosen, gain, missing, lined_up, low, high


@settings(max_examples=300, deadline=None)
@given(st.integers(2, 40), st.integers(0, 2 ** 32 - 1), st.sampled_from([0.05, 0.25, None]),
       st.integers(1, 4), st.sampled_from([1, MAX_TRIES, EVERY_MOVE]),
       st.sampled_from([(4.0, 12.0), (1.0 / 3.0, 1.0), (8.0, 12.0)]),
       st.sampled_from([0.0, STEPS_PER_MM]))
def test_the_kernel_scores_as_the_plain_definition(count, seed, grid, body, tries, reaches,
                                                   steps):
    """Random pages made as the snap makes its tables (feature_table: inactive rows, the page's
    edge and middle lines as rows), items crowded into a strip so that most lines are near and
    crowded pages cut to the nearest candidates; on a grid of 0.05 or 0.25 mm (ties, exact
    alignments, a shift and its opposite) or anywhere; a body of 1-4 rows; the candidate
    shifts as they are or rounded onto the save's grid (``steps`` per mm, as the snap asks)."""
    rng = np.random.default_rng(seed)
    if grid is None:
        centres = rng.uniform(0.0, 60.0, (count, 2))
        halves = rng.uniform(0.5, 20.0, (count, 2))
    else:
        centres = rng.integers(0, int(60 / grid), (count, 2)) * grid
        halves = rng.integers(1, int(20 / grid), (count, 2)) * grid
    active = rng.random(count) < 0.9
    active[0] = True
    edges, middles = np.array([10.0, 50.0]), np.array([30.0])
    reach, farthest = reaches
    window = max(farthest, NEAR_MM) + NEAR_MM
    ranges = scoring_ranges(reach, farthest, window, grid=steps)
    movable = np.flatnonzero(active)
    members = rng.choice(movable, size=min(body, len(movable)), replace=False)
    for axis in (0, 1):
        table = feature_table(centres, halves, active, axis, edges, middles)
        found = score_moves(table, members, ranges, MAX_CANDIDATES, tries)
        assert found == plain_scoring(table, members.tolist(), reach, farthest, window, tries,
                                      steps)


def test_the_kernel_refuses_what_is_not_a_table():
    """Wrong arrays are errors, not reads past their ends."""
    table = feature_table(np.zeros((2, 2)), np.ones((2, 2)), np.ones(2, dtype=bool), 0,
                          np.zeros(1), np.zeros(1))
    for bad in (
        (table[:, :14].copy(), np.array([0]), RANGES),  # not the snap's 15 columns
        (table.astype(np.float32), np.array([0]), RANGES),  # not float64
        (table, np.array([5]), RANGES),  # a row outside the table
        (table, np.array([0], dtype=np.int32), RANGES),  # rows not as int64
        (table, np.array([0]), RANGES[:-1]),  # not scoring_ranges' array
        (table, np.zeros(0, dtype=np.int64), RANGES),  # no body
    ):
        with pytest.raises((TypeError, ValueError, IndexError)):
            score_moves(*bad, MAX_CANDIDATES, MAX_TRIES)


@settings(max_examples=300, deadline=None)
@given(st.integers(2, 40), st.integers(0, 2 ** 32 - 1), st.sampled_from([0.05, 0.25, None]))
def test_the_kernel_finds_the_line_of_the_plain_definition(count, seed, grid):
    """A group's line (snap_scoring_kernel.line_of): the group and every mover with a feature within
    ALIGNED_MM of a line of the group's of the same kind, on random pages of groups (rows
    following others), movers and inactive rows; on a grid many features line up exactly."""
    rng = np.random.default_rng(seed)
    if grid is None:
        centres, halves = rng.uniform(0.0, 60.0, (count, 2)), rng.uniform(0.5, 20.0, (count, 2))
    else:
        centres = rng.integers(0, int(60 / grid), (count, 2)) * grid
        halves = rng.integers(1, int(20 / grid), (count, 2)) * grid
    active = rng.random(count) < 0.9
    follows = rng.random(count) < 0.3
    follows[0] = False
    roots = np.where(follows, rng.choice(np.flatnonzero(~follows), count), np.arange(count))
    movers = rng.random(count) < 0.8
    row = int(rng.choice(np.flatnonzero(roots == np.arange(count))))
    members = np.flatnonzero((roots == row) & active)
    if not len(members):
        members = np.array([row])
    for axis in (0, 1):
        table = feature_table(centres, halves, active, axis, np.array([10.0]), np.array([30.0]))
        rows = table.tolist()
        on = {roots[other] for other in range(count) for member in members.tolist()
              for their, my in zip(range(3, 8), range(8, 13))
              if abs(rows[other][their] - rows[member][my]) <= ALIGNED_MM}
        features = [rows[member][k] for member in members.tolist() for k in (0, 1, 2)]
        expected = ([row] + sorted({root for root in on if movers[root]} - {row}),
                    min(features) - ALIGNED_MM, max(features) + ALIGNED_MM)
        assert line_of(table, members, row, count, roots, movers, ALIGNED_MM) == expected
