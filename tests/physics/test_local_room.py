"""physics.local_room: room found near each item that still overlaps, or stands in its margin,
on a page too large for relocation."""

import numpy as np

from floatpage.physics.bodies import Bodies
from floatpage.physics.engine import Engine
from floatpage.physics.finalize import pair_clearances
from floatpage.physics.local_room import clear_locally

PAGE = (210.0, 297.0)
MARGIN = 5.0


def grid_page(knots: bool = True) -> Bodies:
    """300 blocks of 6 x 4 mm in a loose grid inside A4's margins (a page of more items than
    relocation takes), then three knots: two blocks nearly on one spot, a block on another's
    corner, and a block in the margin."""
    xs, ys = np.meshgrid(np.arange(12.0, 200.0, 11.0), np.arange(12.0, 290.0, 16.0))
    centres = np.column_stack([xs.ravel(), ys.ravel()])[:300]
    if knots:
        centres[1] = centres[0] + [0.5, 0.5]  # nearly on one spot
        centres[3] = centres[2] + [4.0, 2.5]  # on its corner
        centres[5, 0] = 6.0  # 2 mm into the 5 mm margin
    engine = Engine(*PAGE)
    count = len(centres)
    engine.insert_all([f"b{k}" for k in range(count)],
                      [(float(x), float(y), 6.0, 4.0) for x, y in centres], [False] * count,
                      [False] * count)
    return engine.bodies


def clearances(bodies: Bodies) -> np.ndarray:
    i, j = np.triu_indices(bodies.count, 1)
    return pair_clearances(bodies.centres, bodies.sizes / 2, i, j)


def test_overlaps_and_items_in_the_margin_are_set_down_nearby_and_nothing_else_moves():
    bodies = grid_page()
    before = bodies.centres.copy()
    assert clearances(bodies).min() < 0
    moved = clear_locally(bodies, *PAGE, MARGIN)
    assert moved == 3  # one of each knot's pair, and the block in the margin
    assert clearances(bodies).min() >= 0.02 - 1e-9  # no overlap, through a save's rounding
    low = bodies.centres - bodies.sizes / 2
    high = bodies.centres + bodies.sizes / 2
    assert (low >= MARGIN - 1e-9).all() and (high <= np.array(PAGE) - MARGIN + 1e-9).all()
    shifted = np.abs(bodies.centres - before).max(axis=1)
    assert np.count_nonzero(shifted) == 3
    assert shifted.max() < 12.0  # nearby: within a few of its own sizes


def test_a_page_with_nothing_to_clear_is_left_exactly_as_it_is():
    bodies = grid_page(knots=False)
    before = bodies.centres.copy()
    assert clear_locally(bodies, *PAGE, MARGIN) == 0
    assert np.array_equal(bodies.centres, before)
