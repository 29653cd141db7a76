"""The page's items as arrays: the state every force term and integrator reads.

Rows are items in insertion order; ``Engine.ids`` maps a row back to the item's stable id.
Arrays are updated in place inside one ``advance`` call (purity holds at the call's boundary).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

NO_TARGET = -1


def _empty(shape: tuple[int, ...], dtype=float, fill=0.0) -> np.ndarray:
    return np.full(shape, fill, dtype=dtype)


@dataclass
class Bodies:
    """Per-item state.  Shapes: (n, 2) for vectors, (n,) for flags and scalars.

    centres     rectangle centres, mm
    sizes       (w, h), mm, both > 0
    velocities  per mode: mm per time unit (paper) or mm per step (fast)
    decorative  takes no part in forces, is never moved
    held        being dragged: pushes others, is not pushed
    anchors     anchor point per item, NaN where unanchored
    gammas      per-item rigidity of the anchor spring, equation (6)
    hard        hard anchor: the position is set to the anchor after every step
    targets     row of the item this one follows (item-to-item anchor), NO_TARGET if none
    offsets     follower's offset from its target's centre, mm
    bleed       may reach the page edge (no print-safe margin)
    regions     the rectangle an item is confined to, (left, top, right, bottom) in mm, NaN
                where it may use the whole page: a region's edges are walls for its items
    """

    centres: np.ndarray = field(default_factory=lambda: _empty((0, 2)))
    sizes: np.ndarray = field(default_factory=lambda: _empty((0, 2)))
    velocities: np.ndarray = field(default_factory=lambda: _empty((0, 2)))
    decorative: np.ndarray = field(default_factory=lambda: _empty((0,), bool, False))
    held: np.ndarray = field(default_factory=lambda: _empty((0,), bool, False))
    anchors: np.ndarray = field(default_factory=lambda: _empty((0, 2), float, np.nan))
    gammas: np.ndarray = field(default_factory=lambda: _empty((0,), float, 0.0))
    hard: np.ndarray = field(default_factory=lambda: _empty((0,), bool, False))
    targets: np.ndarray = field(default_factory=lambda: _empty((0,), np.int64, NO_TARGET))
    offsets: np.ndarray = field(default_factory=lambda: _empty((0, 2)))
    bleed: np.ndarray = field(default_factory=lambda: _empty((0,), bool, False))
    regions: np.ndarray = field(default_factory=lambda: _empty((0, 4), float, np.nan))
    # group_roots' last answer: (targets and offsets as bytes, roots, offsets)
    _group_roots_cache: tuple[bytes, np.ndarray, np.ndarray] | None = field(
        default=None, init=False, repr=False, compare=False)

    @property
    def count(self) -> int:
        return len(self.centres)

    @property
    def charges(self) -> np.ndarray:
        """q = w * h, the charge of equation (2), shape (n,)."""
        return self.sizes[:, 0] * self.sizes[:, 1]

    @property
    def active(self) -> np.ndarray:
        """Items that take part in the forces (everything but decorations), shape (n,)."""
        return ~self.decorative

    @property
    def followers(self) -> np.ndarray:
        return self.targets != NO_TARGET

    @property
    def free(self) -> np.ndarray:
        """Items the integrator moves by their own forces, shape (n,)."""
        return ~(self.decorative | self.held | self.hard | self.followers)

    def margins(self, margin_mm: float) -> np.ndarray:
        """Each row's print-safe margin, (n,): none for bleed items, ``margin_mm`` otherwise."""
        return np.where(self.bleed, 0.0, margin_mm)

    def insets(self, margin_mm: float, page_w_mm: float, page_h_mm: float
               ) -> tuple[np.ndarray, np.ndarray]:
        """How far each row's walls stand inside the page: from its left and top edges, and
        from its right and bottom edges, (n, 2) each.  The print-safe margin (``margins``), or
        the item's region where that reaches further in.  Everything that keeps items on the
        page (the walls of both modes, the hard clamp, the no-overlap pass, the snap) reads
        these, so a region is a wall exactly as the page's edge is."""
        margins = np.repeat(self.margins(margin_mm)[:, None], 2, axis=1)
        confined = ~np.isnan(self.regions[:, 0])
        if not confined.any():
            return margins, margins.copy()
        low, high = margins.copy(), margins.copy()
        regions = self.regions[confined]
        region_low = regions[:, :2]
        region_high = np.array([page_w_mm, page_h_mm]) - regions[:, 2:]
        low[confined] = np.maximum(low[confined], region_low)
        high[confined] = np.maximum(high[confined], region_high)
        # A region the user drew flush with the page edge, just as large as its item: the
        # margin gives way to the region there (the region was asked for, the margin is a
        # default), rather than both being missed by half.
        extent = np.array([page_w_mm, page_h_mm])
        squeezed = extent - low[confined] - high[confined] < self.sizes[confined]
        low[confined] = np.where(squeezed, region_low, low[confined])
        high[confined] = np.where(squeezed, region_high, high[confined])
        return low, high

    def append(self, centre, size, *, decorative: bool, bleed: bool = False) -> None:
        """Add one unanchored item at rest."""
        self.extend(np.asarray(centre, float)[None], np.asarray(size, float)[None],
                    np.array([decorative]), np.array([bleed]))

    def extend(self, centres: np.ndarray, sizes: np.ndarray, decorative: np.ndarray,
               bleed: np.ndarray) -> None:
        """Add unanchored items at rest, (k, 2) centres and sizes: one copy of every array,
        where adding them one by one copied them all k times (0.5 s for a file of 2,000)."""
        count = len(centres)
        self.centres = np.vstack([self.centres, centres])
        self.sizes = np.vstack([self.sizes, sizes])
        self.velocities = np.vstack([self.velocities, np.zeros((count, 2))])
        self.decorative = np.append(self.decorative, decorative.astype(bool))
        self.held = np.append(self.held, np.zeros(count, bool))
        self.anchors = np.vstack([self.anchors, np.full((count, 2), np.nan)])
        self.gammas = np.append(self.gammas, np.zeros(count))
        self.hard = np.append(self.hard, np.zeros(count, bool))
        self.targets = np.append(self.targets, np.full(count, NO_TARGET)).astype(np.int64)
        self.offsets = np.vstack([self.offsets, np.zeros((count, 2))])
        self.bleed = np.append(self.bleed, bleed.astype(bool))
        self.regions = np.vstack([self.regions, np.full((count, 4), np.nan)])

    def remove(self, row: int) -> None:
        """Drop one row; followers of it become free, later target rows shift down by one."""
        keep = np.arange(self.count) != row
        targets = self.targets.copy()
        targets[targets == row] = NO_TARGET
        targets[targets > row] -= 1
        self.targets = targets
        for name in ("centres", "sizes", "velocities", "decorative", "held", "anchors",
                     "gammas", "hard", "targets", "offsets", "bleed", "regions"):
            setattr(self, name, getattr(self, name)[keep])

    def group_roots(self) -> tuple[np.ndarray, np.ndarray]:
        """Root row of every item's follow chain, and the offset from that root, mm.

        A follower's forces go to its root and its position is set from the root's, so an
        anchored group moves as one rigid body.  Chains are resolved here; cycles are refused
        earlier, by ``Engine.anchor_to``.

        The answer is kept until ``targets`` or ``offsets`` change (they are compared as bytes,
        so an edit in place counts): a settle asks a dozen times on an unchanged page, and on
        a 2,000-item chain each walk was 8 ms.  Callers get copies.
        """
        key = self.targets.tobytes() + self.offsets.tobytes()
        cached = self._group_roots_cache
        if cached is not None and cached[0] == key:
            return cached[1].copy(), cached[2].copy()
        roots, offsets = self._resolve_chains()
        self._group_roots_cache = (key, roots.copy(), offsets.copy())
        return roots, offsets

    def _resolve_chains(self) -> tuple[np.ndarray, np.ndarray]:
        roots = np.arange(self.count)
        offsets = np.zeros((self.count, 2))
        resolved = self.targets == NO_TARGET
        # Walk each unresolved chain up to a resolved row once, then fill the path back down:
        # every row is resolved once, so a chain of n followers costs O(n), not O(n^2).
        for row in np.flatnonzero(~resolved):
            path, current = [], int(row)
            while not resolved[current] and len(path) <= self.count:
                path.append(current)
                current = int(self.targets[current])
            for member in reversed(path):
                parent = int(self.targets[member])
                roots[member] = roots[parent]
                offsets[member] = offsets[parent] + self.offsets[member]
                resolved[member] = True
        return roots, offsets
