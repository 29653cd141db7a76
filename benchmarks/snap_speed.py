"""The alignment snap alone (physics.snapping.snap_page), on the pages it is handed while the
alignment benchmark's scenes settle the `floatpage settle` way (model.layout.settle_project)
and the Engine.settle way (benchmarks/physics.py).

    .venv/bin/python benchmarks/snap_speed.py              # best of 3 per snap
    .venv/bin/python benchmarks/snap_speed.py --repeats 1 --only "50 items"
    .venv/bin/python benchmarks/snap_speed.py --repeats 2 --only "50 items" --engine-only
    .venv/bin/python benchmarks/snap_speed.py --roomy --engine-only   # and the roomy pages

Each snap's input (the bodies after the no-overlap pass) is kept, then snapped again on a copy:
CPU seconds (time.process_time) per scene, best of --repeats, the moves made, and a hash of the
snapped centres over every snap, so that a change meant to make the snap cheaper can show it
makes the same moves (the hash is the same) and what it saves.  Under callgrind (one repeat)
the instruction counts do not depend on the machine's load: the run with --repeats 2 less
the run with --repeats 1 is one snap of each input (--engine-only: the Engine.settle snaps
alone, one per scene).

--roomy adds the pages of issues #10 and #16, where the snap was most of the settle: the
fresh scenes of benchmarks/physics.py (--fresh 16) of 60 to 120 items, seeds 3001, 3002,
3008, 3009, and those of the same kinds from seed 5100 on, which no one tuned on (Engine.settle
snaps only: they are engine scenes).
"""

from __future__ import annotations

import argparse
import copy
import hashlib
import time
from collections import defaultdict
from contextlib import contextmanager

import floatpage.physics.engine as engine_module
from floatpage.model.layout import settle_project
from floatpage.physics import Engine, Params
from floatpage.physics.snapping import snap_page

from alignment import benchmark_scenes, random_scenes, scene_project
from seeded_scenes import Scene, fresh_scenes, load

ROOMY_ITEMS = (60, 80, 120)  # the mid-size pages of fresh_scenes, where the snap costs most


def loaded(scene: Scene) -> Engine:
    """A new engine holding the scene's items where it scattered them (as benchmarks/physics.py
    loads its scenes)."""
    engine = Engine(scene.page_w_mm, scene.page_h_mm, Params())
    load(engine, scene)
    return engine


def roomy_scenes() -> list[Scene]:
    """The fresh scenes of 60-120 items: benchmarks/physics.py's (seed 3000 on) and as many
    again from seed 5100 on."""
    return [scene for first_seed in (3000, 5100) for scene in fresh_scenes(16, first_seed)[:16]
            if scene.name.startswith("seed ") and len(scene.centres) in ROOMY_ITEMS]


@contextmanager
def snaps_captured():
    """While open: every snap the settles ask for, kept as (label, snap_page's arguments) in
    the list it gives, each labelled with what the caller put in the label cell it gives."""
    captured: list[tuple[str, tuple]] = []
    label = [""]

    def keep(bodies, page_w_mm, page_h_mm, params):
        captured.append((label[0], (copy.deepcopy(bodies), page_w_mm, page_h_mm, params)))
        return snap_page(bodies, page_w_mm, page_h_mm, params)

    engine_module.snap_page = keep
    try:
        yield captured, label
    finally:
        engine_module.snap_page = snap_page


def captured_snaps(only: str, engine_only: bool = False,
                   roomy: bool = False) -> list[tuple[str, tuple]]:
    """(label, snap_page's arguments) for every snap the settles ask for."""
    with snaps_captured() as (captured, label):
        engine_scenes = roomy_scenes() if roomy else []
        for scene in benchmark_scenes(quick=True) + random_scenes() + engine_scenes:
            if only not in scene.name:
                continue
            if not engine_only and not any(scene is kept for kept in engine_scenes):
                label[0] = f"settle {scene.name}"
                settle_project(scene_project(scene))
            label[0] = f"Engine.settle {scene.name}"
            loaded(scene).settle()
    return captured


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3, help="timed snaps per input (best)")
    parser.add_argument("--only", default="", help="only the scenes whose name contains this")
    parser.add_argument("--engine-only", action="store_true",
                        help="only the snaps of Engine.settle (benchmarks/physics.py's way)")
    parser.add_argument("--roomy", action="store_true",
                        help="also the fresh pages of 60-120 items (issues #10 and #16)")
    args = parser.parse_args()
    seconds: dict[str, float] = defaultdict(float)
    moves: dict[str, int] = defaultdict(int)
    snapped = hashlib.sha256()
    captured = captured_snaps(args.only, args.engine_only, args.roomy)
    for label, (bodies, page_w_mm, page_h_mm, params) in captured:
        best = float("inf")
        for _ in range(args.repeats):
            trial = copy.deepcopy(bodies)
            start = time.process_time()
            made = snap_page(trial, page_w_mm, page_h_mm, params)
            best = min(best, time.process_time() - start)
        seconds[label] += best
        moves[label] += made
        snapped.update(trial.centres.tobytes())
    print("| settle | scene | snap ms | moves |")
    print("|---|---|---|---|")
    for label in seconds:
        how, name = label.split(" ", 1)
        print(f"| {how} | {name} | {seconds[label] * 1000:.1f} | {moves[label]} |")
    print(f"\nall snaps: {sum(seconds.values()) * 1000:.0f} ms, {sum(moves.values())} moves, "
          f"snapped centres hash {snapped.hexdigest()[:16]}")


if __name__ == "__main__":
    main()
