"""Regions (issue 16): an item confined to a region keeps inside it, as it keeps inside the page,
in the physics, the no-overlap pass and the snap; a region's edges are guides for every item;
a region whose items do not fit makes overlap the last thing to give, never its walls."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from floatpage.physics import Engine, Params
from floatpage.physics.bodies import Bodies
from floatpage.physics.geometry import room_covers
from floatpage.physics.guides import page_lines
from floatpage.physics.quality import MARGIN_TOLERANCE_MM

A4 = (210.0, 297.0)
PROPERTIES = settings(max_examples=20, deadline=None, derandomize=True, database=None,
                      suppress_health_check=[HealthCheck.too_slow])


def engine_with(items, regions, params=Params()):
    """An engine holding ``items`` ((x, y, w, h)), item k confined to ``regions[k]`` (a box
    (left, top, right, bottom), or None)."""
    engine = Engine(*A4, params)
    for k, (x, y, w, h) in enumerate(items):
        engine.insert(f"i{k}", x, y, w, h)
        if regions[k] is not None:
            engine.confine(f"i{k}", *regions[k])
    return engine


def outside(engine, k, box, tolerance=MARGIN_TOLERANCE_MM):
    (x, y), (w, h) = engine.positions()[f"i{k}"], engine.sizes()[f"i{k}"]
    left, top, right, bottom = box
    return (x - w / 2 < left - tolerance or y - h / 2 < top - tolerance
            or x + w / 2 > right + tolerance or y + h / 2 > bottom + tolerance)


def test_items_dropped_outside_their_region_settle_inside_it_with_no_overlap():
    top_third = (0.0, 0.0, 210.0, 99.0)
    items = [(105 + 3 * k, 250 - 2 * k, 40, 25) for k in range(4)] + [(105, 150, 60, 40)]
    engine = engine_with(items, [top_third] * 4 + [None])
    report = engine.settle()
    quality = engine.quality()
    assert report.fits and quality.ok, quality.summary()
    assert quality.outside_region == ()
    assert not any(outside(engine, k, top_third) for k in range(4))


def test_the_region_is_a_wall_and_the_print_margin_still_holds_where_it_meets_the_page():
    """A region flush with the page's edge: the item keeps the page's print-safe margin there
    (5 mm on A4), and the region's own edge inside the page."""
    region = (0.0, 0.0, 100.0, 100.0)
    engine = engine_with([(20, 20, 30, 30), (50, 60, 30, 30)], [region, region])
    engine.settle()
    for k in range(2):
        (x, y), (w, h) = engine.positions()[f"i{k}"], engine.sizes()[f"i{k}"]
        assert x - w / 2 >= 5.0 - MARGIN_TOLERANCE_MM and y - h / 2 >= 5.0 - MARGIN_TOLERANCE_MM
        assert x + w / 2 <= 100.0 + MARGIN_TOLERANCE_MM and y + h / 2 <= 100.0 + MARGIN_TOLERANCE_MM


def test_an_over_full_region_keeps_its_walls_and_reports_the_overlap():
    """Four 60 mm squares cannot share a 100 mm square without overlap: the walls hold, and
    the overlap is reported, not hidden by pushing items out."""
    region = (50.0, 50.0, 150.0, 150.0)
    engine = engine_with([(100 + k, 100, 60, 60) for k in range(4)], [region] * 4)
    report = engine.settle()
    quality = engine.quality()
    assert not report.fits and quality.overlap_count > 0
    assert quality.outside_region == ()


def test_a_follower_confined_to_a_region_keeps_its_whole_group_inside_it():
    """A caption 20 mm below its photo, the caption confined to the top half: the photo, which
    leads, stops where the caption meets the region's wall."""
    engine = Engine(*A4)
    engine.insert("photo", 105, 200, 80, 50)
    engine.insert("caption", 105, 240, 80, 10)
    engine.anchor_to("caption", "photo", 0.0, 35.0)
    engine.confine("caption", 0.0, 0.0, 210.0, 148.5)
    engine.settle()
    assert engine.quality().outside_region == ()
    assert engine.positions()["caption"][1] + 5 <= 148.5 + MARGIN_TOLERANCE_MM


def test_region_edges_are_guide_lines_for_everyone():
    bodies = Bodies()
    bodies.append((50, 50), (20, 20), decorative=False)
    bodies.append((150, 50), (20, 20), decorative=False)
    bodies.regions[0] = (10.0, 20.0, 120.0, 140.0)
    xs, _ = page_lines(*A4, 5.0, 0, bodies.regions)
    ys, _ = page_lines(*A4, 5.0, 1, bodies.regions)
    assert {10.0, 120.0} <= set(xs) and {20.0, 140.0} <= set(ys)


def test_paper_mode_walls_stand_at_the_region():
    """The paper's wall force (4.4) stands at each item's region: an item between its region's
    walls is pushed to their middle, not to the page's."""
    params = Params(mode="paper", heat_decay=0.0)
    confined = engine_with([(30.0, 148.5, 10, 10)], [(0.0, 0.0, 100.0, 297.0)], params)
    free = engine_with([(30.0, 148.5, 10, 10)], [None], params)
    for engine in (confined, free):
        engine.reheat()
        engine.advance(20_000)
    # the middle between the 5 mm margin and the region's edge, against the page's middle
    assert abs(confined.positions()["i0"][0] - 52.5) < 2.0
    assert abs(free.positions()["i0"][0] - 105.0) < 5.0


