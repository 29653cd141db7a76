"""Whether a snap keeps the page at rest: the fast mode's forces on the items a move touches.

A settled page is at rest because every item's forces nearly cancel (a pressed network of
contacts, walls and anchor springs, stopped by friction).  A snap that slides an item 3 mm into
a neighbour's halo, or onto the margin line inside the wall's rest box, leaves forces that the
next gentle run turns into millimetres of drift, and the settled file would no longer be a
fixed point (model.layout.settle_page).  So the snapping step asks this check before each move:
after the move, the net acceleration of the moved item and of every item it touches must stay
within ``REST_ACC`` (or within what it already was).

The forces are the fast mode's own (fast_forces, force_terms) at a cold page: contact pushes
without the sliding share, walls at the target gap, soft anchor springs.  The guide pull is
left out: it is zero on a guide line.
"""

from __future__ import annotations

import numpy as np

from floatpage.physics.bodies import Bodies
from floatpage.physics.fast_forces import (
    blocked_axes, candidate_pairs, touching_pushes, wall_pushes_in, wall_rest_box,
)
from floatpage.physics.force_terms import BETA_DEFAULT, K_ANCHOR, K_CONTACT, K_WALL
from floatpage.physics.geometry import pair_sums, xy_slots

REST_ACC = 0.8  # mm per step^2 on A4: a cold page's run (heat 0.02) moves such an item
# about 0.006 mm a step, below the stillness threshold


class RestCheck:
    """One page's forces, set up once for a snapping pass whose moves stay within ``reach``."""

    def __init__(self, bodies: Bodies, page: tuple[float, float], gap: float,
                 insets: tuple[np.ndarray, np.ndarray], beta: float, reach: float, scale: float,
                 hold: float = 0.0):
        self.bodies, self.page, self.gap = bodies, page, gap
        self.halves = bodies.sizes / 2
        active = bodies.active
        roots, _ = bodies.group_roots()
        self.roots = roots
        charges = np.where(active, bodies.charges, 0.0)
        group_mass = np.bincount(roots, weights=charges, minlength=bodies.count)
        movable = bodies.free[roots] & ~bodies.held & active
        inverse = np.where(movable, 1.0 / np.maximum(group_mass[roots], 1e-12), 0.0)
        i, j = candidate_pairs(bodies.centres, self.halves, np.flatnonzero(active), roots,
                               gap + 2 * reach)
        total = inverse[i] + inverse[j]
        total = np.where(total > 0, total, 1.0)
        self.i, self.j = i, j
        self.share_i, self.share_j = inverse[i] / total, inverse[j] / total
        self.blocked = blocked_axes(bodies.sizes, i, j, *page, 0.0, insets)
        self.reach = self.halves[i] + self.halves[j] + gap  # each pair's, as the contacts keep it
        near, far = insets  # where each row's walls stand (Bodies.insets)
        self.rest_low, self.rest_high = wall_rest_box(self.halves, *page, gap / 2 + near,
                                                      gap / 2 + far)
        anchored = ~np.isnan(bodies.anchors[:, 0]) & ~bodies.hard
        self.anchor_k = np.where(anchored, K_ANCHOR * beta / BETA_DEFAULT * bodies.gammas, 0.0)
        self.anchors = np.where(anchored[:, None], bodies.anchors, 0.0)
        self.movable = bodies.free & active  # roots of groups the integrator moves
        self.limit = REST_ACC * scale
        self.hold = hold  # a line's hold on a group with a feature on it (physics.guides)
        count = bodies.count
        ends = np.concatenate([i, j])
        order = np.argsort(ends, kind="stable")
        split = np.searchsorted(ends[order], np.arange(count + 1))
        pair_ids = np.concatenate([np.arange(len(i)), np.arange(len(j))])[order]
        self.pairs_of = [pair_ids[split[row]:split[row + 1]] for row in range(count)]
        self.group_rows = group_members(roots, active)

    def net(self, rows: np.ndarray, pairs: np.ndarray, centres: np.ndarray) -> np.ndarray:
        """Net acceleration (n, 2), right for ``rows`` (``pairs`` must hold every pair that
        touches them), with the items at ``centres``."""
        i, j = self.i[pairs], self.j[pairs]
        touching, pushes = touching_pushes(centres, self.reach[pairs], i, j,
                                           self.blocked[pairs], 0.0)
        pushes *= K_CONTACT
        pairs, i, j = pairs[touching], i[touching], j[touching]
        acc = pair_sums(self.bodies.count, xy_slots(i), xy_slots(j),
                        pushes * self.share_i[pairs][:, None], pushes * self.share_j[pairs][:, None])
        acc[rows] += K_WALL * wall_pushes_in(centres[rows], self.rest_low[rows],
                                             self.rest_high[rows])
        acc[rows] += self.anchor_k[rows, None] * (self.anchors[rows] - centres[rows])
        return acc

    def keeps_rest(self, members: np.ndarray, axis: int, shift: float, onto_line: bool) -> bool:
        """Whether moving the rigid body ``members`` by ``shift`` along ``axis`` leaves it and
        every group it touches with a net acceleration within the limit, or no larger than
        it was (a group's acceleration is the sum of its members', as the fast mode hands a
        follower's forces to its root).  A move ``onto_line`` leaves the group on a guide,
        whose hold takes up to ``hold`` of its push along ``axis`` (``members`` may be several
        groups lined up, moved as one: each is held on the line by the others)."""
        touching = np.concatenate([self.pairs_of[m] for m in members])
        touched = np.concatenate([members, self.i[touching], self.j[touching]])
        groups = sorted_unique(self.roots[touched])
        groups = groups[self.movable[groups]]
        if len(groups) == 0:
            return True
        rows = np.concatenate([self.group_rows[g] for g in groups])
        pairs = sorted_unique(np.concatenate([self.pairs_of[r] for r in rows]))
        centres = self.bodies.centres
        trial = centres.copy()
        trial[members, axis] += shift
        before = np.abs(self.group_net(rows, pairs, centres, groups)).max(axis=1)
        after = np.abs(self.group_net(rows, pairs, trial, groups))
        if onto_line:
            moved = np.isin(groups, self.roots[members])
            after[moved, axis] = np.maximum(after[moved, axis] - self.hold, 0.0)
        return bool((after.max(axis=1) <= np.maximum(before, self.limit) + 1e-9).all())

    def group_net(self, rows: np.ndarray, pairs: np.ndarray, centres: np.ndarray,
                  groups: np.ndarray) -> np.ndarray:
        """Each group's net acceleration, (len(groups), 2)."""
        per_row = self.net(rows, pairs, centres)[rows]
        summed = np.zeros((self.bodies.count, 2))
        np.add.at(summed, self.roots[rows], per_row)
        return summed[groups]


def sorted_unique(values: np.ndarray) -> np.ndarray:
    """``np.unique`` for the small arrays of one move: a sort and a mask (np.unique's set-up
    cost was a third of the snapping's time)."""
    ordered = np.sort(values)
    keep = np.empty(len(ordered), dtype=bool)
    keep[:1] = True
    np.not_equal(ordered[1:], ordered[:-1], out=keep[1:])
    return ordered[keep]


def group_members(roots: np.ndarray, active: np.ndarray) -> list[np.ndarray]:
    """For each row, the active rows whose group root it is (empty unless it is a root), in
    one sort: a comparison per root cost O(n^2) on a 10,000-item page."""
    order = np.argsort(roots, kind="stable")
    order = order[active[order]]
    bounds = np.searchsorted(roots[order], np.arange(len(roots) + 1))
    return [order[bounds[row]:bounds[row + 1]] for row in range(len(roots))]
