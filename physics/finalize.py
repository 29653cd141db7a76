"""The no-overlap pass: run before every export and at the end of every headless settle.

Physics alone leaves a page *nearly* right (a pressed spring network keeps small overlaps, and
a user may stop it any time).  This pass makes it exactly right when the items fit: it projects
positions until every pair of items is at least ``gutter`` apart edge to edge and every item is
inside the page, moving each pair apart along the axis that needs the smaller move, so the
layout the physics found is kept, only nudged.  It is position-based (Jacobi projection, as in
position-based dynamics), so it cannot blow up.

A crowd can make the gutter impossible even on a half-empty page: 500 small items covering half
of A4 need 94% of it once each grows by a 3 mm gutter, more than rectangles of mixed shapes
pack to.  Then the pass keeps the *widest* gap it can reach rather than a fixed fallback (it
used to drop to exactly half the gutter, leaving 1.5 mm where 2 mm fitted).  Every run
remembers the arrangement with the widest clearance it passed through; the pass bisects
between that clearance and the gutter, each attempt starting from the widest arrangement so
far and aiming only just beyond its clearance, and ends on the widest arrangement seen.  If no
arrangement without overlap turns up, it first runs for plain no-overlap, and when even that
fails (an over-full page) it keeps the arrangement with the least overlap it saw.  Every
clearance aimed at includes ``ROUNDING_MM``, so positions saved to 0.01 mm keep the gap reached
(the widest clearance less ``ROUNDING_MM``), and the full gutter when the pass reports success.
"""

from __future__ import annotations

import numpy as np

from floatpage.physics.bodies import Bodies
from floatpage.physics.constraints import enforce_positions, hand_forces_to_roots
from floatpage.physics.fast_forces import blocked_axes, candidate_pairs
from floatpage.physics.geometry import (
    any_xy, clamp_to_page, group_bounds, max_xy, pair_sums, xy_slots,
)

MAX_ITERATIONS = 1000
SLACK_MM = 1e-3  # each move overshoots by this much, so the projection ends
ROUNDING_MM = 0.01  # positions are saved to 0.01 mm: keep this much beyond the gutter
# where the margin gives way on a page too full for it: halved, then dropped (the pass, the
# relocation and the second start alike)
MARGIN_GIVES_WAY = (0.5, 0.0)
AIM_BEYOND_MM = 0.3  # pairs that break the gutter are pushed this far beyond it
RELAXATION = 1.0
# A run whose remaining violations have not shrunk by STALL_GAIN in STALL_ITERATIONS gives up:
# on a page where the aim does not fit, the last hundreds of iterations of a 1,000-iteration
# run only shuffled items (a failing pass was most of the settle time).
STALL_ITERATIONS = 60
STALL_GAIN = 0.01
# ...or in this many, on a first attempt that has a second start to fall back on (Engine.settle:
# the packing holds the gutter by construction).  The 5-item page's first run was jammed from
# its 3rd round on (its score did not change in the 16th digit) and ran 60 more.
FIRST_ATTEMPT_STALL = 15
# ...or in this many on a page that looks over-full: where the gutter cannot fit by area and
# no arrangement without overlap has turned up (project_within), and where the margin gives
# way (remove_overlaps), which happens only on a page the full attempt left overlapping.
# There a stalled run seldom does more than lessen the overlap a little.  On 36 over-full pages (10 to 60
# items at 85, 90 and 100 %, three seeds) the overlap left was the same to 0.01 % with 20 as
# with 60 (items in the margin 11.39 -> 11.33 on average), the same on eight crowded pages
# (60-500 items) to 0.001 %, and the benchmark's over-full page's pass took 203 -> 104 rounds.
OVERFULL_STALL = 20
# ...and a first attempt with a second start to fall back on gives up once the closest pair's
# shortfall from the clearance has shrunk by less than CREEP_GAIN in the last CREEP_ROUNDS: at
# that pace closing it would take more than 800 rounds (and the pace only slows), past the
# budget.  The stall test alone let such a run creep on while its moves' sum shrank by a
# percent every fifteen rounds: seed 4016 of guide_cost.py's --first-seed 4000 (42 items,
# 55 %) ran 436 rounds with guides, 59 without, then failed and took the packing either way
# (its settle 1.73x the one without guides).  Of 1,240 first attempts that succeeded (seeds
# 2000-12029 of guide_cost.py, guides off and on) the slowest shrank its shortfall by 11.6 %
# in 40 rounds (seed 5012: 214 rounds); the others by at least 68 %.
CREEP_ROUNDS = 40
CREEP_GAIN = 0.05
# When the gutter does not fit: at most this many bisection steps between the widest clearance
# reached and the gutter, stopping once they are this close; each step aims only this far beyond
# its clearance (near the limit, aiming further asks for room that is not there).
FALLBACK_ATTEMPTS = 5
FALLBACK_TOLERANCE_MM = 0.05
FALLBACK_AIM_MM = 0.03


