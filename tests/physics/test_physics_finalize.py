"""The no-overlap pass on small pages."""

import numpy as np
import pytest

from physics import Engine, Params

A4 = (210.0, 297.0)


def pair(held=False):
    engine = Engine(*A4, Params(gutter_mm=3.0))
    engine.insert("a", 50, 50, 20, 20)
    engine.insert("b", 60, 52, 20, 20)
    if held:
        engine.hold("a")
    return engine


def test_overlapping_pair_moves_apart_on_the_cheaper_axis_by_halves():
    engine = pair()
    assert engine.finalize()
    (ax, ay), (bx, by) = engine.positions()["a"], engine.positions()["b"]
    # x needs 20 + 3 - 10 = 13 mm, y would need 21: equal areas share the move on x
    assert (ay, by) == (50.0, 52.0)
    assert (ax + bx) / 2 == pytest.approx(55.0)
    assert 3.0 < bx - ax - 20 < 3.5  # the gutter, plus a little room for rounding


def test_held_item_stays_put():
    engine = pair(held=True)
    assert engine.finalize()
    assert engine.positions()["a"] == (50.0, 50.0)
    assert 73.0 < engine.positions()["b"][0] < 73.5


def test_items_are_brought_inside_the_page():
    engine = Engine(*A4)
    engine.insert("out", -30, 400, 40, 40)
    assert engine.finalize()
    assert engine.positions()["out"] == (20.0, 277.0)


def test_touching_items_with_no_gutter_are_nudged_clear_of_rounding():
    engine = Engine(*A4, Params(gutter_mm=0.0))
    engine.insert("a", 50, 50, 20, 20)
    engine.insert("b", 70, 50, 20, 20)
    assert engine.finalize()
    (ax, _), (bx, _) = engine.positions()["a"], engine.positions()["b"]
    assert 0.01 < bx - ax - 20 < 0.5


def test_an_impossible_page_reports_failure_and_stays_finite():
    engine = Engine(50, 50)
    engine.insert("a", 25, 25, 40, 40)
    engine.insert("b", 26, 25, 40, 40)
    assert not engine.finalize()
    assert np.isfinite(engine.bodies.centres).all()
    assert not engine.quality().off_page


def test_a_clean_page_is_left_alone():
    engine = Engine(*A4, Params(gutter_mm=3.0))
    engine.insert("a", 50, 50, 20, 20)
    engine.insert("b", 73.5, 50, 20, 20)
    engine.insert("c", 50, 73.5, 20, 20)
    before = engine.positions()
    assert engine.finalize()
    assert engine.positions() == before
