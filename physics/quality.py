"""Layout quality measures after Harrington et al. 2004 ("Aesthetic measures for automated
document layout"): overlap, area off the page, minimum gap, evenness of the gaps between
neighbours, and balance.  One function serves ``floatpage check`` and the editor's status line.

Alignment (issue 16: near misses and edge lines per item, the share aligned on both axes) is
part of a page's quality too, offered here with the rest; it is defined in physics.alignment,
beside the thresholds the alignment snap reads.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from floatpage.physics.alignment import Alignment, measure_alignment  # noqa: F401 (offered here)

GAP_TOLERANCE_MM = 1e-6
MARGIN_TOLERANCE_MM = 0.01  # a save rounds to 0.01 mm (towards the page's inside)


@dataclass(frozen=True)
class Quality:
    overlap_area_mm2: float
    overlap_fraction: float  # overlap area / total item area
    overlapping_pairs: tuple[tuple[int, int], ...]  # the first PAIRS_LISTED of them
    off_page_area_mm2: float
    off_page: tuple[int, ...]  # indices of items not wholly inside the page
    min_gap_mm: float  # smallest edge-to-edge gap; negative if overlapping; inf if < 2 items
    gap_evenness: float  # 0..1, 1 = every item's nearest neighbour equally far
    balance: float  # 0..1, 1 = centre of mass of item area at the page centre
    gutter_mm: float = 0.0  # the gap the layout should keep, for ``ok`` and the summary
    # items (not decorations or bleed items) closer to the page edge than the print-safe margin
    in_margin: tuple[int, ...] = ()
    margin_mm: float = 0.0
    overlap_count: int = 0  # every overlapping pair, listed or not
    # the depths of every overlapping pair summed (each as min_gap_mm measures a pair: how far
    # one item must move to clear the other), what model.layout's order weighs overlaps by
    overlap_depth_mm: float = 0.0
    outside_region: tuple[int, ...] = ()  # items not wholly inside the region they are confined to

    @property
    def gutter_kept(self) -> bool:
        """Every gap at least the gutter (a page of fewer than two items keeps it)."""
        return self.min_gap_mm >= self.gutter_mm - GAP_TOLERANCE_MM

    @property
    def ok(self) -> bool:
        """No overlap, nothing off the page, and every gap at least the gutter."""
        return (not self.overlap_count and not self.off_page and not self.in_margin
                and not self.outside_region and self.gutter_kept)

    def summary(self) -> str:
        """One short line for a status bar."""
        gap = "—" if math.isinf(self.min_gap_mm) else f"{self.min_gap_mm:.1f} mm"
        if not self.gutter_kept:
            gap += f" < {self.gutter_mm:g}"
        margin = f"{len(self.in_margin)} in margin · " if self.in_margin else ""
        if self.outside_region:
            margin += f"{len(self.outside_region)} outside region · "
        return (f"{self.overlap_count} overlaps · {len(self.off_page)} off page · "
                f"{margin}gap {gap} · even {self.gap_evenness:.2f} · balance {self.balance:.2f}")


PAIR_BLOCK = 256  # rows compared with all others at once: memory stays O(PAIR_BLOCK * n)
# Pairs kept by index: 10,000 boxes on one spot overlap in 50 million pairs, which as a list
# took gigabytes; the count is kept whole.
PAIRS_LISTED = 1_000


SWEPT_PAIRS = 2_000_000  # a page whose sweep would meet more candidates is measured block by block


def pairwise(centres: np.ndarray, halves: np.ndarray, group: np.ndarray | None
             ) -> tuple[float, list[tuple[int, int]], int, np.ndarray, float]:
    """Total overlap area, the first PAIRS_LISTED overlapping pairs (i < j), how many there
    are, each item's nearest edge gap, and the depths of the overlapping pairs summed.

    On a page of many items that are not piled up, only the pairs within a neighbour's reach
    are measured (``near_pairwise``: the same figures, in O(n log n) and the pairs found);
    otherwise every pair (``all_pairwise``)."""
    count = len(centres)
    if count > PAIR_BLOCK:
        reach = neighbour_reach(centres, count)
        if sweep_candidates(centres, halves, reach) <= SWEPT_PAIRS:  # not piled up
            return near_pairwise(centres, halves, group, reach)
    return all_pairwise(centres, halves, group)


def neighbour_reach(centres: np.ndarray, count: int) -> float:
    """Twice the spacing the items would have if spread evenly over their bounding box: most
    items have their nearest neighbour within it."""
    extent = np.ptp(centres, axis=0) if count else np.zeros(2)
    return max(2.0 * math.sqrt(max(float(extent[0] * extent[1]), 1.0) / max(count, 1)), 1.0)


def sweep_candidates(centres: np.ndarray, halves: np.ndarray, reach: float) -> int:
    """About how many candidate pairs the neighbour search within ``reach`` would make, without
    making them: a pile of 10,000 items on one spot would make 50 million.  The sweep along x
    (below GRID_FROM_ITEMS items) meets the items that start before each item's right edge plus
    ``reach``; the grid beyond that, the items in the cells each item's box covers."""
    from floatpage.physics.fast_forces import GRID_FROM_ITEMS

    if len(centres) < GRID_FROM_ITEMS:
        left = np.sort(centres[:, 0] - halves[:, 0])
        right = np.sort(centres[:, 0] + halves[:, 0])
        return int(np.maximum(np.searchsorted(left, right + reach, "left")
                              - np.arange(1, len(left) + 1), 0).sum())
    cell = max(reach, float(np.median(halves)) * 2)
    low = np.floor((centres - halves) / cell).astype(np.int64)
    high = np.floor((centres + halves + reach) / cell).astype(np.int64)
    spans = (high - low + 1).prod(axis=1)  # cells each item's grown box covers
    per_cell = len(centres) * float(spans.mean()) / max(len(np.unique(
        low[:, 0] * 1_000_003 + low[:, 1])), 1)
    return int(len(centres) * spans.mean() * per_cell)


