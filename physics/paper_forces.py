"""The paper's force terms, one function per equation (sections 4.2, 4.4, 4.5 and 4.6).

Each returns forces of shape (n, 2).  Lengths in mm; ``alpha`` is the caller's effective
repulsion constant (already multiplied by heat and page scale).  A distance is never below
``SIGMA_MIN_MM``, so two items on one point give a large but finite force.
"""

from __future__ import annotations

import numpy as np

SIGMA_MIN_MM = 1.0


def pair_displacements(centres: np.ndarray) -> np.ndarray:
    """Delta[u, v] = centre_u - centre_v, shape (n, n, 2): points from v towards u."""
    return centres[:, None, :] - centres[None, :, :]


def euclidean_distance(displacements: np.ndarray) -> np.ndarray:
    """Equation (7): centre-to-centre distance, shape (n, n)."""
    return np.sqrt(np.einsum("uvk,uvk->uv", displacements, displacements))


def axis_distance(displacements: np.ndarray, sizes: np.ndarray) -> np.ndarray:
    """Equation (8): drop the axis on which the two items' extents intersect.

    If only the y extents intersect (side by side) the distance is |dx|; if only the x extents
    intersect (one above the other) it is |dy|; otherwise (apart on both axes, or overlapping)
    the euclidean distance (7).
    """
    abs_dx = np.abs(displacements[..., 0])
    abs_dy = np.abs(displacements[..., 1])
    meet_x = abs_dx < (sizes[:, None, 0] + sizes[None, :, 0]) / 2
    meet_y = abs_dy < (sizes[:, None, 1] + sizes[None, :, 1]) / 2
    sigma = euclidean_distance(displacements)
    sigma = np.where(meet_y & ~meet_x, abs_dx, sigma)
    return np.where(meet_x & ~meet_y, abs_dy, sigma)


def repulsion(centres: np.ndarray, sizes: np.ndarray, alpha: float, distance: str = "axis",
              sources: np.ndarray | None = None) -> np.ndarray:
    """Equations (2) summed by (3): F_u = sum over v != u of alpha q_v / sigma^2 * Delta / sigma.

    ``sources`` (n,) bool limits which items push (decorations do not); every row still
    receives a force, the caller discards what it does not move.
    """
    if len(centres) < 2:
        return np.zeros_like(centres)
    displacements = pair_displacements(centres)
    if distance == "euclidean":
        sigma = euclidean_distance(displacements)
    elif distance == "axis":
        sigma = axis_distance(displacements, sizes)
    else:
        raise ValueError(f"unknown distance measure {distance!r}")
    sigma = np.maximum(sigma, SIGMA_MIN_MM)
    charges = sizes[:, 0] * sizes[:, 1]
    if sources is not None:
        charges = np.where(sources, charges, 0.0)
    magnitude = alpha * charges[None, :] / sigma**3  # q_v alpha / sigma^2, times 1/sigma of Delta/sigma
    np.fill_diagonal(magnitude, 0.0)
    return np.einsum("uv,uvk->uk", magnitude, displacements)


def wall_forces(centres: np.ndarray, sizes: np.ndarray, page_w_mm: float, page_h_mm: float,
                alpha: float) -> np.ndarray:
    """Section 4.4: each wall pushes like a charge equal to the item's own, sitting on the wall
    at the item's height (left/right) or column (top/bottom), by equation (2).

    Faithful to the paper, including its flaw: an item whose centre has crossed a wall is pushed
    further out, by that wall, with its full charge.
    """
    charges = sizes[:, 0] * sizes[:, 1]
    forces = np.zeros_like(centres)
    for axis, extent in ((0, page_w_mm), (1, page_h_mm)):
        for wall in (0.0, extent):
            delta = centres[:, axis] - wall
            sigma = np.maximum(np.abs(delta), SIGMA_MIN_MM)
            forces[:, axis] += alpha * charges / sigma**3 * delta
    return forces


def anchor_springs(centres: np.ndarray, anchors: np.ndarray, gammas: np.ndarray,
                   beta: float) -> np.ndarray:
    """Equation (6): g = gamma beta Delta, a zero-length spring towards the anchor point.

    Rows whose anchor is NaN (unanchored) get no force.
    """
    pulls = gammas[:, None] * beta * (anchors - centres)
    return np.where(np.isnan(pulls), 0.0, pulls)
