"""What the alignment guides cost outside the snap (issue 16): each page settled the
`floatpage settle` way (model.layout.settle_project) with guides = 0 and with the default, off
and on alternating, best of --repeats; CPU seconds (time.process_time) of the whole settle and
of the time spent inside the alignment snap (physics.snapping.snap_page), and what the settle
did: Engine.settle calls (the full run and the probes), fast-mode steps.

    .venv/bin/python benchmarks/guide_cost.py --repeats 3
    .venv/bin/python benchmarks/guide_cost.py --seeds 7     # plus seven fresh seeded pages
    .venv/bin/python benchmarks/guide_cost.py --before --jitter 6   # and cooled onto the lines

``--before`` also settles each page with guides on the way a settle did before the eighteenth
session, cooling onto the guide lines once still (fast_mode.run_fast's ``cool_onto_guides``, on
the schedule the editor's frames keep; the quiet count that could end it sooner is gone), in the
same run, alternating with the others: its on/off, steps and near misses beside today's.  Near
misses turn on a hair: moving every free item by a normal 1 micrometre before the final pass
changed the 50-item page's 1.90 to 2.06 (one seed of two).  ``--jitter K`` adds K more settles of each page (guides on,
and with --before cooled onto the lines too), each moving every free item by a normal
0.01 mm (seeds 1..K) before its final pass, and prints the near misses averaged over them and
the plain settle: a change of the layouts is better or worse where these averages say so.

"on/off" is the settle with guides over the settle without; "less snap" leaves the snap's time
out of the settle with guides (what the rest of the guides costs: the pull, the hold, the
guided cooling, the probes they bring).

For instruction counts, ``--settle NAME --times K`` only settles that scene K times (guides
``--guides``); run it under callgrind with K = 2 and K = 1 and take the difference (one warm
settle).  ``--free-snap`` makes every snap after the first settle a lookup of what it did
then (the same moves, so the same settle), so the difference is the settle with a snap that
costs nothing:

    valgrind --tool=callgrind --callgrind-out-file=/dev/null .venv/bin/python \
        benchmarks/guide_cost.py --settle "20 items" --guides 1 --times 2 --free-snap
"""

from __future__ import annotations

import argparse
import copy
import time
from dataclasses import replace

import numpy as np

import floatpage.physics.engine as engine_module
from floatpage.model.layout import engine_for_page, settle_project
from floatpage.physics.alignment import measure_alignment
from alignment import benchmark_scenes, random_scenes, scene_project
from seeded_scenes import mixed_scene

SIZES = ((210.0, 297.0), (297.0, 210.0), (148.0, 210.0), (215.9, 279.4), (297.0, 420.0))


class Tally:
    """Counts and times, gathered by wrapping the functions that do the work."""

    def __init__(self) -> None:
        self.snap_s = 0.0
        self.settles = 0
        self.steps = 0

    def install(self) -> None:
        snap, settle, run = engine_module.snap_page, engine_module.Engine.settle, \
            engine_module.run_fast
        tally = self

        def timed_snap(*args, **kwargs):
            start = time.process_time()
            try:
                return snap(*args, **kwargs)
            finally:
                tally.snap_s += time.process_time() - start

        def counted_settle(self, *args, **kwargs):
            tally.settles += 1
            return settle(self, *args, **kwargs)

        def counted_run(*args, **kwargs):
            result = run(*args, **kwargs)
            tally.steps += result[0]
            return result
        engine_module.snap_page = timed_snap
        engine_module.Engine.settle = counted_settle
        engine_module.run_fast = counted_run


TALLY = Tally()
HEADLESS_RUN = engine_module.Engine._run_until_settled


def cooled_onto_the_lines(engine, max_steps: int) -> int:
    """Engine._run_until_settled as it was before the eighteenth session: cooling onto the
    guides once the page is still, as the editor's frames do."""
    steps = 0
    while not engine.settled and steps < max_steps:
        steps += engine._run(min(10_000, max_steps - steps), cool_onto_guides=True)
    return steps


