"""A page's new size, applied to its regions and items (the editor's `S` and `o`): items
keep their relative place, the space between a follower and its target scales, sizes stay
unless they no longer fit.  Apart from the session, so that `S` can resize every page of a
project the same way it resizes the one on screen."""

from __future__ import annotations

from floatpage.model.document import ItemAnchor, Page, PictureItem, PointAnchor
from floatpage.physics import Engine
from floatpage.tui.clear_spaces import scaled_offset, scaled_size
from floatpage.tui.region_edits import body_of, box_of, root_of


def resize_page(page: Page, size: str, orientation: str, width: float, height: float,
                margin: float) -> list[str]:
    """Give ``page`` the size ``width`` x ``height`` mm (named ``size``, in ``orientation``),
    ``margin`` its print-safe margin there; the ids of the items larger than the new page,
    which were made smaller."""
    sx, sy = width / page.width_mm, height / page.height_mm
    own_scale = page_scale_of(page, width, height)
    # Regions keep their share of the page, as items keep their place: one left as it
    # was reached past a smaller page, and the file saved was one no command would open.
    for region in page.regions:
        left, top = round(region.left * sx, 2), round(region.top * sy, 2)
        region.w = min(round((region.left + region.w) * sx, 2), width) - left
        region.h = min(round((region.top + region.h) * sy, 2), height) - top
        region.left, region.top = left, top
    old_sizes = {item.id: (item.w, item.h) for item in page.items}
    too_large = [item.id for item in page.items
                 if not item.decorative and (item.w > width or item.h > height)]
    for item in page.items:
        item.x, item.y = item.x * sx, item.y * sy
        if item.decorative:  # a band across the page keeps spanning it: it stretches
            item.w, item.h = item.w * sx, item.h * sy
        if isinstance(item, PictureItem) and item.lock_aspect:
            # shape kept, as `+` and `-` keep it: clamped side by side, the album's 3:2
            # photos came out 1.08:1 on a 60 mm wide page, and printed stretched
            fit = min(1.0, width / item.w, height / item.h)
            item.w, item.h = item.w * fit, item.h * fit
        item.w, item.h = min(item.w, width), min(item.h, height)
        if item.region:  # no larger than its region (the loader's rule), shape kept
            room = page.region(item.region)
            fit = min(1.0, room.w / item.w, room.h / item.h)
            item.w, item.h = item.w * fit, item.h * fit
        if isinstance(item.anchor, PointAnchor):
            item.anchor.x, item.anchor.y = item.anchor.x * sx, item.anchor.y * sy
        if not (item.decorative or item.group or getattr(item, "bleed", False)):
            # on a page of the same shape, the size the room search tries first: the old
            # one scaled with the page (an item that kept the old margin keeps the new one)
            scaled = scaled_size(item, *old_sizes[item.id], own_scale) \
                if own_scale < 1.0 else None
            keep_inside_margin(item, width, height, margin, scaled)
    scale_follow_offsets(page, old_sizes, sx, sy)
    fit_bodies_to_regions(page)
    page.size, page.orientation = size, orientation
    page.width_mm, page.height_mm = width, height
    return too_large


SAME_SHAPE_WITHIN = 0.02  # two pages are one shape if their sides' ratios differ this little


def page_scale_of(page: Page, width: float, height: float) -> float:
    """The scale of a new page size ``width`` x ``height`` mm against ``page``'s own, where it
    is the same shape and smaller (A4 to A5: 0.707; letter to A4 is not one shape); else 1.
    Positions scale with the page; sizes scaled by as much make the new page the old one
    scaled, every edge and centre that lined up still lined up."""
    sx, sy = width / page.width_mm, height / page.height_mm
    if abs(sx / sy - 1.0) > SAME_SHAPE_WITHIN:
        return 1.0
    return min(1.0, sx, sy)


def fit_bodies_to_regions(page: Page) -> None:
    """Shrink an item confined to a region, with the items that move as one with it, until
    they fit the region together: the whole body keeps inside its root's region (the
    physics' rule).  The item alone was fitted, and its caption left below: `o` on an album
    page with a photo in a region (73 x 54 mm, 38 mm tall once turned) fitted the photo to
    38 mm and left its caption outside, a page no settle could mend (user-walk-12a)."""
    for item in page.items:
        if not item.region or item.decorative:
            continue
        body = body_of(page, item)
        if len(body) == 1 or root_of(page, body) is not item:
            continue
        room = page.region(item.region)
        left, top, right, bottom = box_of(body)
        fit = min(1.0, room.w / (right - left), room.h / (bottom - top))
        if fit >= 1.0:
            continue
        for member in body:
            member.w, member.h = member.w * fit, member.h * fit
            if member is not item:
                member.x = item.x + (member.x - item.x) * fit
                member.y = item.y + (member.y - item.y) * fit
                if isinstance(member.anchor, ItemAnchor):
                    member.anchor.dx, member.anchor.dy = (member.anchor.dx * fit,
                                                          member.anchor.dy * fit)


