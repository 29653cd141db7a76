"""Whether a few free items can stand a gap apart inside a room, decided exactly.

Two rectangles keep a gap g when one stands at least g beside the other or at least g above
it (finalize.pair_clearances: the larger of the two edge-to-edge gaps).  So every layout of n
items picks, for each pair, one of four relations (left of, right of, above, below), and a
choice of relations fits the room exactly when, on each axis, the longest chain of items it
puts one after another, with a gap between each two, fits the room's length (the positions
are then the chain lengths).  Searching the relations pair by pair, with the chains kept as
lower bounds on each item's position and a branch dropped as soon as one runs past the room,
decides the question for the handful of items of a greeting card or a small page, where the
cheaper limits of physics.page_limits (a pair that crosses, a stack) see nothing: four items,
two tall and two wide, that no order keeps 3 mm apart on A4 (benchmarks/gutter_fits.py --seed
1011, page 157), though each pair and each three could.

The search is exponential in the pairs (``MAX_ITEMS`` items: 4^15 relations at most), so it
stops after ``NODE_BUDGET`` steps and then says nothing: a count of steps, not a clock, so the
answer is the same on every machine.
"""

from __future__ import annotations

import numpy as np

MAX_ITEMS = 6
NODE_BUDGET = 50_000  # relations tried in one search before it gives up
GAP_STEPS = 16  # bisection steps for the widest gap (to 1/65536 of the span searched)


class OutOfBudget(Exception):
    """The search tried ``NODE_BUDGET`` relations without an answer."""


def arranges(sizes: np.ndarray, room: np.ndarray, gap: float) -> bool:
    """Whether items of ``sizes`` (n, 2) can stand inside a room of ``room`` (w, h) with
    every pair at least ``gap`` apart (negative: overlapping by at most that much).  Raises
    OutOfBudget when the search runs past its budget."""
    return arrangement(sizes, room, gap) is not None


def arrangement(sizes: np.ndarray, room: np.ndarray, gap: float) -> np.ndarray | None:
    """Top-left corners (n, 2) of one such layout (each item as far up and left as its
    relations let it), or None where there is none."""
    count = len(sizes)
    if (sizes > room + 1e-9).any():
        return None
    alike = twins(sizes)
    choices = []
    for a in range(count):
        for b in range(a + 1, count):
            mine = [(axis, first, second) for axis in (0, 1)
                    if sizes[a, axis] + sizes[b, axis] + gap <= room[axis] + 1e-9
                    for first, second in ((a, b), (b, a))]
            if not mine:
                return None
            if alike[a] == alike[b] > 0:
                mine = in_order(mine, a)
            choices.append(mine)
    choices.sort(key=len)  # the pairs with the fewest ways first: they prune the most
    # a layout mirrored across or down is one too: the first pair of items with no twin keeps
    # its order (mirror first, then relabel the twins, which moves neither of the two)
    single = next((index for index, mine in enumerate(choices)
                   if alike[mine[0][1]] == alike[mine[0][2]] == 0), None)
    if single is not None:
        choices[single] = [(axis, first, second) for axis, first, second in choices[single]
                           if first < second]
    lows = [[0.0] * count, [0.0] * count]  # each item's least position on each axis
    after: list[list[list[int]]] = [[[] for _ in range(count)], [[] for _ in range(count)]]
    spent = [0]
    widths = sizes.tolist()
    limits = [[room[axis] - widths[k][axis] + 1e-9 for k in range(count)] for axis in (0, 1)]

    def place(axis: int, first: int, second: int) -> list[tuple[int, float]] | None:
        """Put ``second`` after ``first`` on ``axis``; the positions raised (to undo), or None
        if a chain runs past the room."""
        raised: list[tuple[int, float]] = []
        after[axis][first].append(second)
        todo = [(first, second)]
        low, limit = lows[axis], limits[axis]
        while todo:
            before, item = todo.pop()
            need = low[before] + widths[before][axis] + gap
            if need > low[item] + 1e-12:
                raised.append((item, low[item]))
                low[item] = need
                if need > limit[item]:
                    return raised
                todo.extend((item, nxt) for nxt in after[axis][item])
        return raised

    def undo(axis: int, first: int, raised: list[tuple[int, float]]) -> None:
        after[axis][first].pop()
        low = lows[axis]
        for item, was in reversed(raised):
            low[item] = was

    def room_left(axis: int, first: int, second: int) -> float:
        """How far ``second``'s far edge would stay inside the room with ``second`` after
        ``first`` on ``axis`` (before the chains after ``second`` move)."""
        low = lows[axis]
        return limits[axis][second] - max(low[second], low[first] + widths[first][axis] + gap)

    def search(index: int) -> bool:
        if index == len(choices):
            return True  # the positions are the least ones: lows
        # the relation that leaves the most room first: where a layout exists, the search
        # mostly walks straight to it (six items with room to spare ran out of budget in
        # the order the pairs were listed)
        options = sorted(choices[index], key=lambda option: room_left(*option), reverse=True)
        for axis, first, second in options:
            spent[0] += 1
            if spent[0] > NODE_BUDGET:
                raise OutOfBudget
            raised = place(axis, first, second)
            fits = all(lows[axis][item] <= limits[axis][item] for item, _ in raised)
            # every pair still to place keeps a way that fits as the chains stand (a pair the
            # placings shut out fails now, not after every way of the pairs between)
            fits = fits and all(any(room_left(*option) >= -1e-9 for option in later)
                                for later in choices[index + 1:])
            if fits and search(index + 1):
                return True
            undo(axis, first, raised)
        return False

    if not search(0):
        return None
    return np.array(lows).T


