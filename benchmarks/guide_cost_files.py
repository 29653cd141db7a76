"""What the alignment guides cost on realistic project files (issue 16: "a settle time at most
1.25x that without guides, in the same run", in every case), where guide_cost.py measures
pages of plain boxes.  The files are fresh_projects.py's (``random_project``): several pages
of different sizes with backgrounds, bleeding pictures, regions, groups, captions that follow
their photos, soft and hard anchors, texts and month panels, each with its own gutter and
margin.

Each page is settled the `floatpage settle` way (model.layout.settle_page) from the file as
drawn, with ``guides = 0`` and with ``guides = 1`` (the default; the file's own setting is
replaced), alternating, best of --repeats; CPU seconds of this process (time.process_time).
Per file: the pages' summed settle off and on and their ratio, and the near misses per item
(physics.alignment) of its pages, off and on.

    .venv/bin/python benchmarks/guide_cost_files.py --seeds 1-40
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from dataclasses import replace
from pathlib import Path

from floatpage.model import load_project
from floatpage.model.layout import copy_of, engine_for_page, settle_page
from fresh_projects import random_project, seed_range


def settle_seconds(page, physics) -> tuple[float, float]:
    """CPU seconds of one settle of a copy of ``page``, and its near misses per item."""
    trial = copy_of(page)
    start = time.process_time()
    settle_page(trial, physics)
    seconds = time.process_time() - start
    return seconds, engine_for_page(trial, physics).alignment().near_misses_per_item


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", default="1-40", help="A-B: fresh_projects.py's seeds")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    ratios = []
    print("| file | pages | off s | on s | on/off | near misses/item off → on (pages) |")
    print("|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as scratch:
        for seed in seed_range(args.seeds):
            folder = Path(scratch) / str(seed)
            project = load_project(random_project(seed, folder))
            best = {0.0: 0.0, 1.0: 0.0}
            misses: dict[float, list[str]] = {0.0: [], 1.0: []}
            for page in project.pages:
                times: dict[float, float] = {0.0: float("inf"), 1.0: float("inf")}
                near: dict[float, float] = {}
                for _ in range(args.repeats):  # off and on alternating
                    for guides in (0.0, 1.0):
                        physics = replace(project.physics, guides=guides)
                        seconds, near[guides] = settle_seconds(page, physics)
                        times[guides] = min(times[guides], seconds)
                for guides in (0.0, 1.0):
                    best[guides] += times[guides]
                    misses[guides].append(f"{near[guides]:.2f}")
            ratio = best[1.0] / best[0.0] if best[0.0] > 0 else 1.0
            ratios.append(ratio)
            print(f"| seed {seed} | {len(project.pages)} | {best[0.0]:.3f} | {best[1.0]:.3f} | "
                  f"{ratio:.2f} | {', '.join(misses[0.0])} → {', '.join(misses[1.0])} |")
    print(f"\non/off over {len(ratios)} files: median {statistics.median(ratios):.2f}, "
          f"worst {max(ratios):.2f}, above 1.25: {sum(r > 1.25 for r in ratios)}")


if __name__ == "__main__":
    main()
