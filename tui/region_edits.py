"""Regions made, changed and removed in the editor (`R`).

The editor drew regions and let an item join one (`Enter`), but a region itself could only be
written in the project file: a user who wanted "photos in the top two-thirds" had to leave the
editor for a text editor.  `R` opens a form for the selected item's region, or for a new one
around the selected item (or the page's top two-thirds, with nothing selected); the answer is
checked by the loader's rules (inside the page, its own name, every item in it fits) before
it becomes one undoable edit.
"""

from __future__ import annotations

import itertools
import math
from typing import Any

from floatpage.model.document import ItemAnchor, Region
from floatpage.tui.dialogs.form import Field, FieldError
from floatpage.tui.item_forms import checked, number

AROUND_MM = 10.0  # a new region around the selected item leaves it this much room each side


def free_region_id(page) -> str:
    taken = {region.id for region in page.regions}
    return next(f"region-{n}" for n in itertools.count(1) if f"region-{n}" not in taken)


def proposed_region(page, item) -> Region:
    """The region the form offers: the item's own, else one around the item and the items
    following it (its caption: where the region is the item's alone, the caption cannot stay
    on the page below it), else the page's top two-thirds (the README's example)."""
    if item is not None and item.region:
        return page.region(item.region)
    if item is None:
        return Region(free_region_id(page), 0.0, 0.0, page.width_mm,
                      round(page.height_mm * 2 / 3, 2))
    own = [item] + [other for other in page.items  # with its caption, which it keeps inside
                    if isinstance(other.anchor, ItemAnchor) and other.anchor.to == item.id]
    left, top, right, bottom = box_of(own)
    left, top = max(0.0, left - AROUND_MM), max(0.0, top - AROUND_MM)
    right = min(page.width_mm, right + AROUND_MM)
    bottom = min(page.height_mm, bottom + AROUND_MM)
    return Region(free_region_id(page), round(left, 2), round(top, 2),
                  round(right - left, 2), round(bottom - top, 2))


def region_choices(page) -> list[tuple[str, str]]:
    """What `R` with nothing selected offers on a page with regions: a new region (the value
    "", which `edit_region` reads as none), or one of the page's to change or remove."""
    def held(region) -> str:
        count = sum(1 for item in page.items if item.region == region.id)
        return f"{count} item(s) in it" if count else "no item in it"
    return [("New region…", "")] + [
        (f"Change or remove {region.id}  ({round(region.w, 1):g} × {round(region.h, 1):g} mm, "
         f"{held(region)})", region.id) for region in page.regions]


def region_fields(region: Region, item, *, new: bool) -> list[Field]:
    name = "Region name" if new else "Region name (empty removes it; its items go free)"
    fields = [Field("id", name, "line", region.id),
              Field("left", "Left edge, from the page's left (mm)", "line", f"{region.left:g}"),
              Field("top", "Top edge, from the page's top (mm)", "line", f"{region.top:g}"),
              Field("w", "Width (mm)", "line", f"{region.w:g}"),
              Field("h", "Height (mm)", "line", f"{region.h:g}")]
    if item is not None:
        fields.append(Field("confine", f"Keep {item.id} inside it", "bool",
                            item.region in ("", region.id)))
    return fields


def parse_region(values: dict[str, Any]) -> dict[str, Any]:
    """The typed region: None for an empty name (remove it), else a Region, each number read
    and checked by the model's own field checks; and whether to confine the item."""
    name = str(values["id"]).strip()
    confine = bool(values.get("confine", False))
    if not name:
        return {"region": None, "confine": False}
    try:
        checked(Region, "id", name, "the region name")
    except ValueError as error:
        raise FieldError("id", str(error)) from None
    numbers = {}
    for key, words in (("left", "the left edge"), ("top", "the top edge"), ("w", "the width"),
                       ("h", "the height")):
        try:
            numbers[key] = number(str(values[key]).strip(), words, Region, key)
        except ValueError as error:
            raise FieldError(key, str(error)) from None
    return {"region": Region(name, **numbers), "confine": confine}


def body_of(page, item) -> list:
    """``item`` and every item that moves as one with it: its group's members and the items
    following any of them (or followed), as the physics joins them, in file order: a region
    holds the body by the walls `shift_room` reads, not the confined item alone."""
    body, grew = {item.id}, True
    while grew:
        grew = False
        groups = {other.group for other in page.items if other.id in body and other.group}
        for other in page.items:
            joined = other.id not in body and (
                other.group in groups
                or isinstance(other.anchor, ItemAnchor) and other.anchor.to in body
                or any(isinstance(member.anchor, ItemAnchor) and member.anchor.to == other.id
                       for member in page.items if member.id in body))
            if joined:
                body.add(other.id)
                grew = True
    return [other for other in page.items if other.id in body]


