"""physics.page_limits: the reasons no arrangement keeps a page's guarantees, each exact for the
items it names, and each what the settle itself then reaches."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from floatpage.physics import Engine
from floatpage.physics.relocation import movable_units, room_for, unit_bounds
from floatpage.physics.page_limits import (
    Crossing, NoRoom, PinnedClash, PinnedOutside, Stack, TooLarge, page_limits,
)


def limits_of(engine: Engine) -> list:
    return page_limits(engine.bodies, engine.page_w_mm, engine.page_h_mm, engine.margin_mm,
                       engine.params.gutter_mm)


def test_a_roomy_page_of_free_items_has_no_limits():
    engine = Engine(210.0, 297.0)
    for k in range(6):
        engine.insert(f"i{k}", 30.0 + 25 * k, 100.0, 40.0, 30.0)
    assert limits_of(engine) == []


def test_two_hard_anchors_on_each_other_clash():
    engine = Engine(148.0, 210.0)
    engine.insert("a", 70.0, 100.0, 30.0, 20.0)
    engine.insert("b", 90.0, 100.0, 30.0, 20.0)
    engine.insert("free", 70.0, 30.0, 20.0, 20.0)
    engine.anchor_point("a", 70.0, 100.0, hard=True)
    engine.anchor_point("b", 90.0, 100.0, hard=True)
    found = limits_of(engine)
    assert found == [PinnedClash((0, 1), pytest.approx(-10.0))]


def test_a_group_wider_than_the_room_is_too_large():
    engine = Engine(105.0, 148.0)  # A6: a 5 mm margin is scaled down for a small card
    engine.insert("lead", 40.0, 70.0, 60.0, 20.0)
    engine.insert("follower", 40.0, 70.0, 40.0, 20.0)
    engine.anchor_to("follower", "lead", -55.0, 0.0)
    (limit,) = limits_of(engine)
    assert isinstance(limit, TooLarge) and limit.rows == (0, 1) and limit.axis == 0
    assert limit.extent_mm == pytest.approx(30 + 55 + 20)
    assert limit.room_mm == pytest.approx(105.0 - 2 * engine.margin_mm)


def test_two_items_that_cannot_be_parted_cross_and_settle_overlaps_them():
    engine = Engine(210.0, 297.0)
    engine.insert("tall", 170.0, 169.0, 70.0, 256.0)
    engine.insert("wide", 105.0, 37.0, 199.5, 75.0)
    (limit,) = limits_of(engine)
    assert isinstance(limit, Crossing) and limit.rows == (0, 1) and not limit.fits_page
    engine.settle()
    assert engine.quality().overlap_count == 1


def test_the_widest_gap_a_crossing_allows_is_the_gap_settle_keeps():
    """Two items one gutter too tall to stack inside a 100 mm card's margins: the gutter gives
    way, to exactly what the room leaves."""
    engine = Engine(100.0, 100.0)
    engine.insert("top", 64.0, 25.0, 57.9, 45.14)
    engine.insert("bottom", 43.0, 74.0, 72.22, 48.17)
    (limit,) = limits_of(engine)
    assert isinstance(limit, Crossing) and limit.fits_page
    room = 100.0 - 2 * engine.margin_mm
    assert limit.widest_gap_mm == pytest.approx(room - 45.14 - 48.17)
    engine.settle()
    quality = engine.quality()
    assert not quality.overlap_count and not quality.in_margin
    assert quality.min_gap_mm == pytest.approx(limit.widest_gap_mm, abs=0.05)


def test_a_hard_anchor_past_the_edge_and_a_decoration_off_the_page_are_named():
    engine = Engine(210.0, 297.0)
    engine.insert("pinned", 10.0, 100.0, 40.0, 30.0)
    engine.anchor_point("pinned", 10.0, 100.0, hard=True)
    engine.insert("band", 200.0, 280.0, 60.0, 10.0, decorative=True)
    engine.insert("free", 100.0, 150.0, 30.0, 30.0)
    found = limits_of(engine)
    assert PinnedOutside(0, pytest.approx(10.0), pytest.approx(10.0 + engine.margin_mm)) in found
    assert PinnedOutside(1, pytest.approx(20.0), pytest.approx(20.0), True) in found
    assert len(found) == 2


def test_pinned_pairs_are_the_same_found_by_the_neighbour_search_or_block_by_block(monkeypatch):
    """A pile of pinned items is compared block by block (the neighbour search would make
    every pair a candidate); both ways list the same closest pairs, at most LISTED."""
    import floatpage.physics.page_limits as limits

    rng = np.random.default_rng(3)
    engine = Engine(210.0, 297.0)
    spots = rng.uniform(60.0, 90.0, (300, 2))
    engine.insert_all([f"p{k}" for k in range(300)],
                      [(float(x), float(y), 6.0, 4.0) for x, y in spots], [False] * 300,
                      [False] * 300)
    for k, (x, y) in enumerate(spots):
        engine.anchor_point(f"p{k}", float(x), float(y), hard=True)
    searched = [limit for limit in limits_of(engine) if isinstance(limit, PinnedClash)]
    monkeypatch.setattr(limits, "SWEEP_BUDGET", 0)
    monkeypatch.setattr(limits, "CROSSING_BLOCK", 64)
    blocked = [limit for limit in limits_of(engine) if isinstance(limit, PinnedClash)]
    assert len(searched) == limits.LISTED
    assert [limit.gap_mm for limit in blocked] == [limit.gap_mm for limit in searched]
    cut = searched[-1].gap_mm  # pairs tied at the cut may be listed either way
    assert ({limit.rows for limit in blocked if limit.gap_mm < cut}
            == {limit.rows for limit in searched if limit.gap_mm < cut})


def stack_engine(*sizes: tuple[float, float]) -> Engine:
    """An A6 card (105 x 148 mm) with items of these sizes in a row across its middle."""
    engine = Engine(105.0, 148.0)
    for k, (w, h) in enumerate(sizes):
        engine.insert(f"i{k}", 20.0 + 10 * k, 74.0, w, h)
    return engine


def test_items_too_wide_to_pair_and_too_tall_to_stack_are_named_and_settle_keeps_that_gap():
    """Three items each wider than half the card's room: no two side by side, and one above
    another they are 3.3 mm too tall for a 3 mm gutter (a random page's, seed 5017)."""
    engine = stack_engine((55.08, 44.76), (36.45, 25.05), (56.82, 52.7), (55.93, 42.82))
    (limit,) = limits_of(engine)
    room = 148.0 - 2 * engine.margin_mm
    assert isinstance(limit, Stack) and limit.rows == (2, 0, 3) and limit.axis == 1
    assert limit.needs_mm == pytest.approx(52.7 + 44.76 + 42.82 + 2 * 3.0)
    assert limit.widest_gap_mm == pytest.approx((room - 52.7 - 44.76 - 42.82) / 2)
    engine.settle()
    quality = engine.quality()
    assert not quality.overlap_count and not quality.in_margin
    assert quality.min_gap_mm == pytest.approx(limit.widest_gap_mm, abs=0.05)


def test_a_stack_with_two_items_narrow_enough_to_pair_is_no_limit():
    engine = stack_engine((55.08, 44.76), (36.45, 25.05), (56.82, 52.7), (40.0, 42.82))
    assert limits_of(engine) == []  # 56.82 + 40 + 3 fit in the card's 100 mm room


def test_members_of_one_group_count_once_in_a_stack():
    """A follower may overlap its lead by its offset, so a lead and its follower are not two
    items that must stand apart: four items 34 mm tall are a stack on the card (145 mm of
    143), three of them and a follower overlapping one are not."""
    sizes = [(56.0, 34.0)] * 4
    assert [type(limit) for limit in limits_of(stack_engine(*sizes))] == [Stack]
    engine = stack_engine(*sizes)
    engine.anchor_to("i1", "i0", 0.0, 5.0)
    assert limits_of(engine) == []


@pytest.mark.parametrize("seed", range(40))
def test_the_stack_found_is_the_tallest_that_brute_force_finds(seed):
    """On random sets of items, the set named is one of the tallest sets (one per group, of
    three or more, no two fitting side by side, no Crossing inside) that trying every subset
    finds, and is named exactly when such a set is taller than the room."""
    rng = np.random.default_rng(seed)
    count = int(rng.integers(3, 9))
    sizes = [(float(w), float(h)) for w, h in
             zip(rng.uniform(20, 80, count), rng.uniform(15, 60, count))]
    engine = stack_engine(*sizes)
    room = np.array([105.0, 148.0]) - 2 * engine.margin_mm
    gutter = engine.params.gutter_mm
    best = {0: room[1] + 0.01, 1: room[0] + 0.01}
    for across in (0, 1):
        along = 1 - across
        for size in range(3, count + 1):
            for chosen in itertools.combinations(range(count), size):
                pairs = itertools.combinations(chosen, 2)
                if all(sizes[a][across] + sizes[b][across] + gutter > room[across] + 0.01
                       for a, b in pairs):
                    tall = sorted((sizes[k][along] for k in chosen), reverse=True)
                    if tall[0] + tall[1] + gutter <= room[along] + 0.01:
                        best[across] = max(best[across], sum(tall) + gutter * (size - 1))
    found = {1 - limit.axis: limit.needs_mm for limit in limits_of(engine)
             if isinstance(limit, Stack)}
    for across in (0, 1):
        limit_room = room[1 - across] + 0.01
        if best[across] > limit_room:
            assert found.get(across) == pytest.approx(best[across])
        else:
            assert across not in found


def test_a_free_item_with_no_room_between_hard_anchors_is_named_with_the_gap_it_can_keep():
    """Two hard-anchored columns leave a 30 mm lane between them: a block 40 mm wide overlaps
    them wherever it goes; 26 mm wide, it keeps 2 mm from each, not the 3 mm gutter; 24 mm
    wide, it keeps the gutter and is no limit."""
    def page(block_w: float) -> Engine:
        engine = Engine(100.0, 100.0)
        m = engine.margin_mm
        engine.insert("block", 50.0, 50.0, block_w, 20.0)
        for name, low, high in (("left", m, 40.0), ("right", 70.0, 100.0 - m)):
            engine.insert(name, (low + high) / 2, 50.0, high - low, 100.0 - 2 * m)
            engine.anchor_point(name, (low + high) / 2, 50.0, hard=True)
        return engine

    # the columns are nearly as tall as the room, so the three are a Stack as well, with the
    # same widest gap
    (limit,) = [limit for limit in limits_of(page(40.0)) if isinstance(limit, NoRoom)]
    assert limit.rows == (0,) and limit.pinned == (1, 2)
    assert not limit.fits_page and limit.widest_gap_mm == pytest.approx(-5.0, abs=0.01)
    (limit,) = [limit for limit in limits_of(page(26.0)) if isinstance(limit, NoRoom)]
    assert limit.fits_page
    assert limit.widest_gap_mm == pytest.approx(2.0, abs=0.01)
    assert limits_of(page(24.0)) == []


@pytest.mark.parametrize("seed", range(40))
def test_no_room_is_exact_against_a_fine_grid(seed):
    """Among random hard-anchored items, a free one is named as having no room exactly when a
    search of every 0.25 mm of the page finds no place that keeps the gutter: a place the grid
    finds, the search must find too."""
    rng = np.random.default_rng(seed)
    engine = Engine(100.0, 80.0)
    engine.insert("free", 50.0, 40.0, *rng.uniform(15, 35, 2))
    for k in range(int(rng.integers(5, 11))):  # no room for it on about one page in five
        x, y = rng.uniform(10, 90), rng.uniform(10, 70)
        engine.insert(f"pin{k}", x, y, *rng.uniform(10, 30, 2))
        engine.anchor_point(f"pin{k}", x, y, hard=True)
    bodies, gutter, margin = engine.bodies, engine.params.gutter_mm, engine.margin_mm
    half = bodies.sizes[0] / 2
    xs = np.arange(margin + half[0], 100.0 - margin - half[0] + 1e-9, 0.25)
    ys = np.arange(margin + half[1], 80.0 - margin - half[1] + 1e-9, 0.25)
    spots = np.stack(np.meshgrid(xs, ys), axis=-1).reshape(-1, 2)
    clear = np.ones(len(spots), dtype=bool)
    for row in range(1, bodies.count):
        gap = (np.abs(spots - bodies.centres[row]) - half - bodies.sizes[row] / 2).max(axis=1)
        clear &= gap >= gutter
    named = any(isinstance(limit, NoRoom) for limit in limits_of(engine))
    if clear.any():
        assert not named
    elif not named:  # the grid missed a sliver the exact search found: it must be real
        (unit,) = movable_units(bodies)
        (low,), (high,) = unit_bounds(bodies, [unit], 100.0, 80.0, margin)
        spot = room_for(bodies, unit, gutter, low, high, clear_only=True)
        gap = (np.abs(spot - bodies.centres[1:]) - half - bodies.sizes[1:] / 2).max(axis=1)
        assert (gap >= gutter - 1e-9).all() and (spot >= low - 1e-9).all()
        assert (spot <= high + 1e-9).all()


def test_an_item_following_a_decoration_is_pinned_with_it():
    """A decoration is never moved, so neither is the item that follows it: set 6.5 mm into
    a hard-anchored item, or past the page's edge, no settle can help (random pages 7011 and
    7029)."""
    engine = Engine(297.0, 420.0)
    engine.insert("band", 152.36, 59.74, 42.04, 14.86, decorative=True)
    engine.insert("caption", 185.45, 59.74, 16.15, 21.28)
    engine.anchor_to("caption", "band", 33.09, 0.0)
    engine.insert("logo", 187.44, 76.61, 26.14, 25.45)
    engine.anchor_point("logo", 187.44, 76.61, hard=True)
    engine.insert("tag", 20.0, 12.27, 9.55, 37.25)
    engine.anchor_to("tag", "band", -130.0, -50.0)
    found = limits_of(engine)
    (clash,) = [limit for limit in found if isinstance(limit, PinnedClash)]
    assert clash.rows == (1, 2) and clash.gap_mm < 0
    (outside,) = [limit for limit in found if isinstance(limit, PinnedOutside)]
    assert outside.row == 3 and not outside.decoration and outside.past_edge_mm > 0
