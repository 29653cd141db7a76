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