def box_of(items) -> tuple[float, float, float, float]:
    """(left, top, right, bottom) around ``items``, mm."""
    return (min(i.x - i.w / 2 for i in items), min(i.y - i.h / 2 for i in items),
            max(i.x + i.w / 2 for i in items), max(i.y + i.h / 2 for i in items))


def members_of(page, old_id: str | None, item, confine: bool) -> list:
    """The items the region will hold: those of the region it replaces, and ``item`` if it is
    to keep inside."""
    members = [other for other in page.items if old_id and other.region == old_id
               and other is not item]
    return members + [item] if item is not None and confine else members


def region_parser(page, old_id: str | None, item, margin_mm: float):
    """`parse_region`, then the loader's rules (`refuse_region`) as the form's error line, so
    a region too large for the page or too small for its items keeps the form open."""
    from floatpage.tui.session import EditError

    def parse(values: dict[str, Any]) -> dict[str, Any]:
        answer = parse_region(values)
        if answer["region"] is None and old_id is None:
            raise ValueError("give the region a name, e.g. photos")
        if answer["region"] is not None:
            try:
                refuse_region(page, old_id, answer["region"],
                              members_of(page, old_id, item, answer["confine"]), margin_mm)
            except EditError as error:
                raise ValueError(str(error)) from None
        return answer
    return parse


def put_region(session, old_id: str | None, answer: dict[str, Any], item_id: str | None) -> str:
    """Make, change (``old_id``) or remove (no name) a region of the session's page, as one
    undoable edit; with ``item_id``, confine that item to it or let it go.  Raises EditError,
    with the loader's reasons, for a region the project file could not hold.  Returns what
    happened, in words."""
    from floatpage.tui.session import EditError

    page = session.page
    new: Region | None = answer["region"]
    item = page.item(item_id) if item_id else None
    session.sync_positions()
    if new is None:
        if old_id is None:
            raise EditError("give the region a name, e.g. photos")
        session.checkpoint(f"remove region {old_id}")
        freed = [other for other in page.items if other.region == old_id]
        for other in freed:
            other.region = ""
        page.regions[:] = [region for region in page.regions if region.id != old_id]
        session.rebuild_engine(sync=False)
        return f'removed region "{old_id}"' + (f"; {len(freed)} item(s) in it go free"
                                               if freed else "")
    members = members_of(page, old_id, item, answer["confine"])
    margin_mm = session.engine.margin_mm
    refuse_region(page, old_id, new, members, margin_mm)
    session.checkpoint(f"region {new.id}")
    if old_id is None:
        page.regions.append(new)
    else:
        page.regions[[region.id for region in page.regions].index(old_id)] = new
    for other in page.items:
        if old_id and other.region == old_id:
            other.region = new.id
    if item is not None:
        item.region = new.id if answer["confine"] else ("" if item.region == new.id
                                                         else item.region)
    moved: set[str] = set()
    for member in members:  # put inside at once, as a drag keeps it inside: with the items
        if member.id in moved:  # moving as one with it, or the group came apart
            continue
        body = body_of(page, member)
        (dx_low, dx_high), (dy_low, dy_high) = shift_room(body, page, margin_mm)
        dx, dy = min(max(0.0, dx_low), dx_high), min(max(0.0, dy_low), dy_high)
        for other in body:
            other.x += dx
            other.y += dy
            moved.add(other.id)
    session.rebuild_engine(sync=False)
    verb = "made" if old_id is None else "changed"
    # to a tenth of a mm, as the preview can show: "127 × 135.47 mm" (two thirds of a 5x8 in
    # card) gave a precision nobody asked for, beside a whole number (user-walk-6)
    return (f'{verb} region "{new.id}" ({round(new.w, 1):g} × {round(new.h, 1):g} mm)'
            + (f'; "{item.id}" keeps inside it' if item is not None and answer["confine"]
               else ""))


