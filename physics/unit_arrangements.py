"""Whether a few free units (a free item, or a rigid group: a photo and its caption) can stand
a gap apart from one another and from the items that cannot move, each inside its own walls,
decided exactly.

physics.arrangements decides this for free items alone between one pair of walls.  A page
with a hard-anchored photo, a header that may only slide down and a photo with its caption
has none of that, and the limits that do see pinned items (physics.room_limits.no_room, one
unit among the pinned ones; physics.pinned_rows, one row) each look at one unit or one row:
on fresh_projects seed 7031 a group, two photos and a header beside a hard anchor overlapped
by 28.8 mm, each alone had room, and `check` sent the page back to `settle`, though no
layout keeps them less than 4.8 mm into each other.

The search is the one of physics.arrangements, on unit positions (each unit's root centre):
two members of different units keep the gap when one stands at least the gap beside or above
the other, so each such pair picks one of four relations, and each relation is a difference
constraint between the two roots (``x_V - x_U >= c``, with the members' offsets in ``c``).  A
member beside an item that cannot move picks one of four too, and each is a bound on its
root (at most, or at least, a value).  A choice of relations fits exactly when the least
positions the constraints allow (the longest chains from each unit's lower bound) stay below
every unit's upper bound, on each axis; a cycle of relations that pushes a unit past itself
fails as it closes.  Pairs that keep the gap wherever their walls let them stand are left
out, so a unit far from a pinned item costs nothing.

Exponential in the pairs, so it stops after ``NODE_BUDGET`` relations tried and then says
nothing (``OutOfBudget``): a count, not a clock, so the answer is the same on every machine.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from floatpage.physics import fixed_relations
from floatpage.physics.arrangements import OutOfBudget

MAX_MEMBERS = 10  # free members (the rows of all units) searched at most
MAX_OBSTACLES = 12  # pinned items near enough to matter, at most
# relations tried in one search before it gives up (about 0.8 s of CPU at ten members, 0.4 s
# at six: each costs more than in a search in a fixed order, since it picks the pair to settle)
NODE_BUDGET = 100_000
# A search's answer depends only on the sizes, the walls, the pinned items and the gap, never
# on where the free items lie, and a settle asks the same page's question again and again
# (page_limits in each relocation and each probe, then _arrange_units): the answers are kept,
# the last MEMO_SIZE of them.  One that ran out of budget cost 1-4 s a settle on seeds 12 and
# 36 of fresh_projects, twelve times over.
MEMO_SIZE = 64
# The key's numbers are taken to this many decimals (mm): a caption's offset from its photo is
# the difference of two saved positions, and its last bits change with where the pair stands
# (19.939999999999998 or 19.94000000000001), so each probe of a settled page searched its
# rooms again (fresh_projects seed 9614 p4: 14 searches where 7 are different, 1.5 s of CPU).
# A difference below 1e-10 mm is far inside the search's own tolerance (EPSILON) and the
# saved file's 0.01 mm.
KEY_DECIMALS = 10
# the widest gap is found to this, a third of the slack it is read with
# (limit_kinds.WIDEST_GAP_SLACK_MM), in at most GAP_STEPS searches after the first ones
GAP_PRECISION_MM = 0.01
GAP_STEPS = 14
EPSILON = 1e-9


class Units(NamedTuple):
    """The free units of a search: ``owner`` (m,) the unit of each member, ``offsets`` and
    ``halves`` (m, 2) each member's centre from its unit's root and half size; ``lowest`` and
    ``highest`` (u, 2) the root centre's walls (relocation.unit_bounds)."""
    owner: np.ndarray
    offsets: np.ndarray
    halves: np.ndarray
    lowest: np.ndarray
    highest: np.ndarray


_memo: dict[bytes, np.ndarray | None | type] = {}


