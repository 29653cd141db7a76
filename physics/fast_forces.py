"""Force terms of the fast mode: short-range pushes between rectangle *edges*, and walls that
push on item edges.

Why not the paper's 1/sigma^2 between centres: a long-range force never vanishes, so the page
only stops when cooling freezes it, and centre distances ignore item shapes (a wide banner and a
small photo overlap long before their centres are close).  Here every item wants a gap ``gap``
(mm) to its neighbours and ``gap / 2`` to the page edge.  ``target_gap`` chooses that gap so the
items with their halos fill the page slightly more than fully: every item is then gently
pressed by its neighbours, and a pressed, damped spring network comes to rest with even gaps.
The pushes vanish at rest, so motion dies out by itself instead of by cooling alone.

Pushes are accelerations in mm per step squared; the integrator scales them by heat.
"""

from __future__ import annotations

import numpy as np

FILL = 0.9  # halo-inflated item area / page area that target_gap aims at
RADIAL_SHARE = 0.5  # share of a push directed along the line between the centres
AXIS_SHARPNESS = 4  # how strongly a push prefers the axis of least penetration


def target_gap(sizes: np.ndarray, page_w_mm: float, page_h_mm: float, gutter_mm: float,
               fill: float = FILL) -> float:
    """Gap g (mm) with sum of (w + g)(h + g) = fill * page area, never below the gutter.

    Solves n g^2 + g sum(w + h) + sum(w h) - fill W H = 0 for its positive root.
    """
    count = len(sizes)
    if count == 0:
        return gutter_mm
    linear = float((sizes[:, 0] + sizes[:, 1]).sum())
    constant = float((sizes[:, 0] * sizes[:, 1]).sum()) - fill * page_w_mm * page_h_mm
    if constant >= 0:
        return gutter_mm
    root = (-linear + np.sqrt(linear * linear - 4.0 * count * constant)) / (2.0 * count)
    return max(float(root), gutter_mm)


def candidate_pairs(centres: np.ndarray, halves: np.ndarray, rows: np.ndarray,
                    groups: np.ndarray, reach: float) -> tuple[np.ndarray, np.ndarray]:
    """Pairs (i, j), i < j, among ``rows`` whose rectangles come within ``reach`` mm.

    A Verlet neighbour list: built now and then with a margin (``reach`` = gap + skin), so each
    step only visits the few pairs that can touch.  Pairs inside one rigid group are left out.
    """
    if len(rows) < 2:
        empty = np.zeros(0, dtype=np.int64)
        return empty, empty
    c, h = centres[rows], halves[rows]
    upper_i, upper_j = np.triu_indices(len(rows), k=1)
    clear = np.abs(c[upper_j] - c[upper_i]) - h[upper_j] - h[upper_i]
    near = (clear[:, 0] < reach) & (clear[:, 1] < reach)
    i, j = rows[upper_i[near]], rows[upper_j[near]]
    different = groups[i] != groups[j]
    return i[different], j[different]


def contact_pushes(centres: np.ndarray, halves: np.ndarray, i: np.ndarray, j: np.ndarray,
                   gap: float) -> np.ndarray:
    """For each pair, the push on j away from i (i gets the opposite), shape (m, 2).

    Each rectangle is grown by gap / 2; the push is the penetration depth of the grown pair,
    split between the axes so that the axis of least penetration takes nearly all of it (a soft
    version of the minimum translation vector: continuous, hence no jitter at corners).
    """
    d = centres[j] - centres[i]
    penetration = halves[i] + halves[j] + gap - np.abs(d)
    touching = (penetration[:, 0] > 0) & (penetration[:, 1] > 0)
    penetration = np.where(touching[:, None], penetration, 0.0)
    sharp = penetration**AXIS_SHARPNESS
    total = sharp[:, 0] + sharp[:, 1]
    total = np.where(total > 0, total, 1.0)
    weights = sharp[:, ::-1] / total[:, None]  # x takes the y share and vice versa
    direction = np.where(d >= 0, 1.0, -1.0)
    pushes = direction * penetration * weights
    if RADIAL_SHARE > 0:
        # A little push along the line between the centres lets an item squeezed in a row slip
        # up or down into a roomier row; pure axis pushes would keep the row jammed.
        length = np.sqrt(np.einsum("mk,mk->m", d, d))
        unit = d / np.where(length > 0, length, 1.0)[:, None]
        depth = np.sqrt(np.einsum("mk,mk->m", pushes, pushes))
        pushes = pushes + RADIAL_SHARE * depth[:, None] * unit
    return pushes


def wall_pushes(centres: np.ndarray, halves: np.ndarray, page_w_mm: float, page_h_mm: float,
                margin: float) -> np.ndarray:
    """Springs that keep every item edge ``margin`` mm inside the page, shape (n, 2).

    An item too large for the page on an axis is pulled to the page's middle on that axis.
    """
    extent = np.array([page_w_mm, page_h_mm])
    low = np.maximum(halves + margin - centres, 0.0)
    high = np.maximum(centres + halves + margin - extent, 0.0)
    pushes = low - high
    too_big = 2 * halves >= extent
    return np.where(too_big, extent / 2 - centres, pushes)
