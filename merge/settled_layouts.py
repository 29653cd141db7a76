"""Settle each distinct page geometry of a merge once per worker, not once per record.

To the physics a page is rectangles: a record's texts are refitted inside boxes that keep the
template's size, so what changes from record to record is a picture's box (its proportions)
and which items dropped out. A thousand records over two dozen pictures are a few dozen
distinct layouts, and settling one costs more than the rest of the record's layout.

Settling is a pure function of the page's geometry and the physics settings (the engine is
seeded), so a record whose page has the geometry of one settled before takes that result:
the same numbers, hence the same PDF bytes, whatever chunk or worker it lands in. The key
holds every field of every item except its text and picture path (what the physics never
reads), so a field the physics learns to read later is in the key without a change here.
"""

from __future__ import annotations

import copy
from collections import OrderedDict
from dataclasses import dataclass, fields

from floatpage.model.document import Page, PhysicsSettings
from floatpage.model.layout import engine_for_page, settle_page

LAYOUTS_KEPT = 512  # per worker process: a bound, so memory stays flat over any data file
NOT_GEOMETRY = ("text", "path")


@dataclass(frozen=True)
class SettledPage:
    """What settling made of one geometry: each item's centre and anchor, and the gate's
    verdict ("" when the page passes)."""

    places: tuple[tuple[float, float, object], ...]  # (x, y, anchor) in item order
    problem: str


def geometry_key(page: Page, settings: PhysicsSettings) -> str:
    items = [(type(item).__name__,
              [(f.name, getattr(item, f.name)) for f in fields(item) if f.name not in NOT_GEOMETRY])
             for item in page.items]
    return repr((page.id, page.width_mm, page.height_mm, settings, items))


def gate_problem(page: Page, settings: PhysicsSettings) -> str:
    """The quality gate after settling: no overlap and nothing off the page ("" if kept)."""
    quality = engine_for_page(page, settings).quality()
    ids = page.item_ids()
    if quality.overlapping_pairs:
        a, b = quality.overlapping_pairs[0]
        return (f'page "{page.id}": items "{ids[a]}" and "{ids[b]}" still overlap after '
                f"settling ({quality.overlap_count} pair(s)); the page is too full "
                "for this record's content")
    if quality.off_page:
        return f'page "{page.id}": item "{ids[quality.off_page[0]]}" lies off the page after settling'
    return ""


class SettledLayouts:
    """The last LAYOUTS_KEPT settled geometries of this process, most recently used last."""

    def __init__(self, kept: int = LAYOUTS_KEPT):
        self.kept = kept
        self.layouts: OrderedDict[str, SettledPage] = OrderedDict()
        self.settled = 0  # how many pages were really settled (the rest came from the memo)

    def settle(self, page: Page, settings: PhysicsSettings) -> str:
        """Settle `page` in place (positions and hard anchors); return the gate's problem."""
        key = geometry_key(page, settings)
        known = self.layouts.get(key)
        if known is None:
            settle_page(page, settings)
            known = SettledPage(tuple((item.x, item.y, copy.deepcopy(item.anchor))
                                      for item in page.items), gate_problem(page, settings))
            self.settled += 1
            self.layouts[key] = known
            if len(self.layouts) > self.kept:
                self.layouts.popitem(last=False)
        else:
            self.layouts.move_to_end(key)
            for item, (x, y, anchor) in zip(page.items, known.places, strict=True):
                item.x, item.y, item.anchor = x, y, copy.deepcopy(anchor)
        return known.problem