def clearances(centres_a: np.ndarray, halves_a: np.ndarray, centres_b: np.ndarray,
               halves_b: np.ndarray) -> np.ndarray:
    """Per-axis clearance between boxes a and b (broadcast), negative where they overlap on
    that axis: the same arithmetic for a pair whichever of its items comes first."""
    return np.abs(centres_a - centres_b) - (halves_a + halves_b)


def overlap_areas(clear: np.ndarray, halves_a: np.ndarray, halves_b: np.ndarray) -> np.ndarray:
    """Overlap area of boxes a and b from their clearances (a box inside another overlaps by
    its own size, not by the depth)."""
    depth = np.minimum(np.clip(-clear, 0.0, None), 2 * np.minimum(halves_a, halves_b))
    return depth[..., 0] * depth[..., 1]


def pair_gaps(clear: np.ndarray) -> np.ndarray:
    """Edge-to-edge gap of pairs from their per-axis clearances (..., 2): the corner distance
    where they are apart on both axes, else the larger clearance (negative: overlapping)."""
    both = (clear > 0).all(axis=-1)
    corner = np.sqrt((np.clip(clear, 0.0, None) ** 2).sum(axis=-1))
    return np.where(both, corner, clear.max(axis=-1))


def near_pairwise(centres: np.ndarray, halves: np.ndarray, group: np.ndarray | None,
                  reach: float) -> tuple[float, list[tuple[int, int]], int, np.ndarray, float]:
    """``pairwise`` from the pairs within ``reach`` (physics.fast_forces.candidate_pairs: every
    pair closer than ``reach`` is among them, so an item's nearest gap found below ``reach`` is
    exact); items with no neighbour that near are measured against every item."""
    from floatpage.physics.fast_forces import candidate_pairs

    count = len(centres)
    rows = np.arange(count)
    groups = rows if group is None else np.asarray(group)
    a, b = candidate_pairs(centres, halves, rows, groups, reach)
    i, j = np.minimum(a, b), np.maximum(a, b)
    clear = clearances(centres[i], halves[i], centres[j], halves[j])
    overlap = overlap_areas(clear, halves[i], halves[j])
    overlapping = overlap > 0
    listed = np.lexsort((j[overlapping], i[overlapping]))[:PAIRS_LISTED]
    hits = [(int(first), int(second)) for first, second
            in zip(i[overlapping][listed], j[overlapping][listed])]
    gaps = pair_gaps(clear)
    nearest = np.full(count, np.inf)
    np.minimum.at(nearest, i, gaps)
    np.minimum.at(nearest, j, gaps)
    far = np.flatnonzero(nearest >= reach)
    far = far[np.argsort(groups[far], kind="stable")]  # a block of one group skips its own
    for start in range(0, len(far), PAIR_BLOCK):
        block = far[start:start + PAIR_BLOCK]
        others = rows
        if (groups[block] == groups[block[0]]).all():  # (a chain of 2,000: no others at all)
            others = np.flatnonzero(groups != groups[block[0]])
        if not len(others):
            nearest[block] = np.inf
            continue
        gaps_far = pair_gaps(clearances(centres[block][:, None, :], halves[block][:, None, :],
                                        centres[others][None, :, :], halves[others][None, :, :]))
        gaps_far[groups[block][:, None] == groups[others][None, :]] = np.inf
        nearest[block] = gaps_far.min(axis=1)
    return (float(overlap.sum()), hits, int(np.count_nonzero(overlapping)), nearest,
            float(-gaps[overlapping].sum()))


