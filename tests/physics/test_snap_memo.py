"""What the snap keeps between its tries (physics.snap_memo): an answer read off one axis holds
until a move along that axis sweeps an item across the span it was read from.  That a snap
which remembers makes exactly the moves of one that works everything out afresh is tested with
the other properties of the snap, in test_guides.py."""

from __future__ import annotations

import numpy as np

from floatpage.physics.guides import features
from floatpage.physics.snap_memo import AxisMemo


def moved(memo: AxisMemo, axis: int, centre_before: float, centre_after: float,
          half: float = 5.0) -> None:
    """An item of half size ``half`` moved along ``axis`` from one centre to another."""
    halves = np.array([[half, half]])
    before = features(np.array([[centre_before, centre_before]]), halves, axis)
    after = features(np.array([[centre_after, centre_after]]), halves, axis)
    memo.moved(axis, before, after)


def test_an_answer_holds_until_a_move_on_its_axis_sweeps_its_span():
    memo = AxisMemo()
    memo.keep("row 3", 0, 40.0, 60.0, "its moves")
    moved(memo, 1, 50.0, 52.0)  # along the other axis, through the span: no matter
    moved(memo, 0, 100.0, 90.0)  # along this axis, 85-105 after: far from 40-60
    assert memo.recall("row 3", 0) == "its moves"
    moved(memo, 0, 20.0, 30.0)  # its high edge reaches 35: still clear of 40
    assert memo.recall("row 3", 0) == "its moves"
    moved(memo, 0, 70.0, 66.0)  # its low edge comes to 61, beyond 60 by 1 mm
    assert memo.recall("row 3", 0) == "its moves"
    moved(memo, 0, 76.0, 65.0)  # its low edge comes to 60: on the span's end
    assert memo.recall("row 3", 0) is None
    assert memo.recall("row 3", 0) is None  # and it is forgotten


def test_a_move_that_jumps_over_the_span_sweeps_it():
    """A move is a slide: an item that ends on the far side of a span crossed it."""
    memo = AxisMemo()
    memo.keep("row 1", 1, 40.0, 42.0, "its line")
    moved(memo, 1, 20.0, 60.0, half=1.0)
    assert memo.recall("row 1", 1) is None