class Jitter:
    """Moves every free item by a normal ``mm`` (seeded) before the first final pass of a
    settle (Engine.finalize): the near misses' sensitivity to a hair of difference."""

    def __init__(self) -> None:
        self.mm, self.seed, self.done = 0.0, 0, True

    def install(self) -> None:
        finalize, jitter = engine_module.Engine.finalize, self

        def jittered(engine, *args, **kwargs):
            if not jitter.done:
                jitter.done = True
                bodies = engine.bodies
                free = bodies.free
                noise = np.random.default_rng(jitter.seed).normal(0.0, jitter.mm, (free.sum(), 2))
                bodies.centres[free] += noise
            return finalize(engine, *args, **kwargs)
        engine_module.Engine.finalize = jittered


JITTER = Jitter()


def settle_once(project, guides: float, fixed_schedule: bool = False, jitter_seed: int = 0,
                ) -> tuple[float, float, int, int, float, bool]:
    """CPU seconds, of them in the snap, Engine.settle calls, steps; near misses per item and
    whether the page keeps zero overlap, the gutter and the margin, as settled.
    ``fixed_schedule``: cooled onto the lines once still (as before the eighteenth session);
    ``jitter_seed`` > 0: jittered before the final pass (Jitter)."""
    trial = copy.deepcopy(project)
    trial.physics = replace(trial.physics, guides=guides)
    engine_module.Engine._run_until_settled = (cooled_onto_the_lines if fixed_schedule
                                               else HEADLESS_RUN)
    JITTER.mm, JITTER.seed, JITTER.done = 0.01, jitter_seed, jitter_seed <= 0
    TALLY.snap_s, TALLY.settles, TALLY.steps = 0.0, 0, 0
    start = time.process_time()
    settle_project(trial)
    seconds = time.process_time() - start
    engine = engine_for_page(trial.pages[0], trial.physics)
    bodies = engine.bodies
    misses = measure_alignment(bodies.centres, bodies.sizes, bodies.decorative)
    return (seconds, TALLY.snap_s, TALLY.settles, TALLY.steps, misses.near_misses_per_item,
            engine.quality().ok)


def free_snap() -> None:
    """Every snap of a page already snapped from the same centres becomes a lookup."""
    real, done = engine_module.snap_page, {}

    def looked_up(bodies, *args, **kwargs):
        key = bodies.centres.tobytes()
        if key in done:
            bodies.centres[:] = done[key]
            return
        real(bodies, *args, **kwargs)
        done[key] = bodies.centres.copy()
    engine_module.snap_page = looked_up


def settle_only(name: str, guides: float, times: int) -> None:
    scene = next(s for s in benchmark_scenes(True) + random_scenes() if name in s.name)
    project = scene_project(scene)
    project.physics = replace(project.physics, guides=guides)
    for _ in range(times):
        settle_project(copy.deepcopy(project))


