"""How well a page lines up: the measures issue 16 sets its goals in.

Alignment is what most separates a designed page from an amateur one (Balinsky, Wiley and
Roberts, DocEng 2009).  Three numbers, over the items that take part in the layout
(decorations are left out: a band across the page lines up with nothing on purpose):

- *near misses per item*: pairs of edges (left and right on one axis, top and bottom on the
  other) or of centres, of different items, that lie between ``ALIGNED_MM`` and ``NEAR_MM``
  apart; an eye sees them as meant to line up and missing;
- *distinct edge lines per item*: the page's edge values, merged where they lie within
  ``ALIGNED_MM``, per item; 4 means nothing lines up, a page on a grid has far fewer;
- *aligned share*: the share of items that line up (edge with edge, or centre with centre)
  with another item on both axes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

ALIGNED_MM = 0.5
NEAR_MM = 4.0


@dataclass(frozen=True)
class Alignment:
    near_misses_per_item: float
    edge_lines_per_item: float
    aligned_share: float

    def summary(self) -> str:
        return (f"alignment: {self.near_misses_per_item:.2f} near misses per item · "
                f"{self.edge_lines_per_item:.2f} edge lines per item · "
                f"{self.aligned_share:.0%} aligned on both axes")

    def short(self) -> str:
        """The three numbers for the editor's details line, where room is short: near misses
        and edge lines per item, the share aligned on both axes."""
        return (f"misses {self.near_misses_per_item:.2f} · lines {self.edge_lines_per_item:.2f}"
                f" · aligned {self.aligned_share:.0%}")


def near_pairs(values: np.ndarray, owners: np.ndarray, low: float, high: float) -> int:
    """Pairs of values of different owners whose distance d has low < d < high."""
    order = np.argsort(values, kind="stable")
    sorted_values, sorted_owners = values[order], owners[order]
    count = 0
    for index in range(len(sorted_values)):
        start = np.searchsorted(sorted_values, sorted_values[index] + low, side="right")
        stop = np.searchsorted(sorted_values, sorted_values[index] + high, side="left")
        start = max(start, index + 1)
        if stop > start:
            count += int(np.count_nonzero(sorted_owners[start:stop] != sorted_owners[index]))
    return count


def lined_up(values: np.ndarray, owners: np.ndarray, count: int) -> np.ndarray:
    """For each owner, whether one of its values lies within ALIGNED_MM of another owner's."""
    order = np.argsort(values, kind="stable")
    sorted_values, sorted_owners = values[order], owners[order]
    found = np.zeros(count, dtype=bool)
    for step in (1, 2, 3):  # an owner has at most two values here, so three steps reach past it
        near = np.abs(sorted_values[step:] - sorted_values[:-step]) <= ALIGNED_MM
        other = sorted_owners[step:] != sorted_owners[:-step]
        hit = near & other
        found[sorted_owners[step:][hit]] = True
        found[sorted_owners[:-step][hit]] = True
    return found


def edge_lines(values: np.ndarray) -> int:
    if len(values) == 0:
        return 0
    ordered = np.sort(values)
    return 1 + int(np.count_nonzero(np.diff(ordered) > ALIGNED_MM))


def measure_alignment(centres: np.ndarray, sizes: np.ndarray,
                      decorative: np.ndarray | None = None) -> Alignment:
    """The three measures for items with centres (n, 2) and sizes (n, 2), in mm."""
    centres, sizes = np.asarray(centres, float), np.asarray(sizes, float)
    if decorative is not None:
        keep = ~np.asarray(decorative, bool)
        centres, sizes = centres[keep], sizes[keep]
    n = len(centres)
    if n == 0:
        return Alignment(0.0, 0.0, 0.0)
    owners = np.arange(n)
    twice = np.concatenate([owners, owners])
    near = 0
    aligned = np.ones(n, dtype=bool)
    lines = 0
    for axis in (0, 1):
        edges = np.concatenate([centres[:, axis] - sizes[:, axis] / 2,
                                centres[:, axis] + sizes[:, axis] / 2])
        near += near_pairs(edges, twice, ALIGNED_MM, NEAR_MM)
        near += near_pairs(centres[:, axis], owners, ALIGNED_MM, NEAR_MM)
        aligned &= lined_up(edges, twice, n) | lined_up(centres[:, axis], owners, n)
        lines += edge_lines(edges)
    return Alignment(near / n, lines / n, float(np.count_nonzero(aligned)) / n if n > 1 else 0.0)
