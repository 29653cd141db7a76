"""The snap's rest check finds its pairs once, where the snap starts, for moves of a few snap
ranges; a body that travels further in one snap (several moves) can meet items its pairs do
not list, and its sums miss that push.  RestCheck.keeps_rest then finds the pairs again where
the items are (RestCheck.refind; the compiled sweeps read the check's parts again).  Held to
the fast mode's own forces at the probe's heat, as a probe's first step feels them."""

from __future__ import annotations

import copy
import tempfile
from dataclasses import replace
from pathlib import Path

import numpy as np

from floatpage.model import load_project
from floatpage.model.layout import copy_of, settle_page
from floatpage.physics import engine as engine_module
from floatpage.physics.constraints import hand_forces_to_roots
from floatpage.physics.fast_forces import target_gap
from floatpage.physics.fast_mode import fast_forces
from floatpage.physics.params import page_margin, page_scale
from floatpage.physics.rest_check import REST_ACC
from floatpage.physics.snapping import snap_page
from floatpage.physics.stillness import PROBE_HEAT

from fresh_projects import random_project


def probe_pushes(bodies, page_w: float, page_h: float, params) -> tuple[np.ndarray, np.ndarray]:
    """Each movable group's push (its length) in a probe's first step from the page as it
    lies: every force of the fast mode at PROBE_HEAT, the lines holding."""
    page = (page_w, page_h)
    roots, _ = bodies.group_roots()
    charges = np.where(bodies.active, bodies.charges, 0.0)
    mass = np.bincount(roots, weights=charges, minlength=bodies.count)
    movable = bodies.free[roots] & ~bodies.held & bodies.active
    inverse = np.where(movable, 1.0 / np.maximum(mass[roots], 1e-12), 0.0)
    near, far = bodies.insets(page_margin(params.margin_mm, *page), *page)
    gap = target_gap(bodies.sizes[bodies.active], *page, params.gutter_mm)
    skin = max(gap / 2, 2.0 * page_scale(*page))
    forces = fast_forces(bodies, *page, params, np.random.default_rng(0), roots, movable,
                         inverse, gap, skin, near, far, align=True, saved=True)
    acc = np.zeros((bodies.count, 2))
    for force in forces:
        force.add_to(acc, bodies.centres, PROBE_HEAT)
    hand_forces_to_roots(acc, roots, bodies.followers)
    groups = np.flatnonzero(movable & (roots == np.arange(bodies.count)))
    return groups, np.sqrt((acc[groups] ** 2).sum(axis=1))


def full_run_snap_input(seed: int):
    """What the full run's snap is handed when fresh_projects.py's file ``seed`` (its first
    page) is settled with guides: the bodies, the page and the params."""
    with tempfile.TemporaryDirectory() as folder:
        project = load_project(random_project(seed, Path(folder)))
    caught = []
    real = engine_module.snap_page

    def catch(bodies, *args):
        caught.append((copy.deepcopy(bodies), *args))
        return real(bodies, *args)

    engine_module.snap_page = catch
    try:
        settle_page(copy_of(project.pages[0]), replace(project.physics, guides=1.0))
    finally:
        engine_module.snap_page = real
    return caught[0]  # the first probe skips the snap (far from rest): the full run's


def test_a_body_that_travels_past_its_pairs_is_checked_with_its_pairs_found_again():
    """Fresh file 30: an item moved 21 mm in the full run's snap and was left pushed 1.77 (the
    limit 0.8, 0.01 before the snap); the settle took a probe more.  Every group is now left
    within the limit or no harder pushed than before the snap."""
    bodies, page_w, page_h, params = full_run_snap_input(30)
    groups, before = probe_pushes(bodies, page_w, page_h, params)
    start = bodies.centres.copy()
    assert snap_page(bodies, page_w, page_h, params) > 10
    after_groups, after = probe_pushes(bodies, page_w, page_h, params)
    assert (after_groups == groups).all()
    limit = REST_ACC * page_scale(page_w, page_h)
    assert (after <= np.maximum(before, limit) + 1e-6).all(), after.max()
    assert np.abs(bodies.centres - start).max() > 8.0  # beyond the pairs' margin (2 snap ranges)


def unlisted_near_numpy(rest, members: np.ndarray, axis: int, shift: float) -> bool:
    """rest_check_kernel.unlisted_near's definition in NumPy: the members' travel (this move
    included) and the farthest any active row went, against the pairs' margin; then any active
    row not a member, not a listed partner, within the gap on both axes."""
    centres, found = rest.bodies.centres, rest.found_at
    moved = centres[members].copy()
    moved[:, axis] += shift
    mine = np.abs(moved - found[members]).max()
    others = np.abs(centres[rest.active_rows] - found[rest.active_rows]).max()
    if mine + others <= rest.pair_margin:
        return False
    for member, at in zip(members.tolist(), moved, strict=True):
        listed = set(members.tolist())
        for pair in rest.pair_lists_of[member]:
            listed.update(rest.pair_ends[pair].tolist())
        for row in rest.active_rows.tolist():
            if row in listed:
                continue
            reach = rest.halves[member] + rest.halves[row] + rest.gap
            if (np.abs(centres[row] - at) < reach).all():
                return True
    return False


def test_unlisted_near_is_its_numpy_definition():
    """On file 30's page as its full run's snap gets it, the check's pairs found there, then
    the items moved as the snap moved them (far past the pairs): single rows moved by shifts
    from nothing to beyond the pairs' margin, on both axes; some of each answer."""
    from floatpage.physics.snapping import snap_limits

    bodies, page_w, page_h, params = full_run_snap_input(30)
    _, _, rest = snap_limits(bodies, page_w, page_h, params)
    snapped = copy.deepcopy(bodies)
    snap_page(snapped, page_w, page_h, params)
    rng = np.random.default_rng(30)
    answers = []
    for centres in (bodies.centres.copy(), snapped.centres):
        bodies.centres[:] = centres  # the check reads the centres live
        for row in rest.active_rows.tolist():
            members = np.array([row], dtype=np.int64)
            for axis in (0, 1):
                for shift in (0.0, *rng.uniform(-30.0, 30.0, 4)):
                    found = rest.unlisted_near(members, axis, float(shift))
                    assert found == unlisted_near_numpy(rest, members, axis, float(shift))
                    answers.append(found)
    assert any(answers) and not all(answers)
