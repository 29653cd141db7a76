"""Motion by the paper's equations (1), (4) and (5), and section 4.7's damping rule."""

from __future__ import annotations

import numpy as np

ITEMS_PER_DELTA = 10  # up to this many items the damping is the given delta


def euler_step(centres: np.ndarray, velocities: np.ndarray, forces: np.ndarray, dt: float,
               delta: float) -> tuple[np.ndarray, np.ndarray]:
    """Explicit Euler, equations (4) and (5).

    x(t+1) = x(t) + dt v(t);  v(t+1) = (v(t) + dt F(t)) (1 - delta).  Unit mass: the paper
    divides by no mass, the charge already scales the forces.
    """
    return centres + dt * velocities, (velocities + dt * forces) * (1.0 - delta)


def kinetic_energy(sizes: np.ndarray, velocities: np.ndarray,
                   mask: np.ndarray | None = None) -> float:
    """Equation (1): epsilon = sum of w h (vx^2 + vy^2), over ``mask`` rows if given."""
    per_item = sizes[:, 0] * sizes[:, 1] * np.einsum("ik,ik->i", velocities, velocities)
    if mask is not None:
        per_item = per_item[mask]
    return float(per_item.sum())


def damping_for_count(delta: float, count: int) -> float:
    """Section 4.7: damping grows with the number of items.

    Up to ITEMS_PER_DELTA items it is delta; beyond, it is as if the velocity were damped
    count / ITEMS_PER_DELTA times per step: 1 - (1 - delta)^(count / 10).  It stays below 1, so
    the system never freezes outright, and equals delta for a small page.
    """
    repeats = max(1.0, count / ITEMS_PER_DELTA)
    return 1.0 - (1.0 - delta) ** repeats
