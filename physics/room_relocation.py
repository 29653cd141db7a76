"""Relocation, the step of Engine.finalize for a page the no-overlap pass left short of the
gutter: items lifted out of their jams (physics.relocation), room by room, each room aiming at
what its own limits leave it (physics.page_limits), and at no overlap where not even that
holds.  A mixin of Engine, as physics.second_start is: it reads and sets the engine's bodies
and parameters, and the engine's module keeps the editing API and the settle that calls it.
"""

from __future__ import annotations

import numpy as np

from floatpage.physics.finalize import (
    MARGIN_GIVES_WAY, MAX_ITERATIONS, ROUNDING_MM, STALL_ITERATIONS, pair_clearances,
    project_within,
)
from floatpage.physics.geometry import GUTTER_FITS_COVER, pinned_items, room_covers, rooms_of
from floatpage.physics.near_arrangement import near_search
from floatpage.physics.page_limits import (
    WIDEST_GAP_SLACK_MM, capping, close_pairs, page_limits, room_caps, unexplained_pairs,
)
from floatpage.physics.relocation import (
    MAX_ITEMS as RELOCATE_MAX_ITEMS, movable_units, placed_anew, relocate_jammed,
)
from floatpage.physics.unit_arrangements import search_of, wider_than, widest_bracket

# relations a search of _arrange_rooms and _arrange_near tries (a tenth of the search's own
# budget, unit_arrangements.NODE_BUDGET): they look for a wider gap on a page the pushes left
# short of it, each finalize of every probe, and with the whole budget fresh_projects seed
# 9616 (three pages of 18, 19 and 4 items) took 31 s of CPU to settle where it took 2.4 s
SET_DOWN_BUDGET = 10_000
NEAR_ROUNDS = 4  # closest pairs whose units _arrange_near sets down, at most
RELOCATED_RUN_STEPS = 20_000  # the gentle run from items set down anew (_relocate_jammed)


