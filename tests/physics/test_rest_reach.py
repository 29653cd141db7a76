"""RestCheck.reached_by (the groups a moved body touches, their rows and their pairs) is worked
out by rest_check_kernel.reach_of, compiled; RestCheck.reach_python, in Python sets, is its
definition.  The compiled sweeps read the answer as the rest check's sums' inputs, so it must be
the same lists in the same order, or a snap would check other pairs than it did before."""

from __future__ import annotations

import numpy as np

from floatpage.physics import Engine, Params
from floatpage.physics.snapping import snap_limits

from seeded_scenes import load, mixed_scene


def checks() -> list:
    """Rest checks of pages a snap starts from: two of followers (groups of several rows, some
    items not movable), a crowded A5 page and a roomy A4 one."""
    from anchored_pages import random_project
    from floatpage.model.layout import engine_for_page

    engines = []
    for seed in (27100, 27101):
        project = random_project(seed, "follow")
        engine = engine_for_page(project.pages[0], project.physics)
        engine.reheat()
        engine.settle(finalize=False)
        engines.append(engine)
    for count, coverage, seed, page in ((40, 0.5, 2022, (148.0, 210.0)),
                                        (25, 0.3, 7, (210.0, 297.0))):
        engine = Engine(*page, Params())
        load(engine, mixed_scene(count, coverage, seed=seed, page_w_mm=page[0],
                                 page_h_mm=page[1]))
        engine.settle(finalize=False)
        engines.append(engine)
    found = []
    for engine in engines:
        page = (engine.page_w_mm, engine.page_h_mm)
        _, _, rest = snap_limits(engine.bodies, *page, engine.params)
        found.append(rest)
    return found


def test_the_compiled_reach_is_the_python_reach():
    """Every group's members (as the sweeps ask), single rows, and random sets of rows with
    repeats: the same groups (dtype and all), rows and pairs, in the same order."""
    rng = np.random.default_rng(16)
    several = 0
    for rest in checks():
        roots = rest.roots
        asked = [np.flatnonzero(roots == root) for root in np.unique(roots)]
        asked += [np.array([row]) for row in range(rest.bodies.count)]
        asked += [rng.integers(0, rest.bodies.count, size=rng.integers(1, 6))
                  for _ in range(20)]
        for members in asked:
            members = members.astype(np.int64)
            groups, rows, pairs = rest.reached_by(members)
            expected_groups, expected_rows, expected_pairs = rest.reach_python(members)
            assert groups.dtype == expected_groups.dtype
            assert groups.tolist() == expected_groups.tolist(), members
            assert rows == expected_rows and pairs == expected_pairs, members
            several += len(groups) > 1
    assert several > 50  # bodies that touch others, not only themselves


def test_the_compiled_reach_refuses_rows_outside_the_page():
    rest = checks()[-1]
    for members in (np.array([rest.bodies.count], dtype=np.int64),
                    np.array([-1], dtype=np.int64)):
        try:
            rest.reached_by(members)
        except IndexError:
            pass
        else:
            raise AssertionError("a row outside the page was reached")
