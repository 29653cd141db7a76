"""Alignment benchmark (issue 16): every sample page, every benchmark scene and a few random
scenes of other page sizes, settled the `floatpage settle` way (model.layout.settle_project)
with the magnetic guides off ([physics] guides = 0) and on (the default), in one run.

    .venv/bin/python benchmarks/alignment.py            # everything (a few minutes)
    .venv/bin/python benchmarks/alignment.py --quick    # without the 200- and 500-item scenes

Per page: near misses per item, distinct edge lines per item and the share aligned on both axes
(physics.alignment), whether the settled page keeps zero overlap, the gutter and the margin
(check --strict's test, physics.quality), and the settle time with guides over without: CPU
seconds of this process (time.process_time, less disturbed than wall time by the other jobs on
a shared machine), best of --repeats runs each, alternating off and on; compare the ratio.
"""

from __future__ import annotations

import argparse
import copy
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

from floatpage.model import load_project
from floatpage.model.document import BlockItem, Page, Project
from floatpage.model.layout import engine_for_page, settle_project
from floatpage.physics.alignment import measure_alignment
from seeded_scenes import Scene, big_item_scene, dropped_scene, mixed_scene

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = ("shop-flyer", "photo-album", "calendar-2027", "greeting-card", "multilingual-card",
           "merge-offers")


def scene_project(scene: Scene) -> Project:
    page = Page(id="page", size="custom", width_mm=scene.page_w_mm, height_mm=scene.page_h_mm,
                items=[BlockItem(id=item_id, x=float(x), y=float(y), w=float(w), h=float(h))
                       for item_id, (x, y), (w, h) in zip(scene.ids, scene.centres, scene.sizes)])
    return Project(title=scene.name, pages=[page])


def benchmark_scenes(quick: bool) -> list[Scene]:
    counts = (5, 20, 50) if quick else (5, 20, 50, 200, 500)
    return [mixed_scene(n, 0.5, seed=1) for n in counts] + [
        mixed_scene(40, 0.9, seed=1), dropped_scene(12), big_item_scene(seed=1)]


def random_scenes() -> list[Scene]:
    """Scenes the guides were never tuned on: other seeds, coverages and page sizes."""
    chosen = []
    for seed, (count, coverage, page) in enumerate([
            (8, 0.3, (127.0, 203.2)), (15, 0.45, (148.0, 210.0)), (30, 0.55, (297.0, 420.0)),
            (12, 0.6, (215.9, 279.4)), (25, 0.35, (210.0, 297.0)), (60, 0.5, (297.0, 210.0))]):
        scene = mixed_scene(count, coverage, seed=100 + seed, page_w_mm=page[0],
                            page_h_mm=page[1])
        chosen.append(replace(scene, name=f"random {count} items, {coverage:.0%}, "
                                           f"{page[0]:g}x{page[1]:g} mm"))
    return chosen


def settle_once(project: Project, guides: float) -> tuple[Project, float]:
    trial = copy.deepcopy(project)
    trial.physics = replace(trial.physics, guides=guides)
    start = time.process_time()
    settle_project(trial)
    return trial, time.process_time() - start


def settled_pair(project: Project, repeats: int) -> tuple[Project, float, Project, float]:
    """The page settled with the guides off and on, and the best time of each over
    ``repeats`` runs, alternating off and on so that the machine's load hits both alike."""
    best_off = best_on = float("inf")
    for _ in range(repeats):
        off, seconds = settle_once(project, 0.0)
        best_off = min(best_off, seconds)
        on, seconds = settle_once(project, 1.0)
        best_on = min(best_on, seconds)
    return off, best_off, on, best_on


def page_rows(project: Project) -> list[tuple[str, str, bool]]:
    """Per page: its name, its alignment figures and whether it keeps every guarantee."""
    rows = []
    for page in project.pages:
        engine = engine_for_page(page, project.physics)
        bodies = engine.bodies
        figures = measure_alignment(bodies.centres, bodies.sizes, bodies.decorative)
        quality = engine.quality()
        rows.append((page.id, f"{figures.near_misses_per_item:.2f} | "
                     f"{figures.edge_lines_per_item:.2f} | {figures.aligned_share:.0%}",
                     quality.ok))
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="skip the 200- and 500-item scenes")
    parser.add_argument("--repeats", type=int, default=5, help="timed settles per case (best)")
    parser.add_argument("--only", default="", help="only the cases whose name contains this")
    args = parser.parse_args()
    cases = [(f"sample {name}", load_project(next((ROOT / "sample_projects" / name).glob("*.toml"))))
             for name in SAMPLES]
    cases += [(f"scene {s.name} ({s.coverage:.0%})", scene_project(s))
              for s in benchmark_scenes(args.quick)]
    cases += [(s.name, scene_project(s)) for s in random_scenes()]
    print("| case | page | off: near misses/item | edge lines/item | aligned | ok "
          "| on: near misses/item | edge lines/item | aligned | ok | settle on/off |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    ratios = []
    for name, project in cases:
        if args.only not in name:
            continue
        off, off_s, on, on_s = settled_pair(project, args.repeats)
        ratios.append(on_s / off_s)
        for (page, before, ok_before), (_, after, ok_after) in zip(page_rows(off), page_rows(on)):
            print(f"| {name} | {page} | {before} | {'yes' if ok_before else 'NO'} | {after} | "
                  f"{'yes' if ok_after else 'NO'} | {on_s / off_s:.2f} ({on_s:.2f} s) |",
                  flush=True)
    print(f"\nsettle time with guides over without: median {np.median(ratios):.2f}, "
          f"worst {max(ratios):.2f}")


if __name__ == "__main__":
    main()
