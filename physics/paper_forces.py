"""The paper's force terms, one function per equation (sections 4.2, 4.4, 4.5 and 4.6).

Each force function returns forces of shape (n, 2).  Lengths in mm; ``alpha`` is the caller's
effective repulsion constant (already multiplied by heat and page scale).  A distance is never
below ``SIGMA_MIN_MM``, so two items on one point give a large but finite force.

Pairwise quantities are kept as two (n, n) arrays, one per axis, rather than one (n, n, 2)
array: the paper mode is the reference the fast mode is timed against, so it should be as
quick as a plain NumPy version of the paper can be (about twice as quick as the (n, n, 2)
form at 50 items), or the comparison would flatter the fast mode.
"""

from __future__ import annotations

import numpy as np

from floatpage.physics.geometry import as_insets

SIGMA_MIN_MM = 1.0


def pair_displacements(centres: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(dx, dy) with dx[u, v] = x_u - x_v, each (n, n): they point from v towards u."""
    return (centres[:, 0, None] - centres[None, :, 0],
            centres[:, 1, None] - centres[None, :, 1])


def contact_reach(sizes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Half-width and half-height sums of every pair, each (n, n): below these centre distances
    two items' extents intersect on that axis.  Fixed while sizes are, so callers that step
    many times compute it once."""
    return ((sizes[:, 0, None] + sizes[None, :, 0]) / 2,
            (sizes[:, 1, None] + sizes[None, :, 1]) / 2)


def euclidean_distance(dx: np.ndarray, dy: np.ndarray) -> np.ndarray:
    """Equation (7): centre-to-centre distance, shape (n, n)."""
    return np.sqrt(dx * dx + dy * dy)


def axis_distance(dx: np.ndarray, dy: np.ndarray,
                  reach: tuple[np.ndarray, np.ndarray]) -> np.ndarray:
    """Equation (8): drop the axis on which the two items' extents intersect.

    If only the y extents intersect (side by side) the distance is |dx|; if only the x extents
    intersect (one above the other) it is |dy|; otherwise (apart on both axes, or overlapping)
    the euclidean distance (7).  ``reach`` is ``contact_reach(sizes)``.
    """
    abs_dx, abs_dy = np.abs(dx), np.abs(dy)
    meet_x, meet_y = abs_dx < reach[0], abs_dy < reach[1]
    sigma = euclidean_distance(dx, dy)
    sigma = np.where(meet_y & ~meet_x, abs_dx, sigma)
    return np.where(meet_x & ~meet_y, abs_dy, sigma)


def repulsion(centres: np.ndarray, sizes: np.ndarray, alpha: float, distance: str = "axis",
              sources: np.ndarray | None = None,
              reach: tuple[np.ndarray, np.ndarray] | None = None) -> np.ndarray:
    """Equations (2) summed by (3): F_u = sum over v != u of alpha q_v / sigma^2 * Delta / sigma.

    ``sources`` (n,) bool limits which items push (decorations do not); every row still
    receives a force, the caller discards what it does not move.  ``reach`` may be passed in
    (``contact_reach(sizes)``) by a caller that steps many times.
    """
    if len(centres) < 2:
        return np.zeros_like(centres)
    dx, dy = pair_displacements(centres)
    if distance == "euclidean":
        sigma = euclidean_distance(dx, dy)
    elif distance == "axis":
        sigma = axis_distance(dx, dy, contact_reach(sizes) if reach is None else reach)
    else:
        raise ValueError(f"unknown distance measure {distance!r}")
    np.maximum(sigma, SIGMA_MIN_MM, out=sigma)
    charges = sizes[:, 0] * sizes[:, 1]
    if sources is not None:
        charges = np.where(sources, charges, 0.0)
    # q_v alpha / sigma^2, times the 1/sigma that turns Delta into a unit vector
    magnitude = (alpha * charges)[None, :] / (sigma * sigma * sigma)
    np.fill_diagonal(magnitude, 0.0)
    # Plain sums rather than a BLAS product (m @ x): their result does not depend on the
    # machine's BLAS kernel, so a project file settles to the same bytes everywhere.
    return np.column_stack([(magnitude * dx).sum(axis=1), (magnitude * dy).sum(axis=1)])


def wall_forces(centres: np.ndarray, sizes: np.ndarray, page_w_mm: float, page_h_mm: float,
                alpha: float, margins: np.ndarray | float = 0.0,
                far_margins: np.ndarray | float | None = None) -> np.ndarray:
    """Section 4.4: each wall pushes like a charge equal to the item's own, sitting on the wall
    at the item's height (left/right) or column (top/bottom), by equation (2).

    Faithful to the paper, including its flaw: an item whose centre has crossed a wall is pushed
    further out, by that wall, with its full charge. The walls stand ``margins`` (one per row,
    or one for all) inside the page's left and top edges and ``far_margins`` (the same if not
    given) inside its right and bottom ones: our print-safe margin and regions, not the
    paper's.
    """
    charges = sizes[:, 0] * sizes[:, 1]
    inset = as_insets(margins)
    far_inset = inset if far_margins is None else as_insets(far_margins)
    near = centres - inset  # distance to the left and top walls
    far = centres - (np.array([page_w_mm, page_h_mm]) - far_inset)  # to the right and bottom ones
    push = np.zeros_like(centres)
    for offset in (near, far):
        sigma = np.maximum(np.abs(offset), SIGMA_MIN_MM)
        push += offset / (sigma * sigma * sigma)
    return alpha * charges[:, None] * push


def anchor_springs(centres: np.ndarray, anchors: np.ndarray, gammas: np.ndarray,
                   beta: float) -> np.ndarray:
    """Equation (6): g = gamma beta Delta, a zero-length spring towards the anchor point.

    Rows whose anchor is NaN (unanchored) get no force.
    """
    pulls = gammas[:, None] * beta * (anchors - centres)
    return np.where(np.isnan(pulls), 0.0, pulls)
