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
from floatpage.model.layout import settle_project
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
