"""The fast mode's forces, one object each, summed by the integrator in fast_mode.run_fast.

A force is anything with ``add_to(acc, centres, heat)`` that adds its acceleration, (n, 2), for
the current centres. The step loop knows none of them by name: a new force (the alignment
guides of the layout-quality issue, say) is one more object in the list `fast_forces` builds.
The paper mode composes its own list the same way (paper_mode.paper_force_terms).
"""

from __future__ import annotations

from typing import Protocol

import numpy as np

from floatpage.physics.bodies import Bodies
from floatpage.physics.fast_forces import (
    RADIAL_SHARE, blocked_axes, candidate_pairs, touching_pushes, wall_pushes_in,
)
from floatpage.physics.geometry import pair_sums, separate_coincident, xy_slots

K_CONTACT = 0.2  # fraction of a penetration turned into acceleration per step
K_WALL = 0.2
K_ANCHOR = 0.2  # anchor spring per step^2 at the default beta: as stiff as a contact
BETA_DEFAULT = 1.0  # Params.beta at which a fast anchor is as stiff as a contact
RADIAL_FADE_HEAT = 0.25  # below this heat the sliding (radial) push fades out
MIN_LIST_STEPS = 5  # a neighbour list rebuilt sooner than this doubles its skin
MAX_SKIN_GROWTH = 4  # ...up to this many times its size at the start
ALL_PAIRS_UP_TO = 16  # a page of at most this many items lists every pair once (see ContactPushes)


class Force(Protocol):
    def add_to(self, acc: np.ndarray, centres: np.ndarray, heat: float) -> None:
        """Add this force's acceleration for ``centres`` at ``heat`` into ``acc``, in place."""


