"""Limits room by room (geometry.rooms_of, page_limits.room_caps), items of two regions never
crossing, and rows of items among pinned ones (page_limits.PinnedStack, physics.pinned_rows): each
exact for what it names, each checked against a brute-force search on small pages."""

from __future__ import annotations

import itertools
import shutil
from pathlib import Path

import numpy as np
import pytest

from floatpage.model import load_project, save_project
from floatpage.model.layout import engine_for_page, settle_project
from floatpage.physics import Engine
from floatpage.physics import pinned_rows
from floatpage.physics.params import Params
from floatpage.physics.page_limits import (
    Crossing, PinnedStack, Stack, close_pairs, page_limits, room_caps, rooms_of,
    unexplained_pairs,
)


ROOMS = Path(__file__).parent / "rooms"


def limits_of(engine: Engine) -> list:
    return page_limits(engine.bodies, engine.page_w_mm, engine.page_h_mm, engine.margin_mm,
                       engine.params.gutter_mm)


def split_page() -> Engine:
    """fresh_projects seed 9's page, cut down: a photos region above a words region."""
    engine = Engine(127.0, 177.8)
    engine.insert("calendar", 58.25, 150.05, 64.29, 34.76)
    engine.insert("photo", 32.07, 98.86, 48.55, 30.48)
    engine.confine("calendar", 0.0, 116.93, 127.0, 177.8)
    engine.confine("photo", 0.0, 0.0, 127.0, 116.93)
    return engine


def test_items_of_two_regions_one_above_the_other_never_cross():
    """Taken as the smaller of the two rooms, the calendar and the photo "could not be
    parted" (a Crossing with a widest gap of -0.28 mm) where the split parts them."""
    engine = split_page()
    assert [limit for limit in limits_of(engine) if isinstance(limit, Crossing)] == []
    engine.settle()
    assert engine.quality().ok


def test_items_of_two_regions_side_by_side_that_cannot_be_parted_still_cross():
    """The span two regions cover together is the room of a pair of their items: two items
    of two regions that overlap each other cross where together they are wider than both
    regions' span and taller than the page."""
    engine = Engine(100.0, 100.0)
    engine.insert("a", 30.0, 50.0, 50.0, 95.0)
    engine.insert("b", 60.0, 50.0, 52.0, 95.0)
    engine.confine("a", 0.0, 0.0, 60.0, 100.0)
    engine.confine("b", 40.0, 0.0, 100.0, 100.0)
    (crossing,) = [limit for limit in limits_of(engine) if isinstance(limit, Crossing)]
    span = 100.0 - 2 * engine.margin_mm
    assert crossing.rows == (0, 1)
    assert crossing.widest_gap_mm == pytest.approx(span - 102.0)


def stacked_regions() -> Engine:
    """A words region whose three wide panels must overlap (a Stack), and a photos region
    above it with room for its two photos side by side."""
    engine = Engine(148.0, 210.0)
    words = (0.0, 120.0, 148.0, 210.0)
    for k in range(3):
        engine.insert(f"panel{k}", 74.0, 165.0, 90.0, 40.0)
        engine.confine(f"panel{k}", *words)
    for k in range(2):
        engine.insert(f"photo{k}", 74.0, 60.0, 50.0, 40.0)
        engine.confine(f"photo{k}", 0.0, 0.0, 148.0, 120.0)
    return engine


def test_a_stack_in_one_region_caps_that_region_only():
    engine = stacked_regions()
    limits = limits_of(engine)
    (stack,) = [limit for limit in limits if isinstance(limit, Stack)]
    rooms = rooms_of(engine.bodies)
    assert rooms[0] == rooms[1] == rooms[2] != rooms[3] == rooms[4] != 0
    caps = room_caps(engine.bodies, limits, rooms)
    assert caps[rooms[0]] == pytest.approx(stack.widest_gap_mm) and stack.widest_gap_mm < 0
    assert caps[rooms[3]] == np.inf and caps[0] == np.inf
    # the photos on each other are not explained by the panels' overlap
    named = {(a, b) for a, b, _ in unexplained_pairs(engine.bodies, limits, 3.0)}
    assert (3, 4) in named


