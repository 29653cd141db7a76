"""Which groups a guide line holds, for the snap's rest check (physics.rest_check).

A group is held on an axis when one of its edges lies within ``ON_LINE_MM`` of another group's
edge or of the page's edge lines, or its centre within it of another group's centre or of the
page's middle (physics.guides).  The rest check asks this of every group a trial move pushes
too hard, for the page as it is and with the move made.  In NumPy each check gathered every
active row's lines, joined them to the page's and compared every row's root with every line's
owner, and then kept the lines up to date move by move to save the gather; compiled
(rest_check_kernel.held_on_lines) every line is worked out afresh from the centres, the same
subtraction or addition of the same floats as before, for less than the kept arrays' upkeep.
Every answer is the same, bit for bit (benchmarks/snap_identity.py checks the snap's moves on
main's inputs).
"""

from __future__ import annotations

import numpy as np

from floatpage.physics.guides import ON_LINE_MM
from floatpage.physics.rest_check_kernel import held_on_lines

NO_ROWS = np.zeros(0, dtype=np.int64)


class LineHold:
    """One page's guide lines per axis, for a snap: the active rows' edges and centres (from
    ``centres``, which the snap moves in place) and the page's own lines."""

    def __init__(self, centres: np.ndarray, halves: np.ndarray, active_rows: np.ndarray,
                 roots: np.ndarray, group_rows: list[np.ndarray],
                 page_lines: list[tuple[np.ndarray, np.ndarray]]):
        self.centres, self.halves, self.roots = centres, halves, roots.astype(np.int64)
        self.active_rows = active_rows.astype(np.int64)
        self.group_rows, self.page_lines = group_rows, page_lines
        self.owners: dict[bytes, tuple[np.ndarray, np.ndarray]] = {}

    def others(self, groups: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """For ``groups``: their rows and each row's group (its index in ``groups``), kept per
        set of groups."""
        key = groups.tobytes()
        found = self.owners.get(key)
        if found is None:
            sizes = [len(self.group_rows[g]) for g in groups]
            rows = np.concatenate([self.group_rows[g] for g in groups]).astype(np.int64)
            owner = np.repeat(np.arange(len(groups), dtype=np.int64), sizes)
            found = self.owners[key] = (rows, owner)
        return found

    def held(self, groups: np.ndarray, axis: int, members: np.ndarray | None = None,
             shift: float = 0.0) -> np.ndarray:
        """(len(groups),): whether a line holds each group on ``axis``, with the page as it is,
        or with ``members`` moved by ``shift`` along it."""
        rows, owner = self.others(groups)
        edges, middles = self.page_lines[axis]
        return np.array(held_on_lines(
            rows, owner, len(groups), self.centres, self.halves, self.active_rows, self.roots,
            edges, middles, axis, NO_ROWS if members is None else members, shift, ON_LINE_MM),
            dtype=bool)
