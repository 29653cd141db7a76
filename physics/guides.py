"""Magnetic alignment guides, as a force of the fast mode (issue 16).

A page looks designed when its items line up; the physics alone spreads them evenly and lines
up nothing.  Every active item offers *guide lines* on each axis: its two edges and its centre.
The page offers its print-safe margin lines (edges) and its centre lines (centres).  An edge
near another item's edge, or a centre near another item's centre, closer than the snap range
(``SNAP_MM`` on A4, scaled with the page's linear size), is pulled onto it.  Held items and
hard-anchored items are guides for the others but are never pulled.

A feature d mm from its guide is pulled with ``k d (1 - |d| / range)``: zero on the line and
at the range's edge, so the force is continuous and nothing jumps.  Each item takes one pull
per axis, from the guide nearest to any of its three features, so two guides never fight over
one item; a follower's pull goes to the root of its group, as all its forces do.  The guides
act once the page has cooled below ``GUIDE_HEAT`` (fading in as it cools): while the page is
hot the items are still finding their places and lines would only hold them back, and a hot
page costs nothing extra.  Which guide an item follows is worked out again (a sort per axis)
every ``REFRESH_STEPS`` steps if an item has moved half the snap range since; in between
the pull follows the chosen partner's current position (a gather), as a Verlet list does for
contacts.  A pull this weak and slow needs no update every step: it is given every
``PULL_EVERY``-th step, that many times as strong (the same average, a quarter of the cost).

On a cold page (heat below ``HOLD_HEAT``, as in the gentle run that tells a settled page is
at rest) a line also *holds* a group with a feature on it, as a magnet holds: a static
friction of up to ``hold`` against the other forces on that axis.  So a page whose items the
snapping step (physics.snapping) put on lines against a slight push is at rest, and stays a
fixed point; the hold is what lets that step align items the forces alone would not leave
there.  A run that starts cold tests a saved layout (model.layout's probes), whose centres the
save rounded to 0.01 mm: there a line holds what lies within ``ON_LINE_MM`` +
``SAVED_SLACK_MM`` of it, or a feature the snap left 0.048 mm from its line, 0.052 mm after
the save, slid away under a push the hold would have taken, in every probe.  There the lines
no longer pull: the pull's work is done while the page cools, and the snap's rest check
(physics.rest_check) weighs a move by the pushes, not by a pull toward a line the snap chose
to leave a feature off.  (A feature 4.3 mm off a line on an A3 page of 12 items still took a
pull of 0.13 mm per step^2 there, on top of a push just within the rest limit: the probe ran
230 steps, moved items 8.7 mm and asked for one more probe, twice the settle without guides.)

The pull acts wherever a page runs below ``GUIDE_HEAT``: a crowded page cools that far while
it spreads, and the editor, once a page is still, cools it onto its lines so that items glide
there as a user watches (fast_mode.run_fast).  A headless settle does not wait for that: the
snap after it lines up what the pull would have (docs/benchmarks.md, eighteenth session).
"""

from __future__ import annotations

import numpy as np

from floatpage.physics.bodies import Bodies
from floatpage.physics.guide_pull_kernel import chosen_pulls, hold as hold_slots, pull as pull_slots
from floatpage.physics.params import page_scale

SNAP_MM = 4.0  # snap range on an A4 page; smaller pages scale it down with their linear size
K_GUIDE = 0.03  # pull per step^2 per mm at strength 1 (about a seventh of a contact's stiffness)
GUIDE_HEAT = 0.3  # the guides pull below this heat, in full below half of it
K_HOLD = 2.0  # a line's hold on a cold page, mm per step^2 on A4: about 10 mm of contact
HOLD_HEAT = 0.05  # the hold acts below this heat: a probe's cold run, not the spreading
ON_LINE_MM = 0.05  # a feature this close to its guide is on it (and held)
SAVED_SLACK_MM = 0.01  # a saved file's centres are rounded to 0.01 mm (model.layout.write_back)
PULL_EVERY = 4  # the pull comes as one push every 4th step, four times as strong
REFRESH_STEPS = 64  # steps between two searches for each item's nearest guide
PAGE = -1  # owner of the page's own guide lines
NOBODY = -2  # owner of nearest_guides' sentinels
LOOKS = np.arange(-2, 3)  # nearest_guides looks two places either side of a query
# nearest_guides' sentinels, two below the sorted values and three above: their values, their
# owner, the index they stand for
BELOW, ABOVE = np.full(2, -np.inf), np.full(3, np.inf)
NOBODY_BELOW, NOBODY_ABOVE = np.full(2, NOBODY), np.full(3, NOBODY)
NONE_BELOW, NONE_ABOVE = np.full(2, -1), np.full(3, -1)
LOW, CENTRE, HIGH = 0, 1, 2  # an item's three features on one axis


