"""Where the alignment snap's time goes (issues #10 and #16), and what cheaper searches would
give up: three measures, each printed as a table.

    .venv/bin/python benchmarks/snap_anatomy.py --probe      # the two snaps of `floatpage settle`
    .venv/bin/python benchmarks/snap_anatomy.py --units      # the snap's time by unit
    .venv/bin/python benchmarks/snap_anatomy.py --variants   # other searches: time, near misses
    .venv/bin/python benchmarks/snap_anatomy.py --census     # scorings that find what they found

--probe settles guide_cost's pages the `floatpage settle` way (model.layout.settle_project) and
times each snap the settle asks for (CPU, best of --repeats): the full run's snap, then the
probe's, which proves the page at rest, with the moves each made and the probe's longest move.
A probe snap that makes no move could be certified idle from the first snap's last sweep; one
that moves (items a few hundredths of a millimetre back onto lines the rounding moved them off)
must run.

--units and --variants snap the inputs benchmarks/snap_speed.py captures with --roomy
--engine-only (the Engine.settle snaps of the alignment scenes and of the roomy fresh pages of
60-120 items, where the snap is most of the settle).  --units times the snap's units from
inside (CPU; the wrappers add a few percent): the scoring of a group alone and of a line
(options), the finding of a line (line_of), the tries that moved and those that did not
(attempt).  --variants replaces the snap's step (``_Snapper.improve``, and the sweeps for the
last one) by a search that does less, and prints CPU (best of --repeats) and the near misses
per item the snap leaves (physics.alignment), summed over the inputs:

- ``main``: the snap as it is;
- ``no lines``: no group moves with its line (a body is one group only);
- ``alone first``: a group tries its own moves first, its line's only if none of those fits;
- ``lines last``: sweeps of groups alone until none moves, then the snap as it is.

None of them is the snap: they show what the line moves cost and what they buy.

--units, --variants and --census wrap or replace _Snapper's Python methods, so they run the
Python sweeps (snap_to_guides(compiled=False), the definition the compiled sweeps of
physics/snap_sweep_kernel.c are held to); --variants' "main, compiled" is the snap as shipped.

--census counts, on the same inputs, the scorings (options worked out, not recalled) of a
group alone and of a line: the first of each (groups, axis), and of the later ones, those that
found the very answer the last one did (the same moves, gain and flags; "none" if no move
helps) and those that found another.  A later scoring runs because a move swept its span: a
certificate that the answer stands would save the ones that found the same.
"""

from __future__ import annotations

import argparse
import copy
import functools
import time
from collections import defaultdict
from contextlib import contextmanager
from dataclasses import replace

import floatpage.physics.engine as engine_module
import floatpage.physics.snapping as snapping
from floatpage.model.layout import settle_project
from floatpage.physics.alignment import measure_alignment

from alignment import benchmark_scenes, random_scenes, scene_project
from snap_speed import captured_snaps


def probe_table(repeats: int) -> None:
    """Per guide_cost page: the settle's CPU with guides and each of its snaps'."""
    scenes = [s for s in benchmark_scenes(True) if s.coverage <= 0.6] + random_scenes()
    real = engine_module.snap_page
    snaps: list[tuple[float, int, float]] = []

    def timed(bodies, *args):
        before = bodies.centres.copy()
        start = time.process_time()
        made = real(bodies, *args)
        seconds = time.process_time() - start
        snaps.append((seconds, made, float(abs(bodies.centres - before).max(initial=0.0))))
        return made

    engine_module.snap_page = timed
    print("| scene | settle ms | first snap ms (moves) | probe snap ms (moves, longest mm) "
          "| probe snap / settle |")
    print("|---|---|---|---|---|")
    try:
        for scene in scenes:
            project = scene_project(scene)
            best = None
            for _ in range(repeats):
                snaps.clear()
                trial = copy.deepcopy(project)
                trial.physics = replace(trial.physics, guides=1.0)
                start = time.process_time()
                settle_project(trial)
                seconds = time.process_time() - start
                if best is None or seconds < best[0]:
                    best = (seconds, list(snaps))
            seconds, taken = best
            first = taken[0] if taken else (0.0, 0, 0.0)
            probes = taken[1:] or [(0.0, 0, 0.0)]
            probe_s = sum(s for s, _, _ in probes)
            print(f"| {scene.name} | {seconds * 1000:.1f} | {first[0] * 1000:.1f} ({first[1]}) "
                  f"| {probe_s * 1000:.1f} ({sum(m for _, m, _ in probes)}, "
                  f"{max(x for _, _, x in probes):.3f}) | {probe_s / seconds:.0%} |")
    finally:
        engine_module.snap_page = real


