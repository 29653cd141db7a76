"""The exact search for a layout of a few items (physics.arrangements): every layout it gives
keeps the gap inside the room, and where it finds none, none exists (held against a plain
enumeration of every relation between every pair)."""

from __future__ import annotations

from itertools import product

import numpy as np
from hypothesis import given, settings, strategies as st

from floatpage.physics.arrangements import OutOfBudget, arrangement, arranges, widest_gap
from floatpage.physics.finalize import pair_clearances

ROOM = np.array([100.0, 140.0])


def every_relation_fits(sizes: np.ndarray, room: np.ndarray, gap: float) -> bool:
    """Plain enumeration: each pair left of, right of, above or below the other, in every
    combination; a combination fits when on each axis the longest chain (Bellman-Ford, with
    a cycle meaning it does not) fits the room."""
    count = len(sizes)
    pairs = [(a, b) for a in range(count) for b in range(a + 1, count)]
    for relations in product(range(4), repeat=len(pairs)):
        edges = [[], []]
        for (a, b), relation in zip(pairs, relations):
            axis, first, second = (relation // 2, a, b) if relation % 2 == 0 else \
                (relation // 2, b, a)
            edges[axis].append((first, second))
        fits = True
        for axis in (0, 1):
            low = [0.0] * count
            for _ in range(count + 1):
                changed = False
                for first, second in edges[axis]:
                    need = low[first] + sizes[first, axis] + gap
                    if need > low[second] + 1e-12:
                        low[second], changed = need, True
                if not changed:
                    break
            else:
                fits = False  # still rising after n rounds: a cycle
            if not fits or any(low[k] + sizes[k, axis] > room[axis] + 1e-9
                               for k in range(count)):
                fits = False
                break
        if fits:
            return True
    return False


sizes_strategy = st.lists(st.tuples(st.floats(5, 95), st.floats(5, 135)), min_size=2,
                          max_size=4).map(np.array)


@given(sizes_strategy, st.floats(0.0, 8.0))
@settings(max_examples=60, deadline=None)
def test_the_search_agrees_with_every_relation_enumerated(sizes, gap):
    assert arranges(sizes, ROOM, gap) == every_relation_fits(sizes, ROOM, gap)


def assert_inside_the_room_keeping(corners: np.ndarray, sizes: np.ndarray, gap: float) -> None:
    """A layout (lower-left corners) inside ROOM with every pair at least ``gap`` apart."""
    assert (corners >= -1e-9).all() and (corners + sizes <= ROOM + 1e-6).all()
    i, j = np.triu_indices(len(sizes), 1)
    clearances = pair_clearances(corners + sizes / 2, sizes / 2, i, j)
    assert clearances.min() >= gap - 1e-6


@given(st.lists(st.tuples(st.floats(2, 95), st.floats(2, 135)), min_size=2,
                max_size=6).map(np.array), st.floats(0.0, 8.0))
@settings(max_examples=60, deadline=None)
def test_a_layout_found_keeps_the_gap_inside_the_room(sizes, gap):
    try:
        corners = arrangement(sizes, ROOM, gap)
    except OutOfBudget:  # a search past its budget says nothing, as it should
        return
    if corners is not None:
        assert_inside_the_room_keeping(corners, sizes, gap)


def test_four_items_no_order_keeps_three_mm_apart_though_every_three_could():
    """Two tall and two wide blocks on A4 inside 5 mm margins (benchmarks/gutter_fits.py
    --seed 1011, page 157): the widest gap all four keep is 2.5 mm, each three keep 3."""
    sizes = np.array([[94.7, 56.3], [92.7, 44.7], [52.1, 245.9], [50.2, 198.0]])
    room = np.array([200.0, 287.0])
    assert not arranges(sizes, room, 3.0)
    for left_out in range(4):
        assert arranges(np.delete(sizes, left_out, axis=0), room, 3.0)
    assert 2.4 < widest_gap(sizes, room, 3.0) < 2.6


# three or four items of one to three sizes, large for the room (most do not fit): pairs,
# threes and fours of twins
twin_sizes_strategy = st.lists(st.tuples(st.floats(25, 70), st.floats(30, 100)), min_size=1,
                               max_size=3).flatmap(
    lambda kinds: st.lists(st.sampled_from(kinds), min_size=3, max_size=4).map(np.array))


@given(twin_sizes_strategy, st.floats(0.0, 8.0))
@settings(max_examples=150, deadline=None)
def test_items_of_one_size_are_searched_once_and_still_agree_with_every_relation(sizes, gap):
    """The search tries twins in one order only (arrangements.in_order); where it finds no
    layout, the plain enumeration, which tries every labelling, finds none either."""
    assert arranges(sizes, ROOM, gap) == every_relation_fits(sizes, ROOM, gap)


two_pairs_strategy = st.tuples(st.tuples(st.floats(20, 80), st.floats(20, 110)),
                               st.tuples(st.floats(20, 80), st.floats(20, 110)),
                               st.permutations(range(4))).map(
    lambda drawn: np.array([drawn[0], drawn[0], drawn[1], drawn[1]])[list(drawn[2])])


@given(two_pairs_strategy, st.floats(0.0, 8.0))
@settings(max_examples=150, deadline=None)
def test_two_pairs_of_twins_agree_with_every_relation(sizes, gap):
    """Each size's twins keep their own order, not one across the two sizes."""
    assert arranges(sizes, ROOM, gap) == every_relation_fits(sizes, ROOM, gap)


@given(twin_sizes_strategy, st.floats(0.0, 8.0))
@settings(max_examples=60, deadline=None)
def test_a_layout_found_for_twins_keeps_the_gap_inside_the_room(sizes, gap):
    corners = arrangement(sizes, ROOM, gap)
    if corners is not None:
        assert_inside_the_room_keeping(corners, sizes, gap)


def test_six_items_with_two_pairs_alike_just_short_of_fitting_are_decided():
    """Two pairs of twins and two more items that keep at most 2.35 mm apart in the room:
    the search tried each layout once per labelling of the twins and ran out of its budget
    (it needs 55,062 steps to say no at 3 mm; 19,486 with the twins in order), so the widest
    gap was unknown."""
    sizes = np.array([[48.2, 25.86], [48.2, 25.86], [46.49, 58.8], [46.49, 58.8],
                      [35.88, 50.63], [37.87, 35.36]])
    assert not arranges(sizes, ROOM, 3.0)
    widest = widest_gap(sizes, ROOM, 3.0)
    assert widest is not None and 2.3 < widest < 2.4
    corners = arrangement(sizes, ROOM, widest)
    i, j = np.triu_indices(len(sizes), 1)
    assert pair_clearances(corners + sizes / 2, sizes / 2, i, j).min() >= widest - 1e-6
    for order in ([5, 3, 1, 4, 2, 0], [2, 0, 3, 5, 1, 4]):  # any labelling: the same answer
        assert widest_gap(sizes[order], ROOM, 3.0) == widest
