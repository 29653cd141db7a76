"""The snap's cheaper units must make the very moves the plain ones made: the lines' hold
(physics.line_hold, compiled) against a plain search of every line, and the scoring that
drops the distances out of every range before its sort against the scoring of them all.
(benchmarks/snap_identity.py checks every move of 63 snaps against main's; these check the
units themselves on a few seeded pages.)"""

from __future__ import annotations

import math

import numpy as np

import floatpage.physics.snapping as snapping
from floatpage.physics import Engine, Params
from floatpage.physics.guides import ON_LINE_MM
from floatpage.physics.line_hold import LineHold
from floatpage.physics.rest_check import RestCheck
from floatpage.physics.snap_scoring import relevant_distance
from floatpage.physics.snapping import snap_limits, snap_to_guides

from seeded_scenes import load, mixed_scene

PAGES = ((120, 3001, (297.0, 210.0)), (30, 7, (210.0, 297.0)))


def settled(count: int, seed: int, page: tuple[float, float]) -> Engine:
    """A seeded page settled without the final pass: near misses for a snap to close."""
    engine = Engine(*page, Params())
    load(engine, mixed_scene(count, 0.4, seed=seed, page_w_mm=page[0], page_h_mm=page[1]))
    engine.settle(finalize=False)
    return engine


def plainly_held(hold: LineHold, page_lines, groups: list[int], axis: int,
                 centres: np.ndarray) -> list[bool]:
    """Whether a line holds each of ``groups`` on ``axis``, group by group from the centres:
    an edge within ON_LINE_MM of another group's edge or a page edge line, a centre of another
    group's centre or the page's middle."""
    active = hold.active_rows
    at, half, roots = centres[:, axis], hold.halves[:, axis], hold.roots
    edges = np.concatenate([at[active] - half[active], at[active] + half[active],
                            page_lines[axis][0]])
    edge_owners = np.concatenate([roots[active], roots[active],
                                  np.full(len(page_lines[axis][0]), -1)])
    middles = np.concatenate([at[active], page_lines[axis][1]])
    middle_owners = np.concatenate([roots[active], np.full(len(page_lines[axis][1]), -1)])
    found = []
    for group in groups:
        rows = active[roots[active] == group]
        mine = np.concatenate([at[rows] - half[rows], at[rows] + half[rows]])
        on_edge = (np.abs(mine[:, None] - edges) <= ON_LINE_MM) & (edge_owners != group)
        on_middle = (np.abs(at[rows][:, None] - middles) <= ON_LINE_MM) & (middle_owners != group)
        found.append(bool(on_edge.any() or on_middle.any()))
    return found


class CheckedHold(LineHold):
    """The lines' hold, each answer also found plainly from the centres (a trial move's: from
    a moved copy)."""

    def held(self, groups, axis, members=None, shift=0.0):
        found = super().held(groups, axis, members, shift)
        centres = self.centres.copy()
        if members is not None:
            centres[members, axis] += shift
        plain = plainly_held(self, self.page_lines, groups.tolist(), axis, centres)
        assert found.tolist() == plain, (groups, axis, members, shift)
        self.compared += len(plain)
        self.held_some += sum(plain)
        return found


class CheckedRest(RestCheck):
    """The snap's rest check, every group's hold on both axes compared after every move, as
    the page is and with the moved rows moved on by a trial shift."""

    def moved(self, rows, axes=(0, 1)):
        super().moved(rows, axes)
        lines = self.lines
        every = np.flatnonzero(lines.roots == np.arange(len(lines.roots)))
        every = np.intersect1d(every, lines.active_rows)
        for axis in (0, 1):
            lines.held(every, axis)
            lines.held(every, axis, rows, 0.02)


def test_the_lines_hold_what_a_plain_search_holds():
    """A roomy page's snap and a small one's, every hold the rest checks ask for and every
    group's after each move compared (hundreds of moves, each making its rows' lines stale)."""
    for count, seed, page in PAGES:
        engine = settled(count, seed, page)
        bodies, params = engine.bodies, engine.params
        clearance, margin, rest = snap_limits(bodies, *page, params)
        lines = rest.lines
        lines.__class__, lines.compared, lines.held_some = CheckedHold, 0, 0
        rest.__class__ = CheckedRest
        # the Python sweeps, which ask LineHold (the compiled ones ask held_on_lines directly
        # and are held to these move for move: test_snap_sweep.py)
        moves = snap_to_guides(bodies, *page, clearance, margin, params.guides, rest,
                               compiled=False)
        assert moves > 20 and lines.compared > 1000 and lines.held_some > 100, (
            count, moves, lines.compared, lines.held_some)