def twins(sizes: np.ndarray) -> list[int]:
    """For each item, a number shared by the items of exactly its size (1, 2, ...), or 0 for
    an item with no twin.  Items of one size are interchangeable here (every item is free in
    the one room), so a layout with two of them swapped is the same layout."""
    keys = [tuple(row) for row in sizes.tolist()]
    shared = [key for key in dict.fromkeys(keys) if keys.count(key) > 1]
    return [shared.index(key) + 1 if key in shared else 0 for key in keys]


def in_order(ways: list[tuple[int, int, int]], a: int) -> list[tuple[int, int, int]]:
    """The ways of twins ``a`` < b that a layout with its twins relabelled needs: ``a``
    left of or above b.  Every layout of rectangles apart has an order of its items in which
    each stands left of or above every later one (the first sequence of its sequence pair:
    Murata et al., "Rectangle-packing-based module placement", ICCAD 1995; with the gap, of
    the items grown by it), so numbering each size's twins in that order gives a layout that
    keeps to this.  Without it, six items with two pairs alike, just short of fitting, ran
    past the budget trying each layout once per labelling of the twins."""
    return [(axis, first, second) for axis, first, second in ways if first == a]


def widest_gap(sizes: np.ndarray, room: np.ndarray, high: float) -> float | None:
    """The widest gap, up to ``high``, at which the items arrange inside ``room`` (to a
    65,536th of the span searched; negative: the least overlap), or None where the search
    runs out of budget.  Where even the largest overlap an item's size allows does not
    arrange them, the most negative gap tried."""
    low = -float(sizes.min())
    try:
        if arranges(sizes, room, high):
            return high
        if not arranges(sizes, room, low):
            return low
        return bisect_widest(lambda gap: arranges(sizes, room, gap), low, high, GAP_STEPS)
    except OutOfBudget:
        return None


def bisect_widest(fits, low: float, high: float, steps: int) -> float:
    """The widest gap between ``low``, which ``fits``, and ``high``, which does not, to
    ``steps`` halvings of the span: the last step of both exact searches (this module's and
    physics.unit_arrangements'), whose answer is monotone in the gap."""
    for _ in range(steps):
        middle = (low + high) / 2
        if fits(middle):
            low = middle
        else:
            high = middle
    return low
