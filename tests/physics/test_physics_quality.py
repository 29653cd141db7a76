"""Quality measures against hand-computed values."""

import math

import numpy as np
import pytest

from floatpage.physics import measure_quality
from floatpage.physics.quality import all_pairwise, pairwise

# Page 100 x 100.  A [10,30]x[10,30]; B [25,45]x[20,30] overlaps A by 5 x 10;
# C [85,105]x[40,60] sticks 5 mm out on the right; D is a decorative backdrop over everything.
CENTRES = [(20, 20), (35, 25), (95, 50), (50, 50)]
SIZES = [(20, 20), (20, 10), (20, 20), (100, 100)]
DECORATIVE = [False, False, False, True]


@pytest.fixture
def quality():
    return measure_quality(100, 100, CENTRES, SIZES, 3.0, decorative=DECORATIVE)


def test_overlap(quality):
    assert quality.overlap_area_mm2 == pytest.approx(50.0)
    assert quality.overlap_fraction == pytest.approx(50.0 / 1000.0)
    assert quality.overlapping_pairs == ((0, 1),)  # the backdrop overlaps nobody by design


def test_off_page(quality):
    assert quality.off_page == (2,)
    assert quality.off_page_area_mm2 == pytest.approx(100.0)


def test_min_gap_is_minus_the_smaller_penetration(quality):
    assert quality.min_gap_mm == pytest.approx(-5.0)


def test_overlap_depth_sums_each_pairs_smaller_penetration():
    # A [0,20]x[0,20]; B [15,35]x[0,10] overlaps it 5 mm deep, C [0,10]x[18,28] 2 mm deep
    quality = measure_quality(100, 100, [(10, 10), (25, 5), (5, 23)],
                              [(20, 20), (20, 10), (10, 10)])
    assert quality.overlap_count == 2
    assert quality.overlap_depth_mm == pytest.approx(7.0)


def test_gap_evenness(quality):
    # nearest-neighbour gaps: A 0 (overlap), B 0, C sqrt(40^2 + 10^2) to B: cv = sqrt 2
    assert quality.gap_evenness == pytest.approx(1 / (1 + math.sqrt(2)))


def test_balance(quality):
    # area-weighted centre (53, 33) vs page centre (50, 50): 1 - mean(3/50, 17/50)
    assert quality.balance == pytest.approx(0.8)


def test_summary_and_ok(quality):
    assert quality.summary() == (
        "1 overlaps · 1 off page · gap -5.0 mm < 3 · even 0.41 · balance 0.80")
    assert not quality.ok


def test_a_clean_even_page():
    quality = measure_quality(100, 100, [(25, 50), (75, 50)], [(20, 20), (20, 20)], 3.0)
    assert quality.ok
    assert quality.min_gap_mm == pytest.approx(30.0)
    assert quality.gap_evenness == pytest.approx(1.0)
    assert quality.balance == pytest.approx(1.0)
    assert quality.summary() == "0 overlaps · 0 off page · gap 30.0 mm · even 1.00 · balance 1.00"


def test_corner_gap_is_euclidean():
    quality = measure_quality(100, 100, [(10, 10), (33, 34)], [(10, 10), (10, 10)])
    assert quality.min_gap_mm == pytest.approx(math.hypot(13, 14))


def test_fewer_than_two_items():
    assert math.isinf(measure_quality(100, 100, [(50, 50)], [(10, 10)]).min_gap_mm)
    empty = measure_quality(100, 100, [], [])
    assert empty.ok and empty.overlap_fraction == 0.0
    assert "gap —" in empty.summary()


def test_many_items_are_measured_from_their_neighbours_with_the_same_figures_as_every_pair():
    """Above PAIR_BLOCK items the pairs come from a neighbour search (quality.near_pairwise);
    the figures must be those of all pairs: overlaps, the pairs listed, and every item's
    nearest gap, also for items far from all others and for anchor groups."""
    rng = np.random.default_rng(5)
    for count, spread in ((600, 200.0), (1500, 400.0)):
        centres = rng.uniform(0, spread, (count, 2))
        centres[:5] = [[-500, -500], [900, 900], [-500, 900], [900, -500], [2000, 0]]  # far off
        halves = rng.uniform(0.5, 6.0, (count, 2))
        groups = np.arange(count)
        groups[rng.random(count) < 0.2] = 7  # one big anchor group, spread over the page
        dense = all_pairwise(centres, halves, groups)
        near = pairwise(centres, halves, groups)
        assert near[2] == dense[2] > 0 and near[1] == dense[1]
        assert near[0] == pytest.approx(dense[0], rel=1e-12)
        assert near[4] == pytest.approx(dense[4], rel=1e-12) and near[4] > 0
        np.testing.assert_array_equal(np.isinf(near[3]), np.isinf(dense[3]))
        finite = np.isfinite(dense[3])
        np.testing.assert_allclose(near[3][finite], dense[3][finite], rtol=0, atol=1e-12)


def test_one_anchor_group_of_many_items_has_no_gap_and_is_measured_quickly():
    count = 2000
    centres = np.column_stack([np.linspace(20, 120, count), np.linspace(20, 120, count)])
    halves = np.ones((count, 2))
    total, hits, overlaps, nearest, depth = pairwise(centres, halves, np.zeros(count, dtype=int))
    assert (total, hits, overlaps, depth) == (0.0, [], 0, 0.0) and np.isinf(nearest).all()