def test_relocation_room_by_room_parts_a_region_beside_one_that_must_overlap(tmp_path):
    """The page-wide cap (the panels' negative gap) stopped every relocation, and the photos
    region kept three overlaps of up to 19 mm; room by room, the photos region is relocated
    at the gutter with the panels held, and only the panels overlap.  A fixed point."""
    path = tmp_path / "rooms-7054.toml"
    shutil.copy(ROOMS / "rooms-7054.toml", path)
    project = load_project(path)
    settle_project(project)
    save_project(project)
    (page,) = project.pages
    engine = engine_for_page(page, project.physics)
    gutter = project.physics.gutter_mm
    limits = page_limits(engine.bodies, page.width_mm, page.height_mm, engine.margin_mm,
                         gutter)
    assert unexplained_pairs(engine.bodies, limits, gutter) == []
    panels = {k for k, item in enumerate(page.items) if item.region == "words"}
    for a, b in engine.quality().overlapping_pairs:
        assert {a, b} <= panels
    photos = [k for k, item in enumerate(page.items) if item.region == "photos"]
    assert not set(engine.quality().in_margin) & set(photos)
    settled = path.read_bytes()
    again = load_project(path)
    settle_project(again)
    save_project(again)
    assert path.read_bytes() == settled


def brute_row_fits(lengths, widths, room, blockers, gap, step=0.5) -> bool:
    """Whether the items fit in one row, by trying every order and every start on a grid."""
    low, high, across_low, across_high = room
    grid = np.arange(low, high + 1e-9, step)
    count = len(lengths)
    above = blockers[:, 2] - gap - across_low
    below = across_high - blockers[:, 3] - gap
    for order in itertools.permutations(range(count)):
        frontier, ok = -np.inf, True
        for k in order:
            blocking = (widths[k] > above) & (widths[k] > below)
            starts = [x for x in grid if x >= (low if frontier == -np.inf else frontier + gap)
                      and x + lengths[k] <= high + 1e-9
                      and not ((x < blockers[blocking, 1] + gap)
                               & (x + lengths[k] > blockers[blocking, 0] - gap)).any()]
            if not starts:
                ok = False
                break
            frontier = starts[0] + lengths[k]
        if ok:
            return True
    return False


@pytest.mark.parametrize("seed", range(40))
def test_a_row_among_blockers_fits_exactly_where_brute_force_finds_a_place(seed):
    rng = np.random.default_rng(seed)
    count = int(rng.integers(2, 5))
    lengths = rng.integers(4, 30, count).astype(float)
    widths = rng.integers(52, 90, count).astype(float)  # any two too tall to stack in 100
    room = (0.0, 100.0, 0.0, 100.0)
    blockers = []
    for _ in range(int(rng.integers(0, 3))):
        x, y = rng.integers(0, 90, 2).astype(float)
        w, h = rng.integers(4, 25, 2).astype(float)
        blockers.append((x, x + w, y, y + h))
    blockers = np.array(blockers, dtype=float).reshape(-1, 4)
    gap = 2.0
    rooms = np.tile(room, (count, 1))
    assert pinned_rows.fits(lengths, widths, rooms, blockers, gap) == brute_row_fits(
        lengths, widths, room, blockers, gap)


def pinned_row_page() -> Engine:
    """fresh_projects seed 17's postcard, cut down: three photos too tall for two to stand
    one above the other, a hard block in the middle of their row and a hard photo."""
    engine = Engine(148.0, 105.0, Params(gutter_mm=4.0, margin_mm=12.0))  # 6 mm here
    engine.insert("wide", 108.4, 40.0, 41.25, 47.66)
    engine.insert("photo", 84.9, 25.36, 32.65, 45.14)
    engine.insert("tall", 136.66, 40.0, 22.68, 57.6)
    engine.insert("block", 68.99, 41.91, 32.84, 33.44)
    engine.insert("hard photo", 107.83, 57.0, 27.73, 56.65)
    engine.anchor_point("block", 68.99, 41.91, hard=True)
    engine.anchor_point("hard photo", 107.83, 57.0, hard=True)
    return engine


