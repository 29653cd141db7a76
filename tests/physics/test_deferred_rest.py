"""The snap's rest check built when a move first asks (physics.deferred_rest): a snap that never
asks never builds it, and one that does makes the very moves of the check built at its start,
by the compiled sweeps and by the Python ones, also when nudges came before the first ask."""

from __future__ import annotations

import copy

import numpy as np

import floatpage.physics.snapping as snapping
from floatpage.physics import Engine, Params
from floatpage.physics.deferred_rest import DeferredRest
from floatpage.physics.rest_check import RestCheck
from floatpage.physics.snapping import snap_limits, snap_page, snap_to_guides

from seeded_scenes import load, mixed_scene

PAGES = [(count, coverage, seed, page) for seed, (count, coverage, page) in enumerate([
    (5, 0.5, (210.0, 297.0)), (8, 0.3, (127.0, 203.2)), (12, 0.6, (215.9, 279.4)),
    (20, 0.5, (210.0, 297.0)), (30, 0.55, (297.0, 420.0)), (45, 0.4, (148.0, 210.0))])]
# its centres on a 0.25 mm grid, this page's snap nudges items before its first longer move
# (of the 101 snaps of benchmarks/snap_identity.py, 10 build their check after moves)
NUDGED_FIRST = (8, 0.3, 12, (127.0, 203.2))


def unsnapped(count: int, coverage: float, seed: int, page: tuple[float, float],
              grid: bool = False) -> Engine:
    """A seeded page settled without its final pass: near misses left for a snap (``grid``:
    its centres then rounded to 0.25 mm)."""
    engine = Engine(*page, Params())
    load(engine, mixed_scene(count, coverage, seed=seed, page_w_mm=page[0], page_h_mm=page[1]))
    engine.settle(finalize=False)
    if grid:
        engine.bodies.centres[:] = np.round(engine.bodies.centres * 4) / 4
    return engine


class Counted(RestCheck):
    """A rest check that counts how often one is made."""

    made = 0

    def __init__(self, *args, **kwargs):
        type(self).made += 1
        super().__init__(*args, **kwargs)


def test_a_snap_that_asks_no_rest_check_builds_none(monkeypatch):
    """A page snapped once and snapped again (the probe's snap): the second tries no move
    beyond a nudge on most pages and must not pay for the rest check's pairs and tables; the
    first always asks (its moves are longer), and builds one check."""
    monkeypatch.setattr(snapping, "RestCheck", Counted)
    unasked = 0
    for count, coverage, seed, page in PAGES:
        engine = unsnapped(count, coverage, seed, page)
        bodies, params = engine.bodies, engine.params
        Counted.made = 0
        assert snap_page(bodies, *page, params) > 0
        assert Counted.made == 1
        Counted.made = 0
        snap_page(bodies, *page, params)
        assert Counted.made <= 1
        unasked += Counted.made == 0
    assert unasked >= 3


def test_a_deferred_rest_check_makes_the_moves_of_one_built_at_the_start(monkeypatch):
    """The same pages snapped with the check built at the start (snap_limits' default) and
    deferred, compiled and in Python: the same moves to the same floats; on some pages the
    deferred check was first asked after moves had been made (its pairs then found at the
    centres the snap started from).  A move, not the snap's putting the page on the save's
    grid before its first (_Snapper.onto_grid), which every check here is built after."""
    late = 0
    gridded = {}  # per page snapped: its centres once on the grid
    onto_grid = snapping._Snapper.onto_grid

    def noting_grid(snapper):
        onto_grid(snapper)
        gridded[id(snapper.bodies)] = snapper.bodies.centres.copy()
    monkeypatch.setattr(snapping._Snapper, "onto_grid", noting_grid)
    for count, coverage, seed, page, grid in [(*p, False) for p in PAGES] + [(*NUDGED_FIRST, True)]:
        engine = unsnapped(count, coverage, seed, page, grid)
        for compiled in (True, False):
            found = []
            for deferred in (False, True):
                bodies = copy.deepcopy(engine.bodies)
                clearance, margin, rest = snap_limits(bodies, *page, engine.params,
                                                      deferred=deferred)
                if deferred:
                    assert isinstance(rest, DeferredRest) and rest.check is None
                    make = rest.make

                    def noted(pair_centres, make=make, bodies=bodies):
                        nonlocal late
                        late += not np.array_equal(bodies.centres, gridded[id(bodies)])
                        return make(pair_centres)
                    rest.make = noted
                moves = snap_to_guides(bodies, *page, clearance, margin, engine.params.guides,
                                       rest, compiled=compiled)
                found.append((moves, bodies.centres.tobytes()))
            assert found[0] == found[1], (count, seed, compiled)
            assert found[0][0] > 0
    assert late == 2  # the nudged page's, compiled and in Python


def test_the_pairs_are_found_where_the_snap_started():
    """A check built after an item moved far finds the pairs the check built before the move
    found, given the centres it started from; without them, other pairs."""
    engine = unsnapped(20, 0.5, 3, (210.0, 297.0))
    bodies, params = engine.bodies, engine.params
    page = (engine.page_w_mm, engine.page_h_mm)
    eager = snap_limits(bodies, *page, params)[2]
    deferred = snap_limits(bodies, *page, params, deferred=True)[2]
    bodies.centres[0] += 40.0  # further than any pair's reach
    late = snap_limits(bodies, *page, params)[2]
    built = deferred.built()
    assert (built.i.tobytes(), built.j.tobytes()) == (eager.i.tobytes(), eager.j.tobytes())
    assert (late.i.tobytes(), late.j.tobytes()) != (eager.i.tobytes(), eager.j.tobytes())