class ContactPushes:
    """Items closer than the gap push apart along their contact (fast_forces.touching_pushes),
    shared by inverse mass; pairs come from a Verlet list rebuilt when anything has moved
    half its skin.

    On a page of at most ``ALL_PAIRS_UP_TO`` items the list is every pair, built once: a
    rebuild (the sweep, the blocked axes, the shares: some sixty NumPy calls) cost two to three
    steps, and a small page rebuilt every 15 steps or so (the one-big-item page 21 times in
    306 steps), while visiting its few dozen pairs every step costs next to nothing more.
    Pairs that do not touch push with nothing, so the sums are those of the Verlet list, up to
    the order in which a row's pushes are added."""

    def __init__(self, bodies: Bodies, rows_active: np.ndarray, roots: np.ndarray,
                 inverse_mass: np.ndarray, movable: np.ndarray, gap: float, skin: float,
                 page: tuple[float, float], gutter_mm: float, scale: float,
                 rng: np.random.Generator,
                 insets: tuple[np.ndarray, np.ndarray] | None = None):
        self.bodies, self.rows_active, self.roots = bodies, rows_active, roots
        self.inverse_mass, self.movable = inverse_mass, movable
        self.gap, self.skin, self.page, self.gutter_mm = gap, skin, page, gutter_mm
        self.scale, self.rng, self.insets = scale, rng, insets
        self.halves = bodies.sizes / 2
        self.base_skin, self.steps_since_build = skin, 0
        self.all_pairs = len(rows_active) <= ALL_PAIRS_UP_TO
        self.build()

    def build(self) -> None:
        # A list that lasts a few steps only costs more to rebuild than its pairs cost to
        # visit: while the page is hot (items move up to the speed limit every step) the skin
        # widens, and narrows back once lists last.
        if self.steps_since_build:
            if self.steps_since_build < MIN_LIST_STEPS:
                self.skin = min(self.skin * 2, self.base_skin * MAX_SKIN_GROWTH)
            elif self.steps_since_build > 4 * MIN_LIST_STEPS:
                self.skin = max(self.skin / 2, self.base_skin)
        self.steps_since_build = 0
        bodies, reach = self.bodies, self.gap + self.skin
        if self.all_pairs:
            i, j = every_pair(self.rows_active, self.roots)
            separate_coincident(bodies, i, j, self.movable, self.rng, self.scale)
        else:
            i, j = candidate_pairs(bodies.centres, self.halves, self.rows_active, self.roots,
                                   reach)
            if separate_coincident(bodies, i, j, self.movable, self.rng, self.scale):
                i, j = candidate_pairs(bodies.centres, self.halves, self.rows_active,
                                       self.roots, reach)
        total = self.inverse_mass[i] + self.inverse_mass[j]
        total = np.where(total > 0, total, 1.0)
        self.i, self.j = i, j
        # (m, 1): ready to scale the pushes, (m, 2)
        self.share_i = (self.inverse_mass[i] / total)[:, None]
        self.share_j = (self.inverse_mass[j] / total)[:, None]
        self.slots_i, self.slots_j = xy_slots(i), xy_slots(j)  # where the pushes land
        blocked = blocked_axes(bodies.sizes, i, j, *self.page, self.gutter_mm, self.insets)
        self.blocked = blocked if blocked.any() else None  # None: two calls less a step
        # centre distance where they touch
        self.touch_reach = self.halves.take(i, axis=0) + self.halves.take(j, axis=0)
        self.reach = self.touch_reach + self.gap
        self.built_at = bodies.centres.copy()

    def add_to(self, acc: np.ndarray, centres: np.ndarray, heat: float) -> None:
        self.steps_since_build += 1
        if not self.all_pairs and (np.abs(centres - self.built_at).max(initial=0.0)
                                   > self.skin / 2):
            self.build()
        touching, pushes = touching_pushes(centres, self.reach, self.i, self.j, self.blocked,
                                           RADIAL_SHARE * min(1.0, heat / RADIAL_FADE_HEAT))
        pushes *= K_CONTACT
        share_i, share_j, slots_i, slots_j = self.share_i, self.share_j, self.slots_i, self.slots_j
        if len(touching) < len(self.i):  # on a small page every listed pair mostly touches
            share_i, share_j = share_i.take(touching, axis=0), share_j.take(touching, axis=0)
            slots_i, slots_j = slots_i.take(touching, axis=0), slots_j.take(touching, axis=0)
        acc += pair_sums(len(acc), slots_i, slots_j, pushes * share_i, pushes * share_j)

    def overlapping(self, centres: np.ndarray) -> bool:
        """Whether any two items' rectangles (not their halos) overlap."""
        depth = self.touch_reach - np.abs(centres.take(self.j, axis=0)
                                          - centres.take(self.i, axis=0))
        return bool(((depth[:, 0] > 0) & (depth[:, 1] > 0)).any())


def every_pair(rows: np.ndarray, roots: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Every pair (i, j), i < j, of ``rows`` (ascending) in different rigid groups, in row
    order (candidate_pairs without the distance test, for a page that is small enough)."""
    first, second = np.triu_indices(len(rows), k=1)
    i, j = rows.take(first), rows.take(second)
    different = roots.take(i) != roots.take(j)
    return i[different], j[different]


class WallPushes:
    """Items closer to the page edge than half the gap are pushed back in (the soft wall;
    the hard one is geometry.clamp_to_page)."""

    def __init__(self, rest_low: np.ndarray, rest_high: np.ndarray):
        self.rest_low, self.rest_high = rest_low, rest_high

    def add_to(self, acc: np.ndarray, centres: np.ndarray, heat: float) -> None:
        acc += K_WALL * wall_pushes_in(centres, self.rest_low, self.rest_high)


class AnchorPulls:
    """A spring towards each soft anchor (equation 6's form, as stiff as a contact at the
    default beta; hard anchors are positions, not forces)."""

    def __init__(self, bodies: Bodies, anchored: np.ndarray, beta: float):
        self.anchored = anchored
        self.anchors = bodies.anchors[anchored]
        self.k = (K_ANCHOR * beta / BETA_DEFAULT * bodies.gammas)[anchored, None]

    def add_to(self, acc: np.ndarray, centres: np.ndarray, heat: float) -> None:
        acc[self.anchored] += self.k * (self.anchors - centres[self.anchored])