def snap_range(page_w_mm: float, page_h_mm: float) -> float:
    """How near a feature must come to a guide to be pulled onto it, mm (4 mm on A4)."""
    return SNAP_MM * page_scale(page_w_mm, page_h_mm)


def features(centres: np.ndarray, halves: np.ndarray, axis: int) -> np.ndarray:
    """Each item's low edge, centre and high edge on ``axis``, shape (n, 3)."""
    c, h = centres[:, axis], halves[:, axis]
    return np.column_stack([c - h, c, c + h])


def page_lines(page_w_mm: float, page_h_mm: float, margin_mm: float, axis: int,
               regions: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The page's own guide lines on ``axis``: (edge lines, centre lines) in mm.  The margin
    lines and the edges of the page's regions (``regions``: (k, 4) left, top, right, bottom,
    NaN rows ignored, as Bodies.regions) are guides for edges, the page's middle for centres."""
    extent = (page_w_mm, page_h_mm)[axis]
    return (np.concatenate([[margin_mm, extent - margin_mm], region_edges(regions, axis)]),
            np.array([extent / 2]))


def region_edges(regions: np.ndarray | None, axis: int) -> np.ndarray:
    """The distinct edges, on ``axis``, of the regions items are confined to: walls for their
    own items, guides for everyone (a region's edge is a line the page's design drew)."""
    if regions is None or not len(regions):
        return np.zeros(0)
    confined = ~np.isnan(regions[:, 0])
    if not confined.any():  # no region: np.unique's answer, without its sort (four calls a
        return np.zeros(0)  # snap's set-up, page_lines, a tenth of it on an 8-item page)
    boxes = regions[confined]
    return np.unique(np.concatenate([boxes[:, axis], boxes[:, axis + 2]]))


def nearest_guides(values: np.ndarray, owners: np.ndarray, queries: np.ndarray,
                   query_owners: np.ndarray, reach: float) -> tuple[np.ndarray, np.ndarray]:
    """For each query value, the index into ``values`` of the nearest value of another owner
    within ``reach`` (-1 if none), and the signed distance to it (query to guide).

    ``values`` need not be sorted.  A query's own owner holds at most two values in one pool
    (an item's two edges), so looking two places either side of its sorted position finds the
    nearest other value.
    """
    order = np.argsort(values, kind="stable")
    if len(values) == 0:
        return np.full(len(queries), -1), np.full(len(queries), np.inf)
    # Sentinels, infinitely far and owned by nobody, two below and three above (a query
    # above every value sorts after the last), so that the five looks
    # need no clipping to the array; they are never nearer than anything, so the answer is
    # the clipped look's.  (np.clip was two fifths of a refresh; the five looks are one
    # (queries, 5) array, where a loop over them took a third longer.)
    # (The sentinels are arrays made once: lists here were converted on every call, four
    # calls a refresh.)
    ordered = np.concatenate([BELOW, values[order], ABOVE])
    ordered_owners = np.concatenate([NOBODY_BELOW, owners[order], NOBODY_ABOVE])
    order = np.concatenate([NONE_BELOW, order, NONE_ABOVE])
    looks = np.searchsorted(ordered, queries)[:, None] + LOOKS  # (queries, 5)
    distance = np.where(ordered_owners[looks] != query_owners[:, None],
                        ordered[looks] - queries[:, None], np.inf)
    # the first of the nearest, as a scan from the lowest look keeping only strict gains
    pick = np.argmin(np.abs(distance), axis=1) + np.arange(0, distance.size, len(LOOKS))
    best = distance.ravel()[pick]
    found = order[looks.ravel()[pick]]
    near = np.abs(best) <= reach
    return np.where(near, found, -1), np.where(near, best, np.inf)