def all_pairwise(centres: np.ndarray, halves: np.ndarray, group: np.ndarray | None
                 ) -> tuple[float, list[tuple[int, int]], int, np.ndarray, float]:
    """``pairwise`` over every pair,
    ``PAIR_BLOCK`` rows at a time: the whole (n, n) matrices took 6.7 GB at 10,000 items, and
    `floatpage check` must stay under 1 GB for any file that loads.  Pairs within one anchor
    group count for neither."""
    n = len(centres)
    total, hits, count, depth = 0.0, [], 0, 0.0
    nearest = np.full(n, np.inf)
    for start in range(0, n, PAIR_BLOCK):
        # Each block of rows against itself and the rows after it: every pair once (the pairs
        # before it were columns of an earlier block), half the work of all against all.
        stop = min(start + PAIR_BLOCK, n)
        block_c, block_h = centres[start:stop], halves[start:stop]
        later_c, later_h = centres[start:], halves[start:]
        clear = clearances(block_c[:, None, :], block_h[:, None, :], later_c[None, :, :],
                           later_h[None, :, :])
        overlap = overlap_areas(clear, block_h[:, None, :], later_h[None, :, :])
        own = np.arange(stop - start)[:, None]
        columns = np.arange(n - start)[None, :]
        upper = columns > own
        excluded = columns == own
        if group is not None:
            same = group[start:stop, None] == group[None, start:]
            upper &= ~same
            excluded |= same
        total += float(overlap[upper].sum())
        overlapping = upper & (overlap > 0)
        count += int(np.count_nonzero(overlapping))
        if len(hits) < PAIRS_LISTED:
            hits += [(int(start + a), int(start + b))
                     for a, b in np.argwhere(overlapping)[:PAIRS_LISTED - len(hits)]]
        gaps = pair_gaps(clear)
        depth -= float(gaps[overlapping].sum())
        gaps[excluded] = np.inf
        nearest[start:stop] = np.minimum(nearest[start:stop], gaps.min(axis=1))
        nearest[start:] = np.minimum(nearest[start:], gaps.min(axis=0))
    return total, hits, count, nearest, depth