def test_a_row_the_pinned_items_leave_no_room_for_is_named():
    engine = pinned_row_page()
    (limit,) = [limit for limit in limits_of(engine) if isinstance(limit, PinnedStack)]
    assert {0, 2} <= set(limit.rows) <= {0, 1, 2} and 3 in limit.pinned
    assert limit.axis == 0 and limit.widest_gap_mm < 0 and limit.fits_page
    # exact for the items it names: at a gap a little wider than it, brute force finds no
    # place for some set of them that must stand in one row; a little narrower, for every
    # such set
    halves = engine.bodies.sizes / 2
    centres = engine.bodies.centres
    blockers = np.array([[centres[k, 0] - halves[k, 0], centres[k, 0] + halves[k, 0],
                          centres[k, 1] - halves[k, 1], centres[k, 1] + halves[k, 1]]
                         for k in (3, 4)])
    rows = list(limit.rows)
    sizes = engine.bodies.sizes[rows]
    margin = engine.margin_mm
    room = (margin, 148.0 - margin, margin, 105.0 - margin)
    for gap, fits in ((limit.widest_gap_mm + 0.01, False), (limit.widest_gap_mm - 0.2, True)):
        rows_found = [brute_row_fits(sizes[chosen, 0], sizes[chosen, 1], room, blockers, gap,
                                     0.05)
                      for size in range(2, len(rows) + 1)
                      for chosen in map(list, itertools.combinations(range(len(rows)), size))
                      if pinned_rows.is_row(sizes[chosen, 1], np.tile(room, (len(chosen), 1)),
                                            gap)]
        assert rows_found and all(rows_found) == fits


def test_settle_gives_up_the_margin_before_it_overlaps_a_row_among_pinned_items():
    """The limit says no layout inside the margins parts them, and one on the page does:
    the margin gives way (issue #16's order), not overlap.  The pass alone kept 16.8 mm."""
    engine = pinned_row_page()
    engine.settle()
    assert engine.quality().overlap_count == 0


def brute_column_fits(heights, walls, gap, step=0.25) -> bool:
    """Whether items fit one above another, each between its own top and bottom walls
    (``walls`` (m, 2)), by trying every order and every start on a grid."""
    for order in itertools.permutations(range(len(heights))):
        frontier = -np.inf
        for k in order:
            low = max(walls[k][0], frontier + gap)
            grid = np.arange(walls[k][0], walls[k][1] + 1e-9, step)
            starts = grid[(grid >= low - 1e-9) & (grid + heights[k] <= walls[k][1] + 1e-9)]
            if not len(starts):
                break
            frontier = starts[0] + heights[k]
        else:
            return True
    return False


def brute_side_by_side(widths, walls_a, walls_b, gap, step=0.25) -> bool:
    """Whether two items fit side by side with ``gap``, each between its own left and right
    walls, on a grid."""
    xs_a = np.arange(walls_a[0], walls_a[1] - widths[0] + 1e-9, step)
    xs_b = np.arange(walls_b[0], walls_b[1] - widths[1] + 1e-9, step)
    left_a = xs_a[:, None] + widths[0] + gap <= xs_b[None, :] + 1e-9
    left_b = xs_b[None, :] + widths[1] + gap <= xs_a[:, None] + 1e-9
    return bool((left_a | left_b).any())


