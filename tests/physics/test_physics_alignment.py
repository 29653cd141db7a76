"""The alignment measures of issue 16, on pages whose answer is known by hand."""

from __future__ import annotations

import numpy as np
import pytest

from floatpage.physics.alignment import measure_alignment


def test_a_grid_has_no_near_misses_few_lines_and_everything_aligned():
    centres = np.array([[x, y] for x in (30.0, 80.0, 130.0) for y in (40.0, 100.0)])
    sizes = np.full((6, 2), 40.0)
    found = measure_alignment(centres, sizes)
    assert found.near_misses_per_item == 0.0
    assert found.edge_lines_per_item == pytest.approx((6 + 4) / 6)  # 6 x lines, 4 y lines
    assert found.aligned_share == 1.0


def test_items_that_just_miss_count_as_near_misses():
    centres = np.array([[50.0, 50.0], [52.0, 120.0]])  # 2 mm apart on x: both edges and centres
    sizes = np.array([[40.0, 30.0], [40.0, 30.0]])
    found = measure_alignment(centres, sizes)
    assert found.near_misses_per_item == pytest.approx(3 / 2)  # left, right and centre pairs
    assert found.edge_lines_per_item == pytest.approx(8 / 2)
    assert found.aligned_share == 0.0


def test_an_items_own_edges_are_not_a_near_miss_and_decorations_are_left_out():
    centres = np.array([[50.0, 50.0], [150.0, 150.0], [100.0, 100.0]])
    sizes = np.array([[2.0, 2.0], [2.0, 2.0], [200.0, 200.0]])  # 2 mm items; a big decoration
    found = measure_alignment(centres, sizes, decorative=np.array([False, False, True]))
    assert found.near_misses_per_item == 0.0
    assert found.edge_lines_per_item == 4.0


def test_the_shipped_flyer_lines_up_better_than_the_issue_found_it():
    from pathlib import Path

    from floatpage.model import load_project
    from floatpage.model.layout import engine_for_page

    root = Path(__file__).resolve().parents[2]
    project = load_project(root / "sample_projects" / "shop-flyer" / "shop-flyer.toml")
    bodies = engine_for_page(project.pages[0], project.physics).bodies
    found = measure_alignment(bodies.centres, bodies.sizes, bodies.decorative)
    # the issue measured 5.7 near misses per item; settled without guides it had 3.84, with
    # them 2.00 (docs/benchmarks.md); the guides' snap never leaves more than it found
    assert found.near_misses_per_item < 3.0