@contextmanager
def units_timed(seconds: dict[str, float], counts: dict[str, int]):
    """While open: the CPU inside the snap's units, by kind of call."""
    options, attempt, line_of = (snapping._Snapper.options, snapping._Snapper.attempt,
                                 snapping._Snapper.line_of)

    def timed_options(self, roots, axis):
        start = time.process_time()
        found = options(self, roots, axis)
        kind = "scoring a line" if len(roots) > 1 else "scoring a group alone"
        seconds[kind] += time.process_time() - start
        counts[kind] += 1
        return found

    def timed_attempt(self, moves, axis):
        start = time.process_time()
        moved = attempt(self, moves, axis)
        kind = ("a try that moved" if moved else
                "a try that did not" if moves.shifts else "nothing to try")
        seconds[kind] += time.process_time() - start
        counts[kind] += 1
        return moved

    def timed_line_of(self, row, axis):
        start = time.process_time()
        found = line_of(self, row, axis)
        seconds["finding a line"] += time.process_time() - start
        counts["finding a line"] += 1
        return found

    snapping._Snapper.options = timed_options
    snapping._Snapper.attempt = timed_attempt
    snapping._Snapper.line_of = timed_line_of
    snapping.snap_to_guides = PYTHON_SWEEPS  # the sweeps that call these methods
    try:
        yield
    finally:
        snapping._Snapper.options, snapping._Snapper.attempt, snapping._Snapper.line_of = (
            options, attempt, line_of)
        snapping.snap_to_guides = MAIN_SWEEPS


def units_table(captured) -> None:
    seconds: dict[str, float] = defaultdict(float)
    counts: dict[str, int] = defaultdict(int)
    total = 0.0
    with units_timed(seconds, counts):
        for _, (bodies, *args) in captured:
            trial = copy.deepcopy(bodies)
            start = time.process_time()
            snapping.snap_page(trial, *args)
            total += time.process_time() - start
    print("| unit | calls | CPU ms | share of the snaps |")
    print("|---|---|---|---|")
    for kind in sorted(seconds, key=seconds.get, reverse=True):
        print(f"| {kind} | {counts[kind]:,} | {seconds[kind] * 1000:.0f} "
              f"| {seconds[kind] / total:.0%} |")
    print(f"\n{len(captured)} snaps, {total * 1000:.0f} ms in all (with the wrappers)")


MAIN_IMPROVE = snapping._Snapper.improve
MAIN_SWEEPS = snapping.snap_to_guides
PYTHON_SWEEPS = functools.partial(MAIN_SWEEPS, compiled=False)  # _Snapper's own methods


def alone_only(self, row: int, axis: int) -> list[int]:
    """The step without line moves."""
    alone = self.options([row], axis)
    if self.attempt(alone, axis):
        self.stuck_lines.clear()
        return alone.roots
    return []


def alone_first(self, row: int, axis: int) -> list[int]:
    """The group's own moves first; its line's only if none of those fits."""
    moved = alone_only(self, row, axis)
    if moved:
        return moved
    alone = self.options([row], axis)
    if not (alone.missing and alone.lined_up):
        return []
    line = self.line_of(row, axis)
    key = (tuple(sorted(line)), axis)
    if len(line) < 2 or key in self.stuck_lines:
        return []
    together = self.options(line, axis)
    if self.attempt(together, axis):
        self.stuck_lines.clear()
        return together.roots
    self.stuck_lines.add(key)
    return []


def lines_last_step(self, row: int, axis: int) -> list[int]:
    if getattr(self, "lines_on", True):
        return MAIN_IMPROVE(self, row, axis)
    return alone_only(self, row, axis)


def lines_last(bodies, page_w_mm, page_h_mm, clearance_mm, margin_mm, strength, rest=None):
    """snap_to_guides with groups alone until none moves, then the snap as it is (lines on)."""
    if strength <= 0:
        return 0
    snapper = snapping._Snapper(bodies, (page_w_mm, page_h_mm), clearance_mm, margin_mm, rest)
    snapper.lines_on = False
    moves, todo = 0, [snapper.movers, snapper.movers]
    for _ in range(snapping.MAX_SWEEPS):
        moved_any = False
        for axis in (0, 1):
            moved = [root for row in todo[axis] for root in snapper.improve(int(row), axis)]
            todo[axis] = snapper.near(moved, axis)
            moves += len(moved)
            moved_any = moved_any or bool(moved)
        if moved_any:
            continue
        if not snapper.lines_on:
            snapper.lines_on = True
            todo = [snapper.movers, snapper.movers]
            continue
        lesser = [[root for row in snapper.movers for root in snapper.try_lesser(int(row), axis)]
                  for axis in (0, 1)]
        if not lesser[0] and not lesser[1]:
            break
        todo = [snapper.near(lesser[axis], axis) for axis in (0, 1)]
        moves += len(lesser[0]) + len(lesser[1])
    return moves


