"""Which groups a guide line holds, for the snap's rest check (physics.rest_check): the page's
lines kept up to date move by move, rather than worked out again at every check.

A group is held on an axis when one of its edges lies within ``ON_LINE_MM`` of another group's
edge or of the page's edge lines, or its centre within it of another group's centre or of the
page's middle (physics.guides).  The rest check asks this of every group a trial move touches,
for the page as it is and with the move made: about two checks per move, each of which used to
gather every active row's lines from the centres, join them to the page's, and compare every
touched row's root with every line's owner.  Here the lines are kept in arrays (updated for the
rows a move moved: ``moved``), the owner comparison is kept per set of groups (it never changes:
groups do not change during a snap), and a trial move patches a copy of its own rows' lines.
Every line is the same subtraction or addition of the same floats as before, so every answer is
the same, bit for bit (benchmarks/snap_identity.py checks the snap's moves on main's inputs).
"""

from __future__ import annotations

import numpy as np

from floatpage.physics.guides import ON_LINE_MM
from floatpage.physics.snap_scoring import trues


class LineHold:
    """One page's guide lines per axis, for a snap: ``edges[axis]`` holds the active rows' low
    edges, then their high edges, then the page's edge lines; ``middles[axis]`` their centres,
    then the page's middle (the order of RestCheck.line_roots)."""

    def __init__(self, centres: np.ndarray, halves: np.ndarray, active_rows: np.ndarray,
                 roots: np.ndarray, group_rows: list[np.ndarray],
                 page_lines: list[tuple[np.ndarray, np.ndarray]],
                 line_roots: list[tuple[np.ndarray, np.ndarray]]):
        self.centres, self.halves, self.roots = centres, halves, roots
        self.group_rows, self.line_roots = group_rows, line_roots
        self.count = len(active_rows)
        self.slot = np.full(len(centres), -1)  # each active row's place among the lines
        self.slot[active_rows] = np.arange(self.count)
        self.grouped = bool((roots != np.arange(len(roots))).any())
        self.edges, self.middles = [], []
        for axis, (page_edges, page_middles) in enumerate(page_lines):
            at, half = centres[:, axis], halves[:, axis]
            theirs, spans = at[active_rows], half[active_rows]
            self.edges.append(np.concatenate([theirs - spans, theirs + spans, page_edges]))
            self.middles.append(np.concatenate([theirs, page_middles]))
        self.owners: dict[bytes, tuple] = {}

    def moved(self, rows: np.ndarray, axes: tuple[int, ...] = (0, 1)) -> None:
        """``rows`` (active) have moved along ``axes``: their lines there from their centres."""
        slots = self.slot[rows]
        for axis in axes:
            at, half = self.centres[rows, axis], self.halves[rows, axis]
            self.edges[axis][slots] = at - half
            self.edges[axis][slots + self.count] = at + half
            self.middles[axis][slots] = at

    def others(self, groups: np.ndarray) -> tuple:
        """For ``groups``: their rows, each row's group (its index in ``groups``) and, per axis,
        which lines belong to another group than each row's (rows, edge lines or middles), kept
        per set of groups."""
        key = groups.tobytes()
        found = self.owners.get(key)
        if found is None:
            sizes = [len(self.group_rows[g]) for g in groups]
            rows = np.concatenate([self.group_rows[g] for g in groups])
            owner = np.repeat(np.arange(len(groups)), sizes)
            mine_roots = self.roots[rows]
            masks = [(np.tile(edge_roots[None, :] != mine_roots[:, None], (2, 1)),
                      middle_roots[None, :] != mine_roots[:, None])
                     for edge_roots, middle_roots in self.line_roots]
            found = self.owners[key] = (rows, owner, masks)
        return found

    def held(self, groups: np.ndarray, axis: int, members: np.ndarray | None = None,
             shift: float = 0.0) -> np.ndarray:
        """(len(groups),): whether a line holds each group on ``axis``, with the page as it is,
        or with ``members`` moved by ``shift`` along it (as RestCheck.on_lines found it on a
        copy of the centres so moved)."""
        rows, owner, masks = self.others(groups)
        other_edge, other_middle = masks[axis]
        at, half = self.centres[:, axis], self.halves[:, axis]
        edges, middles = self.edges[axis], self.middles[axis]
        if members is not None:
            at = at.copy()
            at[members] += shift
            moved_at, moved_half, slots = at[members], half[members], self.slot[members]
            edges, middles = edges.copy(), middles.copy()
            edges[slots] = moved_at - moved_half
            edges[slots + self.count] = moved_at + moved_half
            middles[slots] = moved_at
        mine_at, mine_half = at[rows], half[rows]
        mine = np.concatenate([mine_at - mine_half, mine_at + mine_half])
        on_edge = np.abs(mine[:, None] - edges) <= ON_LINE_MM
        on_edge &= other_edge
        on_middle = np.abs(mine_at[:, None] - middles) <= ON_LINE_MM
        on_middle &= other_middle
        width = len(rows)
        on = on_edge @ trues(len(edges))
        row_held = on[:width] | on[width:] | on_middle @ trues(len(middles))
        if not self.grouped:  # every group one row, in the order of groups
            return row_held
        return np.bincount(owner, row_held, len(groups)) > 0