def overlap_area(centres: np.ndarray, halves: np.ndarray, i: np.ndarray, j: np.ndarray) -> float:
    """Total intersection area of the pairs (i, j), mm^2."""
    d = np.abs(centres[j] - centres[i])
    depth = np.clip(halves[i] + halves[j] - d, 0.0, None)
    depth = np.minimum(depth, 2 * np.minimum(halves[i], halves[j]))
    return float((depth[:, 0] * depth[:, 1]).sum())


def pair_clearances(centres: np.ndarray, halves: np.ndarray, i: np.ndarray, j: np.ndarray
                    ) -> np.ndarray:
    """Clearance of each pair (i, j): the larger of its edge-to-edge gaps along x and along y,
    negative when the two overlap.  A pair keeps a clearance c when this is at least c."""
    gaps = np.abs(centres[j] - centres[i]) - halves[i] - halves[j]
    return max_xy(gaps)


def separation_moves(centres: np.ndarray, halves: np.ndarray, i: np.ndarray, j: np.ndarray,
                     clearance: float, blocked: np.ndarray | None = None) -> np.ndarray:
    """Move of j away from i that clears ``clearance`` on the cheaper axis, shape (m, 2).

    ``blocked`` (m, 2) from blocked_axes forbids an axis on which the pair cannot fit the page.

    Zero for pairs already clear on either axis; slightly more than the need otherwise, so
    that the projection ends in a finite number of iterations instead of creeping up to the
    boundary.
    """
    d = centres[j] - centres[i]
    need = halves[i] + halves[j] + clearance - np.abs(d)
    violating = (need[:, 0] > 0) & (need[:, 1] > 0)
    along_x = need[:, 0] <= need[:, 1]
    if blocked is not None:
        along_x = (along_x & ~blocked[:, 0]) | blocked[:, 1]
    direction = np.where(d >= 0, 1.0, -1.0)
    moves = np.zeros_like(d)
    moves[:, 0] = np.where(violating & along_x, need[:, 0] + SLACK_MM, 0.0)
    moves[:, 1] = np.where(violating & ~along_x, need[:, 1] + SLACK_MM, 0.0)
    return direction * moves


def moves_from_gaps(d: np.ndarray, gaps: np.ndarray, clearance: float,
                    blocked: np.ndarray | None) -> np.ndarray:
    """``separation_moves`` from the pairs' offsets ``d`` and gaps (|d| less both halves),
    computed once per iteration by the projection."""
    need = clearance - gaps
    violating = (need[:, 0] > 0) & (need[:, 1] > 0)
    along_x = need[:, 0] <= need[:, 1]
    if blocked is not None:
        along_x = (along_x & ~blocked[:, 0]) | blocked[:, 1]
    direction = np.where(d >= 0, 1.0, -1.0)
    moves = np.zeros_like(d)
    moves[:, 0] = np.where(violating & along_x, need[:, 0] + SLACK_MM, 0.0)
    moves[:, 1] = np.where(violating & ~along_x, need[:, 1] + SLACK_MM, 0.0)
    return direction * moves