def measure_quality(page_w_mm: float, page_h_mm: float, centres, sizes, gutter_mm: float = 0.0,
                    *, decorative=None, groups=None, margins=None, regions=None) -> Quality:
    """All measures for one page.  ``centres`` and ``sizes`` are (n, 2) arrays in mm.

    ``decorative`` (n,) bool marks items that sit behind the others by design: they count
    for the off-page measure only, not for overlap, gaps or balance.  Indices in the result
    refer to the rows given.  ``groups`` (n,) int gives each item's anchor group (the root of
    its follow chain): a follower sits where its user put it beside its target, so pairs within
    one group count for neither overlap nor gaps. ``margins`` (n,) is each item's print-safe
    margin (0 for bleed items); items closer to the edge than theirs are ``in_margin``.
    ``regions`` (n, 4) is the rectangle (left, top, right, bottom) each item is confined to,
    NaN where none; items not wholly inside theirs are ``outside_region``.
    """
    centres = np.asarray(centres, float).reshape(-1, 2)
    sizes = np.asarray(sizes, float).reshape(-1, 2)
    count = len(centres)
    layered = (np.zeros(count, bool) if decorative is None
               else np.asarray(decorative, bool).reshape(count))
    halves = sizes / 2
    areas = sizes[:, 0] * sizes[:, 1]

    inside_lo = np.clip(centres - halves, 0.0, [page_w_mm, page_h_mm])
    inside_hi = np.clip(centres + halves, 0.0, [page_w_mm, page_h_mm])
    inside_area = np.prod(np.clip(inside_hi - inside_lo, 0.0, None), axis=1)
    off_area = np.clip(areas - inside_area, 0.0, None)
    # The tolerance of a save's rounding, as for the margin (and physics.page_limits): a band
    # 69.75 mm tall cannot be written flush with the page's edge to 0.01 mm, and one 0.005 mm
    # past it was off the page for `check`, which named no reason (page_limits does not name
    # what is within the rounding).
    margin = MARGIN_TOLERANCE_MM
    off_page = tuple(int(k) for k in np.flatnonzero(
        ((centres - halves) < -margin).any(axis=1)
        | ((centres + halves) > np.array([page_w_mm, page_h_mm]) + margin).any(axis=1)))

    in_margin: tuple[int, ...] = ()
    margin_mm = 0.0
    if margins is not None:
        wanted = np.asarray(margins, float).reshape(count)
        margin_mm = float(wanted.max(initial=0.0))
        edge = np.minimum(centres - halves, np.array([page_w_mm, page_h_mm]) - centres - halves)
        short = (edge.min(axis=1) < wanted - MARGIN_TOLERANCE_MM) & ~layered & (wanted > 0)
        off = np.zeros(count, bool)
        off[list(off_page)] = True  # a tuple's `in` per item was O(n^2) on a page far off
        in_margin = tuple(int(k) for k in np.flatnonzero(short & ~off))

    outside_region: tuple[int, ...] = ()
    if regions is not None:
        boxes = np.asarray(regions, float).reshape(count, 4)
        confined = ~np.isnan(boxes[:, 0])
        with np.errstate(invalid="ignore"):
            out = (((centres - halves) < boxes[:, :2] - MARGIN_TOLERANCE_MM)
                   | ((centres + halves) > boxes[:, 2:] + MARGIN_TOLERANCE_MM)).any(axis=1)
        outside_region = tuple(int(k) for k in np.flatnonzero(out & confined & ~layered))

    rows = np.flatnonzero(~layered)
    overlap_total, pairs, overlap_count, min_gap, evenness = 0.0, (), 0, math.inf, 1.0
    overlap_depth = 0.0
    if len(rows) >= 2:
        group = None if groups is None else np.asarray(groups).reshape(count)[rows]
        overlap_total, hits, overlap_count, nearest, overlap_depth = pairwise(
            centres[rows], halves[rows], group)
        pairs = tuple((int(rows[a]), int(rows[b])) for a, b in hits)
        min_gap = float(nearest.min())
        nearest = np.clip(nearest, 0.0, None)
        nearest = nearest[np.isfinite(nearest)]
        mean = nearest.mean() if len(nearest) else 0.0
        evenness = 1.0 / (1.0 + nearest.std() / mean) if mean > 0 else 0.0
    item_area = float(areas[rows].sum())

    balance = 1.0
    if item_area > 0:
        weights = areas[rows]
        centre_of_mass = (centres[rows] * weights[:, None]).sum(axis=0) / item_area
        off_centre = np.abs(centre_of_mass - [page_w_mm / 2, page_h_mm / 2])
        balance = float(np.clip(1.0 - (off_centre / [page_w_mm / 2, page_h_mm / 2]).mean(), 0, 1))

    return Quality(
        overlap_area_mm2=overlap_total,
        overlap_fraction=overlap_total / item_area if item_area > 0 else 0.0,
        overlapping_pairs=pairs,
        off_page_area_mm2=float(off_area.sum()),
        off_page=off_page,
        min_gap_mm=min_gap,
        gap_evenness=float(evenness),
        balance=balance,
        gutter_mm=float(gutter_mm),
        in_margin=in_margin,
        margin_mm=margin_mm,
        overlap_count=overlap_count,
        overlap_depth_mm=overlap_depth,
        outside_region=outside_region,
    )

