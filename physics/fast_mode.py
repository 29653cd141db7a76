"""The default mode: semi-implicit Euler over short-range edge pushes, hard walls on item
edges, a speed limit for smooth motion, and cooling by heat.

Chosen by measurement (see docs/benchmarks.md): explicit Euler on the paper's long-range
forces needs tens of thousands of tiny steps, and cooling it faster freezes it with overlaps;
pushes that vanish at rest, integrated semi-implicitly (v += a; x += v, as d3-force does) with
strong friction, come to rest in about 300 to 2,500 steps, each visiting only nearby pairs (a
Verlet neighbour list).
"""

from __future__ import annotations

import math

import numpy as np

from floatpage.physics.bodies import Bodies
from floatpage.physics.constraints import enforce_positions, hand_forces_to_roots
from floatpage.physics.fast_forces import target_gap, wall_rest_box
from floatpage.physics.force_terms import AnchorPulls, ContactPushes, Force, WallPushes
from floatpage.physics.guides import GUIDE_HEAT, HOLD_HEAT, guide_pulls
from floatpage.physics.geometry import (
    ROOMY_COVER, as_insets, clamp_to_page, group_bounds, grown_cover, lines_up, squared_norms,
)
from floatpage.physics.params import Params, page_margin, page_scale
from floatpage.physics.stillness import STILL_MM_PER_FRAME

FRICTION = 0.4  # share of the velocity lost every step (d3-force's velocityDecay)
SPEED_LIMIT_MM = 2.5  # per step on an A4 page: 25 mm per frame at most, easy to follow
COOLING_ITEMS = 2.25  # fast mode cools at heat_decay * COOLING_ITEMS / sqrt(n) (see cooling_rate)
COOLING_SHARE_RANGE = (0.15, 0.375)
GUIDED_COOLING = 0.02  # heat lost per step once the page has spread out (see run_fast)


def cooling_rate(heat_decay: float, count: int) -> float:
    """Heat lost per fast step.

    A fast step moves items much further than a paper step, yet a full page needs many steps
    at useful heat to unjam: a push has to travel across about sqrt(n) items to reach a
    roomier part of the page.  So the fast mode cools at heat_decay times 2.25 / sqrt(n),
    clipped to [0.15, 0.375] of it.  (docs/benchmarks.md: 1.5 / sqrt(n) within [0.05, 0.25]
    took twice the steps for layouts within the same goals; the higher floor halves the steps
    of a 10,000-item page, whose tiny items need no long unjamming, for 0.06 mm of the
    500-item page's smallest gap.)  A run usually ends on stillness long before the heat
    runs out.
    """
    low, high = COOLING_SHARE_RANGE
    share = COOLING_ITEMS / np.sqrt(max(count, 1))
    return heat_decay * float(np.clip(share, low, high))


def fast_forces(bodies: Bodies, page_w_mm: float, page_h_mm: float, params: Params,
                rng: np.random.Generator, roots: np.ndarray, movable: np.ndarray,
                inverse_mass: np.ndarray, gap: float, skin: float,
                margins: np.ndarray | float = 0.0,
                far_margins: np.ndarray | float | None = None, align: bool = True,
                saved: bool = False) -> list[Force]:
    """The forces the fast mode sums every step; a new force is one more entry here (the
    contacts come first: the step loop asks them whether any items still overlap).
    ``margins`` and ``far_margins`` are where the walls stand (Bodies.insets); ``align`` is
    False on a page too full to line up (geometry.lines_up), where alignment gives way (as
    the snap does, Engine.finalize): a guide's pull against a pressed crowd only kept it
    creeping until the lines' hold stopped it.  ``saved``: the run starts cold, testing a saved
    layout, whose rounding the lines' hold allows for (guides.GuidePulls)."""
    halves = bodies.sizes / 2
    near = as_insets(margins)
    far = near if far_margins is None else as_insets(far_margins)
    rest_low, rest_high = wall_rest_box(halves, page_w_mm, page_h_mm, gap / 2 + near,
                                        gap / 2 + far)
    forces: list[Force] = [
        ContactPushes(bodies, np.flatnonzero(bodies.active), roots, inverse_mass, movable, gap,
                      skin, (page_w_mm, page_h_mm), params.gutter_mm,
                      page_scale(page_w_mm, page_h_mm), rng, (near, far)),
        WallPushes(rest_low, rest_high),
    ]
    anchored = ~np.isnan(bodies.anchors[:, 0]) & ~bodies.hard
    if anchored.any():
        forces.append(AnchorPulls(bodies, anchored, params.beta))
    if align:
        forces += guide_pulls(bodies, roots, (page_w_mm, page_h_mm),
                              page_margin(params.margin_mm, page_w_mm, page_h_mm), params.guides,
                              saved)
    return forces


