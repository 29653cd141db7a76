"""The snap's rest check, built when a move first needs it (physics.snapping.snap_page).

A snap asks the rest check (physics.rest_check) only about a move longer than ``NUDGE_MM``
that fits; a page with no such move never asks.  Two snaps of three on the small pages of
issue #16 are the probe's, which mostly find nothing to move, and the check's set-up (its
pairs, their forces' tables, the lines' hold: some fifty NumPy calls) was half of such a
snap's fixed cost.  So the snap hands the sweeps this stand-in, which builds the check the
first time a move asks.

The check built then is the one the snap would have built at its start: its pairs are found
at the centres the snap started from (kept here, one copy), every other part of it is read
off the sizes, anchors and groups, which a snap never changes, or read live from the centres
as the eager check reads them.  The nudges made before it are forgotten by its kept forces
as by the eager check's (it keeps none yet).  The same moves, bit for bit
(tests/physics/test_deferred_rest.py, benchmarks/snap_identity.py).
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from floatpage.physics.rest_check import RestCheck


class DeferredRest:
    """A RestCheck made by ``make(start_centres)`` at its first use; until then, nothing."""

    def __init__(self, make: Callable[[np.ndarray], RestCheck], centres: np.ndarray):
        self.make, self.start = make, centres.copy()
        self.check: RestCheck | None = None
        self.before: dict = {}  # the check's kept forces, shared once it is built (compiled)

    def built(self) -> RestCheck:
        """The check, built now if it was not yet."""
        if self.check is None:
            self.check = self.make(self.start)
            self.check.before = self.before
        return self.check

    def keeps_rest(self, members: np.ndarray, axis: int, shift: float) -> bool:
        return self.built().keeps_rest(members, axis, shift)

    def moved(self, rows: np.ndarray, axes: tuple[int, ...] = (0, 1)) -> None:
        """A check not built yet keeps no forces to forget."""
        if self.check is not None:
            self.check.moved(rows, axes)

    def compiled_parts(self) -> tuple:
        """The compiled sweeps call this at their first rest check (snap_sweep_kernel)."""
        return self.built().compiled_parts()
