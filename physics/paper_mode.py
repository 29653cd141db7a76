"""The paper's model as one loop: forces (2)+(3), walls (4.4), springs (6), Euler (4)+(5),
cooling and growing damping (4.7).  Kept faithful on purpose, flaws included, so that it can
serve as the reference the fast mode is measured against, and kept lean for the same reason:
what does not change between steps (active rows, pair reaches, anchors) is worked out once per
call, and the common page with nothing held, anchored or decorative skips the bookkeeping.
"""

from __future__ import annotations

import numpy as np

from floatpage.physics.bodies import Bodies
from floatpage.physics.constraints import enforce_positions, hand_forces_to_roots
from floatpage.physics.euler import damping_for_count, euler_step
from floatpage.physics.geometry import separate_coincident
from floatpage.physics.paper_forces import anchor_springs, contact_reach, repulsion, wall_forces
from floatpage.physics.params import Params, page_margin, page_scale
from floatpage.physics.stillness import STILL_MM_PER_FRAME


class Repulsion:
    """Equations (2)+(3): every pair pushes apart, inversely to its distance (7) or (8)."""

    def __init__(self, sizes: np.ndarray, alpha: float, distance: str):
        self.sizes, self.alpha, self.distance = sizes, alpha, distance
        self.reach = contact_reach(sizes)

    def add_to(self, force: np.ndarray, centres: np.ndarray, heat: float) -> None:
        force += repulsion(centres, self.sizes, self.alpha * heat, self.distance, reach=self.reach)


class Walls:
    """Section 4.4: the page's edges (moved in by the print-safe margins) push items back in."""

    def __init__(self, sizes: np.ndarray, page: tuple[float, float], alpha: float,
                 insets: tuple[np.ndarray, np.ndarray]):
        self.sizes, self.page, self.alpha, self.insets = sizes, page, alpha, insets

    def add_to(self, force: np.ndarray, centres: np.ndarray, heat: float) -> None:
        force += wall_forces(centres, self.sizes, *self.page, self.alpha * heat, *self.insets)


class Springs:
    """Equation (6): each anchored item is pulled to its anchor (NaN anchors pull nothing)."""

    def __init__(self, anchors: np.ndarray, gammas: np.ndarray, beta: float):
        self.anchors, self.gammas, self.beta = anchors, gammas, beta

    def add_to(self, force: np.ndarray, centres: np.ndarray, heat: float) -> None:
        force += anchor_springs(centres, self.anchors, self.gammas, self.beta * heat)


class PaperForces:
    """The resultant force on every row for one page whose items keep their sizes and flags:
    the sum of its terms (a new term is one more entry in ``terms``).

    Decorations neither push nor are pushed; every other row gets repulsion (2)+(3), the walls
    (4.4) and, where anchored, its spring (6).
    """

    def __init__(self, bodies: Bodies, page_w_mm: float, page_h_mm: float, params: Params):
        alpha = params.alpha * page_scale(page_w_mm, page_h_mm)
        active = bodies.active
        self.everyone = bool(active.all())
        self.rows = slice(None) if self.everyone else np.flatnonzero(active)
        sizes = bodies.sizes[self.rows]
        near, far = bodies.insets(page_margin(params.margin_mm, page_w_mm, page_h_mm),
                                  page_w_mm, page_h_mm)
        self.terms = [Repulsion(sizes, alpha, params.distance),
                      Walls(sizes, (page_w_mm, page_h_mm), alpha,
                            (near[self.rows], far[self.rows]))]
        anchors = bodies.anchors[self.rows]
        if np.isfinite(anchors).any():
            self.terms.append(Springs(anchors, bodies.gammas[self.rows], params.beta))
        self.count = bodies.count

    def __call__(self, centres: np.ndarray, heat: float) -> np.ndarray:
        """Forces (n, 2) for ``centres`` (n, 2) at the given heat (4.7)."""
        mine = centres[self.rows]
        force = np.zeros_like(mine)
        for term in self.terms:
            term.add_to(force, mine, heat)
        if self.everyone:
            return force
        forces = np.zeros((self.count, 2))
        forces[self.rows] = force
        return forces


def paper_forces(bodies: Bodies, page_w_mm: float, page_h_mm: float, params: Params,
                 heat: float) -> np.ndarray:
    """Resultant force on every row, shape (n, 2); decorations neither push nor are pushed."""
    if not bodies.active.any():
        return np.zeros_like(bodies.centres)
    return PaperForces(bodies, page_w_mm, page_h_mm, params)(bodies.centres, heat)


def run_paper(bodies: Bodies, page_w_mm: float, page_h_mm: float, params: Params, heat: float,
              steps: int, rng: np.random.Generator) -> tuple[int, float, bool]:
    """Advance up to ``steps`` steps in place; stop as soon as the page is still.

    Items sharing one centre feel no force from each other in (2) (their displacement is
    zero), so they are first nudged apart by a seeded jitter, as in the fast mode.

    Returns (steps run, heat after them, settled).  Still means every free item moves less
    than STILL_MM_PER_FRAME (scaled to the page) per frame of ``steps_per_frame`` steps, or
    the heat has fallen to ``heat_min``.
    """
    free = bodies.free
    if not free.any():
        return 0, heat, True
    delta = damping_for_count(params.delta, int(bodies.active.sum()))
    still_speed = (STILL_MM_PER_FRAME * page_scale(page_w_mm, page_h_mm)
                   / (params.steps_per_frame * params.dt))
    roots, root_offsets = bodies.group_roots()
    followers = bodies.followers
    has_followers = bool(followers.any())
    rows = np.flatnonzero(bodies.active)
    i, j = np.triu_indices(len(rows), k=1)
    movable = free[roots] & ~bodies.held & bodies.active
    separate_coincident(bodies, rows[i], rows[j], movable, rng,
                        page_scale(page_w_mm, page_h_mm))
    forces_at = PaperForces(bodies, page_w_mm, page_h_mm, params)
    all_free = bool(free.all())
    moved = slice(None) if all_free else free
    constrained = not all_free  # held, hard-anchored, decorative or following rows
    keep = 1.0 - params.heat_decay
    for done in range(1, steps + 1):
        forces = forces_at(bodies.centres, heat)
        if has_followers:
            hand_forces_to_roots(forces, roots, followers)
        bodies.centres[moved], bodies.velocities[moved] = euler_step(
            bodies.centres[moved], bodies.velocities[moved], forces[moved], params.dt, delta)
        if constrained:
            enforce_positions(bodies, roots, root_offsets)
        heat = max(heat * keep, params.heat_min)
        velocities = bodies.velocities[moved]
        fastest = float(np.max(velocities[:, 0] ** 2 + velocities[:, 1] ** 2))
        if heat <= params.heat_min or fastest < still_speed**2:
            return done, heat, True
    return steps, heat, False
