"""The exact step of the alignment guides: after the no-overlap pass, put near-aligned features
exactly on one line, one checked move at a time.

The guide force (physics.guides) brings features close; contacts and rounding leave them a
fraction of a millimetre apart, and an edge that misses another by 1 mm looks worse than one
that misses it by 20.  So once the page has settled and the no-overlap pass has run, each free
item (with the items that follow it, as one rigid group) in turn tries, on each axis, the moves
that would put one of its features exactly on a guide line within two snap ranges
(``ALIGN_REACH``: another item's edge or centre, a margin line, or for a bleed item the page's
edge, the page's middle), and the moves that would open a near miss it cannot close to just
beyond what the eye reads as one (``ESCAPE_MM``).  Two ranges, not one: a pair such a move
opened lies just beyond one range, and a column of two photos of one width stayed 4.05 mm
apart for good, though the later move that lines them up fit (the photo album's sample).  It may also move as its *line*, with every group lined up with it on
that axis (a column of pictures reaches a band's edge only as a column).  It takes the move
that leaves it the fewest near misses with the rest of the page (each exact alignment
counting as half a miss less), the smallest such move first, and only if the move

- keeps every pair at least the gutter apart (or, where the pass could not reach the gutter,
  no closer than it left them): never an overlap, never a narrower gap;
- keeps the item inside the page and its print-safe margin (bleed items: inside the page);
- leaves the page at rest (physics.rest_check): no item it touches pushed harder than a cold
  page's run would leave in place.  Without this a snapped page drifts millimetres in the next
  gentle run and a settled file stops being a fixed point.  Nudges of at most ``NUDGE_MM`` are
  exempt: they change the forces too little to matter.

Every move taken lowers the page's count of near misses less half its alignments, so the
sweeps end; a page where no move helps is left exactly as it is, which keeps a settled file a
fixed point (model.layout.settle_page).  Held items and hard anchors never move: they are
guides for the others.  On a page too full for the gutter (Engine.finalize), alignment gives
way first and the step does not run.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from floatpage.physics.alignment import NEAR_MM
from floatpage.physics.bodies import Bodies
from floatpage.physics.deferred_rest import DeferredRest
from floatpage.physics.params import Params, page_margin, page_scale
from floatpage.physics.rest_check import RestCheck, group_members
from floatpage.physics.save_grid import STEPS_PER_MM, fitting_grid_shifts, on_save_grid
from floatpage.physics.snap_fit_kernel import fitting_shifts
from floatpage.physics.snap_setup_kernel import fill_feature_table, grid_shifts
from floatpage.physics.snap_scoring_kernel import line_of as find_line, score_moves
from floatpage.physics.snap_sweep_kernel import Sweep
from floatpage.physics.snap_memo import AxisMemo
from floatpage.physics.snap_scoring import (
    ALIGNED_MM, MAX_CANDIDATES, MAX_TRIES, NO_SHIFTS, relevant_distance, scoring_ranges, trues,
)
from floatpage.physics.fast_forces import target_gap
from floatpage.physics.finalize import ROUNDING_MM
from floatpage.physics.geometry import item_bounds
from floatpage.physics.guides import (
    CENTRE, HIGH, LOW, features, hold_strength, page_lines, snap_range,
)

NUDGE_MM = 0.5  # moves this small need no rest check: pairs this close count as aligned anyway
MAX_SWEEPS = 50
ALIGN_REACH = 2.0  # a move onto a line goes up to 2 snap ranges (8 mm on A4): see _Snapper
ESCAPE_REACH = 3.0  # a move out of near misses goes up to 3 snap ranges (12 mm on A4)
EVERY_MOVE = 1 << 30  # ... but once the sweeps end, every move (_Snapper.try_lesser)
TOLERANCE_MM = 1e-9
# a body's features paired with the lines of the same kind: their edges with each of its
# edges, their centre with its centre
THEIRS = np.array([LOW, HIGH, LOW, HIGH, CENTRE])
MINE = np.array([LOW, LOW, HIGH, HIGH, CENTRE])
# the columns of _Snapper's table per axis (feature_table): a row's features, them paired as
# THEIRS and as MINE, its low and high edge (an inactive row's out of every range)
FEATURES, THEIRS_COLUMNS, MINE_COLUMNS = slice(0, 3), slice(3, 8), slice(8, 13)
LOWS_COLUMN, HIGHS_COLUMN = 13, 14


def snap_page(bodies: Bodies, page_w_mm: float, page_h_mm: float, params: Params) -> int:
    """The snapping step of ``Engine.finalize``, after the no-overlap pass: the fast mode's
    guides (the paper mode stays the published model, without them).  Returns the moves made."""
    if params.mode != "fast" or params.guides <= 0:
        return 0
    clearance, margin, rest = snap_limits(bodies, page_w_mm, page_h_mm, params, deferred=True)
    return snap_to_guides(bodies, page_w_mm, page_h_mm, clearance, margin, params.guides, rest)


def snap_limits(bodies: Bodies, page_w_mm: float, page_h_mm: float, params: Params,
                deferred: bool = False) -> tuple[float, float, RestCheck | DeferredRest]:
    """What bounds the page's snap besides its bodies: the clearance every pair keeps (the
    gutter plus the rounding slack), the print-safe margin and the rest check (``deferred``:
    built when a move first asks, physics.deferred_rest; most probes' snaps never do)."""
    margin = page_margin(params.margin_mm, page_w_mm, page_h_mm)
    page = (page_w_mm, page_h_mm)

    def rest_check(pair_centres: np.ndarray | None = None) -> RestCheck:
        gap = target_gap(bodies.sizes[bodies.active], page_w_mm, page_h_mm, params.gutter_mm)
        return RestCheck(bodies, page, gap, bodies.insets(margin, *page), params.beta,
                         snap_range(*page), page_scale(*page), hold_strength(page, params.guides),
                         [page_lines(*page, margin, axis, bodies.regions) for axis in (0, 1)],
                         pair_centres)
    rest = DeferredRest(rest_check, bodies.centres) if deferred else rest_check()
    return params.gutter_mm + ROUNDING_MM, margin, rest


def snap_to_guides(bodies: Bodies, page_w_mm: float, page_h_mm: float, clearance_mm: float,
                   margin_mm: float, strength: float, rest: RestCheck | DeferredRest | None = None,
                   compiled: bool = True) -> int:
    """Snap free items onto their guide lines in place (see the module doc); returns the number
    of moves made.  ``clearance_mm`` is the gap every pair must keep (the gutter plus the
    rounding slack), ``margin_mm`` the page's print-safe margin; strength 0 does nothing.
    ``rest`` is asked before every move beyond a nudge (None: no move is checked).

    The first sweep tries every free item on both axes; a later one only the items with a
    feature near one that moved on that axis (nothing else can have a better move now).

    A sweep tries each body's ``MAX_TRIES`` best moves (by the count they leave): on a crowded
    page a body has dozens that would help, and trying each costs a clearance test and a rest
    check.  Once the sweeps end, each body whose best moves were that many tries the lesser
    ones too (``try_lesser``), and if one moves the sweeps go on from there: when a body's
    best moves are all blocked, a lesser one (a nudge of 0.16 mm that closes a slip, say) often
    is not.  Without this the snap stopped where a move that lowers the count still passed
    every check (benchmarks/near_miss_causes.py, "would move": 11 near-miss pairs of the
    60-item page).

    The snap ends only after a sweep of every mover (and the lesser moves) makes no move: a
    later sweep tries only the movers near a move on its axis, but whether a move fits and
    keeps the page at rest also turns on moves elsewhere (a neighbour that moved across the
    axis, a pushed group's other neighbours), and a move refused early and never tried again
    was made by the next probe's snap (4-17 mm on guide_cost.py's fresh seeds 2003, 2008 and
    2018), so the settle needed one more probe.  A snap of its own result now makes no move
    (tests/physics/test_snap_fixed_point.py)."""
    if strength <= 0:
        return 0
    snapper = _Snapper(bodies, (page_w_mm, page_h_mm), clearance_mm, margin_mm, rest)
    snapper.onto_grid()
    if compiled:  # the sweeps and the memo in C (snap_sweep_kernel): the same moves
        sweep = snapper.compiled()
        improve, try_lesser = sweep.improve, sweep.try_lesser

        def near(moved: list[int], axis: int) -> list[int]:
            return sweep.near(moved, axis, snapper.window)
    else:  # _Snapper's own Python, the definition the compiled sweeps are held to
        def improve(rows: list[int], axis: int) -> list[int]:
            return [root for row in rows for root in snapper.improve(row, axis)]

        def try_lesser(rows: list[int], axis: int) -> list[int]:
            return [root for row in rows for root in snapper.try_lesser(row, axis)]

        def near(moved: list[int], axis: int) -> list[int]:
            return snapper.near(moved, axis).tolist()
    moves = 0
    movers = snapper.movers.tolist()
    todo = [movers, movers]
    for _ in range(MAX_SWEEPS):
        moved_any, every_mover = False, todo[0] is movers and todo[1] is movers
        for axis in (0, 1):
            moved = improve(todo[axis], axis)
            todo[axis] = near(moved, axis)
            moves += len(moved)
            moved_any = moved_any or bool(moved)
        if not moved_any:
            lesser = [try_lesser(movers, axis) for axis in (0, 1)]
            if not lesser[0] and not lesser[1]:
                if every_mover:
                    break
                todo = [movers, movers]  # once more, every mover: see the doc
                continue
            todo = [near(lesser[axis], axis) for axis in (0, 1)]
            moves += len(lesser[0]) + len(lesser[1])
    return moves


class _Snapper:
    """One page's snapping, what every move's test needs computed once.  A mover is a free
    item with the items that follow it (a rigid group, moved as one); ``lines[axis]`` holds
    every row's low edge, centre and high edge on that axis, updated as rows move."""

    def __init__(self, bodies: Bodies, page: tuple[float, float], clearance_mm: float,
                 margin_mm: float, rest: RestCheck | DeferredRest | None):
        self.bodies, self.clearance, self.rest, self.page = bodies, clearance_mm, rest, page
        self.halves = bodies.sizes / 2
        self.active = bodies.active.copy()
        self.roots, _ = bodies.group_roots()
        self.roots_int = self.roots.astype(np.int64, copy=False)
        movable = bodies.free & self.active
        if bodies.held.any():  # most pages hold nothing: no sort, no search (a set-up's 4 %)
            held_groups = np.unique(self.roots[bodies.held])
            movable &= ~np.isin(np.arange(bodies.count), held_groups)
        self.movers = np.flatnonzero(movable)
        groups = group_members(self.roots, self.active)
        self.members = {int(row): groups[row] for row in self.movers}
        self.reach = snap_range(*page)
        self.farthest = ESCAPE_REACH * self.reach  # the longest move
        self.window = max(self.farthest, NEAR_MM) + NEAR_MM  # further apart cannot matter
        # what the scoring reads besides the table (the ranges of distances, the window):
        # what options reads of the distances lies within relevant_distance
        self.ranges = scoring_ranges(ALIGN_REACH * self.reach, self.farthest, self.window,
                                     relevant_distance(self.farthest), STEPS_PER_MM)
        self.lowest, self.highest = item_bounds(bodies, *page, margin_mm)
        keep_near_anchors(bodies, self.lowest, self.highest, ALIGN_REACH * self.reach)
        # what fits reads besides the page: the clearance, the longest move, the tolerance
        self.fit_limits = np.array([clearance_mm, self.farthest, TOLERANCE_MM])
        # per group and axis: too large to fit between its margins (it has no move to make);
        # a group's flags are any of its active rows' (one scatter, not a loop per group:
        # a third of a 50-item page's set-up)
        if len(groups.several) == 0:  # every group one row: its own flags, if active
            too_large = (self.lowest > self.highest) & self.active[:, None]
            bleeding = bodies.bleed & self.active
        else:
            grouped = self.roots[self.active]
            too_large = np.zeros((bodies.count, 2), dtype=bool)
            np.logical_or.at(too_large, grouped, (self.lowest > self.highest)[self.active])
            bleeding = np.zeros(bodies.count, dtype=bool)
            np.logical_or.at(bleeding, grouped, bodies.bleed[self.active])
        is_mover = np.zeros(bodies.count, dtype=bool)
        is_mover[self.movers] = True
        self.mover_mask = is_mover  # per row: whether it is a mover's root (line_of)
        # what compiled hands the sweeps: the movers' flags as bytes, one (two) per row
        self.flag_bytes = ((too_large & is_mover[:, None]).tobytes(),
                           (bleeding & is_mover).tobytes())
        movers, too_large, bleeding = self.movers.tolist(), too_large.tolist(), bleeding.tolist()
        self.too_large = {row: too_large[row] for row in movers}
        # The page's own lines per axis: the margin lines for items that keep the margin,
        # the page's edges for bleed groups (they may reach the edge), and the middle.
        self.bleeds = {row: bleeding[row] for row in movers}
        # the same as sets, for a line's groups (options)
        self.too_large_roots = [{row for row, large in self.too_large.items() if large[axis]}
                                for axis in (0, 1)]
        self.bleed_roots = {row for row, bleeds in self.bleeds.items() if bleeds}
        kinds = sorted(set(self.bleeds.values())) or [False]
        lines = {kind: [page_lines(*page, 0.0 if kind else margin_mm, axis, bodies.regions)
                        for axis in (0, 1)] for kind in kinds}
        # Per axis, one table holds every row's features and what options, line_of, near and
        # neighbours read of them (COLUMNS), so that a move updates it in one operation; below
        # the rows, the page's own lines as rows of their own (page_rows), always near, so that
        # a body's distances to its neighbours' lines and to the page's are one gather.  One
        # table per kind of page lines a mover needs ([bleed]), all kept in step.
        tables = {bleed: [filled_table(bodies.centres, self.halves, self.active, axis,
                                       *lines[bleed][axis]) for axis in (0, 1)]
                  for bleed in kinds}
        self.tables = tables  # [bleed][axis]: (rows + page lines, COLUMNS)
        kept = self.item_tables = tuple(tables[kinds[0]])  # [axis]: what reads the rows alone
        count = bodies.count
        self.lines = [table[:count, FEATURES] for table in kept]
        self.lows = [table[:count, LOWS_COLUMN] for table in kept]
        self.highs = [table[:count, HIGHS_COLUMN] for table in kept]
        # per group moved: its features (mine) before its last move, as floats (near)
        self.moved_from: dict[int, list[float]] = {}
        # Lines (roots, axis) whose move as one failed since the last move on the page: each of
        # their groups would try the same move of the same line again, to the same end.
        self.stuck_lines: set[tuple[tuple[int, ...], int]] = set()
        self.memo = AxisMemo()  # the lines and scores read off one axis, until a move there
        self.tries = MAX_TRIES  # moves a body tries per axis (options), but see try_lesser

    def onto_grid(self) -> None:
        """onto_grid_numpy's moves, their shifts worked out by compiled code
        (snap_setup_kernel.grid_shifts, tests/physics/test_save_grid.py: the same floats): as
        some forty NumPy calls an axis on arrays of a few dozen rows, it was a third of a
        5-item page's snap."""
        movers = self.movers
        if not len(movers):
            return
        centres = self.bodies.centres
        found = np.frombuffer(grid_shifts(
            centres, self.halves, self.active, self.roots_int, self.mover_mask, self.lowest,
            self.highest, self.page, self.clearance, TOLERANCE_MM, float(STEPS_PER_MM)),
            dtype=np.float64).reshape(-1, 2, 2)
        for axis in (0, 1):
            for made in (0, 1):
                shifts = found[:, axis, made]
                moved = np.flatnonzero(shifts)
                if not len(moved):
                    continue
                centres[moved, axis] += shifts[moved]
                for tables in self.tables.values():
                    tables[axis][moved] += shifts[moved, None]
                if self.rest is not None:
                    self.rest.moved(moved, (axis,))

    def onto_grid_numpy(self) -> None:
        """Put each mover on the grid a save writes (physics.save_grid) before the first move,
        its followers shifted with it, where that shift fits (save_grid.fitting_grid_shifts:
        ``fits``' test for every group at once: no pair closer than the clearance or than it
        was, every member inside its margins); the moves, whole steps of the grid, keep it
        there.  A group the shift to the nearest step does not fit for (pressed against a
        neighbour at the clearance) goes to the step on its other side, if that fits, and
        otherwise stays where it is (on a jammed page, rounding must not narrow a gap).  Left
        off the grid, such a group was rounded by the save all the same: on guide_cost.py's
        fresh seeds 2003 and 2018 the next probe's snap then moved an item 4-6 mm.  Held items and hard anchors are no movers: they
        stay exactly where they are.  (Tested group by group through ``fits``, half a
        millisecond on the 50-item page, a third of a small page's snap.)"""
        movers = self.movers
        if not len(movers):
            return
        centres, count = self.bodies.centres, self.bodies.count
        rows = np.flatnonzero(self.active)
        is_mover = self.mover_mask
        for axis in (0, 1):
            here = centres[movers, axis]
            wanted = on_save_grid(here, self.halves[movers, axis], self.page[axis]) - here
            wanted[np.abs(wanted) <= TOLERANCE_MM] = 0.0  # on the grid but for a float
            if not wanted.any():
                continue
            per_root = np.zeros(count)
            per_root[movers] = wanted
            shifts = np.where(is_mover[self.roots] & self.active, per_root[self.roots], 0.0)
            for _ in range(2):  # the nearest step; where it does not fit, the other one
                kept = fitting_grid_shifts(centres, self.halves, rows, self.roots, shifts,
                                           axis, self.lowest, self.highest, self.clearance,
                                           TOLERANCE_MM)
                moved = np.flatnonzero(kept)
                if len(moved):
                    centres[moved, axis] += kept[moved]
                    for tables in self.tables.values():
                        tables[axis][moved] += kept[moved, None]
                    if self.rest is not None:
                        self.rest.moved(moved, (axis,))
                shifts = np.where(kept == 0.0, shifts - np.sign(shifts) / STEPS_PER_MM, 0.0)
                shifts[np.abs(shifts) <= TOLERANCE_MM] = 0.0
                if not shifts.any():
                    break

    def mine(self, row: int, axis: int) -> np.ndarray:
        """The group's features on ``axis`` (low edge, centre, high edge per member)."""
        return self.lines[axis][self.members[row]].ravel()

    def near(self, moved: list[int], axis: int) -> np.ndarray:
        """Movers with a feature within the window of a moved group's features, before or
        after its move, on ``axis``."""
        if not moved:
            return np.zeros(0, dtype=int)
        lines = self.lines[axis]
        spots = [spot for row in moved
                 for spot in (self.moved_from[row], self.mine(row, axis).tolist())]
        lows = np.array([min(spot) - self.window for spot in spots])
        highs = np.array([max(spot) + self.window for spot in spots])
        # every spot at once (a row is touched if it reaches into any): (n, spots) @ Trues
        touched = ((lines[:, LOW, None] < highs) & (lines[:, HIGH, None] > lows)) @ trues(
            len(spots))
        touched = touched[self.roots] | touched  # and the groups of those rows
        return self.movers[touched[self.movers]]

    def improve(self, row: int, axis: int) -> list[int]:
        """Make the best allowed move along ``axis`` of ``row``'s group, or of its *line*: the
        group and every group lined up with it on this axis, moved as one, whichever gains
        more.  A column of pictures whose left edges line up, 3 mm off the band below them,
        reaches the band only as a column: one picture alone would leave the others, a near
        miss for a near miss, or step out of them all and break the column.  Returns the
        groups moved (their roots), none if nothing moved."""
        alone = self.options([row], axis)
        choices = [alone]
        # a group on no near miss gains nothing from its line's move, and one on no line
        # has none (line_of would find it alone)
        if alone.missing and alone.lined_up:
            line = self.line_of(row, axis)
            line_key = (tuple(sorted(line)), axis)
            if len(line) > 1 and line_key not in self.stuck_lines:
                together = self.options(line, axis)
                if together.gain > alone.gain:
                    choices = [together, alone]
                else:
                    choices.append(together)
        for choice in choices:
            if self.attempt(choice, axis):
                self.stuck_lines.clear()
                return choice.roots
            if len(choice.roots) > 1:
                self.stuck_lines.add(line_key)
        return []

    def try_lesser(self, row: int, axis: int) -> list[int]:
        """Once the sweeps have ended: make the best allowed move along ``axis`` of ``row``'s
        group among those beyond its ``MAX_TRIES`` best, which the sweeps tried and found
        blocked (nothing near it has moved since).  A group with fewer moves that help has
        tried them all; the others are scored again without the cut (and without the memo,
        which keeps the cut lists).  Returns the groups moved, as ``improve`` does."""
        if len(self.options([row], axis).shifts) < MAX_TRIES:
            return []
        kept, self.memo, self.tries = self.memo, AxisMemo(), EVERY_MOVE
        try:
            every = self.options([row], axis)
        finally:
            self.memo, self.tries = kept, MAX_TRIES
        if self.attempt(every._replace(shifts=every.shifts[MAX_TRIES:]), axis):
            self.stuck_lines.clear()
            return every.roots
        return []

    def line_of(self, row: int, axis: int) -> list[int]:
        """``row`` and the movers with a feature on one of its group's lines on ``axis`` (an
        edge on an edge, a centre on a centre), in row order after ``row``."""
        known = self.memo.recall(("line", row), axis)
        if known is not None:
            return known
        # compiled (physics/snap_scoring_kernel.c): any pairing of a member's features with another
        # row's within ALIGNED_MM, read from the kind of table whose first rows every kind
        # shares (an inactive row's lines are +inf: on none)
        line, low, high = find_line(self.item_tables[axis], self.members[row], row,
                                    self.bodies.count, self.roots, self.mover_mask, ALIGNED_MM)
        return self.memo.keep(("line", row), axis, low, high, line)

    def options(self, roots: list[int], axis: int) -> "Moves":
        """The moves along ``axis`` that would lower the near misses of the groups of
        ``roots``, moved as one rigid body, best first (at most ``tries``).

        Everything is read off the sorted distances from the body's features to the lines of
        the same kind near them, by bisection: which moves to score, their scores, whether the
        body misses a line now.  Most calls (on the 50-item page, three in five) find no move
        that helps; as a few dozen small NumPy operations a call was a quarter of the snap's
        time, scoring lines another quarter, so the scoring after the memo is one call of
        compiled code (snap_scoring_kernel.score_moves; its distances read from the table of the
        body's kind of page lines, whose rows are the same floats in every kind's table)."""
        if len(roots) == 1:  # most calls: one group, nothing to gather
            root = roots[0]
            members, key, bleed = self.members[root], (root,), self.bleeds[root]
            if self.too_large[root][axis]:
                return Moves(roots, members, NO_SHIFTS, 0.0, False, False)
            known = self.memo.recall(key, axis)
            if known is not None:
                return known
        else:  # a line: its rows gathered only if it is scored or named in another order
            key = tuple(sorted(roots))
            if not self.too_large_roots[axis].isdisjoint(roots):
                return Moves(roots, np.concatenate([self.members[root] for root in roots]),
                             NO_SHIFTS, 0.0, False, False)
            known = self.memo.recall(key, axis)
            if known is not None and known.roots == roots:
                return known
            members = np.concatenate([self.members[root] for root in roots])
            if known is not None:  # the same groups named in another order
                return known._replace(roots=roots, members=members)
            bleed = self.bleed_roots.issuperset(roots)
        # the compiled scoring (physics/snap_scoring_kernel.c): the lines near the body, the sorted
        # distances to them, the candidates, their scores, the best first
        shifts, gain, missing, lined_up, low, high = score_moves(
            self.tables[bleed][axis], members, self.ranges, MAX_CANDIDATES, self.tries)
        found = Moves(roots, members, shifts, gain, missing, lined_up)
        return self.memo.keep(key, axis, low, high, found)

    def attempt(self, moves: "Moves", axis: int) -> bool:
        """Make the first of ``moves`` that fits and keeps the page at rest; whether one did."""
        if len(moves.shifts) == 0:
            return False  # most calls: no move would help
        members = moves.members
        for shift in self.fits(members, axis, moves.shifts):
            if abs(shift) <= NUDGE_MM or self.rest is None \
                    or self.rest.keeps_rest(members, axis, shift):
                before = self.lines[axis][members]
                self.apply(moves.roots, members, axis, shift)
                self.memo.moved(axis, before, self.lines[axis][members])
                return True
        return False

    def apply(self, roots: list[int], members: np.ndarray, axis: int, shift: float) -> None:
        """Move the rigid body ``members`` (the groups of ``roots``) by ``shift`` along
        ``axis``: where each group was (near), the centres, every table, the rest check's
        forces kept for the page as it was.  (The memo is the caller's: attempt's, or the
        compiled sweep's own.)"""
        for root in roots:
            self.moved_from[root] = self.mine(root, axis).tolist()
        self.bodies.centres[members, axis] += shift
        for tables in self.tables.values():
            tables[axis][members] += shift
        if self.rest is not None:
            self.rest.moved(members, (axis,))

    def compiled(self) -> Sweep:
        """This page's sweeps in C (snap_sweep_kernel.Sweep), reading what this snapper
        worked out and making its moves as apply does (moved_from, the centres and every
        table, the rest check's kept forces forgotten).  The rest check's parts are read when
        the first move asks for them (a deferred check is built then)."""
        count = self.bodies.count
        members = [self.members.get(row) for row in range(count)]
        too_large, bleeds = self.flag_bytes  # per row and axis, per row: a mover's flags
        return Sweep(count, members, too_large, bleeds, self.kind_tables(False),
                     self.kind_tables(True), self.item_tables, self.roots, self.mover_mask,
                     self.ranges, ALIGNED_MM,
                     self.rest.compiled_parts if self.rest is not None else None,
                     (self.moved_from, self.bodies.centres, self.rest.before
                      if self.rest is not None else {}),
                     np.concatenate, (self.bodies.centres, self.halves, self.lowest,
                                      self.highest, self.item_tables, self.fit_limits),
                     MAX_CANDIDATES, MAX_TRIES, EVERY_MOVE, NUDGE_MM)

    def kind_tables(self, bleed: bool) -> tuple[np.ndarray, np.ndarray] | None:
        found = self.tables.get(bleed)
        return None if found is None else tuple(found)

    def fits(self, members: np.ndarray, axis: int, shifts: tuple[float, ...]) -> list[float]:
        """The ``shifts`` (in their order) by which the rigid body ``members`` may move along
        ``axis`` as far as the page and its neighbours go: every member inside its margins (or
        no further out than it is), and no pair closer than the clearance (or than it is now).
        The rest check comes after.

        Only the items a move could bring within the clearance are tested: within it of a
        member across the axis, and within it and the longest move along it (on a 600-item
        page the test against every item was two thirds of the snapping's time).  Compiled
        (snap_fit_kernel.fitting_shifts): a body meets a handful of neighbours and tries at most
        ``MAX_TRIES`` moves, and as Python floats (one item) or NumPy tables (a line) the
        calls cost more than the arithmetic, a tenth of the snap."""
        return fitting_shifts(members, axis, shifts, self.bodies.centres, self.halves,
                              self.lowest, self.highest, self.item_tables, self.fit_limits)


def keep_near_anchors(bodies: Bodies, lowest: np.ndarray, highest: np.ndarray,
                      reach: float) -> None:
    """Narrow the centre bounds ``lowest`` and ``highest`` (n, 2) of each item on a spring
    anchor, in place, so that the snap never takes it further from its anchor than ``reach``
    (the snap's own reach onto a line) or than the physics left it, whichever is more: an
    anchor is where the user put the item, and the snap's reach counts from there.  A text
    moved 6 mm off the greeting card's centre line with the arrows, and anchored there, sat
    3 mm off its anchor once the walls had pushed against its spring, and the snap then put
    it back on the centre line, 6 mm from where it was put (user-walk-13).
    Within that reach of its anchor it still lines up; hard anchors and held items never
    move at all."""
    anchored = np.flatnonzero(~np.isnan(bodies.anchors[:, 0]) & ~bodies.hard & bodies.active)
    if not len(anchored):
        return
    centres, anchors = bodies.centres[anchored], bodies.anchors[anchored]
    room = np.maximum(np.abs(centres - anchors), reach)
    low = np.maximum(lowest[anchored], np.minimum(centres, anchors - room))
    high = np.minimum(highest[anchored], np.maximum(centres, anchors + room))
    narrowed = low <= high  # where the walls and the anchor's room meet (else the walls')
    lowest[anchored] = np.where(narrowed, low, lowest[anchored])
    highest[anchored] = np.where(narrowed, high, highest[anchored])


class Moves(NamedTuple):
    """The candidate moves of one rigid body of groups along one axis (_Snapper.options)."""

    roots: list[int]  # the groups moved together
    members: np.ndarray  # their rows
    shifts: tuple[float, ...]  # the moves that lower their near misses, best first
    gain: float  # what the best of them would lower the page's score by
    missing: bool  # whether they miss a line now
    lined_up: bool  # whether they are on a line now (within ALIGNED_MM)


def feature_table(centres: np.ndarray, halves: np.ndarray, active: np.ndarray, axis: int,
                  edges: np.ndarray, middles: np.ndarray) -> np.ndarray:
    """The snap's table of one axis (FEATURES, THEIRS_COLUMNS, MINE_COLUMNS, LOWS_COLUMN,
    HIGHS_COLUMN), one row per item (an inactive one's lines at +inf, its edges out of every
    range), then one per page line: an edge line paired with a
    body's low and high edges, a middle with its centre, +inf where a pairing does not exist
    (a distance no range holds) and always near (its low -inf, its high +inf).  A body's
    distances to the page's lines are then those to rows of the table, the same subtractions
    in the same floats as to each line."""
    lines = features(centres, halves, axis)
    count = len(lines)
    # one array filled column block by column block (the same floats as stacking them)
    table = np.empty((count + len(edges) + len(middles), HIGHS_COLUMN + 1))
    rows, page = table[:count], table[count:]
    rows[:, FEATURES] = lines
    rows[:, THEIRS_COLUMNS] = lines[:, THEIRS]
    rows[:, MINE_COLUMNS] = lines[:, MINE]
    rows[:, LOWS_COLUMN], rows[:, HIGHS_COLUMN] = lines[:, LOW], lines[:, HIGH]
    if not active.all():
        inactive = ~active
        rows[inactive, THEIRS_COLUMNS] = np.inf
        rows[inactive, LOWS_COLUMN], rows[inactive, HIGHS_COLUMN] = np.inf, -np.inf
    page[:] = np.nan
    theirs = page[:, THEIRS_COLUMNS]
    theirs[:] = np.inf
    for column in np.flatnonzero(THEIRS == LOW):  # their low edge: paired with my low, high
        theirs[:len(edges), column] = edges
    theirs[len(edges):, THEIRS == CENTRE] = middles[:, None]
    page[:, LOWS_COLUMN], page[:, HIGHS_COLUMN] = -np.inf, np.inf
    return table


def filled_table(centres: np.ndarray, halves: np.ndarray, active: np.ndarray, axis: int,
                 edges: np.ndarray, middles: np.ndarray) -> np.ndarray:
    """feature_table's table, filled by compiled code (snap_setup_kernel.fill_feature_table):
    the same floats, one call instead of a score of NumPy ones (a tenth of a small page's
    snap, made twice a snap and twice a settle)."""
    table = np.empty((len(centres) + len(edges) + len(middles), HIGHS_COLUMN + 1))
    fill_feature_table(table, centres, halves, active, axis, edges, middles)
    return table
