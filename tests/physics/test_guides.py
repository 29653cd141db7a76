"""The magnetic alignment guides (issue 16): the pull (physics.guides), the exact snap after
the no-overlap pass (physics.snapping), and what they must never do: overlap, leave the page
or the margin, narrow the gutter, move held or hard-anchored items, or stop a settled file
being a fixed point."""

from __future__ import annotations

import copy
import functools
import tempfile
from pathlib import Path
from unittest import mock

import numpy as np
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from floatpage.model import load_project, save_project
from floatpage.model.document import BlockItem, ItemAnchor, Page, PhysicsSettings, PointAnchor, Project
from floatpage.model.layout import AT_REST_MM, settle_project
from floatpage.physics import Engine, Params, snap_memo, snapping
from floatpage.physics.alignment import measure_alignment
from floatpage.physics.bodies import Bodies
from floatpage.physics.finalize import ROUNDING_MM, remove_overlaps
from floatpage.physics.geometry import GUTTER_FITS_COVER, ROOMY_COVER
from floatpage.physics.guides import GuidePulls, snap_range
from floatpage.physics.params import page_margin
from floatpage.physics.quality import measure_quality
from seeded_scenes import big_item_scene, dropped_scene, load, mixed_scene
from floatpage.physics.snapping import (
    EVERY_MOVE, _Snapper, snap_limits, snap_page, snap_to_guides,
)
from floatpage.physics.stillness import PROBE_HEAT

