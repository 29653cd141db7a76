"""Whether a snap keeps the page at rest: the fast mode's forces on the items a move touches.

A settled page is at rest because every item's forces nearly cancel (a pressed network of
contacts, walls and anchor springs, stopped by friction).  A snap that slides an item 3 mm into
a neighbour's halo, or onto the margin line inside the wall's rest box, leaves forces that the
next gentle run turns into millimetres of drift, and the settled file would no longer be a
fixed point (model.layout.settle_page).  So the snapping step asks this check before each move:
after the move, the net acceleration of the moved item and of every item it touches must stay
within ``REST_ACC`` (or within what it already was).

The forces are the fast mode's own (fast_forces, force_terms) at the probe's heat: contact
pushes with what is left of their sliding share there, walls at the target gap, soft anchor
springs.  The guide pull is
left out: it is zero on a guide line.  A group with a feature on a guide line is *held* there
(physics.guides: a static friction of up to ``hold`` on that axis), so what must stay within
the limit is the push the hold leaves, before the move and after it alike.  (Comparing a held
push after the move with the bare push before it let a line of items be pressed harder move
by move: the hold's allowance was counted again at every move, and the page drifted
millimetres in the next probe.)  A move also takes its lines away from every group held on
them, wherever it lies: those groups (its line-mates) are asked too (``keeps_holds``).
"""

from __future__ import annotations

import math

import numpy as np

from floatpage.physics.bodies import Bodies
from floatpage.physics.fast_forces import GRID_FROM_ITEMS, RADIAL_SHARE, candidate_pairs
from floatpage.physics.force_terms import (
    BETA_DEFAULT, K_ANCHOR, K_CONTACT, K_WALL, RADIAL_FADE_HEAT,
)
from floatpage.physics.line_hold import LineHold
from floatpage.physics.guides import ON_LINE_MM
from floatpage.physics.rest_check_kernel import (
    held_on_lines, line_mates, reach_of, rest_net, unlisted_near,
)
from floatpage.physics.snap_setup_kernel import (
    inverse_masses, pair_tables, row_table, sweep_pairs,
)
from floatpage.physics.stillness import PROBE_HEAT

REST_ACC = 0.8  # mm per step^2 on A4: the probe's first step (heat 0.02, friction 0.4) moves
# such an item 0.0096 mm, below the stillness threshold of 0.01 mm a step
NO_ROWS = np.zeros(0, dtype=np.int64)  # RestCheck.net: the page as it is, nothing moved
PROBE_RADIAL = RADIAL_SHARE * min(1.0, PROBE_HEAT / RADIAL_FADE_HEAT)  # the pushes' sliding share