def refuse_region(page, old_id: str | None, new: Region, members: list,
                  margin_mm: float) -> None:
    """EditError for what the loader would refuse (model.project_file): a region reaching past
    the page, a name another region has, an item larger than its region; and for a body (a
    group, an item with its caption) the region would leave no place (`body_misfit`)."""
    from floatpage.tui.session import EditError

    left, top, right, bottom = new.box
    if left < 0 or top < 0 or right > page.width_mm + 1e-9 or bottom > page.height_mm + 1e-9:
        raise EditError(f"the region reaches outside the page ({left:g}-{right:g} mm across, "
                        f"{top:g}-{bottom:g} mm down, on a page of {page.width_mm:g} x "
                        f"{page.height_mm:g} mm): keep left + width and top + height within it")
    if any(region.id == new.id and region.id != old_id for region in page.regions):
        raise EditError(f'this page has a region "{new.id}" already: choose another name')
    for member in members:
        if member.w > new.w + 1e-9 or member.h > new.h + 1e-9:
            raise EditError(f'"{member.id}" is {member.w:.1f} x {member.h:.1f} mm, larger than '
                            f"the region ({new.w:g} x {new.h:g} mm): make the region larger "
                            "or the item smaller")
        misfit = body_misfit(page, member, margin_mm, {item.id: new for item in members})
        if misfit:
            raise EditError(misfit)


def walls_of(item, page, margin_mm: float, regions: dict[str, Region]) -> tuple[float, ...]:
    """(left, top, right, bottom) an item keeps inside: its region (``regions`` first: the
    region an edit gives it), else the page less the print-safe margin (none for bleed)."""
    region = regions.get(item.id) or (page.region(item.region) if item.region and any(
        r.id == item.region for r in page.regions) else None)
    if region is not None:
        return region.box
    margin = 0.0 if getattr(item, "bleed", False) else margin_mm
    return (margin, margin, page.width_mm - margin, page.height_mm - margin)


def root_of(page, body):
    """The member of ``body`` the others follow, as the physics joins them: the one that
    follows no item and leads its group, if any."""
    for item in body:
        follows = isinstance(item.anchor, ItemAnchor) or (
            item.group and page.group_lead(item.group) is not item)
        if not follows:
            return item
    return body[0]


def shift_room(body, page, margin_mm: float, regions: dict[str, Region] | None = None
               ) -> tuple[tuple[float, float], tuple[float, float]]:
    """The shifts along x and along y, each (least, most), that keep ``body`` (moving as one)
    inside its walls by the physics' rule (physics.geometry.group_room): every member inside
    its root's walls (`walls_of`: the root's region, or the margins), and a member confined
    to a region of its own inside that too; least > most where no shift does."""
    regions = regions or {}
    root = root_of(page, body)
    outer = walls_of(root, page, margin_mm, regions)
    room = [[-math.inf, math.inf], [-math.inf, math.inf]]
    for item in body:
        if item.decorative:
            continue
        walls = [outer]
        if item is not root and (item.id in regions or item.region):
            walls.append(walls_of(item, page, margin_mm, regions))
        for wall in walls:
            for axis, (centre, size) in enumerate(((item.x, item.w), (item.y, item.h))):
                room[axis][0] = max(room[axis][0], wall[axis] - (centre - size / 2))
                room[axis][1] = min(room[axis][1], wall[axis + 2] - (centre + size / 2))
    return (room[0][0], room[0][1]), (room[1][0], room[1][1])


def body_misfit(page, member, margin_mm: float, regions: dict[str, Region] | None = None
                ) -> str | None:
    """Why ``member`` and the items moving as one with it (`body_of`) have no place where
    each keeps inside its walls (its region, ``regions`` first, or the margins), in words
    with what to do; None if they have one.  Such a body no settle can fit: `check` said so
    only after the edit was made."""
    body = body_of(page, member)
    if len(body) == 1:
        return None
    across, down = shift_room(body, page, margin_mm, regions)
    if across[0] <= across[1] + 1e-6 and down[0] <= down[1] + 1e-6:
        return None
    left, top, right, bottom = box_of(body)
    region = (regions or {}).get(member.id) or page.region(member.region)
    others = ", ".join(f'"{other.id}"' for other in body if other is not member)
    how, undo = ((f'its group "{member.group}"', f'take "{member.id}" out of its group '
                  "(G, an empty name) first") if member.group else
                 ("the items it follows or that follow it", "bring them closer together, or "
                  "unanchor them (u) first"))
    return (f'"{member.id}" moves as one with {others} ({how}), {right - left:.1f} x '
            f'{bottom - top:.1f} mm together; kept inside the region "{region.id}" '
            f"({region.w:g} x {region.h:g} mm), and all of them inside the walls of the one "
            f'they follow ("{root_of(page, body).id}"), they have no place on the page: make '
            f"the region larger, or {undo}")
