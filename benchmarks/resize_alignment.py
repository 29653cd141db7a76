"""Near misses after a new page size on every page: `S` to a size (or `o`) on every page of
each sample, as the editor does it (the session's resize, each page's room search and its
answer, the save's settle), headless; per sample and size the near misses per item summed over
its pages, the pages under the gutter, and the room search's scales.

real-pages (issue 16): the album made A5 went from 0.00 to 1.18 near misses per item on page 1
and 0.83 on page 2, its captions' space below their photos scaled into the near-miss band.

    .venv/bin/python benchmarks/resize_alignment.py [--samples photo-album,shop-flyer]
        [--sizes A5,A6,A3,turn]

Run it with main's interpreter (`/work/main/.venv/bin/python benchmarks/...`) for the figure
before: it uses only what main's session has (set_page_size, set_orientation, room_scale,
make_room, settle_edited_pages).
"""

from __future__ import annotations

import argparse
import shutil
import sys
import tempfile
from pathlib import Path

from floatpage.model import load_project
from floatpage.model.layout import copy_of, engine_for_page
from floatpage.physics.quality import GAP_TOLERANCE_MM
from floatpage.tui.session import EditSession

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = ("photo-album", "shop-flyer", "calendar-2027", "greeting-card", "multilingual-card",
           "merge-offers")


def resized(sample: str, size: str, scratch: Path) -> tuple[list[float], int, list[float]]:
    """The sample with ``size`` on every page (``turn``: `o`), saved as the editor saves:
    near misses per item per page, the pages under the gutter, the room search's scales."""
    folder = scratch / f"{sample}-{size}"
    shutil.copytree(ROOT / "sample_projects" / sample, folder)
    session = EditSession(load_project(next(folder.glob("*.toml"))))
    if size == "turn":
        turned = "landscape" if session.page.orientation == "portrait" else "portrait"
        session.set_orientation(turned, every_page=True)
    else:
        session.set_page_size(size, session.page.orientation, every_page=True)
    scales = []
    for request in list(session.room_wanted):
        scale = session.room_scale(copy_of(session.project.pages[request.page_index]), request)
        session.make_room(request, scale)
        scales.append(scale)
    session.room_wanted.clear()
    session.settle_edited_pages()
    misses, short = [], 0
    for page in session.project.pages:
        engine = engine_for_page(page, session.project.physics)
        quality = engine.quality()
        short += quality.min_gap_mm < quality.gutter_mm - GAP_TOLERANCE_MM
        misses.append(engine.alignment().near_misses_per_item)
    return misses, short, scales


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", default=",".join(SAMPLES))
    parser.add_argument("--sizes", default="A5,A6,A3,turn")
    args = parser.parse_args()
    total = 0.0
    print("| sample | size | near misses per item, summed | pages | under the gutter | "
          "room scales (least) |")
    print("|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory(prefix="resize-alignment-") as scratch:
        for sample in args.samples.split(","):
            for size in args.sizes.split(","):
                misses, short, scales = resized(sample, size, Path(scratch))
                total += sum(misses)
                print(f"| {sample} | {size} | {sum(misses):.2f} | {len(misses)} | {short} | "
                      f"{min(scales, default=1.0):.3f} |", flush=True)
    print(f"near misses per item, summed over every sample, size and page: {total:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