def run_fast(bodies: Bodies, page_w_mm: float, page_h_mm: float, params: Params, heat: float,
             steps: int, rng: np.random.Generator, spread_out: bool = False,
             cool_onto_guides: bool = True) -> tuple[int, float, bool, bool]:
    """Advance up to ``steps`` steps in place; stop once the page is still.

    Each step: the forces' sum (fast_forces), semi-implicit Euler with friction and a speed
    limit, hard walls, constraints, cooling. Returns (steps run, heat after them, settled,
    spread out: whether the page has spread and now cools onto its guides, which the caller
    hands back to the next call, as the editor runs a page one frame at a time).

    ``cool_onto_guides``: once the page is still, cool on while the guides pull its features
    onto their lines (below).  The editor does, so that items glide onto a line as a user
    watches; a headless settle (Engine.settle) does not, and leaves the lines to the snap
    that follows it (physics.snapping): the cooling was 8-15 % of a settle's steps, while
    the near misses the snap leaves were the same with it and without it (docs/benchmarks.md,
    eighteenth session, "lead").  The lines' hold acts either way on a cold page.
    """
    free = bodies.free
    if not free.any() or steps <= 0:
        return 0, heat, not free.any(), spread_out
    scale = page_scale(page_w_mm, page_h_mm)
    active = bodies.active
    free_rows = np.flatnonzero(free)
    moving = slice(None) if free.all() else free_rows  # plain slices copy nothing
    roots, root_offsets = bodies.group_roots()
    followers = bodies.followers
    charges = np.where(active, bodies.charges, 0.0)
    group_mass = np.bincount(roots, weights=charges, minlength=bodies.count)
    movable = free[roots] & ~bodies.held & active
    inverse_mass = np.where(movable, 1.0 / np.maximum(group_mass[roots], 1e-12), 0.0)
    near, far = bodies.insets(page_margin(params.margin_mm, page_w_mm, page_h_mm), page_w_mm,
                              page_h_mm)
    lowest, highest = group_bounds(bodies, free_rows, roots, root_offsets, near, far,
                                   page_w_mm, page_h_mm)
    constrained = bool((bodies.held | bodies.hard | followers).any())

    gap = target_gap(bodies.sizes[active], page_w_mm, page_h_mm, params.gutter_mm)
    skin = max(gap / 2, 2.0 * scale)
    still_speed = STILL_MM_PER_FRAME * scale / params.fast_steps_per_frame
    speed_limit = SPEED_LIMIT_MM * scale
    any_followers = bool(followers.any())
    cooling = cooling_rate(params.heat_decay, int(active.sum()))
    keep = 1.0 - (max(cooling, GUIDED_COOLING) if spread_out else cooling)
    # Once the page is still, the spreading is over: where it cools onto its guides
    # (``cool_onto_guides``), rather than cool slowly on while nothing moves, the heat drops to
    # where the alignment guides pull in full (GUIDE_HEAT / 2), and cools from there at
    # GUIDED_COOLING a step, until the page is still on its lines below the heat at which the
    # lines hold (without guides, or on a page too full to line up, nothing more to wait for).
    # From 0.9 GUIDE_HEAT, where the pull is a fifth of its strength, that took at least 83
    # steps; from the half, at least 49.
    cover = grown_cover(bodies, near, far, page_w_mm, page_h_mm, params.gutter_mm)
    roomy = cover <= ROOMY_COVER
    aligns = lines_up(cover, int(active.sum()))
    guides_on = params.guides > 0 and aligns and cool_onto_guides
    guided_heat = GUIDE_HEAT / 2
    settled_below = HOLD_HEAT if guides_on else np.inf
    count = bodies.count
    forces = fast_forces(bodies, page_w_mm, page_h_mm, params, rng, roots, movable,
                         inverse_mass, gap, skin, near, far, align=aligns,
                         saved=heat < HOLD_HEAT and not spread_out)
    contacts = forces[0]
    for done in range(1, steps + 1):
        acc = np.zeros((count, 2))
        for force in forces:
            force.add_to(acc, bodies.centres, heat)
        if any_followers:
            hand_forces_to_roots(acc, roots, followers)
        velocities = (bodies.velocities[moving] + heat * acc[moving]) * (1.0 - FRICTION)
        # The top speed is the root of the largest square (the root is monotonic): the speeds
        # themselves are only needed on a step that has to slow something down.
        squares = squared_norms(velocities)
        top_speed = math.sqrt(squares.max())
        if top_speed > speed_limit:
            speeds = np.sqrt(squares)
            too_fast = speeds > speed_limit
            velocities[too_fast] *= (speed_limit / speeds[too_fast])[:, None]
        bodies.velocities[moving] = velocities
        bodies.centres[moving] += velocities
        clamp_to_page(bodies.centres, bodies.velocities, moving, lowest, highest)
        if constrained:
            enforce_positions(bodies, roots, root_offsets)
        heat = max(heat * keep, params.heat_min)
        if top_speed >= still_speed and done % 10 == 0:
            # An item pressed into a wall goes nowhere: judge the motion the walls leave.  On a
            # roomy page the no-overlap pass clears what overlap is left at once; on a tight
            # one a jam pressed into the walls keeps cooling, sliding slowly apart, unless
            # nothing overlaps any more.
            after = bodies.velocities[moving]
            walled = np.sqrt(squared_norms(after).max())
            if walled < still_speed and (roomy or not contacts.overlapping(bodies.centres)):
                top_speed = walled
        if top_speed < still_speed:
            if heat <= settled_below:
                return done, heat, True, spread_out
            heat = min(heat, guided_heat)  # spread out and still: on to where the guides pull
            keep = min(keep, 1.0 - GUIDED_COOLING)
            spread_out = True
        elif heat <= params.heat_min:
            return done, heat, True, spread_out
    return steps, heat, False, spread_out
