"""Issue 10's promise on pages it was never tuned on: where the items fit with the gutter, every
gap ends at least the gutter.

Random pages (A4 both ways, A5, a 5x8 in card, Letter) of 2-60 free items with aspect ratios from
1:8 to 8:1, scattered at random, settle with the default settings; each is filed by how much of
the room inside the print-safe margins its items cover once each is grown by the gutter (the
issue's measure, `geometry.grown_cover`), and counted as keeping the gutter when `settle`
reports it and `check` finds no gap below it and no overlap, and as keeping the margin too
when nothing stands in it. Pages whose items cannot be parted at all (two bars crossing the
room) are counted apart: nothing fits there, whatever the cover. Each page that misses either
is listed (a page whose items cannot all keep the margin, whatever the cover, misses only the
margin; `check` names the limit).

    .venv/bin/python benchmarks/gutter_fits.py              # 300 pages, seed 0
    .venv/bin/python benchmarks/gutter_fits.py --pages 100 --seed 7
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from floatpage.physics import Engine
from floatpage.physics.page_limits import binding, page_limits, unexplained_pairs

PAGES = [(210.0, 297.0), (297.0, 210.0), (148.0, 210.0), (127.0, 203.2), (215.9, 279.4)]
BANDS = [(0.0, 0.6), (0.6, 0.7), (0.7, 0.75), (0.75, 0.8), (0.8, 0.85)]
GUTTER = 3.0


def random_page(rng: np.random.Generator) -> Engine:
    page_w, page_h = PAGES[int(rng.integers(len(PAGES)))]
    count = int(rng.integers(2, 61))
    cover = rng.uniform(0.15, 0.6)
    aspect = np.exp(rng.uniform(np.log(1 / 8), np.log(8), count))
    share = rng.uniform(0.2, 1.0, count)
    area = share / share.sum() * cover * page_w * page_h
    widths = np.minimum(np.sqrt(area * aspect), page_w - 12)
    heights = np.minimum(area / np.sqrt(area * aspect), page_h - 12)
    engine = Engine(page_w, page_h)
    for k in range(count):
        engine.insert(f"i{k}", rng.uniform(0, page_w), rng.uniform(0, page_h), widths[k],
                      heights[k])
    return engine


def grown_cover(engine: Engine) -> float:
    """The share of the room inside the margins the items cover, each grown by the gutter (the
    room too, as items may touch its walls): geometry.grown_cover, written out here so the
    script also runs on code from before it."""
    room = np.array([engine.page_w_mm, engine.page_h_mm]) - 2 * engine.margin_mm + GUTTER
    return float((engine.bodies.sizes + GUTTER).prod(axis=1).sum() / room.prod())


def limit_names(engine: Engine) -> str:
    """What `check` gives as the reason a page misses: the kinds of the limits that bind it
    (physics.page_limits), or "unexplained" where none does or a narrow pair is left that no
    limit accounts for."""
    bodies = engine.bodies
    limits = binding(page_limits(bodies, engine.page_w_mm, engine.page_h_mm, engine.margin_mm,
                                 GUTTER))
    if not limits or unexplained_pairs(bodies, limits, GUTTER):
        return "unexplained"
    return "check names " + ", ".join(sorted({type(limit).__name__ for limit in limits}))


def crossing(engine: Engine) -> bool:
    """Whether two items can be parted neither side by side nor one above the other within
    the margins: no layout keeps them apart."""
    sizes = engine.bodies.sizes
    room = np.array([engine.page_w_mm, engine.page_h_mm]) - 2 * engine.margin_mm
    i, j = np.triu_indices(len(sizes), 1)
    need = sizes[i] + sizes[j]
    return bool(((need[:, 0] > room[0]) & (need[:, 1] > room[1])).any())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pages", type=int, default=300)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    kept = {band: [0, 0, 0] for band in BANDS}  # keep the gutter and margin, pages, the gutter
    crossed, seconds, missed, unexplained = 0, [], [], 0
    for index in range(args.pages):
        engine = random_page(rng)
        cover = grown_cover(engine)
        band = next((band for band in BANDS if band[0] <= cover < band[1]), None)
        if band is None:
            continue
        if crossing(engine):
            crossed += 1
            continue
        start = time.process_time()
        report = engine.settle()
        seconds.append(time.process_time() - start)
        quality = engine.quality()
        gutter = (report.fits and quality.min_gap_mm >= GUTTER and not quality.overlapping_pairs
                  and not quality.off_page)
        ok = gutter and not quality.in_margin
        kept[band][0] += ok
        kept[band][1] += 1
        kept[band][2] += gutter
        if not ok:
            reason = limit_names(engine)
            unexplained += reason == "unexplained"
            missed.append(f"page {index}: {engine.page_w_mm:g}x{engine.page_h_mm:g} mm, "
                          f"{int(engine.bodies.active.sum())} items, grown cover {cover:.1%}: "
                          f"narrowest gap {quality.min_gap_mm:.2f} mm, "
                          f"{len(quality.overlapping_pairs)} overlapping, "
                          f"{len(quality.in_margin)} in the margin, settle fits {report.fits}; {reason}")
    print("| grown cover | pages | keep the gutter and the margin | keep the gutter |")
    print("|---|---|---|---|")
    for (low, high), (good, total, gutter) in kept.items():
        share = f"{good / total:.0%}" if total else "—"
        print(f"| {low:.0%}-{high:.0%} | {total} | {good} ({share}) | {gutter} |")
    print(f"\n{crossed} pages with two items that cannot be parted left out; settle median "
          f"{np.median(seconds):.2f} s CPU, worst {max(seconds):.2f} s")
    print(f"{len(missed)} pages miss the gutter or the margin, {unexplained} of them with no "
          f"limit that check names")
    for line in missed:  # each page that misses: a reader can make it again (random_page); one
        print(line)  # with items in the margin and no narrow gap: check says if a limit forced it


if __name__ == "__main__":
    main()
