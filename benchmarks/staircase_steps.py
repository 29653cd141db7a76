"""Shelves and staircase steps on settled pages no one tuned on (guide_cost.py's fresh seeds,
900-929 by default): the exact alignments (within 0.05 mm) on one axis between two items that
stand apart across it (a shelf's neighbours, not a stack), of the same kind (bottom on
bottom, top on top, centre on centre) against those of crossed kinds only (one's bottom edge on
the other's top edge: a step, which the alignment measure and the snap count as a line).

real-pages (issue 16): a text inserted in the flyer left two of its products a price's height
above their shelf, each price's bottom on its neighbours' prices' tops (insert_shelves.py).

    .venv/bin/python benchmarks/staircase_steps.py [--seeds 30] [--first-seed 900]
"""
from __future__ import annotations

import argparse
import itertools
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from guide_cost import fresh_scenes  # noqa: E402
from alignment import scene_project  # noqa: E402
from floatpage.model.layout import engine_for_page, settle_project  # noqa: E402

ALIGNED = 0.05 + 1e-6  # the snap's exact alignment (physics.snap_scoring.ALIGNED_MM)


def shelves_and_steps(centres: np.ndarray, halves: np.ndarray) -> tuple[int, int]:
    """Pairs of items standing apart across an axis with an exact alignment on it: of the same
    kind, and of crossed kinds only (a step)."""
    same = steps = 0
    for i, j in itertools.combinations(range(len(centres)), 2):
        for axis in (0, 1):
            across = 1 - axis
            if abs(centres[i, across] - centres[j, across]) < halves[i, across] + halves[j, across]:
                continue  # stacked along this axis, not side by side
            mine = (centres[i, axis] - halves[i, axis], centres[i, axis],
                    centres[i, axis] + halves[i, axis])
            theirs = (centres[j, axis] - halves[j, axis], centres[j, axis],
                      centres[j, axis] + halves[j, axis])
            kind = any(abs(a - b) <= ALIGNED for a, b in zip(mine, theirs))
            crossed = abs(mine[0] - theirs[2]) <= ALIGNED or abs(mine[2] - theirs[0]) <= ALIGNED
            same += kind
            steps += crossed and not kind
    return same, steps


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=30)
    parser.add_argument("--first-seed", type=int, default=900)
    args = parser.parse_args()
    same = steps = 0
    for scene in fresh_scenes(args.seeds, args.first_seed):
        project = scene_project(scene)
        settle_project(project)
        bodies = engine_for_page(project.pages[0], project.physics).bodies
        page_same, page_steps = shelves_and_steps(bodies.centres, bodies.sizes / 2)
        same, steps = same + page_same, steps + page_steps
        print(f"{scene.name}: same kind {page_same}, steps {page_steps}", flush=True)
    print(f"in all: same kind {same}, steps {steps} "
          f"({steps / max(1, same + steps):.0%} of the exact alignments side by side)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
