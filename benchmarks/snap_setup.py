"""The alignment snap's fixed cost per call on small pages (issue #16: the guides' settle within
1.25x of the settle without, on every page): what a snap pays before and besides its sweeps.

    .venv/bin/python benchmarks/snap_setup.py --repeats 20
    .venv/bin/python benchmarks/snap_setup.py --repeats 20 --seeds 30 --first-seed 2000

On pages of 5-30 items a settle without guides takes 8-18 ms, and each of its two snaps (the
full run's and the probe's, physics.snapping.snap_page) paid some 0.3 ms of set-up before it
tried a move: the rest check's pairs and tables, the snapper's tables and flags, the compiled
sweeps' arguments.  The inputs are the snaps guide_cost's pages of at most --most items ask
for while they settle the `floatpage settle` way (model.layout.settle_project), plus --seeds
fresh pages of guide_cost (fresh_scenes) of at most --most items.  Per input, best of
--repeats, CPU (time.process_time):

- ``snap``: the whole snap_page;
- ``fixed``: snap_limits, _Snapper and its compiled sweeps' making, plus the rest check's
  making if the snap asks for it (physics.deferred_rest, where the snap builds it only then;
  before it, snap_limits built it every time).

Printed per call (microseconds), for the full run's snaps, the probes' and all.  The same
script runs on a checkout without physics.deferred_rest (the rest check then in snap_limits).
"""

from __future__ import annotations

import argparse
import copy
import inspect
import time

import floatpage.physics.snapping as snapping
from floatpage.model.layout import settle_project

from alignment import benchmark_scenes, random_scenes, scene_project
from guide_cost import fresh_scenes
from snap_speed import snaps_captured

DEFERS = "deferred" in inspect.signature(snapping.snap_limits).parameters


def small_snaps(most: int, seeds: int, first_seed: int) -> list[tuple[str, tuple]]:
    """(first or probe, snap_page's arguments) of every snap the small pages' settles ask for."""
    scenes = [s for s in benchmark_scenes(True) if s.coverage <= 0.6] + random_scenes()
    scenes += fresh_scenes(seeds, first_seed)
    kept = []
    for scene in scenes:
        if len(scene.centres) > most:
            continue
        with snaps_captured() as (captured, label):
            settle_project(scene_project(scene))
        kept += [("first" if k == 0 else "probe", args) for k, (_, args) in enumerate(captured)]
    return kept


def limits(bodies, page_w_mm, page_h_mm, params):
    return (snapping.snap_limits(bodies, page_w_mm, page_h_mm, params, deferred=True) if DEFERS
            else snapping.snap_limits(bodies, page_w_mm, page_h_mm, params))


def asks_rest(bodies, page_w_mm, page_h_mm, params) -> bool:
    """Whether the snap of these bodies builds its deferred rest check (False without one)."""
    if not DEFERS:
        return False
    from floatpage.physics.deferred_rest import DeferredRest
    built, asked = DeferredRest.built, []

    def noted(self):
        asked.append(True)
        return built(self)
    DeferredRest.built = noted
    try:
        snapping.snap_page(copy.deepcopy(bodies), page_w_mm, page_h_mm, params)
    finally:
        DeferredRest.built = built
    return bool(asked)


def timed(bodies, page_w_mm, page_h_mm, params, asks: bool) -> tuple[float, float]:
    """CPU seconds of the whole snap and of its fixed cost, on copies of ``bodies``."""
    trial = copy.deepcopy(bodies)
    start = time.process_time()
    snapping.snap_page(trial, page_w_mm, page_h_mm, params)
    snap = time.process_time() - start
    trial = copy.deepcopy(bodies)
    start = time.process_time()
    clearance, margin, rest = limits(trial, page_w_mm, page_h_mm, params)
    snapping._Snapper(trial, (page_w_mm, page_h_mm), clearance, margin, rest).compiled()
    if asks:
        rest.built()
    return snap, time.process_time() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=20)
    parser.add_argument("--most", type=int, default=30, help="pages of at most this many items")
    parser.add_argument("--seeds", type=int, default=0, help="fresh guide_cost pages to add")
    parser.add_argument("--first-seed", type=int, default=2000)
    args = parser.parse_args()
    snaps = small_snaps(args.most, args.seeds, args.first_seed)
    totals = {kind: [0, 0.0, 0.0, 0] for kind in ("first", "probe")}
    for kind, (bodies, page_w_mm, page_h_mm, params) in snaps:
        asks = asks_rest(bodies, page_w_mm, page_h_mm, params)
        best = [float("inf"), float("inf")]
        for _ in range(args.repeats):
            best = [min(old, new) for old, new in
                    zip(best, timed(bodies, page_w_mm, page_h_mm, params, asks))]
        total = totals[kind]
        total[0] += 1
        total[1] += best[0]
        total[2] += best[1]
        total[3] += asks
    print(f"rest check deferred: {DEFERS}")
    print("| snaps | calls | snap us/call | fixed us/call | rest checks built |")
    print("|---|---|---|---|---|")
    for kind, (calls, snap, fixed, built) in list(totals.items()) + [
            ("all", [sum(t[k] for t in totals.values()) for k in range(4)])]:
        print(f"| {kind} | {calls} | {snap / calls * 1e6:.0f} | {fixed / calls * 1e6:.0f} | "
              f"{built if DEFERS else calls} |")


if __name__ == "__main__":
    main()