VARIANTS = {
    "main, compiled": (MAIN_IMPROVE, MAIN_SWEEPS),
    "main": (MAIN_IMPROVE, PYTHON_SWEEPS),
    "no lines": (alone_only, PYTHON_SWEEPS),
    "alone first": (alone_first, PYTHON_SWEEPS),
    "lines last": (lines_last_step, lines_last),
}


def variants_table(captured, repeats: int) -> None:
    print("| search | CPU ms | moves | near misses per item, summed |")
    print("|---|---|---|---|")
    try:
        for name, (improve, sweeps) in VARIANTS.items():
            snapping._Snapper.improve, snapping.snap_to_guides = improve, sweeps
            total, moves, misses = 0.0, 0, 0.0
            for _, (bodies, *args) in captured:
                best = float("inf")
                for _ in range(repeats):
                    trial = copy.deepcopy(bodies)
                    start = time.process_time()
                    made = snapping.snap_page(trial, *args)
                    best = min(best, time.process_time() - start)
                total, moves = total + best, moves + made
                active = trial.active
                misses += measure_alignment(trial.centres[active], trial.sizes[active],
                                            trial.decorative[active]).near_misses_per_item
            print(f"| {name} | {total * 1000:.0f} | {moves:,} | {misses:.2f} |", flush=True)
    finally:
        snapping._Snapper.improve, snapping.snap_to_guides = MAIN_IMPROVE, MAIN_SWEEPS


def census_table(captured) -> None:
    counts: dict[str, int] = defaultdict(int)
    options = snapping._Snapper.options
    worked_out = [False]
    real_scoring = snapping.score_moves
    last: dict[tuple, tuple] = {}

    def scoring(*args):
        worked_out[0] = True
        return real_scoring(*args)

    def counted(self, roots, axis):
        worked_out[0] = False
        found = options(self, roots, axis)
        if worked_out[0] and self.tries == snapping.MAX_TRIES:  # not try_lesser's full lists
            key = (id(self), tuple(sorted(roots)), axis)
            answer = (found.shifts, found.gain, found.missing, found.lined_up)
            kind = "a line" if len(roots) > 1 else "a group alone"
            earlier = last.get(key)
            if earlier is None:
                counts[kind, "first"] += 1
            elif earlier == answer:
                counts[kind, "same, none" if not found.shifts else "same, moves"] += 1
            else:
                counts[kind, "another"] += 1
            last[key] = answer
        return found

    snapping.score_moves, snapping._Snapper.options = scoring, counted
    snapping.snap_to_guides = PYTHON_SWEEPS  # the sweeps that call options
    try:
        for _, (bodies, *args) in captured:
            snapping.snap_page(copy.deepcopy(bodies), *args)
            last.clear()  # one snap at a time: its snapper's id() is the key's first part
    finally:
        snapping.score_moves, snapping._Snapper.options = real_scoring, options
        snapping.snap_to_guides = MAIN_SWEEPS
    print("| scoring of | first | same, none | same, moves | another |")
    print("|---|---|---|---|---|")
    for kind in ("a group alone", "a line"):
        print(f"| {kind} | " + " | ".join(f"{counts[kind, what]:,}" for what in (
            "first", "same, none", "same, moves", "another")) + " |")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--probe", action="store_true")
    parser.add_argument("--units", action="store_true")
    parser.add_argument("--variants", action="store_true")
    parser.add_argument("--census", action="store_true")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--only", default="", help="only the scenes whose name contains this")
    args = parser.parse_args()
    if args.probe:
        probe_table(args.repeats)
    if args.units or args.variants or args.census:
        captured = captured_snaps(args.only, engine_only=True, roomy=True)
        if args.census:
            census_table(captured)
        if args.units:
            units_table(captured)
        if args.variants:
            variants_table(captured, args.repeats)


if __name__ == "__main__":
    main()
