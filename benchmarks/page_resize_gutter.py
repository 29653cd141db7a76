"""What a new page size on every page leaves: `S` to a size (or `o`) on every page of a
sample, as the editor does it (the session's resize, then each page's room search and its
answer, then the save's settle), headless; per page the room search's scale, the closest gap
after the save's settle against the gutter, and the room searches' CPU seconds.

user-walk-11: the calendar made A6 kept 1.6-2.2 mm of its 3 mm gutter on five pages, the
room search having looked for zero overlap only.

    .venv/bin/python benchmarks/page_resize_gutter.py [--sample calendar-2027] [--size A6]
    .venv/bin/python benchmarks/page_resize_gutter.py --turn   # `o` on every page

Run it with main's interpreter (`/work/main/.venv/bin/python benchmarks/...`) for the figure
before: it uses only what main's session has (set_page_size, room_scale, make_room).
"""

from __future__ import annotations

import argparse
import shutil
import sys
import tempfile
import time
from pathlib import Path

from floatpage.model import load_project
from floatpage.model.layout import copy_of, engine_for_page
from floatpage.physics.quality import GAP_TOLERANCE_MM
from floatpage.tui.session import EditSession

ROOT = Path(__file__).resolve().parents[1]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sample", default="calendar-2027")
    parser.add_argument("--size", default="A6")
    parser.add_argument("--turn", action="store_true", help="`o` on every page instead of S")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="page-resize-gutter-") as scratch:
        folder = Path(scratch) / args.sample
        shutil.copytree(ROOT / "sample_projects" / args.sample, folder)
        session = EditSession(load_project(next(folder.glob("*.toml"))))
        if args.turn:
            turned = "landscape" if session.page.orientation == "portrait" else "portrait"
            session.set_orientation(turned, every_page=True)
        else:
            session.set_page_size(args.size, session.page.orientation, every_page=True)
        scales, started = {}, time.process_time()
        for request in list(session.room_wanted):
            scale = session.room_scale(copy_of(session.project.pages[request.page_index]),
                                       request)
            session.make_room(request, scale)
            scales[session.project.pages[request.page_index].id] = scale
        seconds = time.process_time() - started
        session.room_wanted.clear()
        session.settle_edited_pages()
        short = 0
        print(f"{'page':6} {'scale':>6} {'gap mm':>7}  gutter {session.project.physics.gutter_mm:g}")
        for page in session.project.pages:
            quality = engine_for_page(page, session.project.physics).quality()
            kept = quality.min_gap_mm >= quality.gutter_mm - GAP_TOLERANCE_MM
            short += not kept
            print(f"{page.id:6} {scales.get(page.id, 1.0):6.3f} {quality.min_gap_mm:7.2f}"
                  f"{'' if kept else '  < gutter'}")
        print(f"pages under the gutter: {short} of {len(session.project.pages)}; room searches "
              f"{seconds:.1f} s CPU")
    return 0


if __name__ == "__main__":
    sys.exit(main())
