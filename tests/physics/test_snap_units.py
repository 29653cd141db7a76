"""The snap's cheaper units must make the very moves the plain ones made: the lines' hold kept
move by move (physics.line_hold) against a plain search of every line, and the scoring that
drops the distances out of every range before its sort against the scoring of them all.
(benchmarks/snap_identity.py checks every move of 63 snaps against main's; these check the
units themselves on a few seeded pages.)"""

from __future__ import annotations

import numpy as np

import floatpage.physics.snapping as snapping
from floatpage.physics import Engine, Params
from floatpage.physics.guides import ON_LINE_MM
from floatpage.physics.line_hold import LineHold
from floatpage.physics.snapping import snap_limits, snap_to_guides

from seeded_scenes import load, mixed_scene

PAGES = ((120, 3001, (297.0, 210.0)), (30, 7, (210.0, 297.0)))


def settled(count: int, seed: int, page: tuple[float, float]) -> Engine:
    """A seeded page settled without the final pass: near misses for a snap to close."""
    engine = Engine(*page, Params())
    load(engine, mixed_scene(count, 0.4, seed=seed, page_w_mm=page[0], page_h_mm=page[1]))
    engine.settle(finalize=False)
    return engine


def plainly_held(hold: LineHold, roots: np.ndarray, page_lines, group: int, axis: int,
                 centres: np.ndarray) -> bool:
    """Whether a line holds ``group`` on ``axis``, row by row and line by line in Python: an
    edge within ON_LINE_MM of another group's edge or a page edge line, a centre of another
    group's centre or the page's middle."""
    at, half = centres[:, axis].tolist(), hold.halves[:, axis].tolist()
    others = [row for row in np.flatnonzero(hold.slot >= 0).tolist() if roots[row] != group]
    edges = [at[row] - half[row] for row in others] + [at[row] + half[row] for row in others]
    edges += page_lines[axis][0].tolist()
    middles = [at[row] for row in others] + page_lines[axis][1].tolist()
    for row in hold.group_rows[group].tolist():
        mine = (at[row] - half[row], at[row] + half[row])
        if any(abs(edge - line) <= ON_LINE_MM for edge in mine for line in edges) or any(
                abs(at[row] - line) <= ON_LINE_MM for line in middles):
            return True
    return False


class CheckedHold(LineHold):
    """The kept lines, each answer also found plainly from the centres (moved ones: a copy)."""

    def held(self, groups, axis, members=None, shift=0.0):
        found = super().held(groups, axis, members, shift)
        centres = self.centres.copy()
        if members is not None:
            centres[members, axis] += shift
        plain = [plainly_held(self, self.roots, self.page_lines, group, axis, centres)
                 for group in groups.tolist()]
        assert found.tolist() == plain, (groups, axis, members, shift)
        self.compared += len(plain)
        self.held_some += sum(plain)
        return found


def test_the_kept_lines_hold_what_a_plain_search_holds():
    """A roomy page's snap and a small one's, every hold the rest checks ask for compared
    (hundreds of moves, each making its rows' lines stale)."""
    for count, seed, page in PAGES:
        engine = settled(count, seed, page)
        bodies, params = engine.bodies, engine.params
        clearance, margin, rest = snap_limits(bodies, *page, params)
        lines = rest.lines
        lines.__class__, lines.compared, lines.held_some = CheckedHold, 0, 0
        lines.page_lines = rest.page_lines
        moves = snap_to_guides(bodies, *page, clearance, margin, params.guides, rest)
        assert moves > 20 and lines.compared > 100 and lines.held_some > 20, (
            count, moves, lines.compared, lines.held_some)


def test_scoring_the_relevant_distances_makes_the_moves_of_scoring_them_all(monkeypatch):
    """The same pages snapped with every distance sorted and with the far ones always dropped
    first: the same moves, to the same floats."""
    snapped = []
    for sort_all_below in (1 << 30, 0):
        monkeypatch.setattr(snapping, "SORT_ALL_BELOW", sort_all_below)
        for count, seed, page in PAGES:
            engine = settled(count, seed, page)
            bodies, params = engine.bodies, engine.params
            clearance, margin, rest = snap_limits(bodies, *page, params)
            moves = snap_to_guides(bodies, *page, clearance, margin, params.guides, rest)
            snapped.append((moves, bodies.centres.tobytes()))
    half = len(snapped) // 2
    assert all(moves > 20 for moves, _ in snapped)
    assert snapped[:half] == snapped[half:]
