"""Force terms of the fast mode: short-range pushes between rectangle *edges*, and walls that
push on item edges.

Why not the paper's 1/sigma^2 between centres: a long-range force never vanishes, so the page
only stops when cooling freezes it, and centre distances ignore item shapes (a wide banner and a
small photo overlap long before their centres are close).  Here every item wants a gap ``gap``
(mm) to its neighbours and ``gap / 2`` to the page edge.  ``target_gap`` chooses that gap so
the items with their halos would cover 90% of the page, about as dense as rectangles of mixed
shapes pack by chance: most items then touch their neighbours' halos, so a damped spring
network comes to rest with even gaps (measured: fuller halos jam and leave overlaps, emptier
ones leave clumps).  The pushes vanish at rest, so motion dies out by itself instead of by
cooling alone.

Pushes are accelerations in mm per step squared; the integrator scales them by heat.

Rows of an (n, 2) array are gathered with ``a.take(rows, axis=0)`` and ``a.compress(mask,
axis=0)``, not ``a[rows]`` or ``a[mask]``: with NumPy 2.4 (as setup installs it), indexing an
(n, 2) array by an index array took 4.1 ms for 200,000 rows and ``take`` 0.25 ms (a mask:
3.4 ms against 0.31 ms), the same values bit for bit.  On a 10,000-item page that was a third
of a step.
"""

from __future__ import annotations

import math

import numpy as np

from floatpage.physics.geometry import RELOCATABLE_ITEMS, squared_norms, sum_xy

FILL = 0.9  # halo-grown item area / page area that target_gap aims at
RADIAL_SHARE = 0.5  # share of a push directed along the line between the centres
# A push prefers the axis of least penetration by the 4th power of the depths (see touching_pushes).


def target_gap(sizes: np.ndarray, page_w_mm: float, page_h_mm: float, gutter_mm: float,
               fill: float = FILL) -> float:
    """Gap g (mm) with sum of (w + g)(h + g) = fill * page area: at least the gutter where the
    items keep it at that fill, or where they are few enough for relocation; else the gap a
    crowd can keep (0 where the items alone cover it).

    Solves n g^2 + g sum(w + h) + sum(w h) - fill W H = 0 for its positive root.

    Below the gutter only for a crowd where the gutter cannot fit by area: there the no-overlap
    pass keeps the widest gap it can anyway (finalize), and halos of the full gutter only
    pressed the crowd into itself.  10,000 items of 1-3 mm covering half of A4 need 3.7 times
    the page once each grows by 3 mm; with gutter-wide halos the physics rested with every item
    pushed into its neighbours, and the pass could not part them (3,297 overlapping pairs
    after 43 s); halos of the 0.6 mm that fits spread them without overlap in 8 s.  A page of
    at most ``RELOCATABLE_ITEMS`` keeps the gutter-wide halos: relocation parts what the pass
    leaves there, and works better from the wider spread (fresh_projects seed 7047 p1, 19
    items that must overlap: 5 overlapping pairs with them, 8 without; docs/benchmarks.md,
    thirteenth session).
    """
    count = len(sizes)
    if count == 0:
        return gutter_mm
    linear = float((sizes[:, 0] + sizes[:, 1]).sum())
    constant = float((sizes[:, 0] * sizes[:, 1]).sum()) - fill * page_w_mm * page_h_mm
    floor = gutter_mm if count <= RELOCATABLE_ITEMS else 0.0
    if constant >= 0:
        return floor
    root = (-linear + np.sqrt(linear * linear - 4.0 * count * constant)) / (2.0 * count)
    return max(float(root), floor)


GRID_FROM_ITEMS = 5_000  # from this many rows on, candidates come from a grid (see grid_pairs)


