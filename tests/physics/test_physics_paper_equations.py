"""Each of the paper's equations against values worked out by hand on 2 to 4 items."""

import math

import numpy as np
import pytest

from floatpage.physics.euler import damping_for_count, euler_step, kinetic_energy
from floatpage.physics.paper_forces import (
    SIGMA_MIN_MM, anchor_springs, axis_distance, contact_reach, euclidean_distance,
    pair_displacements,
    repulsion, wall_forces,
)


def test_repulsion_two_items_eq2():
    # A at (0,0) 2x3 (q=6), B at (3,4) 1x1 (q=1); sigma = 5, alpha = 150.
    centres = np.array([[0.0, 0.0], [3.0, 4.0]])
    sizes = np.array([[2.0, 3.0], [1.0, 1.0]])
    forces = repulsion(centres, sizes, alpha=150.0, distance="euclidean")
    # On A: q_B alpha / 25 * (-3, -4) / 5 = 6 * (-0.6, -0.8)
    assert forces[0] == pytest.approx([-3.6, -4.8])
    # On B: q_A alpha / 25 * (3, 4) / 5 = 36 * (0.6, 0.8): the larger charge pushes harder
    assert forces[1] == pytest.approx([21.6, 28.8])


def test_resultant_is_the_sum_eq3():
    # A at the origin, B 10 to the right, C 10 below; unit squares, alpha = 100.
    centres = np.array([[0.0, 0.0], [10.0, 0.0], [0.0, 10.0]])
    sizes = np.ones((3, 2))
    forces = repulsion(centres, sizes, alpha=100.0, distance="euclidean")
    assert forces[0] == pytest.approx([-1.0, -1.0])  # (-1, 0) from B plus (0, -1) from C
    # On B: from A (+1, 0); from C at distance sqrt(200): 100/200 * (10, -10)/sqrt(200)
    c = 100 / 200 / math.sqrt(200) * 10
    assert forces[1] == pytest.approx([1.0 + c, -c])


def test_euclidean_distance_eq7():
    centres = np.array([[1.0, 1.0], [4.0, 5.0], [1.0, 1.0]])
    sigma = euclidean_distance(*pair_displacements(centres))
    assert sigma[0, 1] == pytest.approx(5.0)
    assert sigma[1, 0] == pytest.approx(5.0)
    assert sigma[0, 2] == 0.0


@pytest.mark.parametrize(
    "b_centre, expected",
    [
        ((4.0, 0.5), 4.0),  # y extents meet, x apart: only |dx| counts
        ((0.5, 5.0), 5.0),  # x extents meet, y apart: only |dy| counts
        ((3.0, 4.0), 5.0),  # apart on both axes: euclidean
        ((0.5, 0.5), math.sqrt(0.5)),  # overlapping: euclidean
    ],
)
def test_axis_distance_eq8(b_centre, expected):
    centres = np.array([[0.0, 0.0], b_centre])
    sizes = np.array([[2.0, 2.0], [2.0, 2.0]])
    sigma = axis_distance(*pair_displacements(centres), contact_reach(sizes))
    assert sigma[0, 1] == pytest.approx(expected)
    assert sigma[1, 0] == pytest.approx(expected)


def test_axis_distance_changes_the_force_eq2_with_eq8():
    # Side by side: sigma = |dx| = 4, so on A: 150 * 4 / 16 * (-4, -0.5) / 4
    centres = np.array([[0.0, 0.0], [4.0, 0.5]])
    sizes = np.array([[2.0, 2.0], [2.0, 2.0]])
    axis = repulsion(centres, sizes, alpha=150.0, distance="axis")
    euclid = repulsion(centres, sizes, alpha=150.0, distance="euclidean")
    assert axis[0] == pytest.approx([-37.5, -4.6875])
    sigma = math.sqrt(16.25)
    assert euclid[0] == pytest.approx(np.array([-4.0, -0.5]) * 600 / sigma**3)


def test_repulsion_ignores_sources_switched_off():
    centres = np.array([[0.0, 0.0], [3.0, 4.0]])
    sizes = np.array([[2.0, 3.0], [1.0, 1.0]])
    forces = repulsion(centres, sizes, 150.0, "euclidean", sources=np.array([True, False]))
    assert forces[0] == pytest.approx([0.0, 0.0])  # B does not push
    assert forces[1] == pytest.approx([21.6, 28.8])  # A still does


def test_coincident_items_get_a_finite_force():
    centres = np.array([[5.0, 5.0], [5.0, 5.0]])
    forces = repulsion(centres, np.ones((2, 2)), 150.0, "euclidean")
    assert np.isfinite(forces).all()
    assert SIGMA_MIN_MM > 0


def test_walls_push_with_the_items_own_charge_4_4():
    # Page 100 x 50, item at (20, 10) of 2 x 3 (q = 6), alpha = 1.
    forces = wall_forces(np.array([[20.0, 10.0]]), np.array([[2.0, 3.0]]), 100.0, 50.0, 1.0)
    assert forces[0, 0] == pytest.approx(6 / 20**2 - 6 / 80**2)  # left minus right
    assert forces[0, 1] == pytest.approx(6 / 10**2 - 6 / 40**2)  # top minus bottom


def test_walls_push_an_escaped_item_further_out_as_in_the_paper():
    forces = wall_forces(np.array([[-5.0, 25.0]]), np.array([[2.0, 3.0]]), 100.0, 50.0, 1.0)
    assert forces[0, 0] < 0  # the "thrown off the page for good"


def test_anchor_spring_eq6():
    centres = np.array([[10.0, 10.0], [0.0, 0.0]])
    anchors = np.array([[13.0, 6.0], [np.nan, np.nan]])
    springs = anchor_springs(centres, anchors, np.array([0.5, 1.0]), beta=20.0)
    assert springs[0] == pytest.approx([30.0, -40.0])  # 0.5 * 20 * (3, -4)
    assert springs[1] == pytest.approx([0.0, 0.0])  # unanchored


def test_euler_eq4_eq5():
    centres, velocities = euler_step(np.array([[1.0, 2.0]]), np.array([[3.0, -1.0]]),
                                     np.array([[10.0, 20.0]]), dt=0.1, delta=0.5)
    assert centres[0] == pytest.approx([1.3, 1.9])  # x + dt v(t)
    assert velocities[0] == pytest.approx([2.0, 0.5])  # (v + dt F)(1 - delta)


def test_kinetic_energy_eq1():
    sizes = np.array([[2.0, 3.0], [1.0, 1.0], [4.0, 4.0]])
    velocities = np.array([[1.0, 2.0], [3.0, 0.0], [1.0, 1.0]])
    assert kinetic_energy(sizes, velocities) == pytest.approx(6 * 5 + 1 * 9 + 16 * 2)
    assert kinetic_energy(sizes, velocities, np.array([True, True, False])) == pytest.approx(39)


def test_damping_grows_with_the_item_count_4_7():
    assert damping_for_count(0.01, 3) == pytest.approx(0.01)
    assert damping_for_count(0.01, 20) == pytest.approx(1 - 0.99**2)
    assert damping_for_count(0.01, 200) > damping_for_count(0.01, 50) > 0.01
    assert damping_for_count(0.01, 10_000) < 1.0