@PROPERTIES
@given(st.integers(0, 10_000), st.integers(2, 12), st.floats(0.3, 0.7), st.floats(0.3, 0.7))
def test_settled_items_never_leave_their_region(seed, count, share_w, share_h):
    """Random items, half confined to a random region, from random places (many outside it):
    after settle none of them is outside its region, and none is off the page."""
    rng = np.random.default_rng(seed)
    width, height = share_w * A4[0], share_h * A4[1]
    left = rng.uniform(0, A4[0] - width)
    top = rng.uniform(0, A4[1] - height)
    region = (left, top, left + width, top + height)
    items = [(rng.uniform(10, 200), rng.uniform(10, 287), rng.uniform(5, 25), rng.uniform(5, 25))
             for _ in range(count)]
    regions = [region if k % 2 == 0 else None for k in range(count)]
    engine = engine_with(items, regions, Params(seed=seed))
    engine.settle(max_steps=20_000)
    quality = engine.quality()
    assert quality.outside_region == ()
    assert quality.off_page == ()


@PROPERTIES
@given(st.lists(st.tuples(st.floats(10, 200), st.floats(10, 287), st.floats(5, 120),
                          st.floats(5, 160), st.booleans(), st.floats(-150, 150),
                          st.floats(-200, 200)), min_size=2, max_size=6),
       st.tuples(st.floats(0, 100), st.floats(0, 150), st.floats(30, 110), st.floats(30, 150)))
@example([(60, 60, 30, 20, False, 0, 0), (60, 220, 30, 20, False, 0, 160)], (20, 20, 170, 80))
def test_check_names_a_group_too_large_exactly_where_the_physics_squeezes_it(items, box):
    """page_limits' TooLarge and the walls the physics holds a group to (geometry.group_bounds)
    read one rule (geometry.group_room): check said nothing of a confined lead whose follower,
    outside the region, made the group taller than the region, while the physics held the whole
    group to the region and squeezed it; and a group check called too large must be one the
    physics squeezes.  Each item follows the first; the even ones keep to the region."""
    from floatpage.physics.geometry import group_bounds, group_room
    from floatpage.physics.page_limits import page_limits
    from floatpage.physics.limit_kinds import TooLarge
    left, top, w, h = box
    region = (left, top, left + w, top + h)
    engine = Engine(*A4, Params())
    for k, (x, y, iw, ih, bleed, dx, dy) in enumerate(items):
        engine.insert(f"i{k}", x, y, iw, ih, bleed=bleed)
        if k % 2 == 0:
            engine.confine(f"i{k}", *region)
        if k:
            engine.anchor_to(f"i{k}", "i0", dx, dy)
    bodies = engine.bodies
    roots, offsets = bodies.group_roots()
    near, far = bodies.insets(engine.margin_mm, *A4)
    rows = np.array([0])
    lowest, highest = group_room(bodies, roots, offsets, near, far, *A4)
    bounded_low, bounded_high = group_bounds(bodies, rows, roots, offsets, near, far, *A4)
    named = {limit.axis for limit in page_limits(bodies, *A4, engine.margin_mm, 3.0)
             if isinstance(limit, TooLarge) and limit.rows[0] == 0}
    for axis in (0, 1):
        if lowest[0, axis] <= highest[0, axis]:
            assert axis not in named
            assert bounded_low[0, axis] == lowest[0, axis]
            assert bounded_high[0, axis] == highest[0, axis]
        elif lowest[0, axis] > highest[0, axis] + 1e-9:
            assert axis in named
            assert bounded_low[0, axis] == bounded_high[0, axis]  # squeezed to one place


def test_a_regions_room_is_what_items_that_cannot_move_leave_of_it():
    """A header hard-anchored across the top of a region of photos takes that part of the
    region from them: the photos' room is the rest.  Fresh project seed 7088 crammed ten
    photos into what a header left, and check called the page 70 % full, "run settle", where
    the photos needed 95 % of their room; a soft-anchored item can move away and takes none."""
    region = (0.0, 0.0, 210.0, 150.0)
    photos = [(40 + 60 * (k % 3), 100 + 30 * (k // 3), 50, 20) for k in range(6)]
    items = [(105, 25, 210, 50), (105, 60, 30, 10), *photos]
    engine = engine_with(items, [None, None] + [region] * 6, Params(gutter_mm=0.0))

    def photos_cover():  # the region's room: the page's own comes first (room_covers)
        near, far = engine.bodies.insets(engine.margin_mm, *A4)
        return room_covers(engine.bodies, near, far, *A4, 0.0)[1]

    free = photos_cover()
    engine.anchor_point("i1", 105, 60, hard=False, gamma=0.5)  # soft: takes no room
    assert photos_cover() == free
    engine.anchor_point("i0", 105, 25, hard=True)
    photo_area = 6 * 50 * 20
    room = (210 - 2 * engine.margin_mm) * (150 - engine.margin_mm)  # the margin at three sides
    header = (210 - 2 * engine.margin_mm) * (50 - engine.margin_mm)
    assert free == pytest.approx(photo_area / room)
    assert photos_cover() == pytest.approx(photo_area / (room - header))