@pytest.mark.parametrize("seed", range(30))
def test_a_column_across_rooms_is_named_exactly(seed):
    """A free item narrow for the page but too wide to stand beside any photo of the photos
    region (fresh_projects seed 7114, cut down and drawn at random): where the mixed candidate
    names a column (PinnedStack, axis 1), brute force finds no layout of them at a gap a
    little wider than the one it gives (no two side by side, no column), and a little
    narrower the reason no longer holds; where it names none, brute force finds one."""
    rng = np.random.default_rng(seed)
    engine = Engine(100.0, 120.0, Params(gutter_mm=2.0, margin_mm=0.0))
    split = float(rng.integers(25, 35))
    engine.insert("text", 30.0, 60.0, float(rng.integers(36, 50)), float(rng.integers(40, 70)))
    for k in range(2):
        engine.insert(f"photo{k}", 65.0, 30.0 + 40 * k, float(rng.integers(52, 68)),
                      float(rng.integers(30, 50)))
        engine.confine(f"photo{k}", split, 0.0, 100.0, 120.0)
    limits = [limit for limit in limits_of(engine)
              if isinstance(limit, PinnedStack) and limit.axis == 1]
    sizes = engine.bodies.sizes
    walls = {0: (0.0, 100.0), 1: (split, 100.0), 2: (split, 100.0)}
    heights = sizes[:, 1]
    tops = {k: (0.0, 120.0) for k in range(3)}
    clash = all(not brute_side_by_side(sizes[[a, b], 0], walls[a], walls[b], 2.0)
                for a, b in itertools.combinations(range(3), 2))
    fits = brute_column_fits(heights, [tops[k] for k in range(3)], 2.0)
    if not limits:  # nothing named: the three need not stand in one column, or they fit
        assert not clash or fits
        return
    (limit,) = limits
    rows = list(limit.rows)
    for gap, expected in ((limit.widest_gap_mm + 0.01, False), (limit.widest_gap_mm - 0.3, True)):
        # a layout at this gap: two of them side by side, or all one above another
        beside = any(brute_side_by_side(sizes[[a, b], 0], walls[a], walls[b], gap)
                     for a, b in itertools.combinations(rows, 2))
        assert (beside or brute_column_fits(heights[rows], [tops[k] for k in rows], gap)
                ) == expected


def room_gaps(engine: Engine) -> list[tuple[float, float]]:
    """For each room with free units that one search can take: the closest pair its units
    are in, and the widest gap the search finds for them among every other item where it
    stands (inside the margins)."""
    from floatpage.physics.geometry import pinned_items
    from floatpage.physics.relocation import movable_units
    from floatpage.physics.unit_arrangements import search_of, widest_bracket
    bodies = engine.bodies
    gutter = engine.params.gutter_mm
    rooms = rooms_of(bodies)
    roots, _ = bodies.group_roots()
    pinned = pinned_items(bodies, roots)
    found = []
    for room in np.unique(rooms[bodies.active]):
        units = [unit for unit in movable_units(bodies) if rooms[unit.root] == room]
        if not units:
            continue
        mine = np.zeros(bodies.count, dtype=bool)
        mine[np.concatenate([unit.members for unit in units])] = True
        search = search_of(bodies, bodies.active & ~mine, engine.margin_mm, engine.page_w_mm,
                           engine.page_h_mm, gutter, taken=rooms == room)
        if search is None:
            continue
        obstacles = bodies.centres[search.obstacles], bodies.sizes[search.obstacles] / 2
        widest = widest_bracket(search.walls, *obstacles, gutter)
        rows = np.flatnonzero(bodies.active)
        closest = min(
            (gap for a, b, gap in close_pairs(bodies, rows, roots, gutter)
             if (mine[a] or mine[b]) and not (pinned[a] and pinned[b])), default=gutter)
        found.append((closest, widest.low))
    return found


@pytest.fixture(scope="module")
def settled_9614(tmp_path_factory):
    """rooms-9614.toml settled (its path, and the page's bytes after one settle)."""
    path = tmp_path_factory.mktemp("rooms") / "rooms-9614.toml"
    shutil.copy(ROOMS / "rooms-9614.toml", path)
    project = load_project(path)
    settle_project(project)
    save_project(project)
    return path, path.read_bytes()


def test_a_room_too_many_for_the_whole_pages_search_is_set_down_on_its_own(settled_9614):
    """fresh_projects seed 9614, p4: the photos region's ten members could stand wider apart
    around the rest of the page where it stands than the 0.02 mm the settle left them (the
    whole page's sixteen items were too many for one search, and its rooms were never
    searched alone).  Settled, no room's units can be set down wider, and the file is a
    fixed point."""
    path, settled = settled_9614
    project = load_project(path)
    (page,) = project.pages
    engine = engine_for_page(page, project.physics)
    gaps = room_gaps(engine)
    assert gaps, "the photos region is one search"
    for closest, widest in gaps:
        assert widest <= closest + 0.05
    assert engine.quality().overlap_count == 0
    settle_project(project)
    save_project(project)
    assert path.read_bytes() == settled


