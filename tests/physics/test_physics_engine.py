"""The Engine API in the default (fast) mode: editing, advancing, settling, invariants."""

import itertools

import numpy as np
import pytest

from floatpage.physics import Engine, Params
from seeded_scenes import dropped_scene, load, mixed_scene

A4 = (210.0, 297.0)


def engine_with(scene, **params):
    engine = Engine(scene.page_w_mm, scene.page_h_mm, Params(**params))
    load(engine, scene)
    return engine


def test_empty_page_is_settled():
    engine = Engine(*A4)
    assert engine.settled and engine.ids == () and engine.advance() == 0
    assert engine.settle().steps == 0


def test_insert_order_positions_and_sizes():
    engine = Engine(*A4)
    engine.insert("b", 50, 60, 20, 10)
    engine.insert("a", 100, 100, 30, 40)
    assert engine.ids == ("b", "a")
    assert engine.positions() == {"b": (50.0, 60.0), "a": (100.0, 100.0)}
    assert engine.sizes() == {"b": (20.0, 10.0), "a": (30.0, 40.0)}
    assert not engine.settled


def test_zero_steps_change_nothing():
    engine = engine_with(mixed_scene(10))
    before = engine.positions()
    assert engine.advance(0) == 0
    assert engine.positions() == before


def test_default_advance_runs_one_fast_frame():
    engine = engine_with(mixed_scene(10))
    assert engine.advance() == Params().fast_steps_per_frame


@pytest.mark.parametrize("bad", [float("nan"), float("inf")])
def test_non_finite_input_is_refused(bad):
    engine = Engine(*A4)
    with pytest.raises(ValueError):
        engine.insert("x", bad, 10, 10, 10)
    engine.insert("x", 10, 10, 10, 10)
    with pytest.raises(ValueError):
        engine.move("x", 10, bad)
    with pytest.raises(ValueError):
        engine.resize("x", bad, 10)


def test_bad_edits_are_refused():
    engine = Engine(*A4)
    engine.insert("x", 10, 10, 10, 10)
    with pytest.raises(ValueError):
        engine.insert("x", 10, 10, 10, 10)
    with pytest.raises(ValueError):
        engine.resize("x", 0, 10)
    with pytest.raises(KeyError):
        engine.move("nope", 1, 1)
    with pytest.raises(ValueError):
        engine.anchor_point("x", 1, 1, gamma=1.5)
    with pytest.raises(ValueError):
        Engine(0, 10)


def test_every_operation_reheats():
    engine = engine_with(mixed_scene(6))
    operations = [
        lambda e: e.move("item0", 50, 50), lambda e: e.hold("item0"), lambda e: e.release("item0"),
        lambda e: e.resize("item1", 30, 30), lambda e: e.anchor_point("item2", 40, 40),
        lambda e: e.anchor_to("item3", "item4", 0, 40), lambda e: e.unanchor("item3"),
        lambda e: e.resize_page(200, 280), lambda e: e.delete("item5"),
        lambda e: e.insert("new", 20, 20, 10, 10), lambda e: e.reheat(),
    ]
    for operation in operations:
        engine.settle(finalize=False)
        assert engine.settled
        operation(engine)
        assert not engine.settled and engine.heat == 1.0


def test_delete_keeps_the_other_items_and_their_anchors():
    engine = Engine(*A4)
    for name, x in zip("abc", (40, 100, 160)):
        engine.insert(name, x, 100, 20, 20)
    engine.anchor_to("c", "b", 30, 0)
    engine.delete("a")
    assert engine.ids == ("b", "c")
    engine.settle()
    bx, by = engine.positions()["b"]
    assert engine.positions()["c"] == pytest.approx((bx + 30, by))


def test_kinetic_energy_is_equation_1():
    engine = engine_with(mixed_scene(8))
    engine.advance(5)
    bodies = engine.bodies
    expected = (bodies.sizes.prod(axis=1) * (bodies.velocities**2).sum(axis=1)).sum()
    assert engine.kinetic_energy == pytest.approx(expected) and expected > 0