class RestCheck:
    """One page's forces, set up once for a snapping pass whose moves stay within ``reach``."""

    def __init__(self, bodies: Bodies, page: tuple[float, float], gap: float,
                 insets: tuple[np.ndarray, np.ndarray], beta: float, reach: float, scale: float,
                 hold: float = 0.0,
                 lines: list[tuple[np.ndarray, np.ndarray]] | None = None,
                 pair_centres: np.ndarray | None = None):
        """``pair_centres``: where the pairs are found, if not at the bodies' centres now (a
        check built after a snap's first nudges finds them where the snap started:
        physics.deferred_rest)."""
        self.made_with = (bodies, page, gap, insets, beta, reach, scale, hold, lines)
        self.bodies, self.page, self.gap = bodies, page, gap
        self.halves = bodies.sizes / 2
        active = bodies.active
        roots, _ = bodies.group_roots()
        self.roots = roots
        free = bodies.free
        # The masses, the pairs and the tables compiled (physics/snap_setup_kernel.c): the
        # inverse masses as np.bincount and np.where make them, the pairs as candidate_pairs
        # finds them by its sweep, their table as blocked_axes and the shares of a push, the
        # rows' as wall_rest_box and the anchor springs, in NumPy: the same floats
        # (tests/physics/test_snap_setup.py), for a tenth of a small page's fifty NumPy calls.
        # A page of GRID_FROM_ITEMS rows finds its pairs by the grid.
        inverse = np.frombuffer(inverse_masses(bodies.sizes, roots, active, free, bodies.held))
        at = bodies.centres if pair_centres is None else pair_centres
        if active.sum() < GRID_FROM_ITEMS:
            pair_ends = np.frombuffer(sweep_pairs(at, self.halves, active, roots,
                                                  gap + 2 * reach), dtype=np.int64).reshape(-1, 2)
        else:
            pair_ends = np.column_stack(candidate_pairs(at, self.halves, np.flatnonzero(active),
                                                        roots, gap + 2 * reach)).astype(np.int64)
        # where the pairs were found and how far beyond the gap (unlisted_near)
        self.found_at, self.pair_margin = at.copy(), 2 * reach
        i, j = pair_ends[:, 0], pair_ends[:, 1]
        table, self.pair_lists_of = pair_tables(pair_ends, bodies.sizes, self.halves, inverse,
                                                *insets, *page, gap)
        # per pair: its reach (half sizes summed plus the gap, as the contacts keep it), its
        # blocked axes (blocked_axes, no gutter), its ends' shares of a push
        self.pair_ends, self.pair_table = pair_ends, np.frombuffer(table).reshape(-1, 6)
        self.i, self.j = i, j
        self.reach, self.blocked = self.pair_table[:, 0:2], self.pair_table[:, 2:4] != 0
        self.share_i, self.share_j = self.pair_table[:, 4], self.pair_table[:, 5]
        # per row (the columns rest_net names): its rest box, the walls where Bodies.insets
        # stands them, at the gap (wall_rest_box); its soft anchor's spring and anchor
        self.row_table = np.frombuffer(row_table(
            self.halves, *insets, *page, gap, bodies.anchors, bodies.hard, bodies.gammas,
            K_ANCHOR * beta / BETA_DEFAULT)).reshape(-1, 7)
        self.rest_low, self.rest_high = self.row_table[:, 0:2], self.row_table[:, 2:4]
        self.anchor_k, self.anchors = self.row_table[:, 4], self.row_table[:, 5:7]
        self.movable = free & active  # roots of groups the integrator moves
        # what line_mates reads: per row, whether it is a movable group's root; the roots
        self.movable_roots = (self.movable & (roots == np.arange(bodies.count))).astype(np.bool_)
        self.roots_int = roots.astype(np.int64)
        self.limit = REST_ACC * scale
        self.hold = hold  # a line's hold on a group with a feature on it (physics.guides)
        # the page's own guide lines per axis, (edges, centres): guides.page_lines
        self.page_lines = lines or [(np.zeros(0), np.zeros(0))] * 2
        self.active_rows = np.flatnonzero(active)
        self.group_rows = group_members(roots, active)
        self.lines = LineHold(bodies.centres, self.halves, self.active_rows, roots,
                              self.group_rows, self.page_lines)
        count = bodies.count
        self.grouped = bool((roots != np.arange(count)).any())
        # what the force sum (rest_check_kernel.rest_net) reads besides the tables above
        self.forces = np.array([K_CONTACT, K_WALL, PROBE_RADIAL])
        # what reached_by reads, as Python lists (with pair_lists_of: each row's pairs, as i
        # and then as j, each in pair order)
        self.pair_ends_lists = (i.tolist(), j.tolist())
        self.root_list, self.movable_list = roots.tolist(), self.movable.tolist()
        self.group_row_lists = [rows.tolist() for rows in self.group_rows]
        self.reach_of: dict[bytes, tuple[np.ndarray, list[int], list[int]]] = {}
        self.before: dict[int, tuple] = {}  # per group: as_it_is's hold, push and net

    def compiled_parts(self) -> tuple:
        """What the compiled sweeps' rest check (snap_sweep_kernel: keeps_rest, as_it_is,
        group_sums and unheld, the same decisions on the same floats) reads of this one: the
        pairs a body reaches (reached_by, kept here), the force sums (rest_net), the lines'
        hold (LineHold.held), the rows per group and the pairs per row as lists, the limit and
        the hold.  Its kept pushes of the page as it is are its own, forgotten at every move
        as ``moved`` forgets these."""
        lines = self.lines
        return (self.reached_by, rest_net, (self.bodies.centres, self.pair_ends, self.pair_table,
                                            self.row_table, self.forces),
                held_on_lines, (lines.centres, lines.halves, lines.active_rows, lines.roots,
                                *(tuple(pair) for pair in lines.page_lines), ON_LINE_MM),
                NO_ROWS, np.zeros(self.bodies.count, dtype=np.int64),
                np.zeros(self.bodies.count, dtype=np.int64), self.root_list,
                self.group_row_lists, self.pair_lists_of, self.grouped, float(self.limit),
                float(self.hold), line_mates,
                (self.bodies.centres, self.halves, self.active_rows, self.roots_int,
                 self.movable_roots, ON_LINE_MM), unlisted_near,
                (self.bodies.centres, self.found_at, self.halves, self.active_rows,
                 self.roots_int, self.pair_lists_of, self.pair_ends, float(self.gap),
                 float(self.pair_margin)), self.refind)

    def net(self, rows: list[int], pairs: list[int], members: np.ndarray = NO_ROWS,
            axis: int = 0, shift: float = 0.0) -> list[tuple[float, float]]:
        """Net acceleration of each of ``rows`` (``pairs`` must hold every pair that touches
        them), with ``members`` moved by ``shift`` along ``axis`` (a move being tried) and
        every other item where it is.  The fast mode's sums (ContactPushes, WallPushes,
        AnchorPulls at the probe's heat: pair_sums adds a row's pushes pair by pair, as j and
        as i apart), worked pair by pair on the few pairs of one move, compiled
        (rest_check_kernel.rest_net): the same numbers bit for bit, for a fraction of the time of
        the NumPy terms (thirty calls for a handful of pairs) and of Python floats (most of a
        successful try's time)."""
        return rest_net(rows, pairs, self.bodies.centres, members, axis, shift, self.pair_ends,
                        self.pair_table, self.row_table, self.forces)

    def keeps_rest(self, members: np.ndarray, axis: int, shift: float) -> bool:
        """Whether moving the rigid body ``members`` by ``shift`` along ``axis`` leaves it and
        every group it touches with a net acceleration within the limit, or no larger than
        it was (a group's acceleration is the sum of its members', as the fast mode hands a
        follower's forces to its root; on an axis where the group is on a guide line, less
        the line's hold, before and after the move alike).  ``members`` may be several groups
        lined up, moved as one: each is held on the line by the others.

        Where the body would touch an item its pairs do not list (it, or the item, travelled
        further than the pairs reach in this snap), the pairs are found again first (refind):
        the sums would miss that push.  On fresh project seed 30 (fresh_projects.py) an item
        moved 21 mm in one snap and was left pushed 1.77 (the limit 0.8), and the settle took
        one probe more.  (Refusing such moves instead made the next probe's snap, with pairs
        found afresh, make them: 14 of 90 seeded pages took a probe more.)"""
        if self.unlisted_near(members, axis, shift):
            self.refind()
        groups, rows, pairs = self.reached_by(members)
        if len(groups) == 0:
            return self.keeps_holds(members, axis, shift, groups)
        per_row = self.net(rows, pairs, members, axis, shift)
        if self.grouped:
            after_net = self.group_sums(per_row, rows, groups)
            over = (speed_of(after_net[:, 0], after_net[:, 1]) > self.limit + 1e-9).nonzero()[0]
        else:  # every group one row: the few sums tested as floats, no arrays unless needed
            limit = self.limit + 1e-9
            over = [k for k, (x, y) in enumerate(per_row) if math.sqrt(x * x + y * y) > limit]
            after_net = np.array(per_row) if over else None
        if not len(over):  # within the limit with no hold at all: which lines hold is moot
            return self.keeps_holds(members, axis, shift, groups)
        # only a group over the limit may fail: the hold only lowers a push (unheld), and the
        # bound is at least the limit; so only those are looked at as they are and held
        failing = groups[over]
        held_before, before = self.as_it_is(failing)
        held_after = None
        if self.hold > 0:
            # the move changes no feature across its axis: only ``axis`` is found again
            held_after = held_before.copy()
            held_after[:, axis] = self.lines.held(failing, axis, members, shift)
        after = self.unheld(after_net[over], held_after)
        if not (after <= np.maximum(before, self.limit) + 1e-9).all():
            return False
        return self.keeps_holds(members, axis, shift, groups)

    def refind(self) -> tuple:
        """The check built anew where the items are now (its pairs found there, its kept
        forces forgotten, the same dict emptied), as keeps_rest does when a move would meet a
        row its pairs do not list; returns its compiled parts for the compiled sweeps, which
        read them again (snap_sweep_rest.h)."""
        before = self.before
        self.__init__(*self.made_with, pair_centres=self.bodies.centres.copy())
        before.clear()
        self.before = before
        return self.compiled_parts()

    def unlisted_near(self, members: np.ndarray, axis: int, shift: float) -> bool:
        """Whether ``members`` moved by ``shift`` along ``axis`` would touch an active row their
        pairs do not list (rest_check_kernel.unlisted_near; only looked for once the travel
        since the pairs were found could have outrun them)."""
        return unlisted_near(members, axis, shift, self.bodies.centres, self.found_at,
                             self.halves, self.active_rows, self.roots_int, self.pair_lists_of,
                             self.pair_ends, self.gap, self.pair_margin)

    def keeps_holds(self, members: np.ndarray, axis: int, shift: float,
                    reached: np.ndarray = NO_ROWS) -> bool:
        """Whether moving ``members`` by ``shift`` along ``axis`` leaves every group held on one
        of their lines there (its line-mates, ``line_mates``, wherever they lie; those in
        ``reached`` are weighed by keeps_rest with their pushes after the move) with a push
        within the limit or no larger than it was, once the move has taken the line away.
        Their pushes are as they were (no pair of theirs meets a member); only the hold may
        go.  A group held on a line with an item 17 cm away (guide_cost.py's fresh seed 3004)
        was pushed 1.42 (the limit 1.13) once that item moved off the line, and the next
        probe moved items 4.5 mm: the settle took one probe more.  (Ported from the branch
        rest-guarantee, without its other parts: nudges stay unchecked, the pairs found once.)"""
        if self.hold <= 0:
            return True
        mates = line_mates(members, axis, self.bodies.centres, self.halves, self.active_rows,
                           self.roots_int, self.movable_roots, ON_LINE_MM)
        if len(reached):
            known = set(reached.tolist())
            mates = [group for group in mates if group not in known]
        if not mates:
            return True
        found = np.array(mates, dtype=np.int64)
        # those the move leaves on no line (each was on the members'), then as they were
        found = found[~np.array(self.lines.held(found, axis, members, shift), dtype=bool)]
        if not len(found):
            return True
        held_before, before = self.as_it_is(found)
        losing = held_before[:, axis]
        held_after = held_before[losing]
        held_after[:, axis] = False
        after = self.unheld(self.nets_of(found[losing]), held_after)
        return bool((after <= np.maximum(before[losing], self.limit) + 1e-9).all())

    def nets_of(self, groups: np.ndarray) -> np.ndarray:
        """Each of ``groups``' net acceleration with the page as it is, (len(groups), 2), as
        as_it_is found it (ask that first)."""
        return np.array([self.before[group][2] for group in groups.tolist()]).reshape(-1, 2)

    def reached_by(self, members: np.ndarray) -> tuple[np.ndarray, list[int], list[int]]:
        """The movable groups that the rigid body ``members`` touches (itself among them), their
        rows and every pair that touches those: fixed by the pairs found at the start, so
        worked out once per body (half the bodies a snap checks are checked once), compiled
        (rest_check_kernel.reach_of; ``reach_python`` is the definition)."""
        key = members.tobytes()
        found = self.reach_of.get(key)
        if found is None:
            groups, rows, pairs = reach_of(members, self.pair_lists_of, self.pair_ends,
                                           self.roots_int, self.movable, self.group_row_lists)
            found = self.reach_of[key] = (np.frombuffer(groups, dtype=np.int64).astype(
                self.roots.dtype, copy=False), rows, pairs)
        return found

    def reach_python(self, members: np.ndarray) -> tuple[np.ndarray, list[int], list[int]]:
        """What reached_by answers, in Python sets: the definition its compiled twin is held
        to (tests/physics/test_rest_reach.py)."""
        ends_i, ends_j = self.pair_ends_lists
        pairs_of, roots, movable = self.pair_lists_of, self.root_list, self.movable_list
        touched = set(members.tolist())
        for member in members.tolist():
            for pair in pairs_of[member]:
                touched.add(ends_i[pair])
                touched.add(ends_j[pair])
        groups = sorted({roots[row] for row in touched if movable[roots[row]]})
        rows = [row for group in groups for row in self.group_row_lists[group]]
        pairs = sorted({pair for row in rows for pair in pairs_of[row]})
        return np.array(groups, dtype=self.roots.dtype), rows, pairs

    def as_it_is(self, groups: np.ndarray) -> tuple[np.ndarray | None, np.ndarray]:
        """For ``groups``, with the page as it is: whether a line holds each on each axis (None
        without a hold) and the push the hold leaves.  Kept per group until an item moves
        (``moved``), so the groups of a body whose moves fail one after the other, and those
        its neighbours' moves push too, are worked out once.  (Each group's is its own: its
        rows' sums run over their own pairs in order, whichever other rows are summed.)"""
        known = self.before
        missing = [group for group in groups.tolist() if group not in known]
        if missing:
            found = np.array(missing)
            held = (np.column_stack([self.lines.held(found, axis) for axis in (0, 1)])
                    if self.hold > 0 else None)
            rows = [row for group in missing for row in self.group_row_lists[group]]
            pairs = sorted({pair for row in rows for pair in self.pair_lists_of[row]})
            net = self.group_net(rows, pairs, found)
            for group, held_now, push, acc in zip(missing, held if held is not None else
                                                  [None] * len(missing), self.unheld(net, held),
                                                  net):
                known[group] = (held_now, push, acc)
        entries = [known[group] for group in groups.tolist()]
        held = np.array([holds for holds, _, _ in entries]) if self.hold > 0 else None
        return held, np.array([push for _, push, _ in entries])

    def moved(self, rows: np.ndarray, axes: tuple[int, ...] = (0, 1)) -> None:
        """``rows`` have moved (along ``axes``): forget the forces worked out for the page as
        it was."""
        self.before.clear()

    def unheld(self, acc: np.ndarray, held: np.ndarray | None) -> np.ndarray:
        """Each group's largest push the lines' hold leaves where ``held`` (on a line, per
        group and axis), (len(groups),)."""
        size = np.abs(acc)
        if held is not None:
            size = np.where(held, np.maximum(size - self.hold, 0.0), size)
        return speed_of(size[:, 0], size[:, 1])

    def group_net(self, rows: list[int], pairs: list[int], groups: np.ndarray) -> np.ndarray:
        """Each group's net acceleration with the page as it is, (len(groups), 2)."""
        return self.group_sums(self.net(rows, pairs), rows, groups)

    def group_sums(self, per_row: list[tuple[float, float]], rows: list[int],
                   groups: np.ndarray) -> np.ndarray:
        """Each group's net acceleration, (len(groups), 2), from its ``rows``' (``per_row``,
        the rows of ``groups`` in their order)."""
        per_row = np.array(per_row)
        if not self.grouped:  # every group one row: its own
            return per_row
        summed = np.zeros((self.bodies.count, 2))
        np.add.at(summed, self.roots[rows], per_row)
        return summed[groups]


