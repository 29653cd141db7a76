"""The snap's set-up in C (physics/snap_setup_kernel.c) must make what its NumPy definitions
make, bit for bit: the snapper's tables (snapping.feature_table), the rest check's pairs
(fast_forces.candidate_pairs by its sweep) and their table (blocked_axes, each pair's reach and
shares, each row's pairs), its rows' (masses, rest boxes, anchor springs); and the set-up's
shortcuts for pages without followers or without squeezed items must answer as their plain
definitions.  (benchmarks/snap_identity.py checks every move of 101 snaps against main's; these
check the units on random pages: ties on a grid, groups, inactive rows, walls that differ from
row to row.)"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from floatpage.physics.fast_forces import blocked_axes, candidate_pairs, wall_rest_box
from floatpage.physics.rest_check import group_members
from floatpage.physics.snap_setup_kernel import (
    inverse_masses, pair_tables, row_table, sweep_pairs,
)
from floatpage.physics.snapping import feature_table, filled_table


def random_page(seed: int, count: int, grid: float | None):
    """Centres, half sizes, active rows and group roots of a random page of ``count`` rows
    on a 100 x 140 mm strip (``grid``: centres and sizes on it, so edges tie)."""
    rng = np.random.default_rng(seed)
    if grid is None:
        centres = rng.uniform(0.0, 100.0, (count, 2)) * [1.0, 1.4]
        halves = rng.uniform(0.5, 25.0, (count, 2))
    else:
        centres = rng.integers(0, int(100 / grid), (count, 2)) * grid * [1.0, 1.4]
        halves = rng.integers(1, int(25 / grid), (count, 2)) * grid
    active = rng.random(count) < 0.85
    roots = np.arange(count)
    followers = rng.random(count) < 0.2  # some rows follow an earlier row: one group
    for row in np.flatnonzero(followers):
        if row > 0:
            roots[row] = roots[rng.integers(0, row)]
    return centres, halves, active, roots


@settings(max_examples=200, deadline=None, derandomize=True, database=None)
@given(seed=st.integers(0, 2 ** 32 - 1), count=st.integers(0, 40),
       grid=st.sampled_from([None, 0.25, 2.5]), axis=st.sampled_from([0, 1]),
       edges=st.lists(st.floats(-20.0, 150.0), max_size=5),
       middles=st.lists(st.floats(-20.0, 150.0), max_size=2))
def test_the_filled_table_is_feature_tables(seed, count, grid, axis, edges, middles):
    """Every cell, NaNs and infinities included, as bytes."""
    centres, halves, active, _ = random_page(seed, count, grid)
    edges, middles = np.array(edges, dtype=float), np.array(middles, dtype=float)
    found = filled_table(centres, halves, active, axis, edges, middles)
    expected = feature_table(centres, halves, active, axis, edges, middles)
    assert found.shape == expected.shape
    assert found.tobytes() == expected.tobytes()


@settings(max_examples=300, deadline=None, derandomize=True, database=None)
@given(seed=st.integers(0, 2 ** 32 - 1), count=st.integers(0, 60),
       grid=st.sampled_from([None, 0.25, 2.5]), reach=st.sampled_from([0.0, 3.0, 12.5, 40.0]))
def test_the_swept_pairs_are_candidate_pairs(seed, count, grid, reach):
    """The same pairs in the same order (the force sums add them in that order)."""
    centres, halves, active, roots = random_page(seed, count, grid)
    pairs = np.frombuffer(sweep_pairs(centres, halves, active, roots, reach), dtype=np.int64)
    i, j = candidate_pairs(centres, halves, np.flatnonzero(active), roots, reach)
    expected = np.column_stack([i, j]).astype(np.int64)
    assert pairs.tobytes() == expected.tobytes()


def numpy_tables(pair_ends, sizes, halves, inverse, near, far, page, gap):
    """RestCheck's pair table and each row's pairs as NumPy made them (main before the
    kernel): blocked_axes with no gutter, the shares, a stable sort of the ends."""
    i, j = pair_ends[:, 0], pair_ends[:, 1]
    total = inverse[i] + inverse[j]
    total = np.where(total > 0, total, 1.0)
    share_i, share_j = inverse[i] / total, inverse[j] / total
    blocked = blocked_axes(sizes, i, j, *page, 0.0, (near, far))
    reach = halves[i] + halves[j] + gap
    table = np.column_stack([reach, blocked, share_i, share_j]).astype(float).reshape(len(i), 6)
    ends = np.concatenate([i, j])
    order = np.argsort(ends, kind="stable")
    split = np.searchsorted(ends[order], np.arange(len(sizes) + 1))
    pair_ids = np.concatenate([np.arange(len(i)), np.arange(len(j))])[order]
    return table, [pair_ids[split[row]:split[row + 1]].tolist() for row in range(len(sizes))]


@settings(max_examples=200, deadline=None, derandomize=True, database=None)
@given(seed=st.integers(0, 2 ** 32 - 1), count=st.integers(0, 40),
       grid=st.sampled_from([None, 0.25]), walls=st.sampled_from(["one", "bleed", "regions"]),
       gap=st.sampled_from([0.0, 1.5, 4.0]))
def test_the_pair_tables_are_numpys(seed, count, grid, walls, gap):
    """Pages whose rows' walls are all one margin, some bleed items' (no margin) or some rows'
    regions (walls of their own); masses of zero (held groups) among them."""
    centres, halves, active, roots = random_page(seed, count, grid)
    rng = np.random.default_rng(seed + 1)
    sizes = halves * 2
    near = np.full((count, 2), 5.0)
    if walls == "bleed":
        near[rng.random(count) < 0.3] = 0.0
    far = near.copy()
    if walls == "regions":
        confined = rng.random(count) < 0.3
        near[confined] = rng.uniform(5.0, 60.0, (confined.sum(), 2))
        far[confined] = rng.uniform(5.0, 60.0, (confined.sum(), 2))
    inverse = np.where(rng.random(count) < 0.2, 0.0, 1.0 / rng.uniform(1.0, 900.0, count))
    pair_ends = np.frombuffer(sweep_pairs(centres, halves, active, roots, 30.0),
                              dtype=np.int64).reshape(-1, 2)
    page = (100.0, 140.0)
    table, lists = pair_tables(pair_ends, sizes, halves, inverse, near, far, *page, gap)
    expected_table, expected_lists = numpy_tables(pair_ends, sizes, halves, inverse, near, far,
                                                  page, gap)
    assert table == expected_table.tobytes()
    assert lists == expected_lists


def test_the_kernels_refuse_what_is_not_their_arrays():
    """Wrong arrays are errors, not reads past their ends."""
    centres, halves = np.zeros((3, 2)), np.ones((3, 2))
    active, roots = np.ones(3, dtype=bool), np.arange(3)
    with pytest.raises(ValueError):
        sweep_pairs(centres, halves, active, np.arange(2), 1.0)
    with pytest.raises(IndexError):
        sweep_pairs(centres, halves, active, np.array([0, 1, 7]), 1.0)
    with pytest.raises(TypeError):
        sweep_pairs(centres, halves, active.astype(float), roots, 1.0)
    with pytest.raises(IndexError):
        pair_tables(np.array([[0, 5]]), halves * 2, halves, np.ones(3), halves, halves,
                    10.0, 10.0, 0.0)
    from floatpage.physics.snap_setup_kernel import fill_feature_table
    with pytest.raises(ValueError):  # a row short
        fill_feature_table(np.empty((3, 15)), centres, halves, active, 0, np.zeros(1),
                           np.zeros(0))
    with pytest.raises(ValueError):  # not C-contiguous
        fill_feature_table(np.empty((4, 15))[::-1], centres, halves, active, 0, np.zeros(1),
                           np.zeros(0))


@settings(max_examples=100, deadline=None, derandomize=True, database=None)
@given(seed=st.integers(0, 2 ** 32 - 1), count=st.integers(0, 30), follow=st.booleans())
def test_group_members_are_each_roots_active_rows(seed, count, follow):
    """Pages with followers (the sort) and without (each active row alone): per row, the
    active rows whose root it is, in row order; ``several``, the roots of groups of more than
    one active row."""
    _, _, active, roots = random_page(seed, count, None)
    if not follow:
        roots = np.arange(count)
    found = group_members(roots, active)
    expected = [[member for member in range(count) if roots[member] == row and active[member]]
                for row in range(count)]
    assert [rows.tolist() for rows in found] == expected
    assert all(rows.dtype == np.int64 for rows in found)
    assert found.several.tolist() == [row for row in range(count) if len(expected[row]) > 1]


@settings(max_examples=100, deadline=None, derandomize=True, database=None)
@given(seed=st.integers(0, 2 ** 32 - 1), count=st.integers(1, 30),
       squeezed=st.sampled_from([0.0, 0.2]))
def test_the_wall_rest_box_is_its_definition(seed, count, squeezed):
    """wall_rest_box, which returns early where no item is squeezed, against its whole
    definition, on pages where none is and where some are (too large, or crowded by walls
    that differ from row to row)."""
    rng = np.random.default_rng(seed)
    page = (100.0, 140.0)
    halves = rng.uniform(0.5, 30.0, (count, 2))
    large = rng.random(count) < squeezed
    halves[large] = rng.uniform(45.0, 80.0, (large.sum(), 2))
    near, far = rng.uniform(0.0, 8.0, (count, 2)), rng.uniform(0.0, 8.0, (count, 2))
    extent = np.array(page)
    lowest, highest = halves + near, extent - halves - far
    middle = np.broadcast_to(extent / 2, halves.shape) + (near - far) / 2
    out = (2 * halves >= extent) | (lowest > highest)
    expected = np.where(out, middle, lowest), np.where(out, middle, highest)
    found = wall_rest_box(halves, *page, near, far)
    assert found[0].tobytes() == expected[0].tobytes()
    assert found[1].tobytes() == expected[1].tobytes()


def test_the_movers_flags_without_followers():
    """_Snapper's flags on pages where no row follows another (group_members' shortcut): each
    mover's own, too large per axis and may bleed, and the bytes the compiled sweeps get (a
    mover's flags, nothing for other rows)."""
    from floatpage.physics import Engine, Params
    from floatpage.physics.geometry import item_bounds
    from floatpage.physics.snapping import _Snapper, snap_limits

    from seeded_scenes import load, mixed_scene

    engine = Engine(210.0, 297.0, Params())
    load(engine, mixed_scene(20, 0.5, seed=4, page_w_mm=210.0, page_h_mm=297.0))
    bodies = engine.bodies
    rng = np.random.default_rng(4)
    bodies.bleed[:] = rng.random(bodies.count) < 0.3
    bodies.sizes[1, 0] = 300.0  # too wide for its margins
    bodies.decorative[2] = True  # not active: no mover
    page = (210.0, 297.0)
    clearance, margin, rest = snap_limits(bodies, *page, engine.params, deferred=True)
    snapper = _Snapper(bodies, page, clearance, margin, rest)
    lowest, highest = item_bounds(bodies, *page, margin)
    movers = snapper.movers.tolist()
    assert 1 in movers and 2 not in movers
    too_large, bleeds = bytearray(2 * bodies.count), bytearray(bodies.count)
    for row in movers:
        assert snapper.too_large[row] == [bool(lowest[row, axis] > highest[row, axis])
                                          for axis in (0, 1)]
        assert snapper.bleeds[row] == bool(bodies.bleed[row])
        too_large[2 * row:2 * row + 2] = bytes(snapper.too_large[row])
        bleeds[row] = snapper.bleeds[row]
    assert snapper.too_large[1] == [True, False]
    assert snapper.flag_bytes == (bytes(too_large), bytes(bleeds))