def candidate_pairs(centres: np.ndarray, halves: np.ndarray, rows: np.ndarray,
                    groups: np.ndarray, reach: float) -> tuple[np.ndarray, np.ndarray]:
    """Pairs (i, j), i < j, among ``rows`` whose rectangles come within ``reach`` mm.

    A Verlet neighbour list: built now and then with a margin (``reach`` = gap + skin), so each
    step only visits the few pairs that can touch.  Built by sweep and prune: sorted by left
    edge, each item meets only the items that start before its right edge plus ``reach``,
    which is a few dozen instead of all n (at 500 items, 8 ms became about 1 ms).  On a page of
    thousands of items a column of the sweep holds thousands of items (10,000 small items on
    A4: 3.1 million candidates for 130,000 pairs), so there a grid finds the candidates
    (``grid_pairs``); both give the same pairs in the same order, so the physics sums the same
    numbers either way.  Pairs inside one rigid group are left out.
    """
    empty = np.zeros(0, dtype=np.int64)
    if len(rows) < 2:
        return empty, empty
    c, h = centres.take(rows, axis=0), halves.take(rows, axis=0)
    left = c[:, 0] - h[:, 0]
    order = np.argsort(left, kind="stable")
    # From here on items are numbered in sweep order (the k-th from the left is k), so a pair
    # (a, b) with a < b is in the sweep's orientation and sorts by the single key a * n + b.
    count = len(rows)
    c, h = c.take(order, axis=0), h.take(order, axis=0)
    left_sorted = left.take(order)
    right_sorted = c[:, 0] + h[:, 0]
    if count >= GRID_FROM_ITEMS:
        a, b = grid_pairs(c, h, left_sorted, right_sorted, reach)
    else:
        first = np.arange(1, count + 1)
        stop = np.searchsorted(left_sorted, right_sorted + reach, side="left")
        runs = np.maximum(stop - first, 0)
        total = int(runs.sum())
        if total == 0:
            return empty, empty
        a = np.repeat(np.arange(count), runs)
        b = np.arange(total) - np.repeat(np.cumsum(runs) - runs, runs) + np.repeat(first, runs)
    # x is exact by construction (b starts after a does, before a's right edge + reach)
    y, half_y = c[:, 1], h[:, 1]
    clear_y = np.abs(y.take(b) - y.take(a)) - half_y.take(a) - half_y.take(b)
    near = clear_y < reach
    a, b = a[near], b[near]
    if count >= GRID_FROM_ITEMS:  # the grid finds them cell by cell: back to the sweep's order
        key = np.sort(a * count + b)  # unique keys: any sort gives the same order
        a, b = key // count, key % count
    rows_sorted = rows.take(order)
    a, b = rows_sorted.take(a), rows_sorted.take(b)
    i, j = np.minimum(a, b), np.maximum(a, b)
    different = groups.take(i) != groups.take(j)
    return i[different], j[different]


def grid_pairs(c: np.ndarray, h: np.ndarray, left: np.ndarray, right: np.ndarray,
               reach: float) -> tuple[np.ndarray, np.ndarray]:
    """The sweep's x-candidates (a < b, items numbered in sweep order, b's left edge before
    a's right edge plus ``reach``) that also come within about ``reach`` on y, in no
    particular order, found through a grid: each rectangle, grown by half the reach (and a
    hair), is filed under every cell it covers; two items are candidates where they share a
    cell, counted once, in the cell holding the corner where their grown rectangles start to
    overlap.  The caller's exact y test then keeps the same pairs as the sweep's, and sorts
    them into its order.  ``left`` and ``right`` are the items' edges along x."""
    count = len(c)
    margin = reach / 2 + 1e-6 * max(reach, 1.0)
    low, high = c - h - margin, c + h + margin
    size = float(np.median(2 * h.max(axis=1))) + reach
    size = max(size, 1e-3)
    origin = low.min(axis=0)
    first_cell = np.floor((low - origin) / size).astype(np.int64)
    last_cell = np.floor((high - origin) / size).astype(np.int64)
    spans = last_cell - first_cell + 1
    cells_each = spans[:, 0] * spans[:, 1]
    owner = np.repeat(np.arange(count), cells_each)
    k = np.arange(len(owner)) - np.repeat(np.cumsum(cells_each) - cells_each, cells_each)
    across = np.repeat(spans[:, 0], cells_each)
    first_x, first_y = first_cell[:, 0].copy(), first_cell[:, 1].copy()
    cell_x = first_x.take(owner) + k % across
    cell_y = first_y.take(owner) + k // across
    width = int(last_cell[:, 1].max()) + 2
    key = cell_x * width + cell_y
    filed = np.argsort(key, kind="stable")
    key, owner = key.take(filed), owner.take(filed)
    # every later entry of the same cell is a partner: runs as in the sweep
    ends = np.searchsorted(key, key, side="right")
    runs = ends - np.arange(1, len(key) + 1)
    total = int(runs.sum())
    if total == 0:
        empty = np.zeros(0, dtype=np.int64)
        return empty, empty
    p = np.repeat(np.arange(len(key)), runs)
    q = p + 1 + np.arange(total) - np.repeat(np.cumsum(runs) - runs, runs)
    u, v, cell = owner.take(p), owner.take(q), key.take(p)
    # The overlap's corner is the later of the two low edges on each axis; the cell index is
    # monotonic in the coordinate, so its cell is the later of the two items' first cells
    # (the same cell as flooring the corner itself, in integers).
    corner = (np.maximum(first_x.take(u), first_x.take(v)) * width
              + np.maximum(first_y.take(u), first_y.take(v)))
    once = corner == cell
    u, v = u[once], v[once]
    a, b = np.minimum(u, v), np.maximum(u, v)
    keep = left.take(b) < right.take(a) + reach
    return a[keep], b[keep]


