"""The paper's model as one loop: forces (2)+(3), walls (4.4), springs (6), Euler (4)+(5),
cooling and growing damping (4.7).  Kept faithful on purpose, flaws included, so that it can
serve as the reference the fast mode is measured against.
"""

from __future__ import annotations

import numpy as np

from physics.bodies import Bodies
from physics.constraints import enforce_positions, hand_forces_to_roots
from physics.euler import damping_for_count, euler_step
from physics.fast_mode import separate_coincident
from physics.paper_forces import anchor_springs, repulsion, wall_forces
from physics.params import Params, page_scale
from physics.stillness import STILL_MM_PER_FRAME


def paper_forces(bodies: Bodies, page_w_mm: float, page_h_mm: float, params: Params,
                 heat: float) -> np.ndarray:
    """Resultant force on every row, shape (n, 2); decorations neither push nor are pushed."""
    forces = np.zeros_like(bodies.centres)
    active = bodies.active
    if not active.any():
        return forces
    alpha = params.alpha * page_scale(page_w_mm, page_h_mm) * heat
    centres, sizes = bodies.centres[active], bodies.sizes[active]
    forces[active] = (
        repulsion(centres, sizes, alpha, params.distance)
        + wall_forces(centres, sizes, page_w_mm, page_h_mm, alpha)
        + anchor_springs(centres, bodies.anchors[active], bodies.gammas[active],
                         params.beta * heat)
    )
    return forces


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
    rows = np.flatnonzero(bodies.active)
    i, j = np.triu_indices(len(rows), k=1)
    movable = free[roots] & ~bodies.held & bodies.active
    separate_coincident(bodies, rows[i], rows[j], movable, rng,
                        page_scale(page_w_mm, page_h_mm))
    keep = 1.0 - params.heat_decay
    for done in range(1, steps + 1):
        forces = paper_forces(bodies, page_w_mm, page_h_mm, params, heat)
        hand_forces_to_roots(forces, roots, followers)
        bodies.centres[free], bodies.velocities[free] = euler_step(
            bodies.centres[free], bodies.velocities[free], forces[free], params.dt, delta)
        enforce_positions(bodies, roots, root_offsets)
        heat = max(heat * keep, params.heat_min)
        speeds = np.sqrt(np.einsum("ik,ik->i", bodies.velocities[free], bodies.velocities[free]))
        if heat <= params.heat_min or speeds.max() < still_speed:
            return done, heat, True
    return steps, heat, False