def speed_of(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """The length of pushes (x, y): what the stillness test reads of the speed they give
    (fast_mode.run_fast: the top speed is a Euclidean norm).  The larger of |x| and |y| let a
    push of 0.63 on both axes (0.89 long) pass a limit of 0.79, and the probe's first step
    moved the item 0.0106 mm, not still: the probe ran 262 steps and moved items 8.8 mm (seed
    2008 of benchmarks/guide_cost.py --first-seed 2000).  Spelled as sqrt(x*x + y*y), not
    hypot, so that the compiled sweeps (snap_sweep_rest.h) get the same floats."""
    return np.sqrt(x * x + y * y)


class Groups(list):
    """group_members' answer: per row, its group's active rows; ``several`` holds the roots
    of groups of more than one row (most pages have none)."""

    several: np.ndarray


def group_members(roots: np.ndarray, active: np.ndarray) -> Groups:
    """For each row, the active rows whose group root it is (empty unless it is a root), in
    one sort: a comparison per root cost O(n^2) on a 10,000-item page.  Where no row follows
    another (most pages), each active row alone, without the sort (a snap asks twice)."""
    count = len(roots)
    rows = np.arange(count)
    if (roots == rows).all():
        nothing, flags = rows[:0], active.tolist()
        found = Groups(rows[row:row + 1] if flags[row] else nothing for row in range(count))
        found.several = nothing
        return found
    order = np.argsort(roots, kind="stable")
    order = order[active[order]]
    bounds = np.searchsorted(roots[order], np.arange(count + 1))
    found = Groups(order[bounds[row]:bounds[row + 1]] for row in range(count))
    found.several = np.flatnonzero(np.diff(bounds) > 1)
    return found
