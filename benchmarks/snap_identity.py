"""Whether a change to the alignment snap (physics.snapping) makes exactly the same moves: every
snap's input is captured once, with the centres and move count the snap gave it, and a later
run (another branch) snaps each kept input again and compares, bit for bit.

    # on main (or the commit to compare against): capture and record, a few minutes
    .venv/bin/python benchmarks/snap_identity.py --record /tmp/snaps.pickle
    # on the branch: the same moves?  and CPU per set of pages, best of --repeats
    .venv/bin/python benchmarks/snap_identity.py --check /tmp/snaps.pickle --repeats 3

The inputs are the bodies snap_page is handed while these settle: the alignment benchmark's
scenes (which are guide_cost's) the `floatpage settle` way (model.layout.settle_project) and the
Engine.settle way, benchmarks/physics.py's fresh scenes from seeds 3000-3015 and 5100-5115
(Engine.settle), and anchored_pages.py's pages with soft and hard anchors and followers (the
snap's groups of several rows; `floatpage settle`'s way).  A snap that changes no move changes no later input either, so one recording
serves every such change; a change meant to alter the moves shows here which pages it alters.

Why a recording and not a hash (snap_speed.py prints one): a hash says *that* something moved,
this says which page and which rows, and it checks the inputs from main, not the branch's own.

For instruction counts (robust to the shared machine's load), ``--snaps K`` snaps every kept
input K times and prints nothing timed: under callgrind, the run with K = 2 less the run with
K = 1 is one snap of each input (``--only`` picks pages by label):

    valgrind --tool=callgrind --callgrind-out-file=/dev/null .venv/bin/python \\
        benchmarks/snap_identity.py --check /tmp/snaps.pickle --snaps 2 --only roomy
"""

from __future__ import annotations

import argparse
import copy
import pickle
import time
from collections import defaultdict

import numpy as np

from floatpage.model.layout import settle_project
from floatpage.physics.snapping import snap_page

from alignment import benchmark_scenes, random_scenes, scene_project
from anchored_pages import random_project
from seeded_scenes import fresh_scenes
from snap_speed import loaded, roomy_scenes, snaps_captured

FRESH_SEEDS = (3000, 5100)
ANCHORED = [(seed, "mixed") for seed in range(27000, 27012)] + [
    (seed, "follow") for seed in range(27100, 27106)]  # followers: groups of several rows


def capture() -> list[tuple[str, tuple]]:
    """(label, snap_page's arguments) for every snap the settles ask for; a label starts with
    the set of pages ("guide_cost", "roomy", "fresh" or "anchored"), then the settle and the
    scene."""
    with snaps_captured() as (captured, label):
        for scene in benchmark_scenes(quick=True) + random_scenes():
            label[0] = f"guide_cost settle {scene.name}"
            settle_project(scene_project(scene))
            label[0] = f"guide_cost Engine.settle {scene.name}"
            loaded(scene).settle()
        roomy = {scene.name for scene in roomy_scenes()}
        for first_seed in FRESH_SEEDS:
            for scene in fresh_scenes(16, first_seed):
                kind = "roomy" if scene.name in roomy else "fresh"
                label[0] = f"{kind} Engine.settle {scene.name}"
                loaded(scene).settle()
        for seed, kind in ANCHORED:
            label[0] = f"anchored settle {kind} seed {seed}"
            settle_project(random_project(seed, kind))
    return captured


def snapped(arguments: tuple) -> tuple[np.ndarray, int]:
    """The centres and move count of one snap of a copy of the kept input."""
    bodies, page_w_mm, page_h_mm, params = copy.deepcopy(arguments)
    made = snap_page(bodies, page_w_mm, page_h_mm, params)
    return bodies.centres, made


def record(path: str) -> None:
    kept = [(label, arguments, *snapped(arguments)) for label, arguments in capture()]
    with open(path, "wb") as file:
        pickle.dump(kept, file)
    print(f"recorded {len(kept)} snaps, {sum(entry[3] for entry in kept)} moves, in {path}")


def check(path: str, repeats: int, only: str, snaps: int) -> bool:
    """Snap every kept input again: whether each gives the recorded centres, bit for bit, and
    move count; prints CPU ms per set of pages (best of ``repeats`` per snap)."""
    with open(path, "rb") as file:
        kept = [entry for entry in pickle.load(file) if only in entry[0]]
    if snaps:  # for callgrind: nothing but the snaps
        for _ in range(snaps):
            for _, arguments, _, _ in kept:
                snapped(arguments)
        return True
    seconds: dict[str, float] = defaultdict(float)
    moves: dict[str, int] = defaultdict(int)
    counts: dict[str, int] = defaultdict(int)
    differing = []
    for label, arguments, centres, made in kept:
        best = float("inf")
        for _ in range(repeats):
            start = time.process_time()
            now_centres, now_made = snapped(arguments)
            best = min(best, time.process_time() - start)
        pages = label.split(" ", 1)[0]
        seconds[pages] += best
        moves[pages] += now_made
        counts[pages] += 1
        if now_made != made or now_centres.tobytes() != centres.tobytes():
            rows = np.flatnonzero((now_centres != centres).any(axis=1)).tolist()
            differing.append(f"{label}: moves {made} -> {now_made}, rows differing {rows[:10]}")
    print("| pages | snaps | CPU ms (best of each) | moves |")
    print("|---|---|---|---|")
    for pages in seconds:
        print(f"| {pages} | {counts[pages]} | {seconds[pages] * 1000:.0f} | {moves[pages]} |")
    print(f"\nall: {sum(seconds.values()) * 1000:.0f} ms, {len(kept)} snaps")
    for line in differing:
        print("DIFFERS", line)
    print(f"identical: {len(kept) - len(differing)} of {len(kept)} snaps")
    return not differing


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    what = parser.add_mutually_exclusive_group(required=True)
    what.add_argument("--record", metavar="FILE", help="capture the inputs, snap, keep")
    what.add_argument("--check", metavar="FILE", help="snap the kept inputs again, compare")
    parser.add_argument("--repeats", type=int, default=1, help="timed snaps per input (best)")
    parser.add_argument("--only", default="", help="only the snaps whose label has this")
    parser.add_argument("--snaps", type=int, default=0,
                        help="snap each input this many times, untimed (for callgrind)")
    args = parser.parse_args()
    if args.record:
        record(args.record)
    elif not check(args.check, args.repeats, args.only, args.snaps):
        raise SystemExit(1)


if __name__ == "__main__":
    main()
