"""The alignment snap works on the grid a save writes (physics.save_grid): what it leaves lined
up is still lined up in the file.  Rounded only by the save, pairs the snap had left 0.043-0.048
mm apart (aligned) came back 0.051-0.056 mm apart, near misses, and the next probe's snap moved
items millimetres to close them: a settle took one probe more."""

from __future__ import annotations

import copy


import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import floatpage.physics.engine as engine_module
from floatpage.physics import Engine, Params, snapping
from floatpage.physics.finalize import ROUNDING_MM
from floatpage.model.layout import POSITION_DECIMALS, safe_round, settle_project
from floatpage.physics.alignment import NEAR_MM
from floatpage.physics.save_grid import STEPS_PER_MM, on_save_grid
from floatpage.physics.snap_scoring import ALIGNED_MM

from alignment import scene_project
from seeded_scenes import mixed_scene
from guide_cost import fresh_scenes


def test_the_grid_is_the_saves():
    assert STEPS_PER_MM == 10 ** POSITION_DECIMALS


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(st.floats(-5.0, 305.0), st.floats(0.0, 160.0)), min_size=1,
                max_size=20),
       st.sampled_from([148.0, 210.0, 215.9, 297.0, 279.4, 200.0 / 3.0]))
def test_on_save_grid_rounds_as_a_save_does(items, page):
    """Centres anywhere, also flush with an edge, past it, or of items wider than the page:
    on_save_grid's centre is the save's, but on a tie (a centre half a step between two,
    which the save, as Python's round, takes to the even one), and the save keeps it as it is:
    the snap's layout is the layout saved."""
    centres = np.array([centre for centre, _ in items])
    halves = np.array([half for _, half in items])
    # items flush with each edge, where the nearest step would put them past it
    flush = np.concatenate([halves, page - halves])
    centres, halves = np.concatenate([centres, flush]), np.concatenate([halves, halves, halves])
    gridded = on_save_grid(centres, halves, page).tolist()
    for centre, half, found in zip(centres.tolist(), halves.tolist(), gridded):
        assert safe_round(found, half, page) == found
        steps = centre * STEPS_PER_MM
        if abs(steps - np.floor(steps) - 0.5) > 1e-6:  # not a tie
            assert found == safe_round(centre, half, page)


def out_of_line_once_saved(bodies, page_w_mm: float, page_h_mm: float) -> int:
    """Pairs of features of two items (an edge and an edge, a centre and a centre) within
    ALIGNED_MM on the page as it is, and a near miss once its centres are rounded as
    model.layout.write_back rounds them."""
    active = bodies.active
    centres, halves = bodies.centres[active], bodies.sizes[active] / 2
    broken = 0
    for axis, size in ((0, page_w_mm), (1, page_h_mm)):
        saved = np.array([safe_round(c, h, size) for c, h in zip(centres[:, axis],
                                                                   halves[:, axis])])
        for mine, theirs in (((-1, 1), (-1, 1)), ((0,), (0,))):
            for a in mine:
                for b in theirs:
                    now = np.abs((centres[:, axis] + a * halves[:, axis])[:, None]
                                 - (centres[:, axis] + b * halves[:, axis])[None, :])
                    then = np.abs((saved + a * halves[:, axis])[:, None]
                                  - (saved + b * halves[:, axis])[None, :])
                    np.fill_diagonal(now, np.inf)
                    broken += int(((now <= ALIGNED_MM) & (then > ALIGNED_MM)
                                   & (then < NEAR_MM)).sum())
    return broken


def test_what_the_snap_lines_up_stays_lined_up_once_saved(monkeypatch):
    """Every snap of the settles of three fresh pages (guide_cost.py's seeds 3002, 3017, 3027:
    before the snap worked on the grid, 8, 4 and 14 pairs aligned in its result were near
    misses in the file; on 3017, where the snap makes no move, pairs the guides' hold had
    lined up) leaves no aligned pair the save's rounding puts out of line."""
    snap_page = engine_module.snap_page
    broken, snaps = [], []

    def checked(bodies, page_w_mm, page_h_mm, params):
        moves = snap_page(bodies, page_w_mm, page_h_mm, params)
        snaps.append(moves)
        broken.append(out_of_line_once_saved(bodies, page_w_mm, page_h_mm))
        return moves
    monkeypatch.setattr(engine_module, "snap_page", checked)
    scenes = fresh_scenes(30, 3000)
    for seed in (2, 17, 27):
        settle_project(scene_project(scenes[seed]))
    assert sum(snaps) > 0 and len(snaps) >= 6
    assert broken == [0] * len(broken)