def blocked_axes(sizes: np.ndarray, i: np.ndarray, j: np.ndarray, page_w_mm: float,
                 page_h_mm: float, gutter_mm: float,
                 insets: tuple[np.ndarray, np.ndarray] | None = None) -> np.ndarray:
    """Per pair, (m, 2) bool: True on an axis along which the two items cannot sit apart on
    this page (together wider, or taller, than the room their walls leave).  Such a pair must
    separate on the other axis, however deep it overlaps there; two wide text boxes stack, they
    never try to stand side by side.

    ``insets`` (near, far), as Bodies.insets, are where each row's walls stand: with a 5 mm
    margin, photos 95 and 105 mm wide do not fit side by side on A4 (200 mm between the
    walls); judged against the bare page they jammed against the margins 0.13 mm apart instead
    of stacking with the gutter between them.  A pair's room is the page less the walls of
    whichever of the two stands on each side, in the order that leaves more."""
    extent = np.array([page_w_mm, page_h_mm])
    if not len(i):
        return np.zeros((0, 2), dtype=bool)
    near, far = (np.zeros((1, 2)), np.zeros((1, 2))) if insets is None else (
        np.broadcast_to(np.asarray(side, float), sizes.shape) for side in insets)
    if (near == near[0]).all() and (far == far[0]).all():
        room = extent - near[0] - far[0]  # one margin for all: no need to look pair by pair
    else:
        near_i, near_j = near.take(i, axis=0), near.take(j, axis=0)
        room = extent - np.minimum(near_i + far.take(j, axis=0), near_j + far.take(i, axis=0))
    need = sizes.take(i, axis=0) + sizes.take(j, axis=0) + gutter_mm
    blocked = need > room
    both = blocked.all(axis=1)
    blocked[both] = False  # hopeless either way: let the cheaper axis decide
    return blocked


def contact_pushes(centres: np.ndarray, halves: np.ndarray, i: np.ndarray, j: np.ndarray,
                   gap: float, blocked: np.ndarray | None = None,
                   radial_share: float = RADIAL_SHARE) -> np.ndarray:
    """For each pair, the push on j away from i (i gets the opposite), shape (m, 2): zero for
    pairs whose halos do not touch, ``touching_pushes`` for the rest."""
    touching, pushes = touching_pushes(centres, halves[i] + halves[j] + gap, i, j, blocked,
                                       radial_share)
    pushes_all = np.zeros((len(i), 2))
    pushes_all[touching] = pushes
    return pushes_all


