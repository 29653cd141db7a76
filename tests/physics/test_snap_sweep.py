"""The snap's sweeps in C (physics/snap_sweep_kernel.c: improve, try_lesser, options, line_of,
attempt and the memo) must make exactly the moves of _Snapper's Python methods, their
definition: the same pages snapped both ways, from the same centres, end with the same centres
bit for bit after the same number of moves.  (benchmarks/snap_identity.py checks 105 snaps
against main's; these check the kernel against the Python it replaced on pages drawn here.)"""

from __future__ import annotations

import copy

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from floatpage.physics import Engine, Params
from floatpage.physics.snapping import _Snapper, snap_limits, snap_to_guides

from seeded_scenes import load, mixed_scene


def snapped_both_ways(engine: Engine) -> list[tuple[int, bytes]]:
    """The engine's page snapped by the compiled sweeps and by the Python ones, each from its
    own copy of the bodies: (moves, centres) of each."""
    page = (engine.page_w_mm, engine.page_h_mm)
    found = []
    for compiled in (True, False):
        bodies = copy.deepcopy(engine.bodies)
        clearance, margin, rest = snap_limits(bodies, *page, engine.params)
        moves = snap_to_guides(bodies, *page, clearance, margin, engine.params.guides, rest,
                               compiled=compiled)
        found.append((moves, bodies.centres.tobytes()))
    return found


@settings(max_examples=25, deadline=None, derandomize=True, database=None)
@given(count=st.integers(3, 45), coverage=st.sampled_from([0.25, 0.4, 0.55]),
       seed=st.integers(0, 10_000),
       page=st.sampled_from([(210.0, 297.0), (297.0, 210.0), (148.0, 210.0), (127.0, 203.2)]),
       margin=st.sampled_from([0.0, 5.0]), grid=st.booleans())
def test_the_compiled_sweeps_make_the_python_sweeps_moves(count, coverage, seed, page, margin,
                                                           grid):
    """Seeded pages settled without the final pass (near misses left for the snap), some with
    their centres on a 0.25 mm grid (exact ties between candidate moves, lines shared by
    several groups: the memo's line keys, stuck lines)."""
    engine = Engine(*page, Params(margin_mm=margin))
    load(engine, mixed_scene(count, coverage, seed=seed, page_w_mm=page[0], page_h_mm=page[1]))
    engine.settle(finalize=False)
    if grid:
        engine.bodies.centres[:] = np.round(engine.bodies.centres * 4) / 4
    compiled, python = snapped_both_ways(engine)
    assert compiled == python


def followers_settled() -> list[Engine]:
    """Two anchored pages of photos with followers (groups of several rows), settled without
    their final pass: what the snap would start from."""
    from anchored_pages import random_project
    from floatpage.model.layout import engine_for_page

    engines = []
    for seed in (27100, 27101):
        project = random_project(seed, "follow")
        engine = engine_for_page(project.pages[0], project.physics)
        engine.reheat()
        engine.settle(finalize=False)
        engines.append(engine)
    return engines


def test_the_compiled_sweeps_on_pages_with_followers_and_many_moves():
    """Groups of several rows (followers of an anchored page), and a 120-item page whose snap
    makes hundreds of moves (the memo recalled and invalidated many times, try_lesser's
    moves): the same moves both ways, and enough of them to mean something."""
    engines = followers_settled()
    big = Engine(297.0, 210.0, Params())
    load(big, mixed_scene(120, 0.4, seed=3001, page_w_mm=297.0, page_h_mm=210.0))
    big.settle(finalize=False)
    engines.append(big)
    for engine in engines:
        compiled, python = snapped_both_ways(engine)
        assert compiled == python
        assert compiled[0] > 5
    assert snapped_both_ways(big)[0][0] > 100


def test_a_sweep_refuses_rows_that_are_not_movers():
    engine = Engine(210.0, 297.0, Params())
    load(engine, mixed_scene(6, 0.3, seed=5))
    bodies = engine.bodies
    clearance, margin, rest = snap_limits(bodies, 210.0, 297.0, engine.params)
    sweep = _Snapper(bodies, (210.0, 297.0), clearance, margin, rest).compiled()
    try:
        sweep.improve([bodies.count + 3], 0)
    except IndexError:
        pass
    else:
        raise AssertionError("a row outside the page was swept")


def engines_with_moves() -> list[Engine]:
    """Pages whose first sweeps move many groups: two of followers (groups of several rows),
    a 45-item page, and the same with its centres on a 0.25 mm grid (features exactly a
    window apart)."""
    engines = followers_settled()
    for grid in (False, True):
        engine = Engine(297.0, 210.0, Params())
        load(engine, mixed_scene(45, 0.45, seed=2003, page_w_mm=297.0, page_h_mm=210.0))
        engine.settle(finalize=False)
        if grid:
            engine.bodies.centres[:] = np.round(engine.bodies.centres * 4) / 4
        engines.append(engine)
    return engines


def test_the_compiled_near_finds_the_python_near():
    """Sweep.near (C) against _Snapper.near (NumPy, its definition) on the same snapper after
    the compiled sweeps' moves: every moved group alone, all of them, and random lists of them
    with repeats (a group moved twice in a sweep), on both axes, in several windows (the
    snap's, none, and a wide one)."""
    rng = np.random.default_rng(16)
    asked = 0
    for engine in engines_with_moves():
        page = (engine.page_w_mm, engine.page_h_mm)
        bodies = copy.deepcopy(engine.bodies)
        clearance, margin, rest = snap_limits(bodies, *page, engine.params)
        snapper = _Snapper(bodies, page, clearance, margin, rest)
        sweep = snapper.compiled()
        moved = [sweep.improve(snapper.movers.tolist(), axis) for axis in (0, 1)]
        assert moved[0] and moved[1]
        snap_window = snapper.window
        for window in (snap_window, 0.0, 40.0):
            snapper.window = window
            for axis in (0, 1):
                lists = [[root] for root in moved[axis]] + [moved[axis], []]
                lists += [rng.choice(moved[axis], size=rng.integers(1, 6)).tolist()
                          for _ in range(10)]
                for roots in lists:
                    assert sweep.near(roots, axis, window) == snapper.near(roots, axis).tolist()
                    asked += 1
        snapper.window = snap_window
    assert asked > 200


def test_the_compiled_near_refuses_groups_that_never_moved():
    engine = Engine(210.0, 297.0, Params())
    load(engine, mixed_scene(6, 0.3, seed=5))
    bodies = engine.bodies
    clearance, margin, rest = snap_limits(bodies, 210.0, 297.0, engine.params)
    snapper = _Snapper(bodies, (210.0, 297.0), clearance, margin, rest)
    sweep = snapper.compiled()
    for bad, error in (([snapper.movers[0].item()], KeyError), ([bodies.count + 3], IndexError)):
        try:
            sweep.near(bad, 0, snapper.window)
        except error:
            pass
        else:
            raise AssertionError(f"near of {bad} answered")
