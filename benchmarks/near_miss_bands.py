"""Where the alignment snap leaves pairs of features (issue 16): the near-miss count of
physics.alignment (pairs 0.5-4 mm apart) is one window of many a reader of the page could use,
and a snap that only counts that window may move a pair from 3.9 mm to 4.05 mm, out of the
count and no further apart to the eye.  This prints, per item, pairs of edges (or of centres)
of different items by distance, and near misses for several windows, guides off and on.

    .venv/bin/python benchmarks/near_miss_bands.py              # the eleven scenes up to 60 %
    .venv/bin/python benchmarks/near_miss_bands.py --seeds 10   # and 10 fresh seeded pages
    .venv/bin/python benchmarks/near_miss_bands.py --seeds 16 --first-seed 2000 --fresh-only

Each page is settled the `floatpage settle` way (model.layout.settle_project).
"""

from __future__ import annotations

import argparse

import numpy as np

from floatpage.physics.alignment import near_pairs
from alignment import benchmark_scenes, random_scenes, scene_project, settle_once
from guide_cost import fresh_scenes

WINDOWS = ((0.5, 3.0), (0.5, 4.0), (0.5, 5.0), (0.5, 6.0), (0.5, 8.0))
BINS = np.arange(0.0, 8.01, 0.5)


def feature_sets(centres: np.ndarray, sizes: np.ndarray):
    """Per axis: the items' edges (each owner twice) and their centres, with owners, as
    physics.alignment pairs them."""
    owners = np.arange(len(centres))
    for axis in (0, 1):
        low, high = centres[:, axis] - sizes[:, axis] / 2, centres[:, axis] + sizes[:, axis] / 2
        yield np.concatenate([low, high]), np.concatenate([owners, owners])
        yield centres[:, axis], owners


def page_figures(centres: np.ndarray, sizes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Near misses per window and the histogram of pair distances (BINS), both per item."""
    windows = np.zeros(len(WINDOWS))
    histogram = np.zeros(len(BINS) - 1)
    for values, owners in feature_sets(centres, sizes):
        windows += [near_pairs(values, owners, low, high) for low, high in WINDOWS]
        apart = np.abs(values[:, None] - values[None, :])
        upper = np.triu(owners[:, None] != owners[None, :], 1)
        histogram += np.histogram(apart[upper], BINS)[0]
    return windows / len(centres), histogram / len(centres)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=0, help="fresh seeded pages to add")
    parser.add_argument("--first-seed", type=int, default=500, help="the fresh pages' first seed")
    parser.add_argument("--fresh-only", action="store_true", help="only the fresh seeded pages")
    args = parser.parse_args()
    scenes = [] if args.fresh_only else [
        s for s in benchmark_scenes(True) + random_scenes() if s.coverage <= 0.6]
    scenes += fresh_scenes(args.seeds, args.first_seed)
    header = " | ".join(f"{low:g}-{high:g} mm" for low, high in WINDOWS)
    print(f"| page | guides | {header} |")
    print("|---|---|" + "---|" * len(WINDOWS))
    totals = {0.0: [np.zeros(len(WINDOWS)), np.zeros(len(BINS) - 1)],
              1.0: [np.zeros(len(WINDOWS)), np.zeros(len(BINS) - 1)]}
    items = 0
    for scene in scenes:
        items += len(scene.ids)
        for guides in (0.0, 1.0):
            settled, _ = settle_once(scene_project(scene), guides)
            page = settled.pages[0]
            centres = np.array([[item.x, item.y] for item in page.items])
            sizes = np.array([[item.w, item.h] for item in page.items])
            windows, histogram = page_figures(centres, sizes)
            totals[guides][0] += windows
            totals[guides][1] += histogram * len(centres)
            figures = " | ".join(f"{value:.2f}" for value in windows)
            print(f"| {scene.name} | {'on' if guides else 'off'} | {figures} |", flush=True)
    for guides, (windows, histogram) in totals.items():
        print(f"\nguides {'on' if guides else 'off'}: near misses per item summed over the "
              f"pages: " + ", ".join(f"{low:g}-{high:g} mm {value:.2f}"
                                     for (low, high), value in zip(WINDOWS, windows)))
        print("pairs per item (all pages) by distance: " + ", ".join(
            f"{low:g}-{low + 0.5:g} {count / items:.2f}" for low, count in zip(BINS, histogram)))


if __name__ == "__main__":
    main()
