"""The guided cooling's end (physics.fast_mode.run_fast, physics.guides.GuidePulls.quiet): once
the page has spread it cools onto its guide lines, and that cooling ends as soon as the pull has
nothing left for the snap, not only on the fixed schedule (at least 55 steps at full cost)."""

from __future__ import annotations

import math
from unittest import mock

import numpy as np

from floatpage.model.layout import AT_REST_MM
from floatpage.physics import Engine, Params, fast_mode
from floatpage.physics.guides import GUIDE_HEAT, HOLD_HEAT, QUIET_PULLS, GuidePulls
from floatpage.physics.stillness import PROBE_HEAT
from seeded_scenes import load, mixed_scene

A4 = (210.0, 297.0)
# the fixed schedule's shortest guided cooling: GUIDE_HEAT / 2 down to HOLD_HEAT, 2 % a step
SCHEDULE_STEPS = math.ceil(math.log(HOLD_HEAT / (GUIDE_HEAT / 2)) / math.log(1 - 0.02))
PULL_STEPS_TO_QUIET = (QUIET_PULLS + 1) * 4  # a pull every 4th step (guides.PULL_EVERY)


def page_with(x_mm: float, y_mm: float) -> Engine:
    """One 40 x 30 mm box at (x, y) on A4: nothing pushes it, and only the page's lines guide it."""
    engine = Engine(*A4, Params())
    engine.insert("box", x_mm, y_mm, 40.0, 30.0)
    return engine


def test_a_page_whose_pull_has_nothing_to_do_stops_cooling_after_a_few_pulls():
    # Still at once, the page cools onto its guides: on the fixed schedule for at least 55
    # steps, though nothing moves; now the cooling ends once QUIET_PULLS pulls changed nothing.
    # A box centred on the page: its centre on both middle lines, every pull zero.
    quick, scheduled = page_with(105.0, 148.5), page_with(105.0, 148.5)
    report = quick.settle()
    with mock.patch.object(fast_mode, "QUIET_PULLS", math.inf):
        fixed_steps = scheduled.settle().steps
    assert fixed_steps >= SCHEDULE_STEPS
    assert report.settled and report.steps <= PULL_STEPS_TO_QUIET + 2 < SCHEDULE_STEPS
    # the same page, and at rest: the gentle run that probes a settled page moves nothing
    assert quick.bodies.centres.tolist() == scheduled.bodies.centres.tolist() == [[105.0, 148.5]]
    quick.reheat(PROBE_HEAT)
    quick.settle(finalize=False)
    assert quick.bodies.centres.tolist() == [[105.0, 148.5]]


def test_quiet_counts_pulls_that_bring_no_feature_within_a_nudge_of_its_line():
    centres = np.array([[60.0, 100.0], [150.0, 102.0]])  # b's top 2 mm below a's
    sizes = np.array([[40.0, 30.0], [40.0, 30.0]])
    pull = GuidePulls(centres, sizes, np.ones(2, bool), np.array([False, True]), A4, 5.0, 1.0)
    heat = GUIDE_HEAT / 2
    for _ in range(4 * 3):
        pull.add_to(np.zeros((2, 2)), centres, heat)
    assert pull.quiet == 3  # pulls at steps 1, 4, 8, 12: the first sets the count off
    nearer = centres.copy()
    nearer[1, 1] = 100.4  # b's top within 0.5 mm of a's: the snap can finish it
    for _ in range(4):
        pull.add_to(np.zeros((2, 2)), nearer, heat)
    assert pull.quiet == 0
    pull.start_quiet_count()
    for _ in range(8):
        pull.add_to(np.zeros((2, 2)), nearer, heat)
    assert pull.quiet == 2


def test_a_roomy_seeded_page_cools_for_fewer_steps_and_settles_as_cleanly():
    # benchmarks/guide_cost.py's "random 8 items": 265 steps on the fixed schedule, 243 now
    scene = mixed_scene(8, 0.3, seed=100, page_w_mm=127.0, page_h_mm=203.2)
    engines = []
    for quiet in (QUIET_PULLS, math.inf):
        engine = Engine(scene.page_w_mm, scene.page_h_mm, Params())
        load(engine, scene)
        with mock.patch.object(fast_mode, "QUIET_PULLS", quiet):
            report = engine.settle()
        assert report.settled and report.fits and engine.quality().ok
        engines.append((report.steps, engine))
    assert engines[0][0] < engines[1][0]
