"""Crowds the gutter cannot fit (issue 10: zero overlap on scenes no one tuned on): pages of
300 to 10,000 small items covering 40-70 % of the page, where each item grown by the gutter
would need more than the page, settled by Engine.settle.  Prints per page the wall time, the
overlapping pairs, the smallest gap and the items left in the margin.

    .venv/bin/python benchmarks/crowds.py            # 27 pages: 300, 1,000, 3,000 items
    .venv/bin/python benchmarks/crowds.py --big      # also 10,000 items at 40, 50 and 70 % of A4

Scenes are mixed_scene(n, cover, seed=n + 100 cover) on A4, A6 and A3 (the --big ones: seeds 3,
3 and 4, as in docs/benchmarks.md).
"""

from __future__ import annotations

import argparse
import time

from floatpage.physics.engine import Engine
from floatpage.physics.params import Params
from seeded_scenes import load, mixed_scene

PAGES = ((210.0, 297.0), (105.0, 148.0), (297.0, 420.0))
BIG = ((0.4, 3), (0.5, 3), (0.7, 4))


def settle(count: int, cover: float, seed: int, page: tuple[float, float]) -> str:
    scene = mixed_scene(count, cover, seed=seed, page_w_mm=page[0], page_h_mm=page[1])
    engine = Engine(*page, Params())
    load(engine, scene)
    start = time.perf_counter()
    engine.settle()
    seconds = time.perf_counter() - start
    quality = engine.quality()
    return (f"| {count:,} | {cover:.0%} | {page[0]:g}x{page[1]:g} | {seconds:.1f} | "
            f"{quality.overlap_count} | {quality.min_gap_mm:.2f} | {len(quality.in_margin)} |")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--big", action="store_true", help="also 10,000 items on A4")
    args = parser.parse_args()
    print("| items | cover | page mm | s | overlapping pairs | smallest gap mm | in margin |")
    print("|---|---|---|---|---|---|---|")
    for count in (300, 1000, 3000):
        for cover in (0.4, 0.55, 0.65):
            for page in PAGES:
                print(settle(count, cover, count + int(cover * 100), page), flush=True)
    if args.big:
        for cover, seed in BIG:
            print(settle(10_000, cover, seed, PAGES[0]), flush=True)


if __name__ == "__main__":
    main()