class _Projection:
    """What one page's projection needs, computed once."""

    def __init__(self, bodies: Bodies, page_w_mm: float, page_h_mm: float, gutter_mm: float,
                 margin_mm: float = 0.0):
        self.bodies, self.page, self.gutter_mm = bodies, (page_w_mm, page_h_mm), gutter_mm
        active = bodies.active
        self.rows_active = np.flatnonzero(active)
        self.free_rows = np.flatnonzero(bodies.free)
        # A plain slice when every item is free: indexing by an array of all rows copies and,
        # for (n, 2) arrays, is slow (see fast_forces' module doc).
        self.moving = slice(None) if bodies.free.all() else self.free_rows
        self.roots, self.root_offsets = bodies.group_roots()
        self.followers = bodies.followers
        # Without held items, hard anchors or followers, enforce_positions (some ten NumPy
        # calls every iteration) would only stop the decorations again.
        self.constrained = bool((bodies.held | bodies.hard | self.followers).any())
        self.halves = bodies.sizes / 2
        charges = np.where(active, bodies.charges, 0.0)
        group_mass = np.bincount(self.roots, weights=charges, minlength=bodies.count)
        movable = bodies.free[self.roots] & ~bodies.held & active
        self.inverse_mass = np.where(movable, 1.0 / np.maximum(group_mass[self.roots], 1e-12),
                                     0.0)
        near, far = bodies.insets(margin_mm, page_w_mm, page_h_mm)
        self.insets = (near, far)
        self.bounds = group_bounds(bodies, self.free_rows, self.roots, self.root_offsets,
                                   near, far, page_w_mm, page_h_mm)
        # The same bounds for every row (none for rows that do not move), to tell which
        # groups stand against a wall (see wall_shares).
        self.lowest = np.full((bodies.count, 2), -np.inf)
        self.highest = np.full((bodies.count, 2), np.inf)
        self.lowest[self.free_rows], self.highest[self.free_rows] = self.bounds
        # The arrangement with the widest clearance seen by any run so far, and that clearance
        # (a lower bound, exact below the clearance the run aimed at).
        self.widest, self.widest_state = -np.inf, bodies.centres.copy()

    def note_clearance(self, i: np.ndarray, j: np.ndarray, cap: float) -> None:
        """Remember the current arrangement if its clearance (capped at ``cap``) is the widest
        yet.  (i, j) must hold every pair closer than ``cap``."""
        self.note_reached(cap if len(i) == 0 else min(
            float(pair_clearances(self.bodies.centres, self.halves, i, j).min()), cap))

    def restore_widest(self) -> None:
        self.bodies.centres[:] = self.widest_state
        self.clamp()

    def clamp(self) -> None:
        clamp_to_page(self.bodies.centres, self.bodies.velocities, self.moving, *self.bounds)
        if self.constrained:
            enforce_positions(self.bodies, self.roots, self.root_offsets)
        else:
            self.bodies.velocities[self.bodies.decorative] = 0.0

    def pairs(self, reach: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The pairs within ``reach``, with the axes each may part along.  A pair of which
        neither item moves (hard anchors, held items, what follows them) is left out: no
        projection parts it, and counted in, its gap capped the whole page's.  A page with
        two hard anchors 25 mm into each other let a free item lie 28.6 mm into one of them,
        and gave up the margin for three more (physics.page_limits names such a pair)."""
        i, j = candidate_pairs(self.bodies.centres, self.halves, self.rows_active, self.roots,
                               reach)
        if self.constrained:
            moves = (self.inverse_mass.take(i) > 0) | (self.inverse_mass.take(j) > 0)
            i, j = i[moves], j[moves]
        return i, j, blocked_axes(self.bodies.sizes, i, j, *self.page, self.gutter_mm,
                                  self.insets)

    def pair_halves(self, i: np.ndarray, j: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Per pair, the two half sizes summed (the centre distance at which they touch) and
        twice the smaller (the deepest an overlap can be), (m, 2) each: fixed while the list
        lasts, so worked out once per list rather than every iteration."""
        halves_i, halves_j = self.halves.take(i, axis=0), self.halves.take(j, axis=0)
        return halves_i + halves_j, 2 * np.minimum(halves_i, halves_j)

    def violations(self, clearance: float) -> int:
        i, j, blocked = self.pairs(clearance)
        moves = separation_moves(self.bodies.centres, self.halves, i, j, clearance, blocked)
        return int(any_xy(moves != 0).sum())

    def run(self, clearance: float, iterations: int, aim: float | None = None,
            stall: int = STALL_ITERATIONS, creep: bool = False) -> bool:
        """Jacobi projection in place; True once no pair is closer than ``clearance``.

        Pairs are pushed to ``aim`` (>= clearance): aiming a little beyond what is needed ends
        the projection sooner in a crowd, where neighbours keep undoing each other's moves.
        With ``creep`` the run also gives up where its closest pair creeps towards the
        clearance too slowly to reach it (CREEP_ROUNDS).
        """
        aim = clearance if aim is None else aim
        bodies, count = self.bodies, self.bodies.count
        skin = max(clearance, 2.0)
        i, j, blocked = self.pairs(clearance + skin)
        built_at = bodies.centres.copy()
        best, best_score = bodies.centres.copy(), np.inf
        hsum, deepest = self.pair_halves(i, j)
        last_gain = 0
        shortfalls = []  # per round, the clearance less the closest pair's (with ``creep``)
        for iteration in range(iterations):
            if np.abs(bodies.centres - built_at).max() > skin / 2:
                i, j, blocked = self.pairs(clearance + skin)
                built_at = bodies.centres.copy()
                hsum, deepest = self.pair_halves(i, j)
            # One pass over the pairs' geometry serves every test of this iteration.
            d = bodies.centres.take(j, axis=0) - bodies.centres.take(i, axis=0)
            gaps = np.abs(d) - hsum  # edge-to-edge gap along x and y; negative inside
            closest = float(max_xy(gaps).min()) if len(i) else clearance
            self.note_reached(min(closest, clearance))
            if closest >= clearance:
                return True
            if creep:
                shortfalls.append(clearance - closest)
                if iteration >= CREEP_ROUNDS and shortfalls[-1] > (1.0 - CREEP_GAIN) * \
                        shortfalls[iteration - CREEP_ROUNDS]:
                    break
            moves = moves_from_gaps(d, gaps, aim, blocked)
            violating = any_xy(moves != 0)
            depth = np.minimum(np.maximum(-gaps, 0.0), deepest)
            score = float((depth[:, 0] * depth[:, 1]).sum()) + np.abs(moves).sum()
            if score < best_score:
                if score < best_score * (1.0 - STALL_GAIN):
                    last_gain = iteration
                best, best_score = bodies.centres.copy(), score
            elif iteration - last_gain > stall:
                break  # neighbours only undo each other's moves: this aim is out of reach
            vi, vj, moves = i[violating], j[violating], moves.compress(violating, axis=0)
            share_i, share_j = self.wall_shares(vi, vj, moves)
            shift = pair_sums(count, xy_slots(vi), xy_slots(vj), moves * share_i,
                              moves * share_j)
            hand_forces_to_roots(shift, self.roots, self.followers)
            # An item asked to move by several pairs takes their sum over the square root of
            # their number: plain sums overshoot in stacks, plain averages crawl.
            touches = np.bincount(vi, minlength=count) + np.bincount(vj, minlength=count)
            shift *= RELAXATION / np.sqrt(np.maximum(touches, 1))[:, None]
            bodies.centres[self.moving] += shift[self.moving]
            self.clamp()
        if self.violations(clearance) == 0:
            self.note_reached(clearance)
            return True
        bodies.centres[:] = best
        self.clamp()
        if self.violations(clearance) == 0:
            self.note_reached(clearance)
            return True
        return False

    def wall_shares(self, i: np.ndarray, j: np.ndarray, moves: np.ndarray
                    ) -> tuple[np.ndarray, np.ndarray]:
        """Each pair's share of its move, (m, 1) for i and for j: by inverse mass, except that
        a group standing against a wall in the direction it would be moved takes none, and the
        other the whole move (a wall is an infinite mass).  Shared by mass alone, a small item
        pressed into the margin by a large one took the larger share, the clamp undid it, and
        the pair parted by the large one's share a round: the page with one item larger than
        half of it needed 96 rounds to open one gap by 3.6 mm, 3 % a round."""
        inv, roots = self.inverse_mass, self.roots
        centres = self.bodies.centres
        at_low, at_high = centres <= self.lowest, centres >= self.highest
        if not (at_low.any() or at_high.any()):
            inv_i, inv_j = inv.take(i), inv.take(j)
        else:
            ahead = moves > 0  # j is moved forward on this axis, i back
            behind = moves < 0
            root_i, root_j = roots.take(i), roots.take(j)
            low_i, high_i = at_low.take(root_i, axis=0), at_high.take(root_i, axis=0)
            low_j, high_j = at_low.take(root_j, axis=0), at_high.take(root_j, axis=0)
            stuck_i = any_xy(ahead & low_i | behind & high_i)
            stuck_j = any_xy(ahead & high_j | behind & low_j)
            both = stuck_i & stuck_j  # jammed between walls: nothing helps, share as before
            inv_i = np.where(stuck_i & ~both, 0.0, inv.take(i))
            inv_j = np.where(stuck_j & ~both, 0.0, inv.take(j))
        total = inv_i + inv_j
        total = np.where(total > 0, total, 1.0)
        return (inv_i / total)[:, None], (inv_j / total)[:, None]

    def note_reached(self, clearance: float) -> None:
        """The current arrangement keeps ``clearance``: remember it if that is the widest yet."""
        if clearance > self.widest:
            self.widest, self.widest_state = clearance, self.bodies.centres.copy()


def remove_overlaps(bodies: Bodies, page_w_mm: float, page_h_mm: float, gutter_mm: float,
                    max_iterations: int = MAX_ITERATIONS, margin_mm: float = 0.0,
                    fall_back: bool = True) -> bool:
    """Project positions in place until no two active items are closer than ``gutter_mm`` and
    every item keeps ``margin_mm`` from the page's edges (bleed items keep none).

    Held items, hard anchors and their followers stay put; decorations are ignored.  Returns
    True when the result keeps the gutter everywhere (and so has no overlap).  If the gutter
    cannot be reached, the pass keeps the widest clearance it can reach (see the module doc).
    On a page too full for even that within the margins, the margin gives way next, halved and
    then dropped, and overlap last: the gutter, then the margin, then overlap.  Without
    ``fall_back`` it stops after the first attempt at the gutter (Engine.settle has a second
    start to try first).
    """
    fits = project_within(bodies, page_w_mm, page_h_mm, gutter_mm, max_iterations, margin_mm,
                          fall_back)
    if fits or not fall_back or margin_mm <= 0 or not has_overlap(bodies, page_w_mm, page_h_mm,
                                                                  gutter_mm):
        return fits
    for margin in (margin_mm * share for share in MARGIN_GIVES_WAY):
        project_within(bodies, page_w_mm, page_h_mm, 0.0, max(max_iterations // 3, 1), margin,
                       stall=OVERFULL_STALL)
        if not has_overlap(bodies, page_w_mm, page_h_mm, gutter_mm):
            break
    return False


def has_overlap(bodies: Bodies, page_w_mm: float, page_h_mm: float, gutter_mm: float) -> bool:
    projection = _Projection(bodies, page_w_mm, page_h_mm, gutter_mm)
    return projection.violations(0.0) > 0


def cannot_fit(bodies: Bodies, page_w_mm: float, page_h_mm: float, clearance: float,
               margin_mm: float) -> bool:
    """Whether no arrangement can keep ``clearance`` between every two active items, by area:
    each item grown by the clearance (and cut to the room, which an item larger than the page
    spans at most) needs more than the room, grown by it too, holds.  The room is the page
    less the narrowest walls, so the answer is never wrong, only sometimes "maybe" on a page
    with bleed items.  On the over-full page (40 items covering 90 % of A4) the attempt at the
    gutter was 60 to 80 projection rounds that could not succeed.  Rigid groups and regions
    are left to the projection (a group, or an item, larger than its walls need not stay
    inside the room: a region near the page's edge can hold an item off centre)."""
    active = bodies.active
    if active.sum() < 2 or bodies.followers.any() or not np.isnan(bodies.regions[:, 0]).all():
        return False
    near, far = bodies.insets(margin_mm, page_w_mm, page_h_mm)
    room = np.maximum(np.array([page_w_mm, page_h_mm]) - near[active].min(axis=0)
                      - far[active].min(axis=0), 0.0)
    grown = np.minimum(bodies.sizes[active], room) + clearance
    return float((grown[:, 0] * grown[:, 1]).sum()) > float(((room + clearance)).prod())


def project_within(bodies: Bodies, page_w_mm: float, page_h_mm: float, gutter_mm: float,
                   max_iterations: int, margin_mm: float, fall_back: bool = True,
                   stall: int | None = None) -> bool:
    """The projection at the gutter within the margins; with ``fall_back``, the search for the
    widest gap that fits if it misses.  ``stall``: rounds without gain before a run gives up
    (STALL_ITERATIONS, or FIRST_ATTEMPT_STALL without ``fall_back``, unless given)."""
    projection = _Projection(bodies, page_w_mm, page_h_mm, gutter_mm, margin_mm)
    projection.clamp()
    if len(projection.rows_active) < 2 or len(projection.free_rows) == 0:
        return projection.violations(gutter_mm + ROUNDING_MM) == 0
    hopeless = cannot_fit(bodies, page_w_mm, page_h_mm, gutter_mm + ROUNDING_MM, margin_mm)
    if stall is None:
        stall = STALL_ITERATIONS if fall_back else FIRST_ATTEMPT_STALL
    if not hopeless and projection.run(gutter_mm + ROUNDING_MM, max_iterations,
                                       aim=gutter_mm + AIM_BEYOND_MM, stall=stall,
                                       creep=not fall_back):
        return True
    if not fall_back:
        return False
    iterations = max(max_iterations // 3, 1)
    if projection.widest < ROUNDING_MM:
        # No arrangement without overlap seen yet: first remove the overlaps.  If even that
        # fails the page is over-full, and the run left the arrangement with least overlap.
        # Without a gutter, the run just made was this one: once more from its best
        # arrangement found no less overlap on 36 over-full pages, in 60 to 80 more rounds.
        if gutter_mm == 0 and not hopeless or not projection.run(
                ROUNDING_MM, iterations, aim=AIM_BEYOND_MM,
                stall=OVERFULL_STALL if hopeless else STALL_ITERATIONS):
            return False
    low, high = projection.widest, gutter_mm + ROUNDING_MM
    for _ in range(FALLBACK_ATTEMPTS):
        if high - low < FALLBACK_TOLERANCE_MM:
            break
        clearance = (low + high) / 2
        projection.restore_widest()
        if not projection.run(clearance, iterations, aim=clearance + FALLBACK_AIM_MM):
            high = clearance
        low = projection.widest
    projection.restore_widest()
    return False
