"""Geometry both modes and the no-overlap pass share: rigid groups' extents, the range of
centres that keeps a group on the page, hard walls, and the nudge that parts items sharing a
centre. No forces here: those are in fast_forces.py, paper_forces.py and the Force lists."""

from __future__ import annotations

import numpy as np

from floatpage.physics.bodies import Bodies

# A page whose items, grown by the gutter, cover at most this share of the room inside the
# walls is roomy: its run stops once still, overlap or not (fast_mode.run_fast), and it is
# worth aligning (Engine.finalize).  Fuller pages keep cooling and give alignment up.
ROOMY_COVER = 0.75
# Relocation (physics.relocation) lifts items out of jams on pages of at most this many items;
# beyond, its searches compare too many pairs, and the physics must leave less to part
# (fast_forces.target_gap).
RELOCATABLE_ITEMS = 150
# Issue 10's promise: the gutter is kept wherever the items, each grown by it, cover at most
# this share of the room inside the walls; below it a page the physics jammed gets a second
# start (Engine, packing.packed_layout).
GUTTER_FITS_COVER = 0.85
# Alignment gives way on a fuller page than ROOMY_COVER only if it has more than LINE_UP_ITEMS
# items or its gutter does not fit: the snap's cost grows with the items, and its gain shrinks
# on a pressed crowd (200 items covering half of A4: 28.7 -> 20.4 near misses an item for
# 1.9x the settle).  Up to 60 items it pays: pages of 37-57 items covering 55-57 % of A4, A5
# and A4 landscape (grown cover 0.75-0.85) went from 7.8-10.9 near misses an item, not lined
# up at all, to 3.1-6.5, for 1.2-1.5x the settle, as other pages of that many items cost
# (guide_cost.py --seeds 60 --first-seed 4000: 4006, 4012, 4017); a calendar month of 4
# items covering 76 % lines up as well as one at 70 %.
LINE_UP_ITEMS = 60
JITTER_MM = 0.5  # size of the seeded nudge that separates items on one point (A4)
COINCIDENT_MM = 1e-6
AXES = np.arange(2)  # x, y (see xy_slots)


def xy_slots(rows: np.ndarray) -> np.ndarray:
    """Where rows' x and y sit in a flattened (n, 2) array, 2 r + axis, shape (m, 2): one
    bincount over these slots sums both axes of per-pair terms at once, each slot's terms in
    the same order as one bincount per axis (so the same sums, bit for bit)."""
    return 2 * rows[:, None] + AXES


def pair_sums(count: int, slots_i: np.ndarray, slots_j: np.ndarray, on_i: np.ndarray,
              on_j: np.ndarray) -> np.ndarray:
    """Per row (count, 2): the terms ``on_j`` of the pairs it is the j of, less the terms
    ``on_i`` of the pairs it is the i of (each (m, 2); slots from ``xy_slots``)."""
    size = 2 * count  # float even with no pairs (bincount of nothing counts in integers)
    return np.subtract(np.bincount(slots_j.ravel(), on_j.ravel(), size),
                       np.bincount(slots_i.ravel(), on_i.ravel(), size),
                       dtype=float).reshape(count, 2)


def sum_xy(values: np.ndarray) -> np.ndarray:
    """x + y of each row of an (m, 2) array, shape (m,).

    The row helpers here work column by column: a NumPy reduction along an axis of length 2
    (``values.sum(axis=1)``) pays its loop set-up once per row, 1.7 ms for 75,000 rows against
    0.16 ms for the columns, the same values (two numbers are added, or compared, one way)."""
    return values[:, 0] + values[:, 1]


def squared_norms(values: np.ndarray) -> np.ndarray:
    """x^2 + y^2 of each row of an (m, 2) array (see sum_xy)."""
    x, y = values[:, 0], values[:, 1]
    return x * x + y * y


def max_xy(values: np.ndarray) -> np.ndarray:
    """The larger of x and y in each row of an (m, 2) array (see sum_xy)."""
    return np.maximum(values[:, 0], values[:, 1])


def any_xy(flags: np.ndarray) -> np.ndarray:
    """Whether x or y is set in each row of an (m, 2) bool array (see sum_xy)."""
    return flags[:, 0] | flags[:, 1]


