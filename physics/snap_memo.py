"""What the alignment snap (physics.snapping) has worked out about one axis, kept until a move
on that axis could change it.

The snap's scoring of a body's moves along an axis, and the finding of the groups lined up
with it there, read nothing but the features on that axis of the items within a span around
the body.  A move along the other axis changes none of that, and a move along this axis
changes it only if the moved item's features were or are within the span.  On a page of 50
items the snap scores a body, moves a neighbour far away, and scores the same body again
(its line's other groups do, too): the answer is the one it already had.  So each answer is
kept with its span, and recalled until a move sweeps an item across that span.

Only what is a function of one axis's features is kept: whether a move fits between the
neighbours, or keeps the page at rest, depends on both axes and on the forces, and is asked
afresh every time.
"""

from __future__ import annotations

from typing import Any, Hashable

import numpy as np

from floatpage.physics.guides import HIGH, LOW


class AxisMemo:
    """Answers per (key, axis), each valid while no item moved along the axis has swept the
    span ``[low, high]`` it was read from (the span's ends count as inside: a recall that might
    be stale is never made)."""

    def __init__(self) -> None:
        # per axis, in move order: the span of each moved row, from its lowest edge before or
        # after the move to its highest (the two extents and everything between)
        self.swept: list[list[tuple[float, float]]] = [[], []]
        self.known: dict[tuple[Hashable, int], tuple[int, float, float, Any]] = {}

    def moved(self, axis: int, before: np.ndarray, after: np.ndarray) -> None:
        """Rows moved along ``axis``, their features (k, 3) before and after the move."""
        lows = np.minimum(before[:, LOW], after[:, LOW]).tolist()
        highs = np.maximum(before[:, HIGH], after[:, HIGH]).tolist()
        self.swept[axis].extend(zip(lows, highs))

    def keep(self, key: Hashable, axis: int, low: float, high: float, value: Any) -> Any:
        """Keep ``value``, read from the features within ``[low, high]`` on ``axis``; returns it."""
        self.known[key, axis] = (len(self.swept[axis]), low, high, value)
        return value

    def recall(self, key: Hashable, axis: int) -> Any | None:
        """The kept value, if no move along ``axis`` since it was kept swept its span; else
        None (and it is forgotten)."""
        entry = self.known.get((key, axis))
        if entry is None:
            return None
        since, low, high, value = entry
        swept = self.swept[axis]
        for moved_low, moved_high in swept[since:]:
            if moved_high >= low and moved_low <= high:
                del self.known[key, axis]
                return None
        if since < len(swept):  # checked up to now: the next recall starts here
            self.known[key, axis] = (len(swept), low, high, value)
        return value