def test_scoring_the_relevant_distances_makes_the_moves_of_scoring_them_all(monkeypatch):
    """The same pages snapped with every finite distance sorted and with the far ones dropped
    first (snap_scoring.relevant_distance): the same moves, to the same floats."""
    snapped = []
    for relevant in (lambda farthest: math.inf, relevant_distance):
        monkeypatch.setattr(snapping, "relevant_distance", relevant)
        for count, seed, page in PAGES:
            engine = settled(count, seed, page)
            bodies, params = engine.bodies, engine.params
            clearance, margin, rest = snap_limits(bodies, *page, params)
            moves = snap_to_guides(bodies, *page, clearance, margin, params.guides, rest)
            snapped.append((moves, bodies.centres.tobytes()))
    half = len(snapped) // 2
    assert all(moves > 20 for moves, _ in snapped)
    assert snapped[:half] == snapped[half:]


def test_the_lines_hold_on_pages_with_followers():
    """Groups of several rows (captions and the like following an item) move as one and hold
    as one: the same check on anchored pages whose items follow others."""
    from anchored_pages import random_project
    from floatpage.model.layout import engine_for_page

    grouped = 0
    for seed in (27100, 27101, 27103):
        project = random_project(seed, "follow")
        engine = engine_for_page(project.pages[0], project.physics)
        engine.reheat()
        engine.settle(finalize=False)
        bodies, params = engine.bodies, engine.params
        page = (engine.page_w_mm, engine.page_h_mm)
        clearance, margin, rest = snap_limits(bodies, *page, params)
        lines = rest.lines
        lines.__class__, lines.compared, lines.held_some = CheckedHold, 0, 0
        rest.__class__ = CheckedRest
        moves = snap_to_guides(bodies, *page, clearance, margin, params.guides, rest,
                               compiled=False)  # the sweeps that ask LineHold, as above
        assert moves > 5 and lines.compared > 50, (seed, moves, lines.compared)
        grouped += bool((lines.roots != np.arange(len(lines.roots))).any())
    assert grouped == 3


def test_the_groups_flags_are_any_of_their_active_rows():
    """_Snapper's per-group flags (too large to fit between its margins, per axis; may bleed),
    set by one scatter over the active rows, against their definition, group by group: any of
    the group's active rows.  Pages with followers (groups of several rows), some rows made
    bleed, some too large for their margins on one axis, one follower made inactive."""
    from anchored_pages import random_project
    from floatpage.model.layout import engine_for_page
    from floatpage.physics.geometry import item_bounds
    from floatpage.physics.rest_check import group_members

    checked = 0
    for seed in (27100, 27101, 27102):
        project = random_project(seed, "follow")
        engine = engine_for_page(project.pages[0], project.physics)
        bodies = engine.bodies
        rng = np.random.default_rng(seed)
        bodies.bleed[:] = rng.random(bodies.count) < 0.3
        followers = np.flatnonzero(bodies.group_roots()[0] != np.arange(bodies.count))
        assert len(followers) > 0
        bodies.sizes[followers[0], 0] = engine.page_w_mm * 1.5  # too wide for its margins
        bodies.active[followers[-1]] = False
        page = (engine.page_w_mm, engine.page_h_mm)
        clearance, margin, rest = snap_limits(bodies, *page, engine.params)
        snapper = snapping._Snapper(bodies, page, clearance, margin, rest)
        lowest, highest = item_bounds(bodies, *page, margin)
        groups = group_members(snapper.roots, snapper.active)
        for row in snapper.movers.tolist():
            members = groups[row].tolist()
            assert snapper.too_large[row] == [any(lowest[m, axis] > highest[m, axis]
                                                  for m in members) for axis in (0, 1)]
            assert snapper.bleeds[row] == any(bool(bodies.bleed[m]) for m in members)
            checked += 1
        assert any(large[0] for large in snapper.too_large.values())
        assert any(snapper.bleeds.values()) and not all(snapper.bleeds.values())
    assert checked > 20