A4 = (210.0, 297.0)
CLEARANCE = 3.0 + ROUNDING_MM
PROPERTIES = settings(max_examples=15, deadline=None, derandomize=True, database=None,
                      suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


def bodies_of(*items, bleed=()):
    """Bodies from (x, y, w, h) tuples, at rest."""
    bodies = Bodies()
    for k, (x, y, w, h) in enumerate(items):
        bodies.append((x, y), (w, h), decorative=False, bleed=k in bleed)
    return bodies


def snap(bodies, margin=5.0):
    """The snap's geometry alone (no rest check): what it may do on an open page."""
    return snap_to_guides(bodies, *A4, CLEARANCE, margin, 1.0)


def test_the_snap_range_is_4_mm_on_a4_and_scales_with_the_page():
    assert snap_range(*A4) == 4.0
    assert snap_range(105.0, 148.5) == 2.0  # A6: half the linear size


def test_two_tops_2_mm_apart_are_put_on_one_line():
    bodies = bodies_of((60, 100, 40, 30), (150, 102, 40, 30))
    assert snap(bodies) > 0
    top = bodies.centres[:, 1] - bodies.sizes[:, 1] / 2
    assert abs(top[0] - top[1]) < 1e-9


def test_a_column_a_way_out_of_a_near_miss_left_just_beyond_the_range_is_lined_up():
    # Two photos of one width, one above the other, their left edges 4.05 mm apart: where the
    # snap's own way out of a near miss leaves a pair (ESCAPE_MM), a hair beyond one snap
    # range.  Nothing is a near miss, but lining them up gains three alignments and fits:
    # a line up to two ranges away is a candidate (ALIGN_REACH), so the column lines up.
    bodies = bodies_of((57.5, 73.25, 83.52, 55.72), (53.45, 156.25, 83.52, 55.72))
    assert snap(bodies) > 0
    left = bodies.centres[:, 0] - bodies.sizes[:, 0] / 2
    assert abs(left[0] - left[1]) < 1e-9


def test_an_edge_near_the_margin_line_goes_onto_it_and_a_bleed_edge_onto_the_page_edge():
    bodies = bodies_of((27.0, 150, 40, 30), (190, 240, 40, 30), bleed=(1,))
    snap(bodies)
    assert bodies.centres[0, 0] - 20 == 5.0  # the left margin line
    assert bodies.centres[1, 0] + 20 == 210.0  # the bleed photo to the page's right edge


def test_a_centre_near_the_page_middle_is_centred():
    bodies = bodies_of((107.5, 150, 60, 30))
    snap(bodies)
    assert bodies.centres[0, 0] == 105.0


def test_a_snap_that_would_break_the_gutter_is_refused():
    # b's left edge misses a's by 2 mm, but c sits 3.5 mm to b's left: closing the miss would
    # leave 1.5 mm.  The snap may open the miss instead; it never closes the gutter.
    bodies = bodies_of((80, 60, 40, 30), (82, 95, 40, 30), (38.5 - 20, 95, 40, 30))
    snap(bodies)
    c, h = bodies.centres, bodies.sizes / 2
    assert (c[1, 0] - h[1, 0]) - (c[2, 0] + h[2, 0]) >= CLEARANCE - 1e-9
    quality = measure_quality(*A4, c, bodies.sizes, 3.0)
    assert quality.min_gap_mm >= 3.0


def test_held_and_hard_anchored_items_are_guides_and_never_move():
    bodies = bodies_of((60, 100, 40, 30), (150, 102, 40, 30), (100, 200, 40, 30))
    bodies.held[0] = True
    bodies.hard[2] = True
    bodies.anchors[2] = (100, 200)
    before = bodies.centres.copy()
    snap(bodies)
    assert (bodies.centres[[0, 2]] == before[[0, 2]]).all()
    assert bodies.centres[1, 1] == 100.0  # b came to the held item's line


def test_a_group_moves_as_one():
    bodies = bodies_of((60, 100, 40, 30), (150, 102, 40, 30), (150, 125, 40, 10))
    bodies.targets[2] = 1
    bodies.offsets[2] = (0.0, 23.0)
    snap(bodies)
    assert bodies.centres[0, 1] == bodies.centres[1, 1]  # a and b on one line, however it went
    assert tuple(bodies.centres[2] - bodies.centres[1]) == (0.0, 23.0)


def test_a_column_moves_onto_a_line_as_one():
    # Two pictures whose left edges line up, 3 mm left of a held band's edge.  One alone can
    # only trade its near miss with the band for one with the other picture, or step 4 mm
    # out of both and break the column; moved as one line, both meet the band's edge.
    bodies = bodies_of((32, 60, 40, 40), (32, 120, 40, 40), (105, 250, 180, 20))
    bodies.held[2] = True
    snap(bodies)
    left = bodies.centres[:, 0] - bodies.sizes[:, 0] / 2
    assert tuple(left) == (15.0, 15.0, 15.0)
    assert tuple(bodies.centres[:, 1]) == (60, 120, 250)


def test_strength_zero_leaves_the_no_overlap_pass_alone():
    scene = mixed_scene(20, 0.5, seed=3)
    results = []
    for guides in (0.0, 1.0):
        engine = Engine(*A4, Params(guides=guides))
        load(engine, scene)
        engine.settle(finalize=False)
        results.append(engine)
    off, on = results
    plain = copy.deepcopy(off.bodies)
    remove_overlaps(plain, *A4, 3.0, margin_mm=off.margin_mm)
    off.finalize()
    assert (off.bodies.centres == plain.centres).all()
    assert snap_page(copy.deepcopy(plain), *A4, Params(guides=0.0)) == 0


def test_the_pull_draws_a_near_edge_onto_its_guide():
    centres = np.array([[60.0, 100.0], [150.0, 102.0]])
    sizes = np.array([[40.0, 30.0], [40.0, 30.0]])
    pull = GuidePulls(centres, sizes, np.ones(2, bool), np.array([False, True]), A4, 5.0, 1.0)
    acc = np.zeros((2, 2))
    for _ in range(8):
        pull.add_to(acc, centres, 0.1)
    assert acc[1, 1] < 0 and acc[0].tolist() == [0.0, 0.0]  # up, towards a's line; a is not pulled


def test_settled_pages_line_up_far_better_and_stay_clean():
    for scene in (mixed_scene(20, 0.5, seed=1), dropped_scene(12), mixed_scene(15, 0.4, seed=9)):
        misses = {}
        for guides in (0.0, 1.0):
            engine = Engine(scene.page_w_mm, scene.page_h_mm, Params(guides=guides))
            load(engine, scene)
            report = engine.settle()
            quality = engine.quality()
            assert report.fits and quality.ok
            misses[guides] = measure_alignment(engine.bodies.centres, engine.bodies.sizes
                                               ).near_misses_per_item
        assert misses[1.0] < 0.6 * misses[0.0], (scene.name, misses)


def test_a_crowded_page_whose_gutter_fits_still_lines_up():
    # 40 items covering 56 % of A5: grown by the gutter they need 78 % of the room, past
    # ROOMY_COVER, where alignment gave way on any page of more than 12 items (7.8-10.9 near
    # misses an item left on such pages); up to LINE_UP_ITEMS items it lines up while the
    # gutter fits
    scene = mixed_scene(40, 0.56, seed=1, page_w_mm=148.0, page_h_mm=210.0)
    misses = {}
    for guides in (0.0, 1.0):
        engine = Engine(scene.page_w_mm, scene.page_h_mm, Params(guides=guides))
        load(engine, scene)
        assert ROOMY_COVER < engine.grown_cover() <= GUTTER_FITS_COVER
        report = engine.settle()
        assert report.fits and engine.quality().ok and engine.lines_up
        misses[guides] = engine.alignment().near_misses_per_item
    assert misses[1.0] < 0.6 * misses[0.0], misses


def near_aligned_pairs(centres, sizes, low=0.05, high=0.5):
    """Pairs of same-kind features of different items between ``low`` and ``high`` apart."""
    found = 0
    for axis in (0, 1):
        c, h = centres[:, axis], sizes[:, axis] / 2
        for values in ((c - h, c + h), (c,)):
            pool = np.concatenate(values)
            owners = np.tile(np.arange(len(c)), len(values))
            d = np.abs(pool[:, None] - pool[None, :])
            found += int(((d > low) & (d < high) & (owners[:, None] != owners[None, :])).sum()) // 2
    return found


def test_once_settled_nearly_aligned_pairs_are_exactly_aligned():
    # Pairs 0.05-0.5 mm apart are what the eye takes for a slip.  A few can stay where the
    # gutter forbids closing them (an edge between two items' facing edges), or where closing
    # one opens another (a local minimum of single moves): at most a quarter over the pages.
    # Summed, not per page: on one page the count moves by a few pairs with any change to the
    # snap's search (50 items: 14, then 19 of 60 once lines two ranges away were candidates,
    # while twelve fresh 45-item pages went from 108 to 102 slips and 1378 to 1555 alignments).
    slips = {0.0: 0, 1.0: 0}
    for scene in (mixed_scene(20, 0.5, seed=1), dropped_scene(12), mixed_scene(50, 0.5, seed=1)):
        counts = {}
        for guides in (0.0, 1.0):
            engine = Engine(*A4, Params(guides=guides))
            load(engine, scene)
            engine.settle()
            centres, sizes = engine.bodies.centres, engine.bodies.sizes
            counts[guides] = (near_aligned_pairs(centres, sizes),
                              near_aligned_pairs(centres, sizes, -1.0, 0.05))
        (slips_off, exact_off), (slips_on, exact_on) = counts[0.0], counts[1.0]
        slips[0.0], slips[1.0] = slips[0.0] + slips_off, slips[1.0] + slips_on
        assert exact_on >= 3 * max(exact_off, 1), (scene.name, counts)
    assert slips[1.0] <= slips[0.0] / 4, slips


# ----- properties --------------------------------------------------------------------------

@st.composite
def crowded_pages(draw):
    """Pages whose items sit on a jittered grid (so that many edges nearly line up), some held,
    hard-anchored, following another item, or bleeding; sometimes too full for the gutter."""
    page_w, page_h = draw(st.floats(90, 300)), draw(st.floats(90, 300))
    columns, rows = draw(st.integers(1, 4)), draw(st.integers(1, 4))
    engine = Engine(page_w, page_h, Params(guides=draw(st.sampled_from([0.5, 1.0, 3.0])),
                                           seed=draw(st.integers(0, 100))))
    fill = draw(st.floats(0.3, 1.05))
    cell_w, cell_h = page_w / columns, page_h / rows
    for k in range(columns * rows):
        x = (k % columns + 0.5) * cell_w + draw(st.floats(-4, 4))
        y = (k // columns + 0.5) * cell_h + draw(st.floats(-4, 4))
        w = cell_w * fill * draw(st.floats(0.6, 1.0))
        h = cell_h * fill * draw(st.floats(0.6, 1.0))
        engine.insert(f"i{k}", x, y, w, h, bleed=draw(st.integers(0, 5)) == 0)
    for item in engine.ids:
        role = draw(st.sampled_from(["free", "free", "free", "held", "hard", "follow"]))
        if role == "held":
            engine.hold(item)
        elif role == "hard":
            x, y = engine.positions()[item]
            engine.anchor_point(item, x, y, hard=True)
        elif role == "follow" and item != engine.ids[0]:
            target = engine.ids[0]
            (x, y), (tx, ty) = engine.positions()[item], engine.positions()[target]
            try:
                engine.anchor_to(item, target, x - tx, y - ty)
            except ValueError:
                pass
    engine.advance(draw(st.integers(0, 300)))
    return engine


@PROPERTIES
@given(crowded_pages())
def test_snapping_never_makes_a_page_worse(engine):
    bodies = engine.bodies
    page = (engine.page_w_mm, engine.page_h_mm)
    margin = page_margin(engine.params.margin_mm, *page)
    remove_overlaps(bodies, *page, engine.params.gutter_mm, margin_mm=margin)
    roots, offsets = bodies.group_roots()
    before = measure_quality(*page, bodies.centres, bodies.sizes, engine.params.gutter_mm,
                             groups=roots, margins=bodies.margins(margin))
    fixed = bodies.held | bodies.hard
    pinned = bodies.centres[fixed].copy()
    snap_page(bodies, *page, engine.params)
    after = measure_quality(*page, bodies.centres, bodies.sizes, engine.params.gutter_mm,
                            groups=roots, margins=bodies.margins(margin))
    assert len(after.overlapping_pairs) <= len(before.overlapping_pairs)
    assert set(after.off_page) <= set(before.off_page)
    assert set(after.in_margin) <= set(before.in_margin)
    assert after.min_gap_mm >= min(before.min_gap_mm, engine.params.gutter_mm) - 1e-6
    assert (bodies.centres[fixed] == pinned).all()
    _, offsets_after = bodies.group_roots()
    assert np.allclose(offsets_after, offsets)


def moves_left(bodies, page, params) -> list[tuple[int, int]]:
    """The (root, axis) of every group that a move of its own would still improve on a page
    snapped already: every move that lowers its count scored (no cut to the best few) and
    tried through the snap's own checks (``_Snapper.attempt``, which makes it; on a copy)."""
    bodies = copy.deepcopy(bodies)
    snapper = _Snapper(bodies, page, *snap_limits(bodies, *page, params))
    snapper.tries = EVERY_MOVE
    return [(int(row), axis) for axis in (0, 1) for row in snapper.movers
            if snapper.attempt(snapper.options([int(row)], axis), axis)]


def test_the_snap_ends_only_where_no_move_that_lowers_the_count_passes_its_checks():
    """On the random 60 items of the alignment benchmark, A4 landscape, the snap used to stop
    once a body's 8 best moves were blocked, with a lesser move that passed every check left
    untried (item 25, along x).

    Seeded, not a property over random pages: a later sweep tries again only the bodies near
    a move on the same axis, so a move along x that frees room for a body's move along y is
    not followed up, and Hypothesis finds crowded pages where such a move is left (the next
    settle's probe makes it; the saved file is still a fixed point, model.layout)."""
    scene = mixed_scene(60, 0.5, seed=105, page_w_mm=297.0, page_h_mm=210.0)
    engine = Engine(scene.page_w_mm, scene.page_h_mm, Params())
    load(engine, scene)
    engine.settle()
    page = (engine.page_w_mm, engine.page_h_mm)
    assert moves_left(engine.bodies, page, engine.params) == []


@PROPERTIES
@given(crowded_pages())
def test_a_page_settled_with_guides_is_as_sound_as_the_no_overlap_pass_leaves_it(engine):
    """The physics with the guide force, then the pass and the snap (Engine.finalize), against
    the same physics then the pass alone: guides add no overlap, no item off the page or in
    the margin, and no narrower gap."""
    engine.settle(max_steps=5_000, finalize=False)
    alone = copy.deepcopy(engine)
    remove_overlaps(alone.bodies, alone.page_w_mm, alone.page_h_mm, alone.params.gutter_mm,
                    margin_mm=alone.margin_mm)
    fits = engine.finalize()
    with_guides, without = engine.quality(), alone.quality()
    assert len(with_guides.overlapping_pairs) <= len(without.overlapping_pairs)
    assert set(with_guides.off_page) <= set(without.off_page)
    assert set(with_guides.in_margin) <= set(without.in_margin)
    assert with_guides.min_gap_mm >= min(without.min_gap_mm, engine.params.gutter_mm) - 1e-6
    if fits:
        assert not with_guides.overlapping_pairs
        assert with_guides.min_gap_mm >= engine.params.gutter_mm - 1e-6
    assert np.isfinite(engine.bodies.centres).all()


@st.composite
def near_aligned_projects(draw) -> Project:
    page_w, page_h = round(draw(st.floats(100, 300)), 2), round(draw(st.floats(100, 300)), 2)
    columns, rows = draw(st.integers(1, 3)), draw(st.integers(1, 4))
    items = []
    for k in range(columns * rows):
        w = page_w / columns * draw(st.floats(0.4, 0.7))
        h = page_h / rows * draw(st.floats(0.4, 0.7))
        x = (k % columns + 0.5) * page_w / columns + draw(st.floats(-3, 3))
        y = (k // columns + 0.5) * page_h / rows + draw(st.floats(-3, 3))
        item = BlockItem(id=f"b{k}", x=round(x, 2), y=round(y, 2), w=round(w, 2), h=round(h, 2))
        anchor = draw(st.sampled_from(["none", "none", "soft", "follow"]))
        if anchor == "soft":
            item.anchor = PointAnchor(x=item.x, y=item.y, gamma=draw(st.floats(0.1, 1.0)))
        elif anchor == "follow" and items and items[0].anchor is None:
            item.anchor = ItemAnchor(to=items[0].id, dx=round(item.x - items[0].x, 2),
                                     dy=round(item.y - items[0].y, 2))
        items.append(item)
    physics = PhysicsSettings(seed=draw(st.integers(0, 1000)),
                              guides=draw(st.sampled_from([0.5, 1.0, 3.0])))
    page = Page(id="p", size="custom", width_mm=page_w, height_mm=page_h, items=items)
    return Project(title="near-aligned", physics=physics, pages=[page])


@settings(max_examples=10, deadline=None, derandomize=True, database=None,
          phases=[Phase.explicit, Phase.generate],
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(near_aligned_projects())
def test_a_page_settled_with_guides_is_a_fixed_point(project):
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "page.toml"
        save_project(project, path)
        for _ in range(2):
            loaded = load_project(path)
            settle_project(loaded, max_steps=20_000)
            save_project(loaded)
            if _ == 0:
                settled = path.read_bytes()
        assert path.read_bytes() == settled


def test_a_snapped_page_is_at_rest_for_the_gentle_run_that_probes_it():
    """The snap's rest check compares the push a line's hold leaves, before a move and after it
    alike.  Comparing the held push after a move with the bare push before it counted the
    hold's allowance again at every move: a row of items was pressed harder move by move, and
    the gentle run that asks whether the page is at rest moved them millimetres (3 mm on this
    A5 page, 4.6 mm on the one-big-item page), so settling took probe after probe."""
    scenes = (mixed_scene(15, 0.45, seed=101, page_w_mm=148.0, page_h_mm=210.0),
              big_item_scene(seed=1))
    for scene in scenes:
        engine = Engine(scene.page_w_mm, scene.page_h_mm, Params())
        load(engine, scene)
        engine.settle()
        snapped = engine.bodies.centres.copy()
        engine.reheat(PROBE_HEAT)
        engine.settle(finalize=False)
        drift = np.abs(engine.bodies.centres - snapped).max()
        assert drift <= AT_REST_MM, f"{scene.name}: the probe moved an item {drift:.2f} mm"


# ----- what the snap remembers between its tries (physics.snap_memo) -------------------------

def snapped_twice(bodies, page, params):
    """The page snapped as shipped (the compiled sweeps, their memo in C), and snapped by the
    Python sweeps with a memo that never recalls."""
    remembering = copy.deepcopy(bodies)
    moves = snap_page(remembering, *page, params)
    forgetting = copy.deepcopy(bodies)
    python_sweeps = functools.partial(snapping.snap_to_guides, compiled=False)
    with mock.patch.object(snap_memo.AxisMemo, "recall", lambda self, key, axis: None), \
            mock.patch.object(snapping, "snap_to_guides", python_sweeps):
        fresh_moves = snap_page(forgetting, *page, params)
    return moves, remembering.centres, fresh_moves, forgetting.centres


def test_a_snap_that_remembers_moves_as_one_that_forgets_on_seeded_pages():
    for count, seed in ((20, 1), (50, 1), (30, 3)):
        scene = mixed_scene(count, 0.5, seed=seed)
        engine = Engine(scene.page_w_mm, scene.page_h_mm, Params())
        load(engine, scene)
        engine.settle(finalize=False)
        page = (engine.page_w_mm, engine.page_h_mm)
        bodies = engine.bodies
        remove_overlaps(bodies, *page, engine.params.gutter_mm,
                        margin_mm=page_margin(engine.params.margin_mm, *page))
        moves, centres, fresh_moves, fresh_centres = snapped_twice(bodies, page, engine.params)
        assert moves > 10  # a page the snap works on, many moves near each other
        assert (moves, centres.tobytes()) == (fresh_moves, fresh_centres.tobytes())


@PROPERTIES
@given(crowded_pages())
def test_a_snap_that_remembers_moves_as_one_that_forgets(engine):
    """On pages with held, hard-anchored, following and bleeding items too."""
    page = (engine.page_w_mm, engine.page_h_mm)
    bodies = engine.bodies
    remove_overlaps(bodies, *page, engine.params.gutter_mm,
                    margin_mm=page_margin(engine.params.margin_mm, *page))
    moves, centres, fresh_moves, fresh_centres = snapped_twice(bodies, page, engine.params)
    assert (moves, centres.tobytes()) == (fresh_moves, fresh_centres.tobytes())
