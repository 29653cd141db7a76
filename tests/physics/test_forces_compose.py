"""Forces are terms in a list the integrator sums: a new one needs no change to a step loop."""

import numpy as np

from floatpage.physics import fast_mode
from floatpage.physics.engine import Engine
from floatpage.physics.params import Params


class PullRight:
    """A test force: every item accelerates to the right."""

    def add_to(self, acc, centres, heat):
        acc[:, 0] += 1.0


def x_after_steps(steps: int) -> float:
    engine = Engine(210.0, 297.0, Params())
    engine.insert("a", 105.0, 150.0, 30.0, 30.0)
    engine.insert("b", 140.0, 150.0, 30.0, 30.0)
    engine.advance(steps)
    return float(engine.bodies.centres[0, 0])


def test_an_extra_force_in_the_fast_list_moves_items_without_touching_the_loop(monkeypatch):
    without = x_after_steps(40)
    built = fast_mode.fast_forces
    monkeypatch.setattr(fast_mode, "fast_forces",
                        lambda *args, **kwargs: built(*args, **kwargs) + [PullRight()])
    with_pull = x_after_steps(40)
    assert with_pull > without + 1.0


def fast_list(params: Params) -> list[str]:
    engine = Engine(210.0, 297.0, params)
    engine.insert("a", 60.0, 150.0, 30.0, 30.0)
    engine.insert("b", 70.0, 150.0, 30.0, 30.0)
    bodies = engine.bodies
    roots, _ = bodies.group_roots()
    movable = bodies.free & bodies.active
    forces = fast_mode.fast_forces(bodies, 210.0, 297.0, params, np.random.default_rng(0),
                                   roots, movable, np.ones(2), 3.0, 2.0)
    return [type(force).__name__ for force in forces]


def test_the_fast_list_holds_contacts_walls_guides_and_only_needed_springs():
    assert fast_list(Params()) == ["ContactPushes", "WallPushes", "GuidePulls"]


def test_guides_at_strength_zero_leave_the_list():
    assert fast_list(Params(guides=0.0)) == ["ContactPushes", "WallPushes"]
