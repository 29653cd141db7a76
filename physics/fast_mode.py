"""The default mode: semi-implicit Euler over short-range edge pushes, hard walls on item
edges, a speed limit for smooth motion, and cooling by heat.

Chosen by measurement (see docs/benchmarks.md): explicit Euler on the paper's long-range
forces needs tens of thousands of tiny steps, and cooling it faster freezes it with overlaps;
pushes that vanish at rest, integrated semi-implicitly (v += a; x += v, as d3-force does) with
strong friction, come to rest in about 300 to 2,500 steps, each visiting only nearby pairs (a
Verlet neighbour list).
"""

from __future__ import annotations

import numpy as np

from floatpage.physics.bodies import Bodies
from floatpage.physics.constraints import enforce_positions, hand_forces_to_roots
from floatpage.physics.fast_forces import (
    RADIAL_SHARE, blocked_axes, candidate_pairs, contact_pushes, target_gap, wall_pushes_in,
    wall_rest_box,
)
from floatpage.physics.params import Params, page_scale
from floatpage.physics.stillness import STILL_MM_PER_FRAME

K_CONTACT = 0.2  # fraction of a penetration turned into acceleration per step
K_WALL = 0.2
K_ANCHOR = 0.2  # anchor spring per step^2 at the default beta: as stiff as a contact
BETA_DEFAULT = 1.0  # Params.beta at which a fast anchor is as stiff as a contact
FRICTION = 0.4  # share of the velocity lost every step (d3-force's velocityDecay)
SPEED_LIMIT_MM = 2.5  # per step on an A4 page: 25 mm per frame at most, easy to follow
RADIAL_FADE_HEAT = 0.25  # below this heat the sliding (radial) push fades out
COOLING_ITEMS = 1.5  # fast mode cools at heat_decay * COOLING_ITEMS / sqrt(n) (see cooling_rate)
COOLING_SHARE_RANGE = (0.05, 0.25)
JITTER_MM = 0.5  # size of the seeded nudge that separates items on one point (A4)
COINCIDENT_MM = 1e-6


def group_extents(bodies: Bodies, roots: np.ndarray, root_offsets: np.ndarray
                  ) -> tuple[np.ndarray, np.ndarray]:
    """Bounding box of each rigid group relative to its root's centre, rows indexed by root."""
    halves = bodies.sizes / 2
    low = -halves.copy()
    high = halves.copy()
    members = bodies.followers
    if members.any():
        np.minimum.at(low, roots[members], root_offsets[members] - halves[members])
        np.maximum.at(high, roots[members], root_offsets[members] + halves[members])
    return low, high


def page_bounds(rows: np.ndarray, low: np.ndarray, high: np.ndarray, page_w_mm: float,
                page_h_mm: float) -> tuple[np.ndarray, np.ndarray]:
    """Lowest and highest centre, (len(rows), 2) each, that keeps each group inside the page.

    A group too large for the page on an axis gets one allowed value there: centred.
    """
    extent = np.array([page_w_mm, page_h_mm])
    lowest = -low[rows]
    highest = extent - high[rows]
    too_big = lowest > highest
    middle = extent / 2 - (low[rows] + high[rows]) / 2
    return np.where(too_big, middle, lowest), np.where(too_big, middle, highest)


def clamp_to_page(centres: np.ndarray, velocities: np.ndarray, rows: np.ndarray,
                  lowest: np.ndarray, highest: np.ndarray) -> None:
    """Hard walls, in place: keep each group's box inside the page (bounds from page_bounds).
    The velocity into a wall is dropped."""
    current = centres[rows]
    clamped = np.minimum(np.maximum(current, lowest), highest)
    hit = clamped != current
    if hit.any():
        centres[rows] = clamped
        velocities[rows] = np.where(hit, 0.0, velocities[rows])


def separate_coincident(bodies: Bodies, i: np.ndarray, j: np.ndarray, movable: np.ndarray,
                        rng: np.random.Generator, scale: float) -> bool:
    """Nudge one item of every pair sharing a centre by a seeded random offset (d3's jiggle).

    Returns whether anything moved.  Deterministic for a given generator state.
    """
    same = (np.abs(bodies.centres[j] - bodies.centres[i]) < COINCIDENT_MM).all(axis=1)
    if not same.any():
        return False
    rows = np.where(movable[j[same]], j[same], i[same])
    rows = np.unique(rows[movable[rows]])
    if len(rows) == 0:
        return False
    bodies.centres[rows] += rng.uniform(-JITTER_MM, JITTER_MM, size=(len(rows), 2)) * scale
    return True


def cooling_rate(heat_decay: float, count: int) -> float:
    """Heat lost per fast step.

    A fast step moves items much further than a paper step, yet a full page needs many steps
    at useful heat to unjam: a push has to travel across about sqrt(n) items to reach a
    roomier part of the page.  So the fast mode cools at heat_decay times 1.5 / sqrt(n),
    clipped to [0.05, 0.25] of it, which measured best (docs/benchmarks.md).  A run usually
    ends on stillness long before the heat runs out.
    """
    low, high = COOLING_SHARE_RANGE
    share = COOLING_ITEMS / np.sqrt(max(count, 1))
    return heat_decay * float(np.clip(share, low, high))