def test_the_units_around_the_closest_pair_are_set_down_in_their_window(settled_9614):
    """The same page: set down room by room, the photos region kept 0.3 mm where a free
    text of the page reaches into it; the units around the closest pair, searched inside a
    window around them with the rest where it stands (physics.near_arrangement), find no
    wider gap once settled."""
    from floatpage.physics.geometry import pinned_items
    from floatpage.physics.near_arrangement import near_search
    from floatpage.physics.relocation import movable_units
    from floatpage.physics.unit_arrangements import widest_bracket
    path, _ = settled_9614
    project = load_project(path)
    (page,) = project.pages
    engine = engine_for_page(page, project.physics)
    bodies, gutter = engine.bodies, engine.params.gutter_mm
    roots, _ = bodies.group_roots()
    pinned = pinned_items(bodies, roots)
    rows = np.flatnonzero(bodies.active)
    (a, b, closest), *_ = close_pairs(bodies, rows, roots, gutter,
                                      lambda a, b, gaps: ~(pinned[a] & pinned[b]))
    search = near_search(bodies, movable_units(bodies), (a, b), engine.margin_mm,
                         engine.page_w_mm, engine.page_h_mm, gutter)
    assert search is not None
    obstacles = bodies.centres[search.obstacles], bodies.sizes[search.obstacles] / 2
    assert widest_bracket(search.walls, *obstacles, gutter).low <= closest + 0.05


def test_check_speaks_of_the_gap_a_limit_leaves_not_of_a_gutter_that_fits():
    """The page as main's settle left it: check named the photos region's NoArrangement (the
    widest gap they can all keep is 2.2 mm) and, of the same pairs, that "the 3 mm gutter
    fits ... but is not kept".  The advice now speaks of the 2.2 mm the limit leaves and
    the gap the page keeps."""
    from floatpage.model.page_report import page_report
    project = load_project(ROOMS / "rooms-9614.toml")
    (page,) = project.pages
    engine = engine_for_page(page, project.physics)
    gutter = project.physics.gutter_mm
    lines, problems = page_report(page, engine, gutter)
    text = "\n".join(lines)
    (limit,) = limits_of(engine)
    closest = engine.quality().min_gap_mm
    assert f"the widest gap they can all keep is {limit.widest_gap_mm:.1f} mm" in text
    assert "gutter fits" not in text
    assert (f"they can keep {limit.widest_gap_mm:.1f} mm, not the {gutter:g} mm gutter, but "
            f"page {page.id} keeps {closest:.1f} mm") in text
    assert problems == 1


def test_check_speaks_of_the_cap_where_the_closest_pair_is_a_free_items(settled_9614):
    """Settled, the page's closest pair is a free text beside the capped photos region (its
    cap is the free room's: none), while pairs of the region stand closer than its 2.2 mm:
    check said "the 3 mm gutter fits ... but is not kept" again, below the region's limit."""
    from floatpage.model.page_report import page_report
    path, _ = settled_9614
    project = load_project(path)
    (page,) = project.pages
    engine = engine_for_page(page, project.physics)
    gutter = project.physics.gutter_mm
    limits = limits_of(engine)
    loose = unexplained_pairs(engine.bodies, limits, gutter)
    caps = room_caps(engine.bodies, limits)
    rooms = rooms_of(engine.bodies)
    (limit,) = limits
    assert loose and np.isinf(caps[rooms[loose[0][0]]]) | np.isinf(caps[rooms[loose[0][1]]])
    text = "\n".join(page_report(page, engine, gutter)[0])
    assert "gutter fits" not in text
    assert f"they can keep {limit.widest_gap_mm:.1f} mm, not the {gutter:g} mm gutter" in text
