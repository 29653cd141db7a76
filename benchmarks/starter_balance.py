"""How designed a starter's photo pages look, from any folder of photos (issue 16, "pages that
look designed"): how much of the page the photos take, how evenly the white space is shared
out, and the alignment figures `floatpage check` prints.

A designer gives each row of photos the height its photos need and shares out what is left
evenly between the rows and above and below them.  Per settled page this prints:

- the photos' share of the page's area;
- the empty horizontal bands a reader sees, top to bottom (from the page's top edge to the
  first block, between blocks, from the last to the bottom edge): a block is a photo with its
  caption, or a title;
- the spread of those bands (largest minus smallest; the band above a title, the page's
  margin, left out) and the largest: a page with an empty lower third has one band far
  larger than the rest;
- near misses and distinct edge lines per item (physics.alignment), and whether the page keeps
  zero overlap, the gutter and the margin.

    .venv/bin/python benchmarks/starter_balance.py DIR [DIR ...] [--kind album]
        [--orientation portrait|landscape|both]

Each DIR is a folder of photos (as for ``floatpage new album x.toml --photos DIR``), or the
word ``bundled`` for the starter's own pictures.  The project is made by ``starters.create``
(settled, one process), as ``floatpage new`` makes it.
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

from floatpage import starters
from floatpage.model.document import PictureItem
from floatpage.model.layout import engine_for_page
from floatpage.physics.alignment import measure_alignment


def blocks(page) -> list[tuple[float, float]]:
    """The (top, bottom) of each block on ``page``: an item together with the items anchored
    to it (a photo and its caption), in mm, sorted by top."""
    spans: dict[str, list[float]] = {}
    for item in page.items:
        if getattr(item, "decorative", False):
            continue
        to = getattr(getattr(item, "anchor", None), "to", None)
        key = to if to else item.id
        top, bottom = item.y - item.h / 2, item.y + item.h / 2
        span = spans.setdefault(key, [top, bottom])
        span[0], span[1] = min(span[0], top), max(span[1], bottom)
    return sorted((top, bottom) for top, bottom in spans.values())


def bands(page, margin_mm: float = 0.0) -> list[float]:
    """The heights of the empty horizontal bands from ``margin_mm`` inside the top edge to as
    far inside the bottom edge (0: the page's edges)."""
    found, reached = [], margin_mm
    for top, bottom in blocks(page):
        if top > reached:
            found.append(top - reached)
        reached = max(reached, bottom)
    found.append(max(0.0, page.height_mm - margin_mm - reached))
    return found


def page_figures(page, physics) -> dict:
    engine = engine_for_page(page, physics)
    bodies = engine.bodies
    figures = measure_alignment(bodies.centres, bodies.sizes, bodies.decorative)
    photos = [i for i in page.items if isinstance(i, PictureItem)]
    empty = bands(page)
    titled = any("title" in item.id for item in page.items)
    shared = empty[1:] if titled and len(empty) > 1 else empty
    return {"photos": len(photos), "photo_area": sum(p.w * p.h for p in photos),
            "page_area": page.width_mm * page.height_mm, "bands": empty,
            "spread": max(shared) - min(shared), "largest": max(shared),
            "near": figures.near_misses_per_item, "lines": figures.edge_lines_per_item,
            "ok": engine.quality().ok}


def page_line(page, figures: dict) -> str:
    return (f"{page.id} {page.orientation[:4]} {figures['photos']} photos | area "
            f"{figures['photo_area'] / figures['page_area']:.0%} | bands "
            f"{' '.join(f'{b:.0f}' for b in figures['bands'])} mm | spread "
            f"{figures['spread']:.0f}, largest {figures['largest']:.0f} | near "
            f"{figures['near']:.2f}, lines {figures['lines']:.2f} | "
            f"{'ok' if figures['ok'] else 'NOT OK'}")


def summary(rows: list[dict]) -> str:
    """Over every page: the photos' share of the pages' area, the bands' spread (mean and
    worst), near misses and edge lines per item (mean and worst), pages missing a guarantee."""
    count = len(rows)
    return (f"{count} pages | photos cover {sum(r['photo_area'] for r in rows) / sum(r['page_area'] for r in rows):.1%} "
            f"| spread mean {sum(r['spread'] for r in rows) / count:.1f} mm, worst "
            f"{max(r['spread'] for r in rows):.0f} mm | largest band mean "
            f"{sum(r['largest'] for r in rows) / count:.1f} mm | near misses mean "
            f"{sum(r['near'] for r in rows) / count:.2f}, worst {max(r['near'] for r in rows):.2f} "
            f"| edge lines mean {sum(r['lines'] for r in rows) / count:.2f}, worst "
            f"{max(r['lines'] for r in rows):.2f} | not ok {sum(not r['ok'] for r in rows)}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+", help="photo folders, or 'bundled'")
    parser.add_argument("--kind", default="album")
    parser.add_argument("--orientation", default="both", choices=("portrait", "landscape", "both"))
    parser.add_argument("--keep", default="", help="save the projects in this folder")
    parser.add_argument("--unsettled", action="store_true", help="as the starter builds them")
    args = parser.parse_args()
    orientations = ("portrait", "landscape") if args.orientation == "both" else (args.orientation,)
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        out = Path(args.keep or scratch)
        for folder in args.folders:
            for orientation in orientations:
                name = f"{Path(folder).name}-{orientation}"
                path = out / name / f"{args.kind}.toml"
                photos = None if folder == "bundled" else Path(folder)
                project = starters.create(args.kind, path, photos=photos, year=2027,
                                          orientation=orientation, settle=not args.unsettled)
                print(f"## {folder} ({orientation})", flush=True)
                for page in project.pages:
                    rows.append(page_figures(page, project.physics))
                    print("  " + page_line(page, rows[-1]), flush=True)
    print(summary(rows))


if __name__ == "__main__":
    main()