def test_budget_uses_the_callers_clock():
    ticks = itertools.count()
    clock = lambda: next(ticks) * 0.001  # noqa: E731  each look costs 1 ms
    engine = engine_with(mixed_scene(30))
    steps = engine.advance(1000, budget_s=0.004, clock=clock)
    assert 0 < steps <= 20  # a few chunks of 5 steps, then the budget is spent
    with pytest.raises(ValueError):
        engine.advance(budget_s=0.01)


def test_budget_respects_a_step_cap():
    engine = engine_with(mixed_scene(30))
    assert engine.advance(7, budget_s=10.0, clock=lambda: 0.0) == 7


def test_a_budget_alone_runs_at_most_one_frame():
    """A generous budget must not run a whole settle in one jumpy frame."""
    engine = engine_with(mixed_scene(30))
    assert engine.advance(budget_s=10.0, clock=lambda: 0.0) == Params().fast_steps_per_frame


def test_settle_reaches_stillness_and_a_clean_page():
    engine = engine_with(mixed_scene(30, seed=3))
    report = engine.settle()
    quality = engine.quality()
    assert report.settled and report.fits and report.steps > 0
    assert quality.ok, quality.summary()
    assert engine.kinetic_energy == 0.0


def test_dropped_on_one_point_separate_deterministically():
    first = engine_with(dropped_scene())
    second = engine_with(dropped_scene())
    other_seed = engine_with(dropped_scene(), seed=1)
    for engine in (first, second, other_seed):
        assert engine.settle().settled
    assert first.positions() == second.positions()
    assert first.positions() != other_seed.positions()
    assert first.quality().ok


def test_held_item_stays_and_the_others_make_room():
    engine = Engine(*A4)
    engine.insert("held", 105, 150, 60, 60)
    engine.insert("other", 110, 150, 40, 40)
    engine.hold("held")
    engine.settle()
    assert engine.positions()["held"] == (105.0, 150.0)
    assert engine.quality().ok


def test_hard_and_soft_anchors():
    engine = engine_with(mixed_scene(15, seed=2))
    engine.anchor_point("item0", 60, 60, hard=True)
    engine.anchor_point("item1", 150, 240, gamma=1.0)
    engine.settle(finalize=False)
    assert engine.positions()["item0"] == (60.0, 60.0)
    x, y = engine.positions()["item1"]
    assert np.hypot(x - 150, y - 240) < 25


def test_anchor_cycle_is_refused():
    engine = Engine(*A4)
    for name in "abc":
        engine.insert(name, 50, 50, 10, 10)
    engine.anchor_to("b", "a", 20, 0)
    engine.anchor_to("c", "b", 20, 0)
    with pytest.raises(ValueError):
        engine.anchor_to("a", "c", 20, 0)


def anchored_pair(one_by_one: bool, anchors: list) -> Engine:
    engine = Engine(*A4)
    for k, name in enumerate("abcde"):
        engine.insert(name, 30 + 30 * k, 40 + 20 * k, 10, 8)
    engine.anchor_point("e", 150, 150, hard=True)
    if one_by_one:
        for entry in anchors:
            engine.anchor_to(*entry)
    else:
        engine.anchor_all_to(anchors)
    return engine


def test_anchor_all_to_equals_anchor_to_one_by_one():
    """In order: "d" follows "c" after "c" was placed beside "b"; "e" loses its hard anchor;
    "a" is anchored twice and keeps the second."""
    anchors = [("b", "a", 12, 0), ("c", "b", 0, 9), ("d", "c", 12, 9), ("e", "d", -5, 14),
               ("a", "e", 0, 0.5), ("a", "e", 3, 40)]
    with pytest.raises(ValueError, match="cycle"):
        anchored_pair(True, anchors)  # a -> e -> d -> c -> b -> a
    anchors = [entry for entry in anchors if entry[0] != "a"]
    expected, got = anchored_pair(True, anchors), anchored_pair(False, anchors)
    assert got.positions() == expected.positions()
    for name in ("targets", "offsets", "anchors", "gammas", "hard"):
        np.testing.assert_array_equal(getattr(got.bodies, name), getattr(expected.bodies, name))
    assert not got.settled and got.heat == 1.0


