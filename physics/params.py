"""Tuning constants of the engine, and how they scale with the page.

Units: millimetres for lengths, page origin at the top-left, x to the right, y down; an item's
position is the centre of its rectangle.

The paper's constants keep the paper's names (alpha, beta, delta, dt; gamma is per item) so the
code can be held against its equations.  Section 4.7's decay of alpha and beta is called *heat*:
every step multiplies the heat by ``1 - heat_decay``, a user operation resets it to 1.

Page-size scaling, so that an A4 page and a 5x8 inch card behave alike
----------------------------------------------------------------------
Let ``s = sqrt(page area / A4 area)`` (``page_scale``).  Scaling every length of a page by ``s``
leaves the repulsion (2) and the wall force unchanged (charge ``w*h`` and ``sigma**2`` both grow
by ``s**2``), while a layout that looks the same needs every displacement, hence every force, to
grow by ``s``.  So the paper mode uses ``alpha * s``; the spring (6) already grows with the
displacement, so ``beta`` needs no scaling.  dt, delta and heat_decay are dimensionless per step.
The fast mode is scale-free by construction: its target gap comes from the free area of the page,
and its speed limit and stillness threshold are fractions of the page size.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

A4_W_MM = 210.0
A4_H_MM = 297.0

MODES = ("fast", "paper")
DISTANCES = ("euclidean", "axis")

# The one place the settings' ranges are written: Params checks them, and the project loader
# (floatpage.model) reads them to judge a file.  (low, high, whether low itself is allowed.)
# The upper bounds keep the Euler update (4, 5) finite: alpha = dt = 1e308 overflowed to NaN.
LIMITS: dict[str, tuple[float, float, bool]] = {
    "alpha": (0.0, 1e6, False),
    "beta": (0.0, 1e6, True),
    "delta": (0.0, 1.0, True),
    "dt": (0.0, 1.0, False),
    "steps_per_frame": (1, 100_000, True),
    "heat_decay": (0.0, 0.5, True),
    "gutter_mm": (0.0, 100.0, True),
    "margin_mm": (0.0, 100.0, True),
    "guides": (0.0, 10.0, True),
    "seed": (0, 2**63 - 1, True),
    "heat_min": (0.0, 1.0, True),
    "fast_steps_per_frame": (1, 100_000, True),
}


def out_of_range(name: str, value: float) -> str | None:
    """Why ``value`` is no good for the setting ``name``, in words for a user; None if it is."""
    low, high, low_allowed = LIMITS[name]
    if not math.isfinite(value):
        return "must be a finite number"
    if value < low or value == low and not low_allowed:
        return f"must be {'at least' if low_allowed else 'greater than'} {low:g}"
    if value > high:
        return f"must be at most {high:g}"
    return None


def page_margin(margin_mm: float, page_w_mm: float, page_h_mm: float) -> float:
    """The margin items keep on this page: ``margin_mm`` on A4 and larger, scaled down with the
    page's linear size below it (5 mm on A4, 3.5 mm on A5, 3.2 mm on a 5x8 inch card, as
    printers' safe zones shrink for small cards), and never more than a tenth of the page's
    shorter side."""
    scaled = margin_mm * min(1.0, page_scale(page_w_mm, page_h_mm))
    return min(scaled, 0.1 * min(page_w_mm, page_h_mm))


def page_scale(page_w_mm: float, page_h_mm: float) -> float:
    """Linear size of a page relative to A4 (1.0 for A4, about 0.64 for a 5x8 inch card)."""
    return math.sqrt((page_w_mm * page_h_mm) / (A4_W_MM * A4_H_MM))


@dataclass(frozen=True)
class Params:
    """Every constant the engine reads; immutable so one value can be shared by many pages.

    ``alpha``, ``beta``, ``delta``, ``dt`` and ``distance`` shape the paper mode; the fast mode
    reads ``beta`` (anchor stiffness relative to its own contact stiffness), ``heat_decay``
    (cooled at a fraction of it per step, see ``physics.fast_mode.cooling_rate``),
    ``heat_min``, ``gutter_mm``, ``seed`` and ``fast_steps_per_frame``; it ignores alpha,
    delta, dt and distance.
    """

    mode: str = "fast"  # "fast" | "paper"
    alpha: float = 150.0  # repulsion constant of equation (2), for an A4 page
    beta: float = 1.0  # anchor spring stiffness of equation (6), as model.PhysicsSettings
    delta: float = 0.01  # velocity damping of equation (5), for up to ITEMS_PER_DELTA items
    dt: float = 0.005  # time step of equations (4) and (5)
    steps_per_frame: int = 500  # the paper's steps per drawn frame (paper mode)
    distance: str = "axis"  # "euclidean" (7) | "axis" (8)
    heat_decay: float = 0.01  # 4.7: alpha and beta shrink by this factor every step
    gutter_mm: float = 3.0  # minimum gap that the final pass guarantees when items fit
    # print-safe margin between items and the page edge, on A4; smaller pages scale it down
    # with their linear size (page_margin). Bleed items and decorations are exempt.
    margin_mm: float = 5.0
    # strength of the magnetic alignment guides (physics.guides, physics.snapping); 0 turns
    # them off, 1 is the default pull
    guides: float = 1.0
    seed: int = 0  # seeds the jitter that separates items sitting on one point
    heat_min: float = 0.001  # below this heat the page counts as settled
    fast_steps_per_frame: int = 10  # fast mode's steps per drawn frame (each moves far more)

    def __post_init__(self) -> None:
        if self.mode not in MODES:
            raise ValueError(f"mode must be one of {MODES}, not {self.mode!r}")
        if self.distance not in DISTANCES:
            raise ValueError(f"distance must be one of {DISTANCES}, not {self.distance!r}")
        for name in LIMITS:
            complaint = out_of_range(name, getattr(self, name))
            if complaint:
                raise ValueError(f"{name} {complaint}, not {getattr(self, name)!r}")

    @property
    def frame_steps(self) -> int:
        """Steps in one drawn frame for the selected mode."""
        return self.steps_per_frame if self.mode == "paper" else self.fast_steps_per_frame
