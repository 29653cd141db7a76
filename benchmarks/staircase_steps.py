"""Shelves and staircase steps on settled pages no one tuned on (guide_cost.py's fresh seeds,
900-929 by default): the exact alignments (within 0.05 mm) on one axis between two items that
stand apart across it (a shelf's neighbours, not a stack), of the same kind (bottom on
bottom, top on top, centre on centre) against those of crossed kinds only (one's bottom edge on
the other's top edge: a step, which the alignment measure and the snap count as a line).

real-pages (issue 16): a text inserted in the flyer left two of its products a price's height
above their shelf, each price's bottom on its neighbours' prices' tops (insert_shelves.py).

    .venv/bin/python benchmarks/staircase_steps.py [--seeds 30] [--first-seed 900]
"""
import argparse
import itertools
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from guide_cost import fresh_scenes  # noqa: E402
from alignment import scene_project  # noqa: E402
from floatpage.model.layout import engine_for_page, settle_project  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--seeds", type=int, default=30)
parser.add_argument("--first-seed", type=int, default=900)
args = parser.parse_args()
same = cross = 0
for scene in fresh_scenes(args.seeds, args.first_seed):
    project = scene_project(scene)
    settle_project(project)
    b = engine_for_page(project.pages[0], project.physics).bodies
    c, h = b.centres, b.sizes / 2
    s_page = c_page = 0
    for i, j in itertools.combinations(range(len(c)), 2):
        for axis in (0, 1):
            other = 1 - axis
            if abs(c[i, other] - c[j, other]) < h[i, other] + h[j, other]:
                continue  # stacked along this axis, not side by side
            fi = (c[i, axis] - h[i, axis], c[i, axis], c[i, axis] + h[i, axis])
            fj = (c[j, axis] - h[j, axis], c[j, axis], c[j, axis] + h[j, axis])
            sk = any(abs(fi[k] - fj[k]) <= 0.05 for k in range(3))
            ck = abs(fi[0] - fj[2]) <= 0.05 or abs(fi[2] - fj[0]) <= 0.05
            s_page += sk
            c_page += ck and not sk
    same += s_page; cross += c_page
    print(scene.name, "same-kind", s_page, "staircase", c_page, flush=True)
print("total same-kind", same, "staircase steps", cross)