def test_anchor_all_to_refuses_as_anchor_to_does():
    """A cycle is refused at the anchor that closes it, the ones before it kept (as one by
    one); an unknown id or an offset that is not finite refuses them all."""
    cycle = [("b", "a", 20, 0), ("c", "b", 20, 0), ("a", "c", 20, 0)]
    engine = anchored_pair(False, [])
    with pytest.raises(ValueError, match="cycle"):
        engine.anchor_all_to(cycle)
    assert list(engine.bodies.targets[:3]) == [-1, 0, 1]
    for bad in ([("b", "a", 1, 1), ("x", "a", 1, 1)], [("b", "a", 1, 1), ("c", "a", np.nan, 0)]):
        engine = anchored_pair(False, [])
        before = engine.positions()
        with pytest.raises((KeyError, ValueError)):
            engine.anchor_all_to(bad)
        assert engine.positions() == before and (engine.bodies.targets == -1).all()
    with pytest.raises(ValueError, match="cycle"):
        anchored_pair(False, [("c", "c", 1, 1)])


@pytest.mark.parametrize("length", [2, 3, 4, 5])
def test_anchor_all_to_refuses_a_cycle_of_any_length(length):
    """Pointer jumping brings every row of a cycle of 2 or 4 rows back to itself, which looks
    like the end of a chain: the cycle test must still see it."""
    names = "abcde"[:length]
    cycle = [(names[k], names[(k + 1) % length], 5, 0) for k in range(length)]
    with pytest.raises(ValueError, match="cycle"):
        anchored_pair(False, cycle)


def test_group_roots_follow_edits_in_place_and_hand_out_copies():
    engine = anchored_pair(False, [("b", "a", 12, 0), ("c", "b", 0, 9)])
    roots, offsets = engine.bodies.group_roots()
    assert list(roots[:3]) == [0, 0, 0] and offsets[2].tolist() == [12.0, 9.0]
    roots[:] = 4
    offsets[:] = 99.0
    engine.bodies.offsets[1] = (1.0, 2.0)  # an edit in place
    roots, offsets = engine.bodies.group_roots()
    assert list(roots[:3]) == [0, 0, 0] and offsets[2].tolist() == [1.0, 11.0]
    engine.bodies.targets[2] = -1
    roots, offsets = engine.bodies.group_roots()
    assert list(roots[:3]) == [0, 0, 2] and offsets[2].tolist() == [0.0, 0.0]


def test_follower_group_stays_on_the_page():
    engine = Engine(*A4)
    engine.insert("photo", 190, 150, 60, 40)
    engine.insert("caption", 190, 180, 60, 10)
    engine.anchor_to("caption", "photo", 0, 27)
    engine.settle()
    assert not engine.quality().off_page
    px, py = engine.positions()["photo"]
    assert engine.positions()["caption"] == pytest.approx((px, py + 27))


def test_decorative_item_is_not_moved_and_pushes_nobody():
    engine = Engine(*A4)
    engine.insert("background", 105, 148.5, 210, 297, decorative=True)
    engine.insert("photo", 105, 148.5, 50, 50)
    engine.settle()
    assert engine.positions()["background"] == (105.0, 148.5)
    assert engine.positions()["photo"] == pytest.approx((105.0, 148.5), abs=0.5)
    assert engine.quality().ok


def test_item_larger_than_the_page_is_centred_and_finite():
    engine = Engine(*A4)
    engine.insert("huge", 0, 0, 400, 100)
    engine.insert("small", 100, 100, 30, 30)
    engine.settle()
    x, _ = engine.positions()["huge"]
    assert x == pytest.approx(105.0)
    assert np.isfinite(engine.bodies.centres).all()