def unit_arrangement(units: Units, obstacle_centres: np.ndarray, obstacle_halves: np.ndarray,
                     gap: float, budget: int | None = None) -> np.ndarray | None:
    """_unit_arrangement (below), its answers kept (MEMO_SIZE): the same numbers give the same
    answer, so a kept one is the one a search would find.  ``budget``: relations tried at
    most, NODE_BUDGET unless given."""
    budget = NODE_BUDGET if budget is None else budget
    key = b"".join((np.round(np.asarray(part, dtype=float), KEY_DECIMALS) + 0.0).tobytes()
                   for part in (units.owner, units.offsets, units.halves, units.lowest,
                                units.highest, obstacle_centres, obstacle_halves,
                                [gap, len(units.owner), len(obstacle_centres), budget]))
    if key in _memo:
        found = _memo[key]
    else:
        try:
            found = _unit_arrangement(units, obstacle_centres, obstacle_halves, gap, budget)
        except OutOfBudget:
            found = OutOfBudget
        if len(_memo) >= MEMO_SIZE:
            del _memo[next(iter(_memo))]
        _memo[key] = found
    if found is OutOfBudget:
        raise OutOfBudget
    return None if found is None else found.copy()


def _unit_arrangement(units: Units, obstacle_centres: np.ndarray, obstacle_halves: np.ndarray,
                      gap: float, budget: int) -> np.ndarray | None:
    """Root centres (u, 2) at which every member of each unit keeps ``gap`` (negative: overlaps
    by at most that much) from every member of another unit and from every obstacle, each root
    inside its walls; None where there is none.  Each unit stands as far up and left as the
    relations found let it (physics.fixed_relations spreads a layout over the room its
    relations leave).  Raises OutOfBudget past ``budget`` relations tried."""
    owner, offsets, halves = units.owner, units.offsets, units.halves
    count = len(units.lowest)
    if (units.lowest > units.highest + EPSILON).any():
        return None
    choices: list[list[tuple]] = []
    for i in range(len(owner)):
        for j in range(i + 1, len(owner)):
            u, v = int(owner[i]), int(owner[j])
            if u == v:
                continue
            reach = halves[i] + halves[j] + gap
            ways = []
            clear = False
            for axis in (0, 1):
                for first, second, c in ((u, v, offsets[i, axis] - offsets[j, axis]
                                          + reach[axis]),
                                         (v, u, offsets[j, axis] - offsets[i, axis]
                                          + reach[axis])):
                    if units.lowest[second, axis] - units.highest[first, axis] >= c - EPSILON:
                        clear = True  # kept wherever the walls let them stand
                    if units.lowest[first, axis] + c <= units.highest[second, axis] + EPSILON:
                        ways.append(("edge", axis, first, second, float(c)))
            if clear:
                continue
            if not ways:
                return None
            choices.append(ways)
        for p in range(len(obstacle_centres)):
            u = int(owner[i])
            reach = halves[i] + obstacle_halves[p] + gap
            ways = []
            clear = False
            for axis in (0, 1):
                below = obstacle_centres[p, axis] - reach[axis] - offsets[i, axis]  # at most
                above = obstacle_centres[p, axis] + reach[axis] - offsets[i, axis]  # at least
                if units.highest[u, axis] <= below + EPSILON or \
                        units.lowest[u, axis] >= above - EPSILON:
                    clear = True
                if below >= units.lowest[u, axis] - EPSILON:
                    ways.append(("upper", axis, u, float(below)))
                if above <= units.highest[u, axis] + EPSILON:
                    ways.append(("lower", axis, u, float(above)))
            if clear:
                continue
            if not ways:
                return None
            choices.append(ways)
    choices.sort(key=len)
    involved = [{unit for way in ways for unit in ((way[2], way[3]) if way[0] == "edge"
                                                   else (way[2],))} for ways in choices]
    lows = [units.lowest[:, 0].tolist(), units.lowest[:, 1].tolist()]
    ups = [units.highest[:, 0].tolist(), units.highest[:, 1].tolist()]
    after: list[list[list[tuple[int, float]]]] = [[[] for _ in range(count)] for _ in (0, 1)]
    spent = [0]

    def room_left(way: tuple) -> float:
        kind, axis = way[0], way[1]
        low, up = lows[axis], ups[axis]
        if kind == "edge":
            _, _, first, second, c = way
            return up[second] - max(low[second], low[first] + c)
        _, _, unit, value = way
        if kind == "lower":
            return up[unit] - max(low[unit], value)
        return min(up[unit], value) - low[unit]

    def raise_from(axis: int, start: int, value: float, guard: int,
                   raised: list) -> bool:
        """Raise ``start``'s least position to ``value`` and every chain after it; False where
        one passes its upper bound, or a chain comes back to ``guard`` (a cycle that pushes a
        unit past itself)."""
        low, up = lows[axis], ups[axis]
        todo = [(start, value)]
        while todo:
            unit, need = todo.pop()
            if need <= low[unit] + 1e-12:
                continue
            if unit == guard:
                return False
            raised.append((axis, unit, low[unit]))
            low[unit] = need
            if need > up[unit] + EPSILON:
                return False
            todo.extend((nxt, need + c) for nxt, c in after[axis][unit])
        return True

    def apply(way: tuple) -> tuple[bool, list, tuple | None]:
        """Take ``way``: whether it fits, what it raised, the bound it lowered (to undo)."""
        raised: list = []
        kind, axis = way[0], way[1]
        if kind == "edge":
            _, _, first, second, c = way
            after[axis][first].append((second, c))
            fits = raise_from(axis, second, lows[axis][first] + c, first, raised)
            return fits, raised, None
        _, _, unit, value = way
        if kind == "lower":
            return raise_from(axis, unit, value, -1, raised), raised, None
        lowered = (axis, unit, ups[axis][unit])
        ups[axis][unit] = min(ups[axis][unit], value)
        return lows[axis][unit] <= ups[axis][unit] + EPSILON, raised, lowered

    def undo(way: tuple, raised: list, lowered: tuple | None) -> None:
        if way[0] == "edge":
            after[way[1]][way[2]].pop()
        for axis, unit, was in reversed(raised):
            lows[axis][unit] = was
        if lowered is not None:
            axis, unit, was = lowered
            ups[axis][unit] = was

    def kept(way: tuple) -> bool:
        """Whether the bounds reached keep ``way`` already, wherever the units go from here
        (least positions only rise, greatest only fall): its pair needs no choice."""
        kind, axis = way[0], way[1]
        if kind == "edge":
            _, _, first, second, c = way
            return lows[axis][second] >= ups[axis][first] + c - EPSILON
        _, _, unit, value = way
        if kind == "lower":
            return lows[axis][unit] >= value - EPSILON
        return ups[axis][unit] <= value + EPSILON

    taken: list[tuple] = []
    open_choices = set(range(len(choices)))

    def search() -> bool:
        """Settle the open pair with the fewest ways left that fit (a pair with one is
        forced, and a dead end shows at once), after dropping the pairs the bounds reached
        already keep.  The pairs in the order they were listed took 600,000 relations to rule
        out a 2 mm gap for six units beside a hard-anchored photo with its caption on a 5 x 7
        in card, this order 74,000 (each dearer: 0.34 s against 0.6 s)."""
        dropped, fewest, index = [], 0, -1
        for k in open_choices:
            ways = choices[k]
            if any(kept(way) for way in ways):
                dropped.append(k)
                continue
            left = sum(room_left(way) >= -EPSILON for way in ways)
            if index < 0 or left < fewest or (left == fewest and k < index):
                fewest, index = left, k
        open_choices.difference_update(dropped)
        try:
            if index < 0:
                return True
            open_choices.discard(index)
            try:
                for way in sorted(choices[index], key=room_left, reverse=True):
                    spent[0] += 1
                    if spent[0] > budget:
                        raise OutOfBudget
                    fits, raised, lowered = apply(way)
                    # every open pair keeps a way that fits: only those of a unit whose
                    # bounds just moved can have lost theirs (the rest were checked before)
                    touched = {unit for _, unit, _ in raised}
                    if lowered is not None:
                        touched.add(lowered[1])
                    fits = fits and all(
                        any(room_left(other) >= -EPSILON for other in choices[later])
                        for later in open_choices if not touched.isdisjoint(involved[later]))
                    if fits:
                        taken.append(way)
                        if search():
                            return True
                        taken.pop()
                    undo(way, raised, lowered)
                return False
            finally:
                open_choices.add(index)
        finally:
            open_choices.update(dropped)

    if not search():
        return None
    return np.array(lows).T