def grown_cover(bodies: Bodies, near: np.ndarray, far: np.ndarray, page_w_mm: float,
                page_h_mm: float, gutter_mm: float) -> float:
    """The share of the room inside the walls (``near``, ``far`` as Bodies.insets) that the
    active items cover once each is grown by the gutter, the room grown by it too since items
    may touch the walls: how tight a page is.  A page with regions has several rooms: the
    page inside the walls of its free items, holding every item, and each region, holding the
    items confined to it; the page is as tight as its tightest room.  (Until the tenth
    session the page's room was the page less the widest walls of any item: two regions that
    split a page left it no room, and `check` said its items needed 10^15 % of it, and a
    page with regions was never aligned, re-started or relocated.)"""
    covers = room_covers(bodies, near, far, page_w_mm, page_h_mm, gutter_mm)
    return float(covers.max()) if len(covers) else 0.0


def rooms_of(bodies: Bodies) -> np.ndarray:
    """The room of each row, (n,) int: 0 for the items free to go anywhere on the page, k > 0
    for those confined to the k-th region (grown_cover's rooms).  Items of two
    regions never meet, so what the items of one room rule out says nothing of another's."""
    rooms = np.zeros(bodies.count, dtype=int)
    confined = bodies.active & ~np.isnan(bodies.regions[:, 0])
    if confined.any():
        _, inverse = np.unique(bodies.regions[confined], axis=0, return_inverse=True)
        rooms[confined] = inverse.ravel() + 1
    return rooms


def room_covers(bodies: Bodies, near: np.ndarray, far: np.ndarray, page_w_mm: float,
                page_h_mm: float, gutter_mm: float) -> np.ndarray:
    """``grown_cover`` of each room, (rooms,): the page's first, then each region's, in the
    order of ``rooms_of`` (empty on a page with no active item)."""
    active = bodies.active
    if not active.any():
        return np.zeros(0)
    near, far = (np.broadcast_to(np.asarray(side, float), bodies.sizes.shape)
                 for side in (near, far))
    grown = (bodies.sizes + gutter_mm).prod(axis=1)
    of_room = rooms_of(bodies)
    free = active & (of_room == 0)
    # A page whose every item is confined has no room of free items: its page room (walls of
    # every item, the words region's top and the photos region's bottom) was 0 mm tall, and a
    # page of two regions "needed 9,416 % of it" (check gave that as the reason)
    rooms = [(np.flatnonzero(active), free)] if free.any() else [(np.zeros(0, int), active)]
    for room in range(1, int(of_room.max()) + 1):
        rows = np.flatnonzero(active & (of_room == room))
        rooms.append((rows, rows))
    extent = np.array([page_w_mm, page_h_mm])
    # items that cannot move take room; a decoration takes none (an item may lie on it)
    pinned = (pinned_items(bodies, bodies.group_roots()[0]) & ~bodies.decorative
              if len(rooms) > 1 else None)  # only regions need it: a page without is spared
    covers = []
    for number, (rows, walls) in enumerate(rooms):
        if not len(rows):
            covers.append(0.0)
            continue
        low = np.max(near[walls], axis=0)
        high = extent - np.max(far[walls], axis=0)
        area = float((np.maximum(high - low, 0.0) + gutter_mm).prod())
        if number:  # a region: less what items that cannot move, not of it, take of it
            others = np.flatnonzero(pinned & (of_room != number))
            area -= taken_by(bodies, others, low, high, gutter_mm)
        covers.append(float(grown[rows].sum()) / max(area, 1e-9))
    return np.array(covers)


def pinned_items(bodies: Bodies, roots: np.ndarray) -> np.ndarray:
    """Rows that no push moves: hard anchors and held items, and everything following one or
    following a decoration (a decoration is never moved, so neither is a caption set beside
    it: on a random page one stood past the page's edge, another 6.5 mm into a hard anchor)."""
    fixed = bodies.hard | bodies.held | bodies.decorative
    return bodies.active & (fixed | fixed[roots])


def taken_by(bodies: Bodies, rows: np.ndarray, low: np.ndarray, high: np.ndarray,
             gutter_mm: float) -> float:
    """The area of the room between ``low`` and ``high`` (its top-left and bottom-right
    corners), grown by half the gutter on each side, that ``rows``' boxes, grown the same way,
    cover: room the room's own items cannot use.  A header hard-anchored across a page's top,
    in a region of photos, takes a quarter of it: fresh project seed 7088 crammed ten photos
    into what was left and check called the page roomy (70 %) where it was full (95 %).
    Pinned items that overlap each other count twice here; they clash, which check names on
    its own (page_limits.PinnedClash)."""
    if not len(rows):
        return 0.0
    half = bodies.sizes[rows] / 2 + gutter_mm / 2
    inside_low = np.maximum(bodies.centres[rows] - half, low - gutter_mm / 2)
    inside_high = np.minimum(bodies.centres[rows] + half, high + gutter_mm / 2)
    return float(np.prod(np.maximum(inside_high - inside_low, 0.0), axis=1).sum())


