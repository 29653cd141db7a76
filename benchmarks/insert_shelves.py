"""The flyer's shelves after one text inserted in the middle and a save (real-pages, issue 16):
the editor's `t` headless (EditSession.make_item in the page's text style, insert_item, the
room search and its answer, the live physics to rest), then the save's settle; per shelf row
the photos' bottom edges and the prices' centres, the near misses per item, and the moves of
the save's snaps (the snap's own Python, the definition the compiled sweeps are held to).

    .venv/bin/python benchmarks/insert_shelves.py            # as the editor does it
    .venv/bin/python benchmarks/insert_shelves.py --gather   # each row put on its median
                                                             # bottom edge before each snap

``--gather`` is an experiment, not the product: what the snap makes of the rows when they come
to it on one line each (a gathering step the snap does not have).
"""

from __future__ import annotations

import argparse
import shutil
import sys
import tempfile
from pathlib import Path

import numpy as np

import floatpage.physics.engine as engine_module
from floatpage.model import load_project
from floatpage.model.layout import copy_of, engine_for_page, settle_project
from floatpage.physics import snapping
from floatpage.tui.session import EditSession

ROOT = Path(__file__).resolve().parents[1]
ROWS = ("1234", "5678")
SEEN: dict = {"ids": [], "snapping": False}


def shelves(page) -> str:
    items = {item.id: item for item in page.items}
    lines = []
    for row in ROWS:
        photos = [items[f"product-{k}"] for k in row]
        prices = [items[f"product-{k}-price"] for k in row]
        lines.append(f"  photos' bottoms {[round(p.y + p.h / 2, 2) for p in photos]}, "
                     f"prices' centres {[round(p.y, 2) for p in prices]}")
    return "\n".join(lines)


def gathered(bodies) -> None:
    """Each shelf row's photos, with their prices, on the row's median bottom edge."""
    ids = SEEN["ids"]
    for row in ROWS:
        rows = [ids.index(f"product-{k}") for k in row]
        bottoms = bodies.centres[rows, 1] + bodies.sizes[rows, 1] / 2
        target = float(np.median(bottoms))
        for index, k in zip(rows, row):
            shift = target - (bodies.centres[index, 1] + bodies.sizes[index, 1] / 2)
            bodies.centres[index, 1] += shift
            bodies.centres[ids.index(f"product-{k}-price"), 1] += shift


def traced(gather: bool):
    """Engine.settle and the snap, told: each snap's moves (the Python sweeps)."""
    settle, apply = engine_module.Engine.settle, snapping._Snapper.apply

    def snap_page(bodies, w, h, params):
        if params.mode != "fast" or params.guides <= 0:
            return 0
        if gather:
            gathered(bodies)
        clearance, margin, rest = snapping.snap_limits(bodies, w, h, params, deferred=True)
        SEEN["snapping"] = True
        moves = snapping.snap_to_guides(bodies, w, h, clearance, margin, params.guides, rest,
                                        compiled=False)
        SEEN["snapping"] = False
        print(f"    a snap: {moves} moves")
        return moves

    def told_settle(self, *args, **kwargs):
        SEEN["ids"] = list(self.ids)
        return settle(self, *args, **kwargs)

    def told_apply(self, roots, members, axis, shift):
        if SEEN["snapping"]:
            print(f"      {'xy'[axis]} {shift:+6.2f} {[SEEN['ids'][root] for root in roots]}")
        return apply(self, roots, members, axis, shift)

    engine_module.snap_page = snap_page
    engine_module.Engine.settle = told_settle
    snapping._Snapper.apply = told_apply


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gather", action="store_true")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="insert-shelves-") as scratch:
        folder = Path(scratch) / "shop-flyer"
        shutil.copytree(ROOT / "sample_projects" / "shop-flyer", folder)
        path = folder / "shop-flyer.toml"
        project = load_project(path)
        print("as shipped\n" + shelves(project.pages[0]))
        session = EditSession(project)
        session.insert_item(session.make_item("text", text="New offer"))
        for request in list(session.room_wanted):
            scale = session.room_scale(copy_of(project.pages[request.page_index]), request)
            session.make_room(request, scale)
        session.room_wanted.clear()
        session.engine.settle(finalize=False)  # the live physics, to rest
        session.sync_positions()
        print("the live physics at rest\n" + shelves(session.page))
        traced(args.gather)
        print("the save's settle")
        session.pages_edited.add(session.page.id)
        session.settle_edited_pages()
        session.sync_positions()
        page = session.page
        alignment = engine_for_page(page, project.physics).alignment()
        print("saved\n" + shelves(page) + f"\n  {alignment.summary()}")
        session.save()
        again = load_project(path)
        before = {item.id: (item.x, item.y) for item in again.pages[0].items}
        engine_module.snap_page = snapping.snap_page  # a plain settle, no gathering
        settle_project(again)
        moved = max(max(abs(a - b) for a, b in zip(before[item.id], (item.x, item.y)))
                    for item in again.pages[0].items)
        print(f"a second settle (plain) moves an item at most {moved:.2f} mm")
    return 0


if __name__ == "__main__":
    sys.exit(main())