def arranges(units: Units, obstacle_centres: np.ndarray, obstacle_halves: np.ndarray,
             gap: float) -> bool:
    """Whether unit_arrangement finds a layout (raises OutOfBudget as it does)."""
    return unit_arrangement(units, obstacle_centres, obstacle_halves, gap) is not None


class Bracket(NamedTuple):
    """What the search tells of the widest gap: the units keep ``low``, in ``layout`` (root
    centres, (u, 2), spread over the room its relations leave), and no layout keeps ``high``;
    ``exact`` where no search on the way ran out of budget, so that ``low`` is the widest gap
    to GAP_PRECISION_MM."""
    low: float
    high: float
    exact: bool
    layout: np.ndarray | None  # None where no layout was found at all


def widest_bracket(units: Units, obstacle_centres: np.ndarray, obstacle_halves: np.ndarray,
                   high: float) -> Bracket | None:
    """The widest gap, up to ``high``, as far as searches within their budget tell.  None
    where the search cannot tell whether ``high`` itself fits (or, where it does not, whether
    any overlap does).

    It climbs: each layout found fixes a choice of relations, and physics.fixed_relations finds
    the widest gap that choice keeps without a search; the search is then asked only whether
    any choice keeps GAP_PRECISION_MM more.  A bisection asked it eight or more times near
    the answer, where each question is hardest (3 s of CPU to check a 5 x 7 in card whose six
    units keep 1.63 mm, not 2; this asks five questions, 1.1 s).  A question that runs out of
    budget ends the climb with what is proved: on a page of nine members around two hard
    anchors (fresh_projects seed 51, p1) the gutter was ruled out at once, a layout found 18.0
    mm into each other, and the search at 9.0 mm ran out: the search said nothing, `check`
    sent the page back to settle, and the settle kept 18.8 mm."""
    obstacles = obstacle_centres, obstacle_halves

    def layout_at(gap: float) -> np.ndarray | None | type:
        try:
            return unit_arrangement(units, *obstacles, gap)
        except OutOfBudget:
            return OutOfBudget

    roots = layout_at(high)
    if roots is OutOfBudget:
        return None
    if roots is not None:
        return _climbed(units, obstacles, roots, high, np.inf, True)
    exact, start, ruled_out = True, -float(2 * units.halves.max()), high
    roots = layout_at(0.0) if high > 0 else None
    if roots is OutOfBudget:
        exact, roots = False, None
    elif roots is not None:
        start = 0.0  # items that can just touch are no overlap
    else:
        ruled_out = min(high, 0.0)
    if roots is None:
        roots = layout_at(start)
        if roots is OutOfBudget:
            return None
        if roots is None:
            return Bracket(start, start, True, None)  # no layout even that far into each other
    found = _climbed(units, obstacles, roots, start, ruled_out, exact)
    for _ in range(GAP_STEPS):
        if found.high - found.low <= GAP_PRECISION_MM:
            break
        ask = found.low + GAP_PRECISION_MM
        roots = layout_at(ask)
        if roots is OutOfBudget:
            return found._replace(exact=False)
        if roots is None:
            return found._replace(high=ask)
        found = _climbed(units, obstacles, roots, ask, found.high, found.exact)
    return found


