"""Whether the alignment snap is a fixed point of itself (issue 16: the extra probes): each
page settled the `floatpage settle` way, and the snap after its full run (the first snap a
plainly scattered page makes, model.layout.settle_page) snapped once more, on its result as it
is and on it rounded as a save writes it (0.01 mm).  A snap that moves items there is a probe
more: the probe finds the page not at rest.

    .venv/bin/python benchmarks/snap_again.py --seeds 30 --first-seed 2000
    .venv/bin/python benchmarks/snap_again.py --seeds 30 --first-seed 3000 --only 3004,3016
"""

from __future__ import annotations

import argparse

import numpy as np

import floatpage.physics.engine as engine_module
import floatpage.physics.snapping as snapping
from floatpage.model.layout import settle_project
from alignment import scene_project
from guide_cost import fresh_scenes


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=30)
    parser.add_argument("--first-seed", type=int, default=2000)
    parser.add_argument("--only", default="", help="seeds, comma-separated")
    args = parser.parse_args()
    only = {int(seed) for seed in args.only.split(",") if seed}
    snap, state = snapping.snap_page, {"first": True, "row": ""}

    def snapped_again(bodies, page_w_mm, page_h_mm, params):
        moves = snap(bodies, page_w_mm, page_h_mm, params)
        if state["first"]:
            state["first"] = False
            kept = bodies.centres.copy()
            again = [snap(bodies, page_w_mm, page_h_mm, params)]
            far = [np.abs(bodies.centres - kept).max()]
            bodies.centres[:] = np.round(kept, 2)
            rounded = bodies.centres.copy()
            again.append(snap(bodies, page_w_mm, page_h_mm, params))
            far.append(np.abs(bodies.centres - rounded).max())
            bodies.centres[:] = kept
            state["row"] = (f"| {moves} | {again[0]} ({far[0]:.2f} mm) "
                            f"| {again[1]} ({far[1]:.2f} mm) |")
        return moves
    engine_module.snap_page = snapped_again
    print("| page | first snap's moves | snapped again: moves (farthest) | rounded, then "
          "again |")
    print("|---|---|---|---|")
    for index, scene in enumerate(fresh_scenes(args.seeds, args.first_seed)):
        if only and args.first_seed + index not in only:
            continue
        state["first"], state["row"] = True, "| no snap | | |"
        settle_project(scene_project(scene))
        print(f"| {scene.name} {state['row']}", flush=True)


if __name__ == "__main__":
    main()