def lines_up(cover: float, count: int) -> bool:
    """Whether a page of ``count`` active items whose grown cover (``grown_cover``) is
    ``cover`` is worth aligning: the guide force pulls and the snap runs."""
    return cover <= ROOMY_COVER or (count <= LINE_UP_ITEMS and cover <= GUTTER_FITS_COVER)


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


def item_bounds(bodies: Bodies, page_w_mm: float, page_h_mm: float, margin_mm: float
                ) -> tuple[np.ndarray, np.ndarray]:
    """Lowest and highest centre, (n, 2) each, that keeps each item on its own inside its
    walls (Bodies.insets); lowest above highest where it is too large for them.  For an item
    that moves as a group, see ``group_bounds``."""
    near, far = bodies.insets(margin_mm, page_w_mm, page_h_mm)
    halves = bodies.sizes / 2
    return halves + near, np.array([page_w_mm, page_h_mm]) - halves - far


def group_bounds(bodies: Bodies, rows: np.ndarray, roots: np.ndarray, root_offsets: np.ndarray,
                 near: np.ndarray, far: np.ndarray, page_w_mm: float, page_h_mm: float
                 ) -> tuple[np.ndarray, np.ndarray]:
    """Lowest and highest centre, (len(rows), 2) each, that keeps the rigid group of each root
    in ``rows`` inside its walls: ``near`` and ``far`` (n, 2) are where every row's walls stand
    from the page's left/top and right/bottom edges (Bodies.insets: the print-safe margin, or a
    region).  A group fits wherever its root's walls and every confined member's allow.

    A group too large for its walls on an axis gets one allowed value there: centred between
    them, but inside its region, or the page, where it fits there (``squeezed``).
    """
    low, high = group_extents(bodies, roots, root_offsets)
    extent = np.array([page_w_mm, page_h_mm])
    lowest = -low[rows] + near[rows]
    highest = extent - high[rows] - far[rows]
    edges = bodies.insets(0.0, page_w_mm, page_h_mm)  # the walls without the margin
    margins = page_margins(bodies, near)[rows]
    squeezed(lowest, highest, -low[rows] + edges[0][rows], extent - high[rows] - edges[1][rows],
             [(-low[rows] + margins, extent - high[rows] - margins), (-low[rows], extent - high[rows])])
    confine_followers(bodies, roots, root_offsets, (low, high), rows, lowest, highest, near,
                      far, extent, edges)
    return lowest, highest


def group_room(bodies: Bodies, roots: np.ndarray, root_offsets: np.ndarray, near: np.ndarray,
               far: np.ndarray, page_w_mm: float, page_h_mm: float
               ) -> tuple[np.ndarray, np.ndarray]:
    """Lowest and highest centre of each root, (n, 2) each and indexed by row, that keeps its
    rigid group inside its walls by the rule ``group_bounds`` applies: the whole group inside
    its root's walls, and a follower confined to a region inside that region too.  Lowest
    passes highest where the group is too large for them; ``group_bounds`` then squeezes it
    (``squeezed``), and physics.page_limits names it (``TooLarge``), so the two can never
    disagree on which groups fit.  Rows that are not roots get their own item's room."""
    low, high = group_extents(bodies, roots, root_offsets)
    extent = np.array([page_w_mm, page_h_mm])
    lowest = -low + near
    highest = extent - high - far
    followers = np.flatnonzero(bodies.active & bodies.followers
                               & ~np.isnan(bodies.regions[:, 0]))
    if len(followers):
        halves = bodies.sizes[followers] / 2
        offsets = root_offsets[followers]
        np.maximum.at(lowest, roots[followers], halves - offsets + near[followers])
        np.minimum.at(highest, roots[followers], extent - halves - offsets - far[followers])
    return lowest, highest


def page_margins(bodies: Bodies, near: np.ndarray) -> np.ndarray:
    """Each row's print-safe margin as the walls ``near`` (Bodies.insets) were drawn at, (n, 1):
    what an unconfined item keeps (none for bleed items), regions aside."""
    unconfined = np.isnan(bodies.regions[:, 0]) & ~bodies.bleed
    margin = float(near[unconfined].min()) if unconfined.any() else 0.0
    return bodies.margins(margin)[:, None]


