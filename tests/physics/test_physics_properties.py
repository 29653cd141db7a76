"""Property tests over random scenes: finite, on the page, clean when the items fit, and
deterministic for a seed.  Examples are kept few so the folder stays fast."""

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from floatpage.physics import Engine, Params

FAST = settings(max_examples=25, deadline=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


@st.composite
def scenes(draw, max_items=12, max_coverage=None):
    """(page_w, page_h, [(x, y, w, h)], seed): items anywhere, also off the page or stacked."""
    page_w = draw(st.floats(60, 400))
    page_h = draw(st.floats(60, 400))
    count = draw(st.integers(1, max_items))
    unit = st.floats(0.02, 0.6)
    place = st.floats(-0.5, 1.5)
    stacked = draw(st.booleans())
    items = []
    for _ in range(count):
        w, h = draw(unit) * page_w, draw(unit) * page_h
        if stacked and items:
            x, y = items[0][:2]
        else:
            x, y = draw(place) * page_w, draw(place) * page_h
        items.append((x, y, w, h))
    if max_coverage is not None:
        area = sum((w + 3) * (h + 3) for _, _, w, h in items)
        factor = min(1.0, np.sqrt(max_coverage * page_w * page_h / area))
        items = [(x, y, w * factor, h * factor) for x, y, w, h in items]
    return page_w, page_h, items, draw(st.integers(0, 2**16))


def build(scene, mode="fast"):
    page_w, page_h, items, seed = scene
    engine = Engine(page_w, page_h, Params(mode=mode, seed=seed))
    for k, (x, y, w, h) in enumerate(items):
        engine.insert(f"i{k}", x, y, w, h)
    return engine


def inside(engine, tolerance=1e-6):
    centres, halves = engine.bodies.centres, engine.bodies.sizes / 2
    fits = (2 * halves <= [engine.page_w_mm, engine.page_h_mm]).all(axis=1)
    low_ok = (centres - halves >= -tolerance).all(axis=1)
    high_ok = (centres + halves <= np.array([engine.page_w_mm, engine.page_h_mm]) + tolerance)
    return (~fits | (low_ok & high_ok.all(axis=1))).all()


@FAST
@given(scenes())
def test_fast_mode_stays_finite_and_on_the_page(scene):
    engine = build(scene)
    engine.settle(max_steps=3000)
    assert np.isfinite(engine.bodies.centres).all()
    assert np.isfinite(engine.bodies.velocities).all()
    assert inside(engine)


@FAST
@given(scenes(max_items=8))
def test_fast_mode_is_deterministic_for_a_seed(scene):
    first, second = build(scene), build(scene)
    first.settle(max_steps=1500)
    second.settle(max_steps=1500)
    assert np.array_equal(first.bodies.centres, second.bodies.centres)


@FAST
@given(scenes(max_items=10, max_coverage=0.35))
def test_items_that_fit_end_clean(scene):
    """Gutter-grown items covering at most 35% of the page: zero overlap, gutter kept."""
    engine = build(scene)
    report = engine.settle(max_steps=5000)
    quality = engine.quality()
    assert report.fits and quality.ok, quality.summary()


@settings(max_examples=15, deadline=None)
@given(scenes(max_items=6))
def test_paper_mode_never_produces_nan(scene):
    engine = build(scene, mode="paper")
    engine.advance(1000)
    assert np.isfinite(engine.bodies.centres).all()
    assert np.isfinite(engine.kinetic_energy)


@st.composite
def edited_scenes(draw):
    """A scene plus a random mix of decorations, held items, point anchors and followers."""
    scene = draw(scenes(max_items=8))
    count = len(scene[2])
    roles = draw(st.lists(st.sampled_from(["free", "decorative", "held", "hard", "soft",
                                           "follower"]), min_size=count, max_size=count))
    return scene, roles


@FAST
@given(edited_scenes())
def test_constraints_keep_the_page_finite_and_in_order(data):
    scene, roles = data
    page_w, page_h, items, seed = scene
    engine = Engine(page_w, page_h, Params(seed=seed))
    for k, ((x, y, w, h), role) in enumerate(zip(items, roles)):
        engine.insert(f"i{k}", x, y, w, h, decorative=role == "decorative")
    for k, role in enumerate(roles):
        if role == "held":
            engine.hold(f"i{k}")
        elif role in ("hard", "soft"):
            engine.anchor_point(f"i{k}", page_w / 3, page_h / 3, gamma=0.5, hard=role == "hard")
        elif role == "follower" and k > 0:
            engine.anchor_to(f"i{k}", f"i{k - 1}", 5.0, 5.0)
    before = engine.positions()
    engine.settle(max_steps=2000)
    after = engine.positions()
    assert np.isfinite(engine.bodies.centres).all()
    for k, role in enumerate(roles):
        if role in ("decorative", "held"):
            assert after[f"i{k}"] == before[f"i{k}"]
        elif role == "hard":
            assert after[f"i{k}"] == (page_w / 3, page_h / 3)
        elif role == "follower" and k > 0:
            tx, ty = after[f"i{k - 1}"]
            assert after[f"i{k}"] == pytest.approx((tx + 5.0, ty + 5.0))
