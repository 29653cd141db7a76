"""physics.relocation: a page where the gutter fits but the pushes jam (soft anchors pulling
their items back into a crowd, hard anchors the others must flow around) has jammed items
lifted out and set down where they keep the gutter."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from floatpage.model import load_project, save_project
from floatpage.model.layout import engine_for_page, settle_project
from floatpage.physics import Engine
from floatpage.physics.finalize import pair_clearances
from floatpage.physics.relocation import crowding, room_for

JAMS = Path(__file__).parent / "jams"


@pytest.mark.parametrize("name", sorted(path.name for path in JAMS.glob("*.toml")))
def test_a_page_that_jammed_keeps_the_gutter_and_stays_a_fixed_point(tmp_path, name):
    """Each file settled to a gap of 0.6-1.2 mm before relocation (the packed second start
    does not apply: its soft anchors pull their items back into the jam)."""
    path = tmp_path / name
    shutil.copy(JAMS / name, path)
    project = load_project(path)
    settle_project(project)
    save_project(project)
    for page in project.pages:
        quality = engine_for_page(page, project.physics).quality()
        assert quality.ok, quality.summary()
        assert quality.min_gap_mm >= project.physics.gutter_mm - 1e-6
    settled = path.read_bytes()
    again = load_project(path)
    settle_project(again)
    save_project(again)
    assert path.read_bytes() == settled


def test_room_for_finds_the_nearest_place_that_keeps_the_clearance():
    engine = Engine(100.0, 100.0)
    engine.insert("left", 20.0, 50.0, 30.0, 80.0)
    engine.insert("right", 80.0, 50.0, 30.0, 80.0)
    engine.insert("lost", 35.0, 50.0, 20.0, 20.0)  # over "left"
    engine.anchor_point("lost", 30.0, 90.0)
    bodies = engine.bodies
    halves = bodies.sizes[2] / 2
    spot = room_for(bodies, 2, 3.0, halves + 2.0, np.array([100.0, 100.0]) - halves - 2.0)
    assert spot is not None
    bodies.centres[2] = spot
    i, j = np.array([0, 1]), np.array([2, 2])
    assert (pair_clearances(bodies.centres, bodies.sizes / 2, i, j) >= 3.0 - 1e-9).all()
    # between the two columns (x 38-62 keeps 3 mm from each), at the height nearest the anchor
    assert spot[0] == pytest.approx(48.0) and spot[1] == pytest.approx(88.0)


def test_without_room_an_item_goes_where_it_crowds_the_others_least():
    engine = Engine(100.0, 100.0)
    engine.insert("wall", 50.0, 50.0, 90.0, 90.0)
    engine.insert("lost", 50.0, 50.0, 20.0, 20.0)
    bodies = engine.bodies
    halves = bodies.sizes[1] / 2
    low, high = halves + 2.0, np.array([100.0, 100.0]) - halves - 2.0
    assert room_for(bodies, 1, 3.0, low, high, clear_only=True) is None
    spot = room_for(bodies, 1, 3.0, low, high)
    # a corner: the grown item covers the wall by the least there
    assert np.abs(spot - 50.0) == pytest.approx([38.0, 38.0])
    reach = (bodies.sizes[:1] + 20.0) / 2 + 3.0
    assert crowding(spot[None], bodies.centres[:1], reach)[0] \
        < crowding(np.array([[50.0, 50.0]]), bodies.centres[:1], reach)[0]