def wider_than(units: Units, obstacle_centres: np.ndarray, obstacle_halves: np.ndarray,
               floor: float, high: float, budget: int) -> Bracket | None:
    """A layout that keeps ``floor`` (at most ``high``), found by one search within
    ``budget`` and widened by its own relations (physics.fixed_relations), without the climb
    of ``widest_bracket``; None where the search finds none or runs out.  For a layout
    better than one at hand, where the widest is not needed: relocation asks this of every
    room and every closest pair, each finalize of every probe (RoomRelocation._set_down)."""
    obstacles = obstacle_centres, obstacle_halves
    try:
        roots = unit_arrangement(units, *obstacles, floor, budget)
    except OutOfBudget:
        return None
    if roots is None:
        return None
    return _climbed(units, obstacles, roots, floor, high, False)


def _climbed(units: Units, obstacles: tuple, roots: np.ndarray, low: float, high: float,
             exact: bool) -> Bracket:
    """The widest gap between ``low`` (which the layout ``roots`` keeps) and ``high`` (inf: no
    higher than ``low``) that the relations of ``roots`` keep, as a Bracket."""
    relations = fixed_relations.held_relations(units, *obstacles, roots)
    found, layout = fixed_relations.widest_for_relations(
        units, relations, low, high if np.isfinite(high) else low)
    return Bracket(found, high if np.isfinite(high) else found, exact, layout)


