"""The benchmark scenes are what they claim to be; the fast mode's cooling rule."""

import numpy as np
import pytest

from floatpage.physics.fast_mode import COOLING_ITEMS, COOLING_SHARE_RANGE, cooling_rate
from seeded_scenes import big_item_scene, dropped_scene, mixed_scene


@pytest.mark.parametrize("count, coverage", [(5, 0.5), (50, 0.5), (40, 0.9)])
def test_mixed_scene_covers_what_it_says_and_is_seeded(count, coverage):
    scene = mixed_scene(count, coverage, seed=3)
    assert len(scene.ids) == count
    assert scene.coverage == pytest.approx(coverage)
    assert np.array_equal(scene.centres, mixed_scene(count, coverage, seed=3).centres)
    assert not np.array_equal(scene.centres, mixed_scene(count, coverage, seed=4).centres)
    halves = scene.sizes / 2
    fits = (scene.sizes <= [scene.page_w_mm, scene.page_h_mm]).all(axis=1)
    inside = ((scene.centres - halves >= 0)
              & (scene.centres + halves <= [scene.page_w_mm, scene.page_h_mm])).all(axis=1)
    assert inside[fits].all()


def test_dropped_and_big_item_scenes():
    dropped = dropped_scene(12)
    assert (dropped.centres == dropped.centres[0]).all()
    big = big_item_scene()
    assert big.sizes[0].prod() > 0.5 * big.page_w_mm * big.page_h_mm
    assert big.coverage <= 0.6


def test_cooling_slows_with_the_square_root_of_the_item_count():
    low, high = COOLING_SHARE_RANGE
    assert cooling_rate(0.01, 4) == pytest.approx(0.01 * high)  # capped for small pages
    assert cooling_rate(0.01, 100) == pytest.approx(0.01 * COOLING_ITEMS / 10)
    assert cooling_rate(0.01, 100_000) == pytest.approx(0.01 * low)
    assert cooling_rate(0.0, 50) == 0.0


def test_a_crowd_too_dense_for_the_gutter_settles_without_overlap():
    """1,000 items of 1-4 mm covering 55 % of a 74 x 105 mm card: the 3 mm gutter cannot fit
    (each item would need four times its area), but no overlap can.  With gutter-wide halos the
    physics pressed the crowd into itself and the no-overlap pass left 177 overlapping pairs;
    with halos of the gap that fits (fast_forces.target_gap) none is left."""
    from floatpage.physics.engine import Engine
    from seeded_scenes import load

    scene = mixed_scene(1000, 0.55, seed=4, page_w_mm=74.0, page_h_mm=105.0)
    engine = Engine(scene.page_w_mm, scene.page_h_mm)
    load(engine, scene)
    engine.settle()
    quality = engine.quality()
    assert quality.overlap_count == 0 and not quality.off_page
    assert quality.min_gap_mm > 0.0

