"""Where the alignment guides' cost goes, per page of benchmarks/guide_cost.py (issue 16): each
page settled the `floatpage settle` way with guides = 0 and with the default, off and on
alternating, best of --repeats by the whole settle's CPU time (time.process_time), and the
difference split into

- the snap: physics.snapping.snap_page, in the full run's finalize and in the probes';
- the guide force in the steps: GuidePulls.add_to (the pull, its refresh, the hold);
- more or fewer steps in the full run: the change in its step count (guides on, the page cools
  from GUIDE_HEAT / 2 to HOLD_HEAT once still, at GUIDED_COOLING a step) at the cost of a step
  without guides (the full run's time without them over its steps);
- the first-pass check at rest: Engine._first_pass_fails, which only a run with guides asks
  (without them the run ends where it would be asked, and finalize makes the same pass once);
- the probes' runs besides the guide force;
- the rest: what the wrappers leave unexplained (each step's own cost differs a little with
  the guides on: the hold's branch, the timers themselves).

    .venv/bin/python benchmarks/guide_cost_parts.py --repeats 3
"""

from __future__ import annotations

import argparse
import copy
import time
from collections import defaultdict
from dataclasses import replace

import floatpage.model.layout as layout
import floatpage.physics.engine as engine_module
import floatpage.physics.guides as guides_module
from alignment import benchmark_scenes, random_scenes, scene_project

TIMES: defaultdict[str, float] = defaultdict(float)
WHERE = ["full"]  # "probe" inside model.layout.probe_rest


def timed(owner, name: str, key: str, where: str | None = None, steps: bool = False) -> None:
    real = getattr(owner, name)

    def wrapper(*args, **kwargs):
        if where:
            WHERE.append(where)
        start = time.process_time()
        try:
            result = real(*args, **kwargs)
        finally:
            TIMES[f"{key}:{WHERE[-1]}"] += time.process_time() - start
            if where:
                WHERE.pop()
        if steps:
            TIMES[f"steps:{WHERE[-1]}"] += result[0]
        return result
    setattr(owner, name, wrapper)


def install() -> None:
    timed(layout, "probe_rest", "all", where="probe")
    timed(engine_module, "run_fast", "run", steps=True)
    timed(engine_module, "snap_page", "snap")
    timed(engine_module.Engine, "_first_pass_fails", "first")
    timed(guides_module.GuidePulls, "add_to", "force")


def settle_once(project, guides: float) -> dict[str, float]:
    TIMES.clear()
    trial = copy.deepcopy(project)
    trial.physics = replace(trial.physics, guides=guides)
    start = time.process_time()
    layout.settle_project(trial)
    TIMES["total"] = time.process_time() - start
    return dict(TIMES)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    install()
    print("| scene | off ms | on ms | on − off | snap (full + probes) | guide force in the steps "
          "| more or fewer steps (full run) | first-pass check at rest "
          "| probes' runs besides the force | rest |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    scenes = [s for s in benchmark_scenes(True) if s.coverage <= 0.6] + random_scenes()
    settle_once(scene_project(scenes[0]), 1.0)  # imports and first calls out of the figures
    for scene in scenes:
        project = scene_project(scene)
        best: dict[float, dict[str, float]] = {}
        for _ in range(args.repeats):
            for guides in (0.0, 1.0):
                result = settle_once(project, guides)
                if guides not in best or result["total"] < best[guides]["total"]:
                    best[guides] = result
        off, on = best[0.0], best[1.0]

        def ms(times, key):
            return times.get(key, 0.0) * 1000
        snap = ms(on, "snap:full") + ms(on, "snap:probe")
        force = ms(on, "force:full") + ms(on, "force:probe")
        steps_off, steps_on = int(off.get("steps:full", 0)), int(on.get("steps:full", 0))
        per_step = (ms(off, "run:full") - ms(off, "first:full")) / max(steps_off, 1)
        steps = (steps_on - steps_off) * per_step
        first = ms(on, "first:full") - ms(off, "first:full")
        probes = ms(on, "run:probe") - ms(on, "force:probe") - ms(off, "run:probe")
        delta = ms(on, "total") - ms(off, "total")
        rest = delta - snap - force - steps - first - probes
        print(f"| {scene.name} | {ms(off, 'total'):.1f} | {ms(on, 'total'):.1f} | {delta:+.1f} "
              f"| {snap:.1f} | {force:.1f} | {steps:+.1f} ({steps_off} → {steps_on}) "
              f"| {first:.1f} | {probes:+.1f} | {rest:+.1f} |", flush=True)


if __name__ == "__main__":
    main()
