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


@given(st.lists(st.tuples(st.floats(2, 95), st.floats(2, 135)), min_size=2,
                max_size=6).map(np.array), st.floats(0.0, 8.0))
@settings(max_examples=60, deadline=None)
def test_a_layout_found_keeps_the_gap_inside_the_room(sizes, gap):
    try:
        corners = arrangement(sizes, ROOM, gap)
    except OutOfBudget:  # six items, two pairs alike, 1 mm short: says nothing, as it should
        return
    if corners is None:
        return
    assert (corners >= -1e-9).all() and (corners + sizes <= ROOM + 1e-6).all()
    i, j = np.triu_indices(len(sizes), 1)
    clearances = pair_clearances(corners + sizes / 2, sizes / 2, i, j)
    assert clearances.min() >= gap - 1e-6


def test_four_items_no_order_keeps_three_mm_apart_though_every_three_could():
    """Two tall and two wide blocks on A4 inside 5 mm margins (benchmarks/gutter_fits.py
    --seed 1011, page 157): the widest gap all four keep is 2.5 mm, each three keep 3."""
    sizes = np.array([[94.7, 56.3], [92.7, 44.7], [52.1, 245.9], [50.2, 198.0]])
    room = np.array([200.0, 287.0])
    assert not arranges(sizes, room, 3.0)
    for left_out in range(4):
        assert arranges(np.delete(sizes, left_out, axis=0), room, 3.0)
    assert 2.4 < widest_gap(sizes, room, 3.0) < 2.6