class RoomRelocation:
    """Engine's relocation (see the module doc)."""

    def _may_relocate(self) -> bool:
        """Whether a page the no-overlap pass left short of the gutter may have items lifted
        out of the jam (physics.relocation): the fast mode, few enough items."""
        count = int(self._bodies.active.sum())
        return self.params.mode == "fast" and 2 <= count <= RELOCATE_MAX_ITEMS

    def _relocate_rooms(self) -> bool:
        """Relocation room by room (``_relocate_by_moves``), then, where it leaves pairs that
        no limit explains, the page's free units set down by an exact search
        (``_arrange_units``); whether the whole page keeps the gutter in the end."""
        bodies = self._bodies
        gutter = self.params.gutter_mm
        limits = capping(page_limits(bodies, self.page_w_mm, self.page_h_mm, self.margin_mm,
                                     gutter))
        if self._relocate_by_moves(limits):
            return True
        if unexplained_pairs(bodies, limits, gutter):
            return self._arrange_units()
        return False

    def _arrange_units(self) -> bool:
        """The page's free units (a free item, or one with the items following it) set down
        where an exact search of every way each stands beside or above another, and beside or
        above each item that cannot move, keeps the widest gap (physics.unit_arrangements),
        each midway in the room its relations leave it: inside the margins where that gap is
        no overlap, else with the margins given way where that is, else wherever the least
        overlap is (overlap last).  Only where that gap is wider than the page's closest pair
        now.  The moves and the set-downs of relocation look for room for one unit at a time:
        on fresh_projects seed 7129 five units among a hard-anchored header and a photo with
        its caption on a 55 x 85 mm card kept six overlaps of up to 15.6 mm where they can
        all stand touching, and on seeds 7031 and 7062 the moves left overlaps of 28.8 mm and
        29.5 mm where 4.8 mm and 0.8 mm are the least.  Where the page's units are too many
        for one search, room by room (``_arrange_rooms``) and around the closest pairs
        (``_arrange_near``).  Whether the gutter is kept."""
        bodies = self._bodies
        gutter = self.params.gutter_mm
        roots, _ = bodies.group_roots()
        pinned = pinned_items(bodies, roots)
        search = search_of(bodies, pinned, self.margin_mm, self.page_w_mm, self.page_h_mm,
                           gutter)
        if search is None:
            if self.grown_cover() > GUTTER_FITS_COVER and self._closest_gap() >= 0:
                # a page too full for the gutter to be promised, and without overlap: the
                # set-downs of rooms and pairs found little there and cost the most
                # (anchored_pages --kind follow --first 27000: pages of 42-61 items at 87-97 %,
                # 0.26-0.73 s of CPU each on main, 0.61-1.50 s with them, every verdict the
                # same).  Overlap they still part: fresh_projects seed 9638 p2 kept nine
                # overlaps of up to 14.3 mm without them, none with them.
                return False
            self._arrange_rooms()
            # the rooms again after the pairs: a room whose units a free item crowded may
            # have room now (seed 9614 p4: a words region 2.29 mm from a free text, 3 mm after)
            if self._arrange_near():
                self._arrange_rooms()
            return not unexplained_pairs(bodies, [], gutter)
        placed = self._set_down(search, self._closest_gap())
        return placed is not None and placed >= gutter - ROUNDING_MM

    def _arrange_rooms(self) -> bool:
        """``_arrange_units`` for a page whose units are too many for one search: the units
        of each room (geometry.rooms_of: each region, then the free items) set down at the
        widest gap they keep from one another and from every other item where it stands,
        where that is wider than the room's closest pair now.  Sound: the other items stay,
        so every pair the room's units are not in keeps its gap, and every pair they are in
        keeps the wider one.  fresh_projects seed 9614, p4: ten members of a photos region
        around a hard-anchored photo with its caption can keep 2.2 mm (check's limit, room
        by room), and the settle kept 0.02 mm, since the page's sixteen items were too many
        for the whole page's search.  Whether any room's units moved."""
        bodies = self._bodies
        gutter = self.params.gutter_mm
        rooms = rooms_of(bodies)
        units = movable_units(bodies)
        moved = False
        for room in [*range(1, int(rooms.max(initial=0)) + 1), 0]:
            taken = rooms == room
            members = [unit.members for unit in units if taken[unit.root]]
            if not members:
                continue
            mine = np.zeros(bodies.count, dtype=bool)
            mine[np.concatenate(members)] = True
            search = search_of(bodies, bodies.active & ~mine, self.margin_mm, self.page_w_mm,
                               self.page_h_mm, gutter, taken=taken)
            if search is not None:
                moved |= self._set_down(search, self._closest_gap(mine), quick=True) is not None
        return moved

    def _arrange_near(self) -> bool:
        """The units around the page's closest pair set down by the search of
        physics.near_arrangement (each inside a window around where they stand, every other
        item an obstacle where it stands), where that beats their closest pair, up to
        NEAR_ROUNDS times: a page whose rooms are each too many for one search (see that
        module).  Whether any unit moved."""
        bodies = self._bodies
        gutter = self.params.gutter_mm
        roots, _ = bodies.group_roots()
        pinned = pinned_items(bodies, roots)
        units = movable_units(bodies)
        moved = False
        for _ in range(NEAR_ROUNDS):
            closest = close_pairs(bodies, np.flatnonzero(bodies.active), roots, gutter,
                                  lambda a, b, gaps: ~(pinned[a] & pinned[b]))
            if not closest:
                break
            a, b, _ = closest[0]
            search = near_search(bodies, units, (a, b), self.margin_mm, self.page_w_mm,
                                 self.page_h_mm, gutter)
            if search is None:
                break
            mine = np.zeros(bodies.count, dtype=bool)
            mine[search.rows] = True
            if self._set_down(search, self._closest_gap(mine), quick=True) is None:
                break
            moved = True
        return moved

    def _set_down(self, search, closest_mm: float, quick: bool = False) -> float | None:
        """``search``'s units set down at the widest gap it finds (see ``_arrange_units``),
        where that is wider than ``closest_mm``: that gap, or None where they stay.
        ``quick``: at the first layout one search finds wider than that (within
        SET_DOWN_BUDGET relations, inside the margins), widened by its own relations
        (unit_arrangements.wider_than), not the widest."""
        bodies = self._bodies
        gutter = self.params.gutter_mm
        obstacles = bodies.centres[search.obstacles], bodies.sizes[search.obstacles] / 2
        floor = closest_mm + WIDEST_GAP_SLACK_MM
        if floor >= gutter:
            return None  # no search keeps more than the gutter
        if quick:
            decided = wider_than(search.walls, *obstacles, floor, gutter, SET_DOWN_BUDGET)
            return None if decided is None else self._place(search, decided.layout,
                                                            decided.low)
        decided = widest_bracket(search.walls, *obstacles, gutter)
        if decided is None:
            return None
        if decided.low < 0:  # the margin gives way before overlap does
            on_page = widest_bracket(search.page_walls, *obstacles, gutter)
            if on_page is not None and on_page.low > decided.low + WIDEST_GAP_SLACK_MM:
                decided = on_page
        # where the search ran out of its budget on the way to the widest gap, the layout it
        # found is still one the units can be set down in (seed 51 p1: 18.0 mm into each
        # other where the pass left 18.8 mm)
        widest, spots = decided.low, decided.layout
        if spots is None or widest <= floor:
            return None
        return self._place(search, spots, widest)

    def _place(self, search, spots: np.ndarray, gap_mm: float) -> float:
        """``search``'s units set down with their roots at ``spots`` (u, 2); ``gap_mm``."""
        bodies = self._bodies
        for unit, spot in zip(search.units, spots):
            unit.place(bodies.centres, spot)
            bodies.velocities[unit.carried] = 0.0
        return gap_mm

    def _closest_gap(self, among: np.ndarray | None = None) -> float:
        """The page's closest pair of items of different groups, not both pinned (negative:
        the deepest overlap), or the closest with an item ``among`` (n,) bool in it; inf with
        none."""
        bodies = self._bodies
        roots, _ = bodies.group_roots()
        pinned = pinned_items(bodies, roots)
        rows = np.flatnonzero(bodies.active)
        i, j = np.triu_indices(len(rows), 1)
        i, j = rows[i], rows[j]
        keep = (roots[i] != roots[j]) & ~(pinned[i] & pinned[j])
        if among is not None:
            keep &= among[i] | among[j]
        gaps = pair_clearances(bodies.centres, bodies.sizes / 2, i[keep], j[keep])
        return float(gaps.min(initial=np.inf))

    def _relocate_by_moves(self, limits: list) -> bool:
        """Relocation room by room (geometry.rooms_of: each region, then the page's free
        items), each room's items lifted out of its jams while every other item stays where
        it is (held, for the while): whether the whole page keeps the gutter in the end.
        A room's own limits cap what it aims at (page_limits.room_caps), and its own cover
        says whether the gutter, or no overlap, fits there (``_relocate_room``).  A page of
        one room, or one whose rooms all leave a gap, is relocated as a whole first, as it
        always was (room by room, a free photo among two regions held where they stood found
        no room that the whole page's relocation had found: fresh_projects seed 14).  Taken
        as a whole, three panels that must overlap in a words region stopped the relocation
        of the photos region above it, which kept three overlaps of up to 19 mm it had room
        to part (tests/physics/rooms/rooms-7054.toml)."""
        bodies = self._bodies
        gutter = self.params.gutter_mm
        rooms = rooms_of(bodies)
        caps = room_caps(bodies, limits, rooms)
        limited = np.zeros(len(caps), dtype=bool)  # a room a limit names (a TooLarge too)
        forced = np.zeros(len(caps), dtype=bool)  # overlap there even without the margins
        for limit in limits:
            limited[rooms[list(limit.rows)]] = True
            if getattr(limit, "widest_gap_mm", 0.0) < 0 and not limit.fits_page:
                forced[rooms[list(limit.rows)]] = True
        near, far = bodies.insets(self.margin_mm, self.page_w_mm, self.page_h_mm)
        covers = room_covers(bodies, near, far, self.page_w_mm, self.page_h_mm, gutter)
        packed = room_covers(bodies, near, far, self.page_w_mm, self.page_h_mm, 0.0)
        if caps.min() >= 0:  # the page as a whole first, as it always was
            fits = self._relocate_room(caps.min(), limited.any(), forced.any(), covers.max(),
                                       packed.max())
            if fits or len(caps) == 1 or not unexplained_pairs(bodies, limits, gutter):
                return fits
        held = bodies.held.copy()
        try:
            for room in [*range(1, len(caps)), 0]:  # the free items last, around the regions
                bodies.held[:] = held | (bodies.active & (rooms != room))
                # only the room's own pairs count now (page_limits: held items are pinned)
                aim = min(caps[room], gutter)
                if unexplained_pairs(bodies, [], aim - WIDEST_GAP_SLACK_MM if aim >= 0 else 0.0):
                    self._relocate_room(caps[room], limited[room], forced[room], covers[room],
                                        packed[room])
        finally:
            bodies.held[:] = held
        return not unexplained_pairs(bodies, [], gutter)

    def _relocate_room(self, cap_mm: float, limited: bool, forced: bool, cover: float,
                       packed: float) -> bool:
        """Relocation of the items that may move (the whole page, or one room of it with the
        rest held): at the gutter where it fits by area (``cover``, each item grown by it,
        at most GUTTER_FITS_COVER of the room) and no limit names the room (``limited``); at
        ``cap_mm``, the widest gap the room's limits leave, where they do; else at no overlap
        (where ``packed``, the cover without a gutter, fits), inside the margins where no
        limit forces overlap there (``cap_mm`` < 0), else with the margin giving way, unless
        overlap is ``forced`` even then.  Whether the gutter was kept."""
        if cover <= GUTTER_FITS_COVER and cap_mm >= 0:
            if limited:
                if not self._relocate_to_cap(cap_mm):
                    self._part_crowd()  # no move kept that gap: no overlap, at least
                return False
            if self._relocate_jammed(self.params.gutter_mm):
                return True
        elif packed > GUTTER_FITS_COVER or forced:
            return False  # overlap may be forced: the margin gave way first (remove_overlaps)
        self._part_crowd(inside_margins=cap_mm >= 0)  # no move kept the gutter: no overlap
        return False

    def _part_crowd(self, inside_margins: bool = True) -> None:
        """A page too full for the gutter but not for its items alone, left overlapping by
        the pass (which gave up the margin for it too): physics.relocation aims at zero
        overlap inside the margins.  45 small items on a 10 cm card, 98 % of the room with
        the gutter and 65 % without, kept four overlaps and three items in the margin
        (random page 11000).  Also where relocation aimed at the gutter and failed: an A5
        page of captioned photos at 84.7 % kept two overlaps of 9 mm (fresh_projects seed
        3, tests/physics/jams/crowd-fresh-3.toml).  Where no move parts them inside the
        margins (or a limit says none can, not ``inside_margins``), the margin gives way,
        halved and then dropped, as in the pass (finalize.remove_overlaps): overlap last.
        Three photos that must stand in one row beside a hard block and a hard photo on a
        postcard (page_limits.PinnedStack) overlapped by 16.8 mm, where dropping the margin
        left room for all (fresh_projects seed 17)."""
        shares = ((1.0,) if inside_margins else ()) + MARGIN_GIVES_WAY
        for margin in [self.margin_mm * share for share in shares]:
            if not unexplained_pairs(self._bodies, [], 0.0) or self._relocate_jammed(0.0, margin):
                return
            if self.margin_mm <= 0:
                return

    def _relocate_to_cap(self, cap_mm: float) -> bool:
        """A page whose own items rule the gutter out (physics.page_limits.capping: a pair
        that cannot be parted, items that must stack, a unit with no room) keeps the widest
        gap they leave, ``cap_mm``, where the pass fell short of it: physics.relocation aims
        at that gap instead of the gutter, two roundings inside it so that the saved file
        keeps it to 0.02 mm.  Four items that must stack on Letter, a perfect packing to
        0.27 mm, were left 81.6 mm into each other by the pass alone (benchmarks/gutter_fits.py
        --seed 23).  A page already within WIDEST_GAP_SLACK_MM of the gap is left as it is, so
        that a settled page stays a fixed point.  Whether the page keeps that gap (where no
        limit caps it, ``cap_mm`` inf, there is nothing to aim at: True).  Where it does not,
        the caller aims at no overlap next: four items of three rooms on a banner that had to
        stand in one row 0.07 mm too long for the gutter kept the pass's two overlaps of
        13.9 mm (fresh_projects seed 118, tests/cli/fresh_projects/row-across-rooms-118)."""
        if cap_mm < 0:
            return False  # overlap is forced: the margin gives way first (finalize.remove_overlaps)
        if not np.isfinite(cap_mm) or not unexplained_pairs(self._bodies, [],
                                                            cap_mm - WIDEST_GAP_SLACK_MM):
            return True
        return self._relocate_jammed(cap_mm - 2 * ROUNDING_MM)

    def _relocate_jammed(self, gutter_mm: float, margin_mm: float | None = None) -> bool:
        """physics.relocation from the widest arrangement the pass reached, aiming at
        ``gutter_mm`` inside ``margin_mm`` (the page's margin unless given); back to that
        arrangement if no move lets the pass keep it."""
        bodies = self._bodies
        widest = bodies.centres.copy()
        margin = self.margin_mm if margin_mm is None else margin_mm

        def project() -> bool:  # as patient as the pass's own first attempt
            return project_within(bodies, self.page_w_mm, self.page_h_mm, gutter_mm,
                                  MAX_ITERATIONS, margin, fall_back=False,
                                  stall=STALL_ITERATIONS)
        if relocate_jammed(bodies, self.page_w_mm, self.page_h_mm, gutter_mm, margin,
                           project):
            return True
        placed = placed_anew(bodies, self.page_w_mm, self.page_h_mm, gutter_mm, margin)
        if placed is not None and self._spread_from(placed, RELOCATED_RUN_STEPS, project):
            return True
        bodies.centres[:] = widest
        return False

