"""The second start of Engine.settle, for a page of free items the physics jammed short of
the gutter where it fits: the items packed (physics.packing) and settled gently from there;
past the margin where the margin must give way; and, where the gutter cannot fit, the widest
gap a packing keeps.  A mixin of Engine (it reads and sets the engine's bodies and
parameters): the engine's module keeps the editing API and the settle that calls this.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import numpy as np

from floatpage.physics.finalize import MARGIN_GIVES_WAY, ROUNDING_MM
from floatpage.physics.geometry import GUTTER_FITS_COVER
from floatpage.physics.packing import MAX_ITEMS, packed_layout
from floatpage.physics.params import Params, page_margin

# The second start is spread already: the physics only evens it out, cooling onto its guides
# from the first step (GUIDED_COOLING).  From 0.1 the packed items crept apart for 120 steps
# on the 5-item page; from 0.2 they are still after 88, as evenly spread (evenness 0.68).
SECOND_START_HEAT = 0.2
WIDEST_GAP_STEP_MM = 0.05  # _widest_packed_gap's bisection stops this close


class SecondStart:
    """Engine's second start (see the module doc)."""

    def _second_start_applies(self) -> bool:
        """Whether a page that misses the gutter gets a second start: free items only (with
        anchors, groups, held items or regions the order is the user's), that fit with the
        gutter (each grown by it, at most GUTTER_FITS_COVER of the room), and few enough
        for the packing (packing.MAX_ITEMS)."""
        bodies = self._bodies
        rows = np.flatnonzero(bodies.active)
        if not 2 <= len(rows) <= MAX_ITEMS or self.params.mode != "fast" or not (
                bodies.free[rows].all() and np.isnan(bodies.anchors[rows, 0]).all()
                and np.isnan(bodies.regions[rows, 0]).all() and not bodies.followers.any()):
            return False
        return self.grown_cover() <= GUTTER_FITS_COVER

    def _settle_from_packing(self, max_steps: int, align: bool = True) -> bool:
        """The second start: the items packed (packing.packed_layout) and settled gently from
        there; if the physics jams again, the packing itself, which holds the gutter by
        construction (less evenly spread than the physics would leave it).  Should neither
        keep it, back to the first run, searching for the widest gap it can keep; and where
        that gives the margin up, packed again past the margin (_pack_past_the_margin), and
        where it keeps the margin, the widest gap a packing reaches if that is wider
        (_widest_packed_gap)."""
        bodies = self._bodies
        rows = np.flatnonzero(bodies.active)
        first = bodies.centres.copy()
        start = self._packed_start(rows, self.margin_mm)
        if start is not None and self._spread_from(
                start, max_steps, lambda: self.finalize(fall_back=False, align=align)):
            return True
        bodies.centres[:] = first
        if self.finalize(align=align):
            return True
        if self.quality().in_margin:
            return self._pack_past_the_margin(rows, max_steps, align)
        self._widest_packed_gap(rows, max_steps, align, self.params)
        return False

    def _packed_start(self, rows: np.ndarray, margin_mm: float,
                      gap_mm: float | None = None) -> np.ndarray | None:
        """The page's centres with ``rows`` packed within ``margin_mm`` of its edges at
        ``gap_mm`` (the gutter by default), with the rounding slack, or None where the packing
        finds no way."""
        bodies = self._bodies
        near, far = bodies.insets(margin_mm, self.page_w_mm, self.page_h_mm)
        low = near[rows].max(axis=0)
        high = np.array([self.page_w_mm, self.page_h_mm]) - far[rows].max(axis=0)
        gap = self.params.gutter_mm if gap_mm is None else gap_mm
        packed = packed_layout(bodies.sizes[rows], low, high, gap + 2 * ROUNDING_MM)
        if packed is None:
            return None
        start = bodies.centres.copy()
        start[rows] = packed
        return start

    def _pack_past_the_margin(self, rows: np.ndarray, max_steps: int, align: bool) -> bool:
        """A page whose items cannot all keep the margin, where the search for the widest gap
        gave the margin up and left a gap under the gutter: packed again with the margin
        halved, then dropped (as the pass gives it way), at the gutter, and settled gently
        there.  Items that must stand in the margin then stand there with the gutter between
        them, not 0.1 mm apart (three bars too wide to stand beside a tall one, stacked 318 mm
        high in the 287 mm inside A4's margins, and 206.9 mm side by side on its 210 mm
        width: benchmarks/gutter_fits.py --seed 2611, page 33).  The physics runs with its
        walls at the smaller margin; the snap keeps the page's own.  Where the gutter does
        not fit even with the margin dropped, the widest gap a packing reaches there, if
        wider than the search's (_widest_packed_gap).  Returns whether the gutter holds."""
        params, searched = self.params, self._bodies.centres.copy()
        for share in MARGIN_GIVES_WAY:
            smaller = replace(params, margin_mm=params.margin_mm * share)
            margin = page_margin(smaller.margin_mm, self.page_w_mm, self.page_h_mm)
            start = self._packed_start(rows, margin)
            if start is not None and self._spread_with(start, smaller, max_steps, align,
                                                       margin):
                return True
        self._bodies.centres[:] = searched
        self._bodies.velocities[:] = 0.0
        self._widest_packed_gap(rows, max_steps, align, replace(params, margin_mm=0.0))
        return False

    def _spread_with(self, start: np.ndarray, smaller: Params, max_steps: int, align: bool,
                     margin_mm: float, gap_mm: float | None = None) -> bool:
        """_spread_from with the walls at the margin of ``smaller``, kept by a no-overlap pass
        at ``margin_mm`` and ``gap_mm`` (the gutter by default); the page's own parameters
        again for the snap and afterwards."""
        params = self.params

        def keeps() -> bool:
            self.params = params  # the snap keeps the page's margin and lines
            return self.finalize(fall_back=False, align=align, margin_mm=margin_mm,
                                 gutter_mm=gap_mm)
        self.params = smaller
        try:
            return self._spread_from(start, max_steps, keeps)
        finally:
            self.params = params

    def _widest_packed_gap(self, rows: np.ndarray, max_steps: int, align: bool,
                           params: Params) -> None:
        """Where the gutter is out of reach within the margin of ``params``: the widest gap
        (to 0.05 mm) at which a packing fits there, by bisection, taken if it is wider than
        what the page has now.  The search for the widest gap works on the order the physics
        left, and can leave a few hundredths of a millimetre where another order holds 2.5
        mm (four items on A4, two tall and two wide: gutter_fits.py --seed 1011, page 157);
        with the margin dropped, 2.95 mm where it had left 0.1 mm (seed 404, page 23)."""
        now = max(self.quality().min_gap_mm, 0.0)
        margin = page_margin(params.margin_mm, self.page_w_mm, self.page_h_mm)
        low, high = now, self.params.gutter_mm
        found = None
        while high - low > WIDEST_GAP_STEP_MM:
            middle = (low + high) / 2
            start = self._packed_start(rows, margin, middle)
            if start is None:
                high = middle
            else:
                low, found = middle, start
        if found is None:
            return
        kept = self._bodies.centres.copy()
        if not self._spread_with(found, params, max_steps, align, margin, low) or \
                self.quality().min_gap_mm < now:
            self._bodies.centres[:] = kept
        self._bodies.velocities[:] = 0.0

    def _spread_from(self, start: np.ndarray, max_steps: int, keeps: Callable[[], bool]
                     ) -> bool:
        """A start that holds the gutter by construction (the packing, or the items set down
        anew by physics.relocation), settled gently from there: whether ``keeps`` (a no-overlap
        pass, True when it holds the gutter) holds after the run, or else on the start itself,
        less evenly spread than the physics would leave it.  Leaves the page as ``keeps`` left
        it."""
        bodies = self._bodies
        bodies.centres[:] = start
        bodies.velocities[:] = 0.0
        self.reheat(SECOND_START_HEAT)
        self._spread_out = True  # spread already: it cools at the guided rate (fast_mode.run_fast)
        self._run_until_settled(max_steps)
        if keeps():
            return True
        bodies.centres[:] = start
        return keeps()
