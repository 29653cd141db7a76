"""The fast mode's force terms on 2 to 3 items."""

import numpy as np
import pytest

from floatpage.physics import fast_forces
from floatpage.physics.fast_forces import candidate_pairs, contact_pushes, target_gap, wall_pushes


def test_target_gap_solves_the_fill_equation():
    sizes = np.array([[40.0, 30.0], [20.0, 50.0], [10.0, 10.0]])
    gap = target_gap(sizes, 210, 297, gutter_mm=3.0, fill=0.9)
    inflated = ((sizes + gap).prod(axis=1)).sum()
    assert inflated == pytest.approx(0.9 * 210 * 297)


def test_target_gap_is_the_gutter_or_more_where_the_gutter_fits_at_the_fill():
    few = np.array([[40.0, 30.0], [20.0, 50.0], [10.0, 10.0]])
    assert target_gap(few, 210, 297, gutter_mm=3.0) > 3.0
    # the gutter exactly: the halos at 3 mm fill 90 % of the page
    side = np.sqrt(0.9 * 210 * 297 / 100) - 3.0
    assert target_gap(np.full((100, 2), side), 210, 297, gutter_mm=3.0) == pytest.approx(3.0)


def test_target_gap_below_the_gutter_is_the_gap_that_fits_for_a_crowd_where_the_gutter_does_not():
    """A crowd (more items than relocation takes) whose gutter-wide halos cannot fit is given
    halos of the gap that does, so the physics spreads it instead of pressing it into itself;
    one that fills the page alone, none.  A page of fewer items keeps the gutter's halos."""
    crowd = np.full((2000, 2), 2.5)  # 12,500 mm^2 on 62,370: 5.5 mm each with the gutter
    gap = target_gap(crowd, 210, 297, gutter_mm=3.0)
    assert 0.0 < gap < 3.0
    assert ((crowd + gap).prod(axis=1)).sum() == pytest.approx(0.9 * 210 * 297)
    assert target_gap(np.full((200, 2), 18.0), 210, 297, gutter_mm=3.0) == 0.0  # 64,800 mm^2
    assert target_gap(np.full((100, 2), 23.0), 210, 297, gutter_mm=3.0) == 3.0  # few: as before
    assert target_gap(np.full((30, 2), 50.0), 210, 297, gutter_mm=3.0) == 3.0  # over-full, few


def test_no_push_between_items_further_apart_than_the_gap():
    centres = np.array([[0.0, 0.0], [20.0, 0.0]])  # 10 mm apart edge to edge
    halves = np.full((2, 2), 5.0)
    pushes = contact_pushes(centres, halves, np.array([0]), np.array([1]), gap=9.0)
    assert pushes == pytest.approx(np.zeros((1, 2)))


def test_side_by_side_items_push_apart_mostly_along_x():
    centres = np.array([[0.0, 0.0], [9.0, 0.5]])
    halves = np.full((2, 2), 5.0)
    pushes = contact_pushes(centres, halves, np.array([0]), np.array([1]), gap=2.0)
    # grown by the gap, the pair penetrates by 3 mm on x and 11.5 mm on y
    axis_x = 3.0 * 11.5**4 / (3.0**4 + 11.5**4)
    axis_y = 11.5 * 3.0**4 / (3.0**4 + 11.5**4)
    depth = np.hypot(axis_x, axis_y)
    unit = np.array([9.0, 0.5]) / np.hypot(9.0, 0.5)
    expected = np.array([axis_x, axis_y]) + fast_forces.RADIAL_SHARE * depth * unit
    assert pushes[0] == pytest.approx(expected)
    assert pushes[0, 0] > 10 * abs(pushes[0, 1])


def test_push_on_j_points_away_from_i():
    centres = np.array([[10.0, 10.0], [8.0, 4.0]])  # j up and to the left
    halves = np.full((2, 2), 4.0)
    push = contact_pushes(centres, halves, np.array([0]), np.array([1]), gap=0.0)[0]
    assert push[1] < 0 and push[0] <= 0


