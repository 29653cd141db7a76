"""The paper mode through the Engine: one step against the equations, section 4.7's cooling,
held, decorative and anchored items, and page-size scaling."""

import numpy as np
import pytest

from floatpage.physics import Engine, Params, page_scale
from floatpage.physics.euler import damping_for_count
from floatpage.physics.paper_mode import paper_forces

A4 = (210.0, 297.0)
PAPER = Params(mode="paper")


def two_items(params=PAPER, page=A4):
    engine = Engine(*page, params)
    engine.insert("a", 80, 100, 40, 30)
    engine.insert("b", 120, 110, 20, 50)
    return engine


def test_one_step_is_explicit_euler_on_the_summed_forces():
    engine = two_items()
    before = engine.bodies.centres.copy()
    forces = paper_forces(engine.bodies, *A4, PAPER, heat=1.0)
    assert engine.advance(1) == 1
    delta = damping_for_count(PAPER.delta, 2)
    # (4) with v(t) = 0: positions unchanged; (5): v = dt F (1 - delta)
    assert engine.bodies.centres == pytest.approx(before)
    assert engine.bodies.velocities == pytest.approx(PAPER.dt * forces * (1 - delta))
    velocities = engine.bodies.velocities.copy()
    engine.advance(1)
    assert engine.bodies.centres == pytest.approx(before + PAPER.dt * velocities)


def test_items_repel_each_other():
    engine = two_items()
    gap_before = abs(engine.positions()["b"][0] - engine.positions()["a"][0])
    engine.advance(2000)
    assert abs(engine.positions()["b"][0] - engine.positions()["a"][0]) > gap_before


def test_heat_decays_each_step_and_an_operation_resets_it():
    engine = two_items()
    engine.advance(3)
    assert engine.heat == pytest.approx(0.99**3)
    engine.move("a", 50, 60)
    assert engine.heat == 1.0
    assert not engine.settled


def test_many_steps_per_call_by_default():
    engine = two_items(Params(mode="paper", heat_decay=0.0))
    assert engine.advance() == PAPER.steps_per_frame


def test_cooling_settles_the_page():
    engine = two_items()
    report = engine.settle(finalize=False)
    assert report.settled and engine.settled
    assert engine.advance() == 0  # nothing to do once settled


def test_held_item_pushes_but_is_not_pushed():
    engine = two_items()
    engine.hold("a")
    a_before, b_before = engine.positions()["a"], engine.positions()["b"]
    engine.advance(500)
    assert engine.positions()["a"] == a_before
    assert engine.positions()["b"] != b_before
    engine.release("a")
    engine.advance(500)
    assert engine.positions()["a"] != a_before


def test_decorative_item_takes_no_part():
    plain = two_items()
    decorated = two_items()
    decorated.insert("frame", 100, 105, 150, 150, decorative=True)
    plain.advance(300)
    decorated.advance(300)
    assert decorated.positions()["frame"] == (100.0, 105.0)
    for item in ("a", "b"):
        assert decorated.positions()[item] == pytest.approx(plain.positions()[item])


def test_hard_anchor_holds_the_position_after_every_step():
    engine = two_items()
    engine.anchor_point("a", 90, 100, hard=True)
    engine.advance(500)
    assert engine.positions()["a"] == (90.0, 100.0)


def test_soft_anchor_pulls_towards_its_point():
    free, anchored = two_items(), two_items()
    anchored.anchor_point("a", 80, 100, gamma=1.0)
    free.advance(2000)
    anchored.advance(2000)
    distance = lambda e: np.hypot(*(np.subtract(e.positions()["a"], (80, 100))))  # noqa: E731
    assert distance(anchored) < distance(free)


def test_follower_keeps_its_offset_from_the_target():
    engine = two_items()
    engine.anchor_to("b", "a", 35, 5)
    engine.advance(800)
    ax, ay = engine.positions()["a"]
    assert engine.positions()["b"] == pytest.approx((ax + 35, ay + 5))


def test_page_scale():
    assert page_scale(*A4) == pytest.approx(1.0)
    card = page_scale(127.0, 203.2)  # 5 x 8 inches
    assert card == pytest.approx(np.sqrt(127.0 * 203.2 / (210 * 297)))


def test_a_scaled_page_moves_alike():
    """Paper mode on A5 (A4 scaled by 1/sqrt 2) traces the A4 motion scaled by the same factor."""
    s = 1 / np.sqrt(2)
    big = two_items()
    small = Engine(210 * s, 297 * s, PAPER)
    small.insert("a", 80 * s, 100 * s, 40 * s, 30 * s)
    small.insert("b", 120 * s, 110 * s, 20 * s, 50 * s)
    big.advance(400)
    small.advance(400)
    assert small.bodies.centres == pytest.approx(big.bodies.centres * s, rel=1e-9)


def test_items_on_one_point_separate_deterministically():
    def run(seed):
        engine = Engine(*A4, Params(mode="paper", seed=seed))
        engine.insert("a", 100, 100, 30, 30)
        engine.insert("b", 100, 100, 30, 30)
        engine.advance(500)
        return engine.positions()

    first = run(0)
    assert first["a"] != first["b"]
    assert run(0) == first and run(1) != first