def run_fast(bodies: Bodies, page_w_mm: float, page_h_mm: float, params: Params, heat: float,
             steps: int, rng: np.random.Generator) -> tuple[int, float, bool]:
    """Advance up to ``steps`` steps in place; stop once the page is still.

    Returns (steps run, heat after them, settled).
    """
    free = bodies.free
    if not free.any() or steps <= 0:
        return 0, heat, not free.any()
    scale = page_scale(page_w_mm, page_h_mm)
    active = bodies.active
    rows_active = np.flatnonzero(active)
    free_rows = np.flatnonzero(free)
    moving = slice(None) if free.all() else free_rows  # plain slices copy nothing
    roots, root_offsets = bodies.group_roots()
    followers = bodies.followers
    halves = bodies.sizes / 2
    charges = np.where(active, bodies.charges, 0.0)
    group_mass = np.bincount(roots, weights=charges, minlength=bodies.count)
    movable = free[roots] & ~bodies.held & active
    inverse_mass = np.where(movable, 1.0 / np.maximum(group_mass[roots], 1e-12), 0.0)
    low, high = group_extents(bodies, roots, root_offsets)
    lowest, highest = page_bounds(free_rows, low, high, page_w_mm, page_h_mm)
    constrained = bool((bodies.held | bodies.hard | followers).any())

    gap = target_gap(bodies.sizes[active], page_w_mm, page_h_mm, params.gutter_mm)
    rest_low, rest_high = wall_rest_box(halves, page_w_mm, page_h_mm, gap / 2)
    skin = max(gap / 2, 2.0 * scale)
    still_speed = STILL_MM_PER_FRAME * scale / params.fast_steps_per_frame
    speed_limit = SPEED_LIMIT_MM * scale
    anchored = ~np.isnan(bodies.anchors[:, 0]) & ~bodies.hard
    any_anchored, any_followers = bool(anchored.any()), bool(followers.any())
    anchor_k = K_ANCHOR * params.beta / BETA_DEFAULT * bodies.gammas
    keep = 1.0 - cooling_rate(params.heat_decay, len(rows_active))
    count = bodies.count

    def build():
        i, j = candidate_pairs(bodies.centres, halves, rows_active, roots, gap + skin)
        if separate_coincident(bodies, i, j, movable, rng, scale):
            i, j = candidate_pairs(bodies.centres, halves, rows_active, roots, gap + skin)
        total = inverse_mass[i] + inverse_mass[j]
        total = np.where(total > 0, total, 1.0)
        blocked = blocked_axes(bodies.sizes, i, j, page_w_mm, page_h_mm, params.gutter_mm)
        return i, j, inverse_mass[i] / total, inverse_mass[j] / total, blocked

    i, j, share_i, share_j, blocked = build()
    built_at = bodies.centres.copy()
    for done in range(1, steps + 1):
        if np.abs(bodies.centres - built_at).max(initial=0.0) > skin / 2:
            i, j, share_i, share_j, blocked = build()
            built_at = bodies.centres.copy()
        pushes = K_CONTACT * contact_pushes(bodies.centres, halves, i, j, gap, blocked,
                                            RADIAL_SHARE * min(1.0, heat / RADIAL_FADE_HEAT))
        acc = np.empty((count, 2))
        for axis in (0, 1):
            acc[:, axis] = (np.bincount(j, pushes[:, axis] * share_j, minlength=count)
                            - np.bincount(i, pushes[:, axis] * share_i, minlength=count))
        acc += K_WALL * wall_pushes_in(bodies.centres, rest_low, rest_high)
        if any_anchored:
            acc[anchored] += anchor_k[anchored, None] * (bodies.anchors[anchored]
                                                          - bodies.centres[anchored])
        if any_followers:
            hand_forces_to_roots(acc, roots, followers)
        velocities = (bodies.velocities[moving] + heat * acc[moving]) * (1.0 - FRICTION)
        speeds = np.sqrt(velocities[:, 0] * velocities[:, 0] + velocities[:, 1] * velocities[:, 1])
        top_speed = speeds.max()
        if top_speed > speed_limit:
            too_fast = speeds > speed_limit
            velocities[too_fast] *= (speed_limit / speeds[too_fast])[:, None]
        bodies.velocities[moving] = velocities
        bodies.centres[moving] += velocities
        clamp_to_page(bodies.centres, bodies.velocities, moving, lowest, highest)
        if constrained:
            enforce_positions(bodies, roots, root_offsets)
        heat = max(heat * keep, params.heat_min)
        if heat <= params.heat_min or top_speed < still_speed:
            return done, heat, True
    return steps, heat, False
