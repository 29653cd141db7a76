"""A snap of the snap's own result makes no move (physics.snapping.snap_to_guides: the sweeps
end only after a sweep of every mover finds none).  A later sweep tries only the movers near a
move on its axis; a move refused early (it did not fit, or pressed a group too hard, while a
neighbour stood where it later left) was never tried again, and the next probe's snap made it,
so the settle needed one probe more."""

from __future__ import annotations

import copy
from dataclasses import replace

import numpy as np

import floatpage.physics.engine as engine_module
from floatpage.model.layout import safe_round, settle_project
from floatpage.physics.snapping import snap_limits, snap_to_guides

from alignment import scene_project
from guide_cost import fresh_scenes


def test_the_snap_of_a_snapped_page_moves_nothing(monkeypatch):
    """guide_cost.py's fresh seed 2008 (23 items on Letter): the full run's snap, snapped
    again at once, compiled and in Python (before the last sweep of every mover: 3 moves,
    one of 16.7 mm, and the settle took two probes more)."""
    snap_page = engine_module.snap_page
    again = []

    def snapped_twice(bodies, page_w_mm, page_h_mm, params):
        moves = snap_page(bodies, page_w_mm, page_h_mm, params)
        if not again:
            for compiled in (True, False):
                twice = copy.deepcopy(bodies)
                clearance, margin, rest = snap_limits(twice, page_w_mm, page_h_mm, params)
                moves_again = snap_to_guides(twice, page_w_mm, page_h_mm, clearance, margin,
                                             params.guides, rest, compiled=compiled)
                again.append((moves_again, np.abs(twice.centres - bodies.centres).max()))
        return moves
    monkeypatch.setattr(engine_module, "snap_page", snapped_twice)
    project = scene_project(fresh_scenes(30, 2000)[8])
    project.physics = replace(project.physics, guides=1.0)
    settle_project(project)
    assert again == [(0, 0.0), (0, 0.0)]


def test_the_snap_of_a_snapped_page_as_saved_moves_nothing(monkeypatch):
    """guide_cost.py's fresh seeds 2003 and 2018 (55 items each): the full run's snap, its
    centres rounded as a save rounds them (model.layout.safe_round), snapped again.  The
    snap works on the save's grid, so the save changes nothing it scored; before "aligned"
    took a millionth of slack, two centres the snap left exactly 0.05 mm apart (its floats:
    0.04999999999995, aligned) came back from the file 0.05000000000001 apart (a near miss),
    and the probe's snap moved an item 4.2 mm (5.7 on 2018): a probe more."""
    snap_page = engine_module.snap_page
    again = []

    def snapped_as_saved(bodies, page_w_mm, page_h_mm, params):
        moves = snap_page(bodies, page_w_mm, page_h_mm, params)
        if not snapped_as_saved.done:
            snapped_as_saved.done = True
            saved = copy.deepcopy(bodies)
            for row in np.flatnonzero(saved.active):
                saved.centres[row] = [
                    safe_round(saved.centres[row, axis], saved.sizes[row, axis] / 2, size)
                    for axis, size in ((0, page_w_mm), (1, page_h_mm))]
            clearance, margin, rest = snap_limits(saved, page_w_mm, page_h_mm, params)
            before = saved.centres.copy()
            again.append(snap_to_guides(saved, page_w_mm, page_h_mm, clearance, margin,
                                        params.guides, rest))
            again.append(float(np.abs(saved.centres - before).max()))
        return moves
    monkeypatch.setattr(engine_module, "snap_page", snapped_as_saved)
    scenes = fresh_scenes(30, 2000)
    for seed in (3, 18):
        snapped_as_saved.done = False
        project = scene_project(scenes[seed])
        project.physics = replace(project.physics, guides=1.0)
        settle_project(project)
    assert len(again) == 4
    assert again[0::2] == [0, 0] and max(again[1::2]) < 1e-9