class Search(NamedTuple):
    """A page's free units set up for the search: ``units`` (relocation.Unit, as
    movable_units lists them), ``walls`` their Units inside the margins, ``page_walls`` with
    the margins given way, ``rows`` every member, ``obstacles`` the pinned rows near enough to
    matter."""
    units: list
    walls: Units
    page_walls: Units
    rows: np.ndarray
    obstacles: np.ndarray


def search_of(bodies, pinned: np.ndarray, margin_mm: float, page_w_mm: float,
              page_h_mm: float, gutter_mm: float, taken: np.ndarray | None = None
              ) -> Search | None:
    """The page's search, or None where it is out of reach (more than MAX_MEMBERS free members
    or MAX_OBSTACLES pinned items within their reach, nothing to part, a unit too large for
    its walls: page_limits.TooLarge names that).  With ``taken`` (n,) bool, only the units
    whose root it marks: the others are left out, and ``pinned`` says which items stand
    as obstacles."""
    from floatpage.physics.relocation import movable_units, unit_bounds  # relocation uses this
    units = movable_units(bodies)
    if taken is not None:
        units = [unit for unit in units if taken[unit.root]]
    if not units:
        return None
    rows = np.concatenate([unit.members for unit in units])
    if len(rows) > MAX_MEMBERS:
        return None
    owner = np.concatenate([np.full(len(unit.members), k) for k, unit in enumerate(units)])
    offsets = np.concatenate([unit.offsets for unit in units])
    halves = bodies.sizes[rows] / 2
    lowest, highest = unit_bounds(bodies, units, page_w_mm, page_h_mm, margin_mm)
    if (lowest > highest + EPSILON).any():
        return None
    page_lowest, page_highest = unit_bounds(bodies, units, page_w_mm, page_h_mm, 0.0)
    obstacles = np.flatnonzero(pinned & bodies.active)
    if len(obstacles):  # those a member's box can come within the gutter of
        near = page_lowest[owner] + offsets - halves - gutter_mm  # (m, 2)
        far = page_highest[owner] + offsets + halves + gutter_mm
        low = bodies.centres[obstacles] - bodies.sizes[obstacles] / 2
        high = bodies.centres[obstacles] + bodies.sizes[obstacles] / 2
        within = ((near[:, None] < high[None]) & (far[:, None] > low[None])).all(axis=2)
        obstacles = obstacles[within.any(axis=0)]
    if len(obstacles) > MAX_OBSTACLES or len(units) + len(obstacles) < 2:
        return None
    return Search(units, Units(owner, offsets, halves, lowest, highest),
                  Units(owner, offsets, halves, page_lowest, page_highest), rows, obstacles)


def arranged(units: Units, obstacle_centres: np.ndarray, obstacle_halves: np.ndarray,
             roots: np.ndarray, gap: float) -> bool:
    """Whether root centres ``roots`` (u, 2) keep ``gap`` between every two members of
    different units and from every obstacle, inside the walls."""
    if ((roots < units.lowest - EPSILON) | (roots > units.highest + EPSILON)).any():
        return False
    centres = roots[units.owner] + units.offsets
    clear = (np.abs(centres[:, None] - centres[None]) - units.halves[:, None]
             - units.halves[None]).max(axis=2)
    apart = units.owner[:, None] != units.owner[None]
    if (clear[apart] < gap - 1e-6).any():
        return False
    if len(obstacle_centres) == 0:
        return True
    clear = (np.abs(centres[:, None] - obstacle_centres[None]) - units.halves[:, None]
             - obstacle_halves[None]).max(axis=2)
    return bool((clear >= gap - 1e-6).all())
