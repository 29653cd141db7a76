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


def contact_accelerations(monkeypatch, all_pairs_up_to: int, shifts: np.ndarray):
    """The contact force of a 12-item page before and after its items move by ``shifts``,
    with the list of every pair (small pages) or the Verlet list, and the force itself."""
    from floatpage.physics import force_terms
    from seeded_scenes import load, mixed_scene

    monkeypatch.setattr(force_terms, "ALL_PAIRS_UP_TO", all_pairs_up_to)
    scene = mixed_scene(12, 0.6, seed=3)
    engine = Engine(scene.page_w_mm, scene.page_h_mm, Params())
    load(engine, scene)
    bodies = engine.bodies
    roots, _ = bodies.group_roots()
    movable = bodies.free & bodies.active
    contacts = fast_mode.fast_forces(bodies, scene.page_w_mm, scene.page_h_mm, Params(),
                                     np.random.default_rng(0), roots, movable,
                                     np.ones(bodies.count), 3.0, 2.0)[0]
    found = []
    for shift in (np.zeros_like(shifts), shifts):
        bodies.centres += shift
        acc = np.zeros((bodies.count, 2))
        contacts.add_to(acc, bodies.centres, 0.5)
        found.append(acc)
    return found, contacts


def test_a_small_page_lists_every_pair_once_and_pushes_as_the_verlet_list(monkeypatch):
    shifts = np.random.default_rng(1).uniform(-30.0, 30.0, (12, 2))  # far beyond any skin
    every, listed_all = contact_accelerations(monkeypatch, 16, shifts)
    verlet, listed_near = contact_accelerations(monkeypatch, 0, shifts)
    assert len(listed_all.i) == 12 * 11 // 2 > len(listed_near.i)
    assert listed_all.steps_since_build == 2  # built once, never again
    assert listed_near.steps_since_build == 0  # the Verlet list was rebuilt for the moved page
    for mine, theirs in zip(every, verlet):
        assert np.abs(theirs).max() > 0.1  # items touch: there is something to compare
        np.testing.assert_allclose(mine, theirs, rtol=1e-12, atol=1e-12)