@settings(max_examples=100, deadline=None, derandomize=True, database=None)
@given(seed=st.integers(0, 2 ** 32 - 1), count=st.integers(0, 30),
       squeezed=st.sampled_from([0.0, 0.2]), gap=st.sampled_from([0.0, 1.5, 4.0]))
def test_the_rows_table_is_numpys(seed, count, squeezed, gap):
    """RestCheck's row table against the NumPy that made it: the rest boxes (wall_rest_box at
    the gap, walls that differ from row to row, items too large or crowded among them), the
    soft anchors' springs (no anchor, hard anchors: none) and the masses (groups of several
    rows, inactive and held rows, groups that do not move)."""
    centres, halves, active, roots = random_page(seed, count, None)
    rng = np.random.default_rng(seed + 2)
    large = rng.random(count) < squeezed
    halves[large] = rng.uniform(45.0, 80.0, (large.sum(), 2))
    near, far = rng.uniform(0.0, 8.0, (count, 2)), rng.uniform(0.0, 8.0, (count, 2))
    anchors = np.where(rng.random((count, 1)) < 0.5, centres, np.nan)
    hard, gammas = rng.random(count) < 0.3, rng.uniform(0.5, 2.0, count)
    page, scale = (100.0, 140.0), 0.8 * 1.3 / 1.1
    found = np.frombuffer(row_table(halves, near, far, *page, gap, anchors, hard, gammas, scale))
    low, high = wall_rest_box(halves, *page, gap / 2 + near, gap / 2 + far)
    anchored = ~np.isnan(anchors[:, 0]) & ~hard
    expected = np.column_stack([low, high, np.where(anchored, scale * gammas, 0.0),
                                np.where(anchored[:, None], anchors, 0.0)])
    assert found.tobytes() == expected.tobytes()
    sizes, free, held = halves * 2, rng.random(count) < 0.8, rng.random(count) < 0.1
    inverse = np.frombuffer(inverse_masses(sizes, roots, active, free, held))
    mass = np.bincount(roots, weights=np.where(active, sizes[:, 0] * sizes[:, 1], 0.0),
                       minlength=count)
    movable = free[roots] & ~held & active
    assert inverse.tobytes() == np.where(movable, 1.0 / np.maximum(mass[roots], 1e-12),
                                         0.0).tobytes()