def touching_pushes(centres: np.ndarray, reach: np.ndarray, i: np.ndarray, j: np.ndarray,
                    blocked: np.ndarray | None = None, radial_share: float = RADIAL_SHARE
                    ) -> tuple[np.ndarray, np.ndarray]:
    """The pairs (i, j) whose halos touch, as indices into them, and the push on j away from i
    for each (i gets the opposite), shape (k, 2).  ``reach`` (m, 2) is each pair's half sizes
    summed plus the gap: the step loop keeps it from one neighbour list to the next.

    Each rectangle is grown by gap / 2; the push is the penetration depth of the grown pair,
    split between the axes so that the axis of least penetration takes nearly all of it (a soft
    version of the minimum translation vector: continuous, hence no jitter at corners), plus
    ``radial_share`` of it along the line between the centres.  ``blocked`` (m, 2) removes an
    axis on which the pair cannot separate within the page.
    """
    d = centres.take(j, axis=0) - centres.take(i, axis=0)  # take: see the module doc
    penetration = reach - np.abs(d)
    # Only touching pairs push: the rest of the arithmetic runs on them alone (in a crowd of
    # 10,000 items this was most of a step), element for element as on all pairs.
    touching = (np.minimum(penetration[:, 0], penetration[:, 1]) > 0).nonzero()[0]
    if not len(touching):
        return touching, np.zeros((0, 2))
    if len(touching) < len(d):  # all of them touch on most steps of a small page: no gather
        d, penetration = d.take(touching, axis=0), penetration.take(touching, axis=0)
        if blocked is not None:
            blocked = blocked.take(touching, axis=0)
    if blocked is not None and not blocked.any():
        blocked = None
    squared = penetration * penetration
    sharp = squared * squared  # AXIS_SHARPNESS = 4
    if blocked is not None:
        sharp = np.where(blocked[:, ::-1], 0.0, sharp)  # a blocked axis gets no share
        sharp = np.where(blocked, sharp + 1.0, sharp)  # ...and leaves it all to the other
    total = sum_xy(sharp)
    total[total == 0] = 1.0
    weights = sharp[:, ::-1] / total[:, None]  # x takes the y share and vice versa
    # +-1 times it, exactly, by the sign of d: as where(d >= 0, p, -p) but in one call (they
    # differ at d = -0.0 only, which needs a centre at -0.0: the walls keep them inside)
    pushes = np.copysign(penetration, d)
    pushes *= weights
    if radial_share == 0:
        return touching, pushes
    # A little push along the line between the centres lets an item squeezed in a row slip
    # up or down into a roomier row; pure axis pushes would keep the row jammed.  It is not
    # the gradient of any energy (it makes touching items slide along each other), so the
    # fast mode fades it out as the page cools.
    length = np.sqrt(squared_norms(d))
    length[length == 0] = 1.0
    depth = np.sqrt(squared_norms(pushes))
    radial = (radial_share * depth / length)[:, None] * d
    if blocked is not None:
        radial[blocked] = 0.0
    pushes += radial
    return touching, pushes


def wall_rest_box(halves: np.ndarray, page_w_mm: float, page_h_mm: float, margin,
                  far_margin=None) -> tuple[np.ndarray, np.ndarray]:
    """Where each centre may rest without a wall push: lowest and highest, (n, 2) each.
    The walls stand ``margin`` inside the left and top edges and ``far_margin`` (the same if
    not given) inside the right and bottom ones.

    An item too large for the page (with its margins) on an axis may only rest in the middle
    between its walls there.
    """
    extent = np.array([page_w_mm, page_h_mm])
    far = margin if far_margin is None else far_margin
    lowest = halves + margin
    highest = extent - halves - far
    too_big = 2 * halves >= extent
    crowded = lowest > highest  # fits, but not with both margins: rest in the middle
    squeezed = too_big | crowded
    if not squeezed.any():  # most pages: every item its own box (the snap's set-up asks)
        return lowest, highest
    middle = np.broadcast_to(extent / 2, halves.shape)
    if far_margin is not None:
        middle = middle + (np.asarray(margin) - np.asarray(far)) / 2
    lowest = np.where(squeezed, middle, lowest)
    highest = np.where(squeezed, middle, highest)
    return lowest, highest


def wall_pushes_in(centres: np.ndarray, lowest: np.ndarray, highest: np.ndarray) -> np.ndarray:
    """Springs back into the rest box from wall_rest_box, shape (n, 2)."""
    # The same numbers as max(lowest - c, 0) - max(c - highest, 0) (lowest <= highest, and a
    # difference negated is exact), in three NumPy calls instead of five.
    return np.minimum(np.maximum(centres, lowest), highest) - centres


def wall_pushes(centres: np.ndarray, halves: np.ndarray, page_w_mm: float, page_h_mm: float,
                margin: float) -> np.ndarray:
    """Springs that keep every item edge ``margin`` mm inside the page, shape (n, 2).

    An item too large for the page on an axis is pulled to the page's middle on that axis.
    """
    return wall_pushes_in(centres, *wall_rest_box(halves, page_w_mm, page_h_mm, margin))