def test_over_full_page_stays_finite_and_on_the_page():
    engine = engine_with(mixed_scene(40, coverage=1.6, seed=5))
    report = engine.settle()
    assert not report.fits
    assert np.isfinite(engine.bodies.centres).all()
    assert not engine.quality().off_page


def test_walls_hold_against_a_crowd():
    engine = engine_with(mixed_scene(40, coverage=0.9, seed=1))
    engine.settle()
    quality = engine.quality()
    assert not quality.off_page
    assert quality.overlap_fraction < 0.108


def test_resize_page_brings_items_back_inside():
    engine = engine_with(mixed_scene(10, coverage=0.3))
    engine.settle()
    engine.resize_page(150, 200)
    engine.settle()
    quality = engine.quality()
    # 62 % of the smaller page inside its 3.5 mm margins: the gutter gives way first
    assert not quality.off_page and not quality.overlapping_pairs and not quality.in_margin


def test_a5_and_a4_give_the_same_quality():
    """The fast mode is scale-free but for the gutter: an A4 page and its A5 copy both end clean
    and similarly even."""
    s = 1 / np.sqrt(2)
    scene = mixed_scene(20, seed=4)
    big = engine_with(scene)
    small = Engine(210 * s, 297 * s)
    for item_id, (x, y), (w, h) in zip(scene.ids, scene.centres, scene.sizes):
        small.insert(item_id, x * s, y * s, w * s, h * s)
    big.settle()
    small.settle()
    assert big.quality().ok and small.quality().ok
    assert small.quality().gap_evenness == pytest.approx(big.quality().gap_evenness, abs=0.15)


@pytest.mark.parametrize("mode", ["fast", "paper"])
def test_moving_a_follower_keeps_it_where_it_was_put(mode):
    """Like the editor's drag: the follower's offset becomes the new one, it does not snap back."""
    engine = Engine(210, 297, Params(mode=mode))
    engine.insert("photo", 100, 100, 60, 40)
    engine.insert("caption", 100, 130, 60, 10)
    engine.anchor_to("caption", "photo", 0, 30)
    engine.move("caption", 100, 70)  # from below the photo to above it
    engine.advance(200)
    (px, py), (cx, cy) = engine.positions()["photo"], engine.positions()["caption"]
    assert (cx - px, cy - py) == pytest.approx((0.0, -30.0))


def test_editing_a_decoration_leaves_a_settled_page_at_rest():
    # A decoration takes no part in the forces: moving, holding, releasing or resizing it gives
    # the layout nothing to answer, where a full reheat re-spread the whole page (the flyer's
    # header band, nudged, moved its products 10 mm).  One with a follower still reheats.
    engine = Engine(210, 297, Params())
    engine.insert("band", 105, 20, 210, 40, decorative=True)
    engine.insert("a", 60, 150, 50, 40)
    engine.insert("b", 150, 150, 50, 40)
    engine.settle()
    before = engine.positions()
    engine.move("band", 105, 22)
    engine.hold("band")
    engine.release("band")
    engine.resize("band", 200, 38)
    assert engine.settled
    assert engine.advance(100) == 0
    after = engine.positions()
    assert {k: after[k] for k in "ab"} == {k: before[k] for k in "ab"}
    engine.insert("caption", 105, 45, 40, 8)
    engine.anchor_to("caption", "band", 0, 23)
    engine.settle()
    engine.move("band", 105, 24)
    assert not engine.settled


def test_the_quality_key_ignores_decorations_only():
    # The editor measures a still page's quality once per quality_key: moving a decoration
    # must keep it, anything the measures read must change it.
    engine = Engine(210, 297, Params())
    engine.insert("band", 105, 20, 210, 40, decorative=True)
    engine.insert("a", 60, 150, 50, 40)
    key = engine.quality_key()
    engine.move("band", 105, 30)
    assert engine.quality_key() == key
    engine.move("a", 61, 150)
    assert engine.quality_key() != key
    key = engine.quality_key()
    engine.resize("a", 50, 41)
    assert engine.quality_key() != key
    key = engine.quality_key()
    engine.resize_page(200, 297)
    assert engine.quality_key() != key
