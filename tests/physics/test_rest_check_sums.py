"""The snap's rest check (physics.rest_check) sums the forces of a move's few pairs pair by pair
in compiled code (rest_check_kernel.rest_net) instead of the fast mode's vectorised terms: it must
give the same numbers bit for bit, or a snap would take other moves than the physics it checks
for (and a settled file would stop being a fixed point)."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from floatpage.physics import Engine, Params
from floatpage.physics.fast_forces import target_gap, touching_pushes, wall_pushes_in
from floatpage.physics.force_terms import K_CONTACT, K_WALL
from floatpage.physics.geometry import pair_sums, xy_slots
from floatpage.physics.guides import hold_strength, page_lines, snap_range
from floatpage.physics.params import page_margin, page_scale
from floatpage.physics.rest_check import PROBE_RADIAL, RestCheck
from floatpage.physics.rest_check_kernel import rest_net

from seeded_scenes import load, mixed_scene

coordinate = st.floats(-30.0, 30.0, allow_nan=False)
pair = st.tuples(coordinate, coordinate, st.floats(0.0, 25.0), st.floats(0.0, 25.0),
                 st.booleans(), st.booleans())


@settings(max_examples=300, deadline=None)
@given(st.lists(pair, min_size=1, max_size=12), st.sampled_from([0.0, PROBE_RADIAL, 0.5]),
       st.data())
def test_one_pairs_push_is_the_vectorised_push_bit_for_bit(pairs, radial_share, data):
    """The compiled push of one pair (rest_net's pair_push) against touching_pushes, on pairs
    exactly touching, on one point, on one line, with blocked axes or none."""
    # some pairs exactly touching, on one point, or on one line
    pairs = [(0.0, 0.0, reach_x, reach_y, *rest) if k % 5 == 1 else
             (reach_x, dy, reach_x, reach_y, *rest) if k % 5 == 2 else
             (dx, 0.0, reach_x, reach_y, *rest) if k % 5 == 3 else
             (dx, dy, reach_x, reach_y, *rest)
             for k, (dx, dy, reach_x, reach_y, *rest) in enumerate(pairs)]
    centres = np.array([[dx, dy] for dx, dy, *_ in pairs] + [[0.0, 0.0]])
    j = np.arange(len(pairs))
    i = np.full(len(pairs), len(pairs))  # every pair from the last row, at the origin
    reach = np.array([[reach_x, reach_y] for _, _, reach_x, reach_y, _, _ in pairs])
    blocked = np.array([[bx, by] for *_, bx, by in pairs])
    if data.draw(st.booleans()):
        blocked[:] = False  # touching_pushes drops an all-clear table: its other path
    touching, pushes = touching_pushes(centres, reach, i, j, blocked, radial_share)
    # each pair's push on its j alone: every other force off (no contact constant, no walls,
    # no springs, i takes no share), so a row's net is 0.0 plus its push
    pair_table = np.column_stack([reach, blocked, np.zeros(len(pairs)), np.ones(len(pairs))])
    row_table = np.zeros((len(centres), 7))
    row_table[:, :2], row_table[:, 2:4] = -np.inf, np.inf
    found = np.array(rest_net(j.tolist(), j.tolist(), centres, np.zeros(0, dtype=np.int64), 0,
                              0.0, np.column_stack([i, j]).astype(np.int64), pair_table,
                              row_table, np.array([1.0, 0.0, radial_share])))
    expected = np.zeros((len(pairs), 2))
    expected[touching] += pushes
    assert (found + 0.0).tobytes() == (expected + 0.0).tobytes()  # a signed zero is summed away


def vectorised_net(rest: RestCheck, rows: list[int], pairs: list[int],
                   centres: np.ndarray) -> np.ndarray:
    """The rows' net acceleration by the fast mode's vectorised terms (touching_pushes,
    pair_sums, wall_pushes_in, the anchor springs) on the rest check's pairs, in their order."""
    pairs, rows = np.array(pairs, dtype=int), np.array(rows, dtype=int)
    i, j = rest.i[pairs], rest.j[pairs]
    touching, pushes = touching_pushes(centres, rest.reach[pairs], i, j, rest.blocked[pairs],
                                       PROBE_RADIAL)
    pushes *= K_CONTACT
    pairs, i, j = pairs[touching], i[touching], j[touching]
    acc = pair_sums(rest.bodies.count, xy_slots(i), xy_slots(j),
                    pushes * rest.share_i[pairs][:, None], pushes * rest.share_j[pairs][:, None])
    acc[rows] += K_WALL * wall_pushes_in(centres[rows], rest.rest_low[rows], rest.rest_high[rows])
    acc[rows] += rest.anchor_k[rows, None] * (rest.anchors[rows] - centres[rows])
    return acc[rows]


def settled(count: int, coverage: float, seed: int, page: tuple[float, float]) -> Engine:
    """A seeded page settled without the final pass (Engine.finalize): pressed contacts,
    items on the walls, near misses for a snap to close."""
    scene = mixed_scene(count, coverage, seed=seed, page_w_mm=page[0], page_h_mm=page[1])
    engine = Engine(*page, Params())
    load(engine, scene)
    engine.settle(finalize=False)
    return engine


def test_the_rest_checks_sums_are_the_fast_modes_bit_for_bit():
    """On settled seeded pages (pressed contacts, items on the walls), before and after a
    trial move of each item, as keeps_rest asks."""
    for count, seed, page in ((30, 7, (210.0, 297.0)), (16, 3, (148.0, 210.0))):
        engine = settled(count, 0.55, seed, page)
        bodies, params = engine.bodies, engine.params
        margin = page_margin(params.margin_mm, *page)
        gap = target_gap(bodies.sizes[bodies.active], *page, params.gutter_mm)
        rest = RestCheck(bodies, page, gap, bodies.insets(margin, *page), params.beta,
                         snap_range(*page), page_scale(*page), hold_strength(page, params.guides),
                         [page_lines(*page, margin, axis, bodies.regions) for axis in (0, 1)])
        touched = 0
        for row in range(bodies.count):
            groups, rows, pairs = rest.reached_by(np.array([row]))
            for shift in (0.0, 1.3, -2.7):
                centres = bodies.centres.copy()
                centres[row, 0] += shift
                found = np.array(rest.net(rows, pairs, np.array([row]), 0, shift)
                                 ).reshape(-1, 2)
                expected = vectorised_net(rest, rows, pairs, centres)
                assert found.tobytes() == expected.tobytes(), (count, seed, row, shift)
                touched += int(np.any(found != 0.0))
        assert touched > count  # the pages are pressed: most sums are not zero