class GuidePulls:
    """The force: each free item is pulled, per axis, onto its nearest guide line.

    The chosen pulls are kept flat, over ``centres.ravel()`` (row * 2 + axis): the pulled
    coordinate, the guide's coordinate (or the pulled one's own, with a zero factor, for a
    page line) and fixed offsets, so a step costs a handful of whole-array operations."""

    def __init__(self, centres: np.ndarray, sizes: np.ndarray, active: np.ndarray,
                 pulled: np.ndarray, page: tuple[float, float], margin_mm: float,
                 strength: float, roots: np.ndarray | None = None,
                 regions: np.ndarray | None = None, saved: bool = False):
        self.halves = sizes / 2
        self.roots = np.arange(len(centres)) if roots is None else roots
        self.grouped = bool((self.roots != np.arange(len(centres))).any())
        self.flat_roots = (self.roots[:, None] * 2 + np.arange(2)).ravel()  # per flat slot
        self.hold = hold_strength(page, strength)
        # A run that tests a saved layout (saved: it starts cold) holds what the snap left on
        # a line even after the save's rounding moved it a little further.
        self.holds_within = ON_LINE_MM + (SAVED_SLACK_MM if saved else 0.0)
        # |distance| of each chosen pull to its line at the last pull (None before the first):
        # the slots on their line, and the groups to hold, are read off it only when a hold
        # needs them (hold_on_lines), not at every pull of the spreading
        self.apart: np.ndarray | None = None
        self.apart_slots = np.zeros(0, dtype=int)  # the flat slots those distances are of
        self.holding: np.ndarray | None = None  # flat slots to hold, from apart when needed
        self.guides = np.flatnonzero(active)  # rows whose features are guides
        self.pulled = np.flatnonzero(pulled & active)  # rows the force moves
        self.page, self.margin_mm, self.regions = page, margin_mm, regions
        self.k = K_GUIDE * strength
        self.reach = snap_range(*page)
        self.steps = 0
        self.own = np.zeros(0, dtype=int)
        self.refreshed_at: np.ndarray | None = None
        self.fixed: list[tuple[np.ndarray, np.ndarray] | None] = [None, None]  # page_lines

    def page_lines(self, axis: int) -> tuple[np.ndarray, np.ndarray]:
        """The page's own lines on ``axis`` (page_lines), worked out on the first refresh and
        kept: no motion changes them."""
        if self.fixed[axis] is None:
            self.fixed[axis] = page_lines(*self.page, self.margin_mm, axis, self.regions)
        return self.fixed[axis]

    def refresh(self, centres: np.ndarray) -> None:
        """Choose, per pulled item and axis, the feature to pull and the line to pull it to:
        the nearest line of another owner within the snap range to one of its features (an
        edge to the guides' edges and the margin lines, its centre to their centres and the
        page's middle; nearest_guides defines it), the edge first on a tie, then the low edge.

        Compiled (guide_pull_kernel.chosen_pulls, one call for both axes): as NumPy the
        search and the choices were some eighty calls, about 0.25 ms a refresh and two to
        seven refreshes a settle, most of what the pull costs (benchmarks/guide_cost_parts.py);
        tests/physics/test_guide_lookups.py holds it to that NumPy, bit for bit."""
        self.refreshed_at = centres.copy()
        room = 2 * len(self.pulled)
        own, partner = np.empty(room, dtype=np.int64), np.empty(room, dtype=np.int64)
        factor, offset = np.empty(room), np.empty(room)
        kept = chosen_pulls(np.ascontiguousarray(centres, dtype=float), self.halves,
                            self.pulled, self.guides, *self.page_lines(0), *self.page_lines(1),
                            self.reach, own, partner, factor, offset)
        self.own, self.partner = own[:kept], partner[:kept]
        self.factor, self.offset = factor[:kept], offset[:kept]

    def add_to(self, acc: np.ndarray, centres: np.ndarray, heat: float) -> None:
        """The pull (every ``PULL_EVERY``-th step), then, on a cold page, the hold.  The hold
        needs the other forces' sum, so this term comes last in the list (fast_forces)."""
        if heat >= GUIDE_HEAT:
            return
        self.steps += 1
        if self.steps % PULL_EVERY == 0 or self.refreshed_at is None:
            self.pull(acc, centres, heat)
        if heat < HOLD_HEAT and self.apart is not None:
            self.hold_on_lines(acc)

    def pull(self, acc: np.ndarray, centres: np.ndarray, heat: float) -> None:
        if self.refreshed_at is None or (
                self.steps % REFRESH_STEPS == 0
                and np.abs(centres - self.refreshed_at).max() > self.reach / 2):
            self.refresh(centres)
        if len(self.own) == 0:
            return
        # cold, the lines hold and no longer pull (see the module doc): the distances are
        # still measured, for the hold
        share = min(1.0, 2.0 * (1.0 - heat / GUIDE_HEAT)) if heat >= HOLD_HEAT else 0.0
        apart = np.empty(len(self.own))
        # compiled (guide_pull_kernel.pull): distance = factor * partner + offset - own, then
        # acc[own] += PULL_EVERY * k * share * distance * max(1 - |distance| / reach, 0), the
        # NumPy's operations in its order (ten calls every fourth step of a cooling page)
        pull_slots(acc, centres, self.own, self.partner, self.factor, self.offset, self.reach,
                   PULL_EVERY * self.k * share, apart)
        # Which groups to hold is worked out only on a cold page (hold_on_lines), from the
        # distances kept here: while the page spreads it was NumPy calls a pull for nothing
        # (a dozen, then the three that picked the slots on their line).
        self.apart, self.apart_slots, self.holding = apart, self.own, None

    def hold_on_lines(self, acc: np.ndarray) -> None:
        """Static friction at a line: a group with a feature on its guide keeps its place on
        that axis unless the other forces on it (summed over the group, as the integrator
        hands a follower's forces to its root) exceed ``hold``; then only the excess moves it."""
        if self.holding is None:
            # the flat slots (root * 2 + axis) to hold, one entry per root and axis: both axes
            # in one pass, where a pass per axis was twice the NumPy calls in every step of a
            # probe (4.9 % of the settle on the 25-item page of benchmarks/guide_cost.py)
            on_line = self.apart_slots[self.apart <= self.holds_within]
            rows, axes = on_line // 2, on_line % 2
            self.holding = np.flatnonzero(np.bincount(self.roots[rows] * 2 + axes,
                                                      minlength=acc.size))
        if len(self.holding) == 0:
            return
        # compiled (guide_pull_kernel.hold): per held slot its total push (its group's, summed
        # as np.bincount sums), kept = sign(total) * max(|total| - hold, 0), acc += kept -
        # total; the NumPy's arithmetic, asked every step of a cold page
        hold_slots(acc, self.holding, self.flat_roots if self.grouped else None, self.hold)