def squeezed(lowest: np.ndarray, highest: np.ndarray, lowest_edge: np.ndarray,
             highest_edge: np.ndarray,
             page: list[tuple[np.ndarray, np.ndarray]] = ()) -> None:
    """Where ``lowest`` passes ``highest`` (a group too large for its walls), one value
    between them, in place: the middle, moved inside the bounds the walls leave without the
    print-safe margin (``*_edge``) where the group fits inside those.  The margin gives way
    first, then a region's edge, never the page's: a photo whose caption follows it, 51.5 mm
    tall in a region 52.8 mm tall whose top is the page's, was centred between the top margin
    and the region's bottom and stood 0.7 mm out of its region (fresh_projects seed 76), which
    no limit names.  Where the group does not fit its region even so, it is kept on the page
    (``page``: the lowest and highest value that keep it there), if it fits the page: a block
    in an 80 mm region with a follower 160 mm below it was centred on the region, 20 mm past
    the page's top edge (tests/model/test_regions_groups.py).  ``page`` lists such bounds
    to try in turn: inside the page's margins, then inside its edges."""
    short = lowest > highest
    if not short.any():
        return
    middle = (lowest + highest) / 2
    fits = lowest_edge <= highest_edge
    middle = np.where(fits, np.clip(middle, lowest_edge, np.maximum(highest_edge, lowest_edge)),
                      middle)
    for page_low, page_high in page:
        on_page = ~fits & (page_low <= page_high)
        middle = np.where(on_page, np.clip(middle, page_low, np.maximum(page_high, page_low)),
                          middle)
        fits = fits | on_page
    lowest[:] = np.where(short, middle, lowest)
    highest[:] = np.where(short, middle, highest)


def as_insets(margins: np.ndarray | float) -> np.ndarray | float:
    """Margins as something that broadcasts against (n, 2): one per row becomes a column."""
    inset = np.asarray(margins, float)
    return inset[:, None] if inset.ndim == 1 else inset


def confine_followers(bodies: Bodies, roots: np.ndarray, root_offsets: np.ndarray,
                      extents: tuple[np.ndarray, np.ndarray],
                      rows: np.ndarray, lowest: np.ndarray, highest: np.ndarray,
                      near: np.ndarray, far: np.ndarray, extent: np.ndarray,
                      edges: tuple[np.ndarray, np.ndarray]) -> None:
    """Narrow the roots' bounds (for ``rows``) in place so that followers confined to a region
    keep inside it too.  Only followers with a region need this; the rest share their root's
    page margins, which group_extents already counts (``extents``: its answer, which the
    caller has).  ``edges`` are the walls without the margin (Bodies.insets at 0), for a group
    too large for its walls (``squeezed``)."""
    followers = np.flatnonzero(bodies.followers & ~np.isnan(bodies.regions[:, 0]))
    if not len(followers):
        return
    margins = page_margins(bodies, near)
    position = {int(row): k for k, row in enumerate(rows)}
    halves = bodies.sizes / 2
    low, high = extents
    for member in followers:
        k = position.get(int(roots[member]))
        if k is None:
            continue
        root = int(roots[member])
        offset = root_offsets[member]
        lowest_edge = np.maximum(-low[root] + edges[0][root],
                                 halves[member] - offset + edges[0][member])
        highest_edge = np.minimum(extent - high[root] - edges[1][root],
                                  extent - halves[member] - offset - edges[1][member])
        lowest[k] = np.maximum(lowest[k], halves[member] - offset + near[member])
        highest[k] = np.minimum(highest[k], extent - halves[member] - offset - far[member])
        page_low = np.maximum(-low[root], halves[member] - offset)
        page_high = np.minimum(extent - high[root], extent - halves[member] - offset)
        squeezed(lowest[k], highest[k], lowest_edge, highest_edge,
                 [(page_low + margins[member], page_high - margins[member]),
                  (page_low, page_high)])


def clamp_to_page(centres: np.ndarray, velocities: np.ndarray, rows: np.ndarray,
                  lowest: np.ndarray, highest: np.ndarray) -> None:
    """Hard walls, in place: keep each group's box inside the page (bounds from group_bounds).
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
    centres = bodies.centres  # take, not [j]: see fast_forces' module doc
    offsets = centres.take(j, axis=0) - centres.take(i, axis=0)
    close = np.abs(offsets) < COINCIDENT_MM
    same = close[:, 0] & close[:, 1]
    if not same.any():
        return False
    rows = np.where(movable[j[same]], j[same], i[same])
    rows = np.unique(rows[movable[rows]])
    if len(rows) == 0:
        return False
    bodies.centres[rows] += rng.uniform(-JITTER_MM, JITTER_MM, size=(len(rows), 2)) * scale
    return True