def fresh_scenes(count: int, first_seed: int = 500):
    """``count`` seeded pages of 8-60 items covering 25-60 % of five page sizes, seeds from
    ``first_seed`` on (500 gives the pages every session has measured; another first seed,
    pages of other counts and coverages too)."""
    rng = np.random.default_rng(2026 + first_seed - 500)
    chosen = []
    for seed in range(first_seed, first_seed + count):
        items = int(rng.integers(8, 61))
        coverage = float(rng.uniform(0.25, 0.6))
        w, h = SIZES[seed % len(SIZES)]
        scene = mixed_scene(items, coverage, seed=seed, page_w_mm=w, page_h_mm=h)
        chosen.append(replace(scene, name=f"seed {seed}: {items} items, {coverage:.0%}, "
                                           f"{w:g}x{h:g} mm"))
    return chosen


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--only", default="")
    parser.add_argument("--seeds", type=int, default=0, help="fresh seeded pages to add")
    parser.add_argument("--first-seed", type=int, default=500, help="the fresh pages' first seed")
    parser.add_argument("--settle", default="", help="only settle this scene --times times")
    parser.add_argument("--guides", type=float, default=1.0)
    parser.add_argument("--times", type=int, default=1)
    parser.add_argument("--free-snap", action="store_true")
    parser.add_argument("--before", action="store_true",
                        help="also settle cooling onto the lines, as before the eighteenth session")
    parser.add_argument("--jitter", type=int, default=0,
                        help="near misses averaged over this many jittered settles too")
    args = parser.parse_args()
    if args.free_snap:
        free_snap()
    if args.settle:
        settle_only(args.settle, args.guides, args.times)
        return
    TALLY.install()
    JITTER.install()
    scenes = [s for s in benchmark_scenes(True) if s.coverage <= 0.6] + random_scenes()
    scenes += fresh_scenes(args.seeds, args.first_seed)
    before = ("| before on/off | steps before | near misses before → now "
              + ("| jittered before → now " if args.jitter else "")) if args.before else ""
    jittered = "| jittered " if args.jitter and not args.before else ""
    print("| scene | off s | on s | on/off | snap s | on less snap / off "
          f"| settles off → on | steps off → on | near misses/item off → on {before}{jittered}| ok |")
    print("|---" * (10 + (3 + bool(args.jitter) if args.before else bool(args.jitter))) + "|")
    ratios, rests, misses, old_ratios, old_misses = [], [], [], [], []
    jitter_now, jitter_before = [], []
    for scene in scenes:
        if args.only not in scene.name:
            continue
        project = scene_project(scene)
        best_off = best_on = best_old = None
        for _ in range(args.repeats):
            off = settle_once(project, 0.0)
            on = settle_once(project, 1.0)
            best_off = off if best_off is None or off[0] < best_off[0] else best_off
            best_on = on if best_on is None or on[0] < best_on[0] else best_on
            if args.before:
                old = settle_once(project, 1.0, fixed_schedule=True)
                best_old = old if best_old is None or old[0] < best_old[0] else best_old
        ratio, rest = best_on[0] / best_off[0], (best_on[0] - best_on[1]) / best_off[0]
        ratios.append(ratio)
        rests.append(rest)
        misses.append(best_on[4])
        ok = "yes" if best_on[5] and (best_old is None or best_old[5]) else "NO"
        extra = ""
        if args.jitter:
            jitter_now.append(np.mean([best_on[4]] + [settle_once(project, 1.0, jitter_seed=k)[4]
                                                      for k in range(1, args.jitter + 1)]))
        if args.before:
            old_ratios.append(best_old[0] / best_off[0])
            old_misses.append(best_old[4])
            extra = (f"| {old_ratios[-1]:.2f} | {best_old[3]} | {best_old[4]:.2f} → "
                     f"{best_on[4]:.2f} ")
            if args.jitter:
                jitter_before.append(np.mean(
                    [best_old[4]] + [settle_once(project, 1.0, True, k)[4]
                                     for k in range(1, args.jitter + 1)]))
                extra += f"| {jitter_before[-1]:.2f} → {jitter_now[-1]:.2f} "
        elif args.jitter:
            extra = f"| {jitter_now[-1]:.2f} "
        print(f"| {scene.name} | {best_off[0]:.3f} | {best_on[0]:.3f} | {ratio:.2f} | "
              f"{best_on[1]:.4f} | {rest:.2f} | {best_off[2]} → {best_on[2]} | "
              f"{best_off[3]} → {best_on[3]} | {best_off[4]:.2f} → {best_on[4]:.2f} {extra}| {ok} |",
              flush=True)
    print(f"\non/off: median {np.median(ratios):.2f}, worst {max(ratios):.2f}; "
          f"less snap: median {np.median(rests):.2f}, worst {max(rests):.2f}; "
          f"near misses/item with guides, summed: {sum(misses):.2f}")
    if args.before:
        worse = sum(now > then + 1e-9 for now, then in zip(misses, old_misses))
        better = sum(now < then - 1e-9 for now, then in zip(misses, old_misses))
        print(f"before (cooled onto the lines): on/off median {np.median(old_ratios):.2f}, worst "
              f"{max(old_ratios):.2f}; near misses summed {sum(old_misses):.2f} → "
              f"{sum(misses):.2f}; pages worse {worse}, better {better}")
    if args.jitter:
        line = f"jittered near misses (plain settle and {args.jitter} jittered), summed: "
        if args.before:
            line += f"{sum(jitter_before):.2f} → "
        print(line + f"{sum(jitter_now):.2f}")


if __name__ == "__main__":
    main()