def kept_by(engine: Engine) -> tuple[frozenset[str], bool]:
    """What the engine's page keeps now, which the room found after a change must let it keep:
    the ids of the items that keep their print-safe margin, and whether every gap keeps the
    gutter (one measure of the page for both)."""
    quality = engine.quality()
    return frozenset(engine.ids) - {engine.ids[k] for k in quality.in_margin}, quality.gutter_kept


def size_words(size: str, width: float, height: float) -> str:
    """A page size as the status line says it: "A5", or "120 x 170 mm"."""
    return f"{width:g} × {height:g} mm" if size == "custom" else size


def keep_inside_margin(item, width_mm: float, height_mm: float, margin_mm: float,
                       size: tuple[float, float] | None = None) -> None:
    """Move the item, and its point anchor, just far enough that the item keeps the print-safe
    margin where it fits inside it (centred where it does not). Scaled with a turned page, a
    footer hard-anchored 5 mm above the bottom of an A4 flyer ended 2.9 mm above it, and no
    settle could move it (issue 16)."""
    def kept(centre: float, size: float, page: float) -> float:
        low, high = margin_mm + size / 2, page - margin_mm - size / 2
        return page / 2 if low > high else min(max(centre, low), high)

    w, h = size or (item.w, item.h)
    item.x, item.y = kept(item.x, w, width_mm), kept(item.y, h, height_mm)
    if isinstance(item.anchor, PointAnchor):
        item.anchor.x = kept(item.anchor.x, w, width_mm)
        item.anchor.y = kept(item.anchor.y, h, height_mm)


def scale_follow_offsets(page: Page, old_sizes: dict[str, tuple[float, float]], sx: float,
                         sy: float) -> None:
    """Scale each follower's offset from its target with a new page size, as positions scale,
    and put it there; the members of a group keep to their lead the same way.  Left as it was,
    a follower 160 mm below its target on A4 stood past the bottom of an A6 page, and the
    saved offsets no longer matched the saved positions; a group's members, their centres
    scaled but not their sizes, came to overlap one another for good.  Item sizes do not
    scale, so on an axis where two stand apart the space between their edges scales (a caption
    2.5 mm below its photo keeps clear of it), but never into the near-miss band from outside
    it (tui.clear_spaces); where they overlap on an axis (a caption centred
    under its photo, a label on a picture), the centres' offset scales.  Positions are set
    target first, down each chain.  Called with positions already scaled by (sx, sy)."""
    by_id = {item.id: item for item in page.items}
    leads = {item.group: page.group_lead(item.group) for item in page.items if item.group}
    done: set[str] = set()

    def scaled(offset: float, scale: float, axis: int, item, target) -> float:
        old_half = (old_sizes[item.id][axis] + old_sizes[target.id][axis]) / 2
        new_half = ((item.w, item.h)[axis] + (target.w, target.h)[axis]) / 2
        return round(scaled_offset(offset, old_half, new_half, scale), 2) + 0.0

    def place(item) -> None:
        if item.id in done:
            return
        done.add(item.id)
        anchor = item.anchor
        if isinstance(anchor, ItemAnchor) and anchor.to in by_id:
            target = by_id[anchor.to]
            place(target)
            anchor.dx = scaled(anchor.dx, sx, 0, item, target)
            anchor.dy = scaled(anchor.dy, sy, 1, item, target)
            item.x, item.y = target.x + anchor.dx, target.y + anchor.dy
        elif item.group and leads.get(item.group) is not None \
                and leads[item.group] is not item and not isinstance(anchor, ItemAnchor):
            lead = leads[item.group]
            dx, dy = (item.x - lead.x) / sx, (item.y - lead.y) / sy  # as it was
            place(lead)
            item.x = lead.x + scaled(dx, sx, 0, item, lead)
            item.y = lead.y + scaled(dy, sy, 1, item, lead)

    for item in page.items:
        place(item)