def test_a_group_pressed_on_the_side_of_its_nearest_step_takes_the_other():
    """An item 0.004 mm right of a step and exactly the clearance from a held item on its
    left: its nearest step would narrow the gap, so it takes the step on its right (0.006 mm
    away).  Left off the grid, the save rounded it to its nearest all the same."""
    engine = Engine(200.0, 100.0, Params(guides=1.0))
    clearance = engine.params.gutter_mm + ROUNDING_MM
    right_x = 110.004
    left_x = right_x - 40.0 - clearance
    engine.insert("left", left_x, 50.0, 40.0, 20.0)
    engine.insert("right", right_x, 50.0, 40.0, 20.0)
    engine.hold("left")
    bodies = engine.bodies
    bodies.centres[:] = [[left_x, 50.0], [right_x, 50.0]]
    clearance_mm, margin, rest = snapping.snap_limits(bodies, 200.0, 100.0, engine.params)
    snapper = snapping._Snapper(bodies, (200.0, 100.0), clearance_mm, margin, rest)
    snapper.onto_grid()
    assert bodies.centres[0, 0] == left_x  # held: never rounded
    assert bodies.centres[1, 0] == pytest.approx(110.01, abs=1e-9)  # not 110.00
    assert bodies.centres[1, 0] - left_x - 40.0 >= clearance - 1e-9


@settings(max_examples=60, deadline=None)
@given(st.integers(2, 40), st.sampled_from([0.3, 0.55, 0.8]), st.integers(0, 10_000),
       st.sampled_from([(210.0, 297.0), (127.0, 203.2), (297.0, 420.0)]), st.booleans())
def test_the_compiled_grid_shifts_are_onto_grid_numpys(count, coverage, seed, page, jammed):
    """Seeded pages settled without their final pass (rows pressed at the gap), some rows
    held or following another; ``jammed``: every centre set 0.001-0.009 mm off the grid, so
    that steps are refused and the other step tried: the same centres and tables to the
    float, compiled and in NumPy."""
    scene = mixed_scene(count, coverage, seed=seed, page_w_mm=page[0], page_h_mm=page[1])
    engine = Engine(*page, Params(guides=1.0, seed=seed))
    for item_id, (x, y), (w, h) in zip(scene.ids, scene.centres, scene.sizes):
        engine.insert(item_id, float(x), float(y), float(w), float(h))
    rng = np.random.default_rng(seed)
    for k, item_id in enumerate(engine.ids[1:], start=1):
        role = rng.integers(0, 6)
        if role == 0:
            engine.hold(item_id)
        elif role == 1:
            (x, y), (tx, ty) = engine.positions()[item_id], engine.positions()[engine.ids[0]]
            try:
                engine.anchor_to(item_id, engine.ids[0], x - tx, y - ty)
            except ValueError:
                pass
    engine.settle(2_000, finalize=False)
    if jammed:
        bodies = engine.bodies
        bodies.centres[:] = (np.round(bodies.centres, 2)
                             + rng.integers(1, 10, bodies.centres.shape) / 1000.0)
    found = []
    for way in ("onto_grid", "onto_grid_numpy"):
        bodies = copy.deepcopy(engine.bodies)
        clearance, margin, rest = snapping.snap_limits(bodies, *page, engine.params)
        snapper = snapping._Snapper(bodies, page, clearance, margin, rest)
        getattr(snapper, way)()
        found.append((bodies.centres.tobytes(),
                      [table.tobytes() for tables in snapper.tables.values() for table in tables]))
    assert found[0] == found[1]