def guide_pulls(bodies: Bodies, roots: np.ndarray, page: tuple[float, float],
                margin_mm: float, strength: float, saved: bool = False) -> list[GuidePulls]:
    """The guide force for one page, as a list of zero or one force (none at strength 0).

    Free items and the followers of free items are pulled (a follower's pull moves its whole
    group); every active item, held and hard-anchored ones included, is a guide."""
    active = bodies.active
    if strength <= 0 or not active.any():
        return []
    pulled = (bodies.free | bodies.followers & bodies.free[roots]) & ~bodies.held
    return [GuidePulls(bodies.centres, bodies.sizes, active, pulled, page, margin_mm, strength,
                       roots, bodies.regions, saved)]


def hold_strength(page: tuple[float, float], strength: float) -> float:
    """How hard a line holds a group on it, mm per step^2 (``K_HOLD`` on A4, scaled)."""
    return K_HOLD * strength * page_scale(*page)


def lines_met(centres: np.ndarray, sizes: np.ndarray, active: np.ndarray, roots: np.ndarray,
              row: int, page: tuple[float, float], margin_mm: float, within: float,
              regions: np.ndarray | None = None) -> list[tuple[int, float]]:
    """The guide lines ``row``'s features lie on, within ``within`` mm: (axis, mm), sorted.

    An edge meets other items' edges, the margin lines and the regions' edges, a centre other items' centres and
    the page's middle; items of ``row``'s own rigid group are left out (a caption always lines
    up with its own photo).  The editor draws these while an item moves."""
    others = np.flatnonzero(active & (roots != roots[row]))
    halves = sizes / 2
    met: set[tuple[int, float]] = set()
    for axis in (0, 1):
        mine = features(centres[row:row + 1], halves[row:row + 1], axis)[0]
        theirs = features(centres[others], halves[others], axis)
        edges_page, centres_page = page_lines(*page, margin_mm, axis, regions)
        edges = np.concatenate([theirs[:, LOW], theirs[:, HIGH], edges_page])
        middles = np.concatenate([theirs[:, CENTRE], centres_page])
        for value, pool in ((mine[LOW], edges), (mine[HIGH], edges), (mine[CENTRE], middles)):
            hits = pool[np.abs(pool - value) <= within]
            met.update((axis, round(float(hit), 2)) for hit in hits)
    return sorted(met)