def test_walls_push_item_edges_inwards():
    centres = np.array([[4.0, 50.0], [97.0, 96.0], [50.0, 50.0]])
    halves = np.full((3, 2), 3.0)
    pushes = wall_pushes(centres, halves, 100.0, 100.0, margin=2.0)
    assert pushes[0] == pytest.approx([1.0, 0.0])  # left edge at 1 mm, wants 2
    assert pushes[1] == pytest.approx([-2.0, -1.0])  # right and bottom edges too close
    assert pushes[2] == pytest.approx([0.0, 0.0])


def test_an_item_wider_than_the_page_is_pulled_to_its_middle():
    pushes = wall_pushes(np.array([[30.0, 50.0]]), np.array([[60.0, 5.0]]), 100.0, 100.0, 2.0)
    assert pushes[0] == pytest.approx([20.0, 0.0])


def test_candidate_pairs_skip_far_pairs_and_rigid_groups():
    centres = np.array([[0.0, 0.0], [12.0, 0.0], [100.0, 100.0], [0.0, 12.0]])
    halves = np.full((4, 2), 5.0)
    rows = np.arange(4)
    groups = np.array([0, 1, 2, 0])  # row 3 follows row 0
    i, j = candidate_pairs(centres, halves, rows, groups, reach=3.0)
    assert sorted(zip(i.tolist(), j.tolist())) == [(0, 1), (1, 3)]


def test_sweep_and_prune_finds_exactly_the_brute_force_pairs():
    rng = np.random.default_rng(0)
    for trial in range(100):
        count = int(rng.integers(0, 40))
        centres = rng.uniform(0, 100, (count, 2))
        halves = rng.uniform(0.5, 20, (count, 2))
        if count > 2 and trial % 5 == 0:
            centres[1] = centres[0]  # a tie in left edges
        rows = np.flatnonzero(rng.random(count) < 0.8)
        groups = np.arange(count)
        if count > 3:
            groups[3] = 0
        reach = float(rng.uniform(0.1, 10))
        i, j = candidate_pairs(centres, halves, rows, groups, reach)
        upper_i, upper_j = np.triu_indices(len(rows), k=1)
        a, b = rows[upper_i], rows[upper_j]
        clear = np.abs(centres[b] - centres[a]) - halves[a] - halves[b]
        near = (clear < reach).all(axis=1) & (groups[a] != groups[b])
        expected = set(zip(a[near].tolist(), b[near].tolist()))
        assert set(zip(i.tolist(), j.tolist())) == expected
        assert len(i) == len(expected)


@pytest.mark.parametrize("count, coverage, reach", [(6_000, 0.3, 5.0), (2_500, 0.9, 1.0),
                                                   (3_000, 0.5, 12.0)])
def test_the_grid_finds_the_sweeps_pairs_in_the_sweeps_order(monkeypatch, count, coverage, reach):
    """On big pages the neighbour list comes from a grid; the physics must sum the very same
    pairs in the very same order, or a settled page would settle differently."""
    from floatpage.physics import Engine, Params
    from seeded_scenes import load, mixed_scene

    scene = mixed_scene(count, coverage, seed=3)
    engine = Engine(scene.page_w_mm, scene.page_h_mm, Params())
    load(engine, scene)
    bodies = engine.bodies
    rows = np.arange(bodies.count)
    groups = rows.copy()
    groups[1::7] = groups[0::7][:len(groups[1::7])]  # some rigid groups, left out either way
    found = {}
    for name, threshold in (("sweep", 10**9), ("grid", 1)):
        monkeypatch.setattr(fast_forces, "GRID_FROM_ITEMS", threshold)
        found[name] = fast_forces.candidate_pairs(bodies.centres, bodies.sizes / 2, rows, groups,
                                                  reach)
    assert len(found["grid"][0]) > 0
    assert np.array_equal(found["sweep"][0], found["grid"][0])
    assert np.array_equal(found["sweep"][1], found["grid"][1])
