"""What `floatpage check` says of one page: its measures, and for each guarantee it misses
(zero overlap, on the page, the print-safe margin, the gutter), why and what to do.

A miss that the items themselves force (physics.page_limits) is named as such, with the items
and the numbers, so that nobody runs `floatpage settle` again and again on a page no settle
can fix.  Only a miss nothing explains is sent back to `settle`.
"""

from __future__ import annotations

import numpy as np

from floatpage.model.errors import printable
from floatpage.physics.quality import measure_alignment
from floatpage.physics.page_limits import (
    Crossing, Limit, NoArrangement, NoRoom, PinnedClash, PinnedOutside, PinnedStack, Stack,
    TooLarge, binding,
    page_limits, room_caps, too_large, unexplained_pairs,
)
from floatpage.physics.geometry import GUTTER_FITS_COVER, pinned_items, room_covers, rooms_of

SHOWN = 5  # reasons of one kind spelled out; the rest are counted
AXIS_WORDS = (("wide", "across"), ("tall", "down"))
SETTLE = "run `floatpage settle`"  # the advice for a miss a settle may fix (and only for one)
# what helps a page a settle cannot mend (page_reasons' ``stuck``, and check's closing line)
MAKE_ROOM = ("make room: make items smaller, choose a larger page size (S in the editor), or "
             "move some items to another page")


TINY_MM = 1.0  # a side shorter than this: a box no one sees, nor prints legibly
KIND_WORDS = {"text": "a text", "picture": "a picture", "calendar": "a calendar"}


def tiny_items(page) -> list[str]:
    """Warnings for the texts, pictures and calendars with a side under TINY_MM, each naming
    the item and the page: a 0.4 mm picture or calendar (a slip of the mouse, a typo of 0.5
    for 50) passed `check` without a word.  Blocks are left out: a 0.3 mm block is a rule."""
    found = []
    for item in page.items:
        if item.kind in KIND_WORDS and min(item.w, item.h) < TINY_MM:
            found.append(f'item "{item.id}" on page "{page.id}": its box is {item.w:g} × '
                         f"{item.h:g} mm, under {TINY_MM:g} mm "
                         f"{'wide' if item.w <= item.h else 'tall'}, too small for "
                         f"{KIND_WORDS[item.kind]} to be seen or printed (enlarge the box, "
                         "or remove the item)")
    return found


def empty_page_notes(project) -> list[str]:
    """A note for each page that holds no item: an `N` too many in the editor, or a page
    whose items were all moved or deleted, printed as a blank sheet in the PDF and `check`
    said nothing but "0 overlaps · even 1.00" of it (user-walk-8).  A note, not a problem:
    a blank page can be meant (the back of a card), so `--strict` still passes."""
    notes = []
    for page in project.pages:
        if page.items:
            continue
        shows = ("only its background" if page.background is not None
                 and (page.background.color or page.background.picture) else "a blank page")
        notes.append(f'page "{page.id}" has no items: it prints as {shows}; put '
                     "something on it, or remove the page (D on it in the editor)")
    return notes


def page_report(page, engine, gutter_mm: float, *, stuck: bool = False
                ) -> tuple[list[str], int]:
    """The lines `check` prints for ``page`` (settled or not, as it lies in the file) and the
    number of layout problems it counts for ``--strict``.  Only the misses no reason explains
    carry the advice SETTLE (``settle_may_help``), and only where a settle mends some of
    them: ``stuck`` (``settle_mends`` found it does not) gives what helps instead."""
    lines, problems, _ = page_reasons(page, engine, gutter_mm, stuck=stuck)
    return lines, problems


def settle_mends(page, physics, problems: int) -> bool:
    """Whether a settle of ``page`` (on a copy: the page is left as it is) leaves fewer than
    ``problems``, the count ``page_report`` gave the page as it is (the caller has it: its
    limits are the dearest part of a report).  A page a settle leaves as it is (a card's size
    typed down to A6, settled: items off it), or moves without mending (too full), was sent
    back to `settle` by
    every line and by `check --strict`'s closing line, and settle then said "another settle
    changes nothing" (user-walk-9, user-walk-10).  As costly as a settle of the page; `check`
    asks only of a page whose lines would send the user to settle."""
    from floatpage.model.errors import FloatpageError
    from floatpage.model.layout import copy_of, engine_for_page, settle_page

    trial = copy_of(page)
    try:
        settle_page(trial, physics)
    except FloatpageError:  # settle refuses the page (items piled up): it says why itself
        return True
    after = page_report(trial, engine_for_page(trial, physics), physics.gutter_mm)[1]
    return after < problems


def page_reasons(page, engine, gutter_mm: float, *, stuck: bool = False
                 ) -> tuple[list[str], int, str]:
    """``page_report``'s lines and count, and the same reason in a few words for the
    editor's status line: which guarantee gave way (the gutter, then the margin, then
    overlap) and why, e.g. "gutter 1.2 of 3 mm: page too full (94 % of the room)".  The
    editor said "some gaps narrow" and left the why to `check` (user-walk-6).  Empty
    when nothing gave way.  ``stuck``: a settle mends none of it (``settle_mends``), so no
    line sends the user to settle; each says what helps instead."""
    quality = engine.quality()
    if not page.items:  # no measure means anything here: "even 1.00 · balance 1.00" of nothing
        return [f"page {page.id}: no items"], 0, ""
    bodies = engine.bodies
    lines = [f"page {page.id}: {quality.summary()}",
             f"  {measure_alignment(bodies.centres, bodies.sizes, bodies.decorative).summary()}"]
    problems = (quality.overlap_count + len(quality.off_page) + len(quality.in_margin)
                + len(quality.outside_region))
    name = _namer(page)
    limits = (page_limits(bodies, page.width_mm, page.height_mm, engine.margin_mm, gutter_mm)
              if not quality.ok else too_large(bodies, page.width_mm, page.height_mm,
                                               engine.margin_mm))
    # a group too large for its walls is a problem even where the file keeps them as
    # written: the next settle squeezes it (geometry.squeezed), so it is not a settled layout
    counted = set(quality.outside_region) | set(quality.off_page) | set(quality.in_margin)
    problems += sum(isinstance(limit, TooLarge) and not set(limit.rows) & counted
                    for limit in limits)
    oversized = {row for limit in limits if isinstance(limit, TooLarge) for row in limit.rows}
    why = _short_why(limits, name)
    for k in quality.outside_region:
        item = page.items[k]
        if k in oversized:  # named below, with what to do: settle cannot
            continue
        lines.append(f'  item "{printable(item.id)}" is not wholly inside its region '
                     f'"{printable(item.region)}": '
                     + ("a settle leaves it there: make the region larger, or the item "
                        "smaller, or move the items in its way" if stuck
                        else f"{SETTLE}, or make the region larger"))
    if quality.in_margin:
        shown = _some([name(k) for k in quality.in_margin[:SHOWN]], len(quality.in_margin))
        lines.append(f"  {len(quality.in_margin)} item(s) inside the {quality.margin_mm:.1f} mm "
                     f"print-safe margin: {shown}; where a page is too full the gutter gives "
                     "way first, then the margin: "
                     + ("" if stuck or binding(limits)
                        or engine.grown_cover() > GUTTER_FITS_COVER else f"{SETTLE}, ")
                     + "make items smaller, mark items that may touch the edge `bleed = true`, "
                     "or lower margin_mm in [physics]")
    lines += _explain(limits, name, gutter_mm, engine.margin_mm, page)
    named = {row for limit in limits if isinstance(limit, (PinnedOutside, TooLarge))
             for row in getattr(limit, "rows", (getattr(limit, "row", -1),))}
    off = [k for k in quality.off_page if k not in named]
    if off:  # every item off the page is named, by a limit or here: never a bare count
        lines.append(f"  {len(off)} item(s) reach past the page's edge: "
                     f"{_some([name(k) for k in off[:SHOWN]], len(off))}; "
                     + (f"a settle leaves them there: move them (or their anchors) onto the "
                        f"page, or {MAKE_ROOM}" if stuck else f"{SETTLE}, or move them onto the page"))
    loose = unexplained_pairs(bodies, limits, gutter_mm) if not quality.ok else []
    overlapping = [(a, b) for a, b, gap in loose if gap < 0]
    if overlapping:
        pairs = _some([f"{name(a)} and {name(b)}" for a, b in overlapping[:SHOWN]],
                      len(overlapping))
        packed, room = _tightest_room(page, engine, 0.0)
        if packed > GUTTER_FITS_COVER:
            why = why or f"page too full ({packed:.0%} of {_short_room(room)})"
            lines.append(
                f"  overlapping: {pairs}; the items may not fit on page {page.id} at all: "
                f"even without the gutter they need {packed:.0%} of {room}, more than the {GUTTER_FITS_COVER:.0%} rectangles of mixed shapes "
                "seldom pack tighter than; make items smaller, or move some to another page")
        else:
            why = why or "anchors box them in, or r (reheat) parts them"
            lines.append(f"  overlapping: {pairs}; " + (
                "a settle leaves them overlapping, so hard anchors or anchored groups box "
                "them in: move an anchor, or " + MAKE_ROOM if stuck else
                f"{SETTLE}; if they still overlap after it, hard anchors or anchored groups "
                "box them in: move an anchor, make items smaller, or move some to another "
                "page"))
    elif loose:
        need, room = _tightest_room(page, engine, gutter_mm)
        if need > GUTTER_FITS_COVER:
            why = why or f"page too full ({need:.0%} of {_short_room(room)})"
            lines.append(
                f"  note: the {gutter_mm:g} mm gutter may not fit on page {page.id}: its "
                f"items, each grown by the gutter, need {need:.0%} of {room}, more than the {GUTTER_FITS_COVER:.0%} up to which settle promises "
                f"it (rectangles of mixed shapes seldom pack tighter), so settle keeps the "
                f"widest gap it finds; make items smaller, move some to another page or lower "
                f"gutter_mm or margin_mm to keep it")
        elif (cap := _loose_cap(bodies, limits, loose)) < gutter_mm:
            kept = max(min(gap for _, _, gap in loose), 0.0)
            why = why or f"{cap:.1f} mm fits: r (reheat) may mend it"
            lines.append(
                f"  they can keep {cap:.1f} mm, not the {gutter_mm:g} mm gutter, but page "
                f"{page.id} keeps {kept:.1f} mm "
                f"({_some([f'{name(a)} and {name(b)}' for a, b, _ in loose[:SHOWN]], len(loose))}"
                f" stand closer than that): {SETTLE}; if a settled page still keeps less, its anchors or "
                f"the order its items lie in jam it: move an anchored item or nudge items "
                f"apart, and settle again")
            problems += 1
        else:
            why = why or "it fits: r (reheat) may mend it"
            lines.append(
                f"  the {gutter_mm:g} mm gutter fits on page {page.id} (its items grown by it "
                f"need {need:.0%} of {room}) but is not kept" + (
                    ", and a settle does not mend it: its anchors or the order its items lie "
                    "in jam it: move an anchored item or nudge items apart, then settle "
                    "again" if stuck else
                    f": {SETTLE}; if a settled page still misses it, its anchors or the "
                    f"order its items lie in jam it: move an anchored item or nudge items "
                    f"apart, and settle again"))
            problems += 1
    return lines, problems, _short(quality, why or "r (reheat) may mend it")


def _loose_cap(bodies, limits: list[Limit], loose: list[tuple[int, int, float]]) -> float:
    """The narrowest of the gaps the limits leave the ``loose`` pairs, each as
    unexplained_pairs reads it (room_caps: the wider cap of the rooms of its items that move);
    inf where no limit caps any.  A page whose room a limit caps below the gutter was told
    both that its items "cannot all stand 3 mm apart ... the widest gap they can all keep is
    2.2 mm" and that "the 3 mm gutter fits ... but is not kept" (fresh_projects seed 9614,
    p4): the advice speaks of the gap the limit leaves instead.  The narrowest, not the
    closest pair's: there a free text beside the capped region (a pair whose cap is the
    free room's, none) was the closest, and the gutter was said to fit again."""
    roots, _ = bodies.group_roots()
    pinned = pinned_items(bodies, roots)
    rooms = rooms_of(bodies)
    caps = room_caps(bodies, limits, rooms)
    return float(min(max(-np.inf if pinned[a] else caps[rooms[a]],
                         -np.inf if pinned[b] else caps[rooms[b]]) for a, b, _ in loose))


def _short(quality, why: str) -> str:
    """What gave way, the last of the gutter, the margin and overlap to give way first, and
    ``why``; empty when nothing did."""
    if quality.overlap_count:
        gave = f"{quality.overlap_count} overlap{'s' if quality.overlap_count != 1 else ''}"
    elif quality.in_margin:
        gave = f"margin ({len(quality.in_margin)} in it)"
    elif not quality.gutter_kept:
        gave = f"gutter {max(quality.min_gap_mm, 0.0):.1f} of {quality.gutter_mm:g} mm"
    elif quality.off_page or quality.outside_region:
        gave = "walls"
    else:
        return ""
    return f"{gave}: {why}"


def _short_room(room: str) -> str:
    """``_tightest_room``'s name for the room, in a few words."""
    return "the room" if room.startswith("the room inside") else "its region"


def _short_why(limits: list[Limit], name) -> str:
    """The first reason `check` gives (``_explain``'s order), in a few words."""
    for limit in binding(limits):
        rows = getattr(limit, "rows", None) or (getattr(limit, "row", 0),)
        first = name(rows[0])
        if isinstance(limit, PinnedClash):
            return f"pinned {first} and {name(rows[1])} meet"
        if isinstance(limit, PinnedOutside):
            return f"{first} is pinned there"
        if isinstance(limit, TooLarge):
            return f"{first} too large for its room"
        if isinstance(limit, Crossing):
            return f"{first} and {name(rows[1])} too big to part"
        if isinstance(limit, (Stack, PinnedStack)):
            return f"{len(rows)} items too big to stand side by side"
        if isinstance(limit, NoRoom):
            return f"no room for {first} by the pinned items"
        if isinstance(limit, NoArrangement):
            return "no arrangement keeps it"
    return ""


def _past_lead_region(limit: Limit, page) -> bool:
    """Whether ``limit`` is a lead confined to a region whose followers make its rigid group
    larger than the region on an axis.  The physics keeps a group inside its lead's walls
    (geometry.group_room), so such a chain can never sit in the region, and no settle mends it
    (check used to send the user to `settle`, which then wrote nothing).  Such a chain gets
    its own sentence (``_chain_sentence``), which names the region's size, not the margin
    inside it: the margin gives way, and check names that on its own line."""
    if not isinstance(limit, TooLarge) or len(limit.rows) < 2:
        return False
    lead = page.items[limit.rows[0]]
    if not lead.region or not any(region.id == lead.region for region in page.regions):
        return False
    region = page.region(lead.region)
    return limit.extent_mm > (region.w, region.h)[limit.axis] + 0.01


def _tightest_room(page, engine, gutter_mm: float) -> tuple[float, str]:
    """How much of its tightest room the page's items need, each grown by ``gutter_mm``
    (Engine.grown_cover, which is the same number), and how a sentence names that room: a
    region's, where that is the tightest, since "95 % of the room inside the margins" on a page
    half empty but for one full region sent the user looking for room that was there."""
    bodies = engine.bodies
    near, far = bodies.insets(engine.margin_mm, page.width_mm, page.height_mm)
    covers = room_covers(bodies, near, far, page.width_mm, page.height_mm, gutter_mm)
    tightest = int(np.argmax(covers)) if len(covers) else 0
    if tightest == 0:
        return (float(covers[0]) if len(covers) else 0.0), "the room inside the margins"
    row = int(np.flatnonzero(rooms_of(bodies) == tightest)[0])
    return float(covers[tightest]), (f'the room of region "{printable(page.items[row].region)}"'
                                     " that items which cannot move leave")


def _chain_sentence(page, chain: TooLarge, name) -> str:
    rows, axis, extent = chain.rows, chain.axis, chain.extent_mm
    root = page.items[rows[0]]
    region = page.region(root.region)
    room = (region.w, region.h)[axis]
    followers = _some([name(row) for row in rows[1:1 + SHOWN]], len(rows) - 1)
    size_word, _ = AXIS_WORDS[axis]
    side = "taller" if axis == 1 else "wider"
    companions, closer = _companions(page, rows)
    if "dx and dy" in closer:
        closer = f"bring the followers closer (their anchor {'dy' if axis == 1 else 'dx'})"
    return (f"item {name(rows[0])} with {companions} ({followers}) is "
            f"{extent:.1f} mm {size_word}, but its region \"{printable(root.region)}\" is "
            f"{room:.1f} mm {size_word}, and an item keeps those moving with it inside its "
            f"region: no settle can fit them; {closer}, make the region {side}, or take "
            f"{name(rows[0])} out of the region")


def settle_may_help(lines: list[str]) -> bool:
    """Whether any of page_report's ``lines`` sends the user to `settle`: `check`'s closing
    line repeats that advice only then (it said "run `floatpage settle` to fix overlaps"
    below a page whose every miss was named as one no settle can fix)."""
    return any(SETTLE in line for line in lines)


SETTLE_FIXES = (("  overlapping:", "the overlaps"), ("reach past the page's edge",
                                                    "the items off the page"),
                ("print-safe margin", "the items in the margin"),
                ("not wholly inside its region", "the items outside their region"),
                ("gutter fits", "the gap under the gutter"))


def what_settle_fixes(lines: list[str]) -> str:
    """What the lines that send the user to `settle` ask it to fix, in words, for `check`'s
    closing line: it said "to fix overlaps" under a page of 0 overlaps whose gap was short."""
    found = [words for needle, words in SETTLE_FIXES
             if any(SETTLE in line and needle in line for line in lines)]
    return " and ".join(dict.fromkeys(found)) or "what the lines above name"


def _some(shown: list[str], total: int) -> str:
    """The first of ``total`` things, and how many more there are."""
    return ", ".join(shown) + (f" and {total - len(shown)} more" if total > len(shown) else "")


def _namer(page):
    items = page.items

    def name(row: int) -> str:
        return f'"{printable(items[row].id)}"'
    return name


def _explain(limits: list[Limit], name, gutter_mm: float, margin_mm: float, page=None
             ) -> list[str]:
    lines: list[str] = []
    for kind in (PinnedClash, PinnedOutside, TooLarge, Crossing, Stack, NoRoom, PinnedStack,
                 NoArrangement):
        mine = [limit for limit in limits if isinstance(limit, kind)]
        for limit in mine[:SHOWN]:
            lines.append("  " + _sentence(limit, name, gutter_mm, margin_mm, page))
        if len(mine) > SHOWN:
            lines.append(f"  … and {len(mine) - SHOWN} more like it")
    return lines


def _sentence(limit: Limit, name, gutter_mm: float, margin_mm: float, page=None) -> str:
    if isinstance(limit, PinnedClash):
        a, b = (name(row) for row in limit.rows)
        where = (f"overlap by {-limit.gap_mm:.1f} mm" if limit.gap_mm < 0
                 else f"stand {limit.gap_mm:.1f} mm apart, less than the {gutter_mm:g} mm gutter")
        return (f"items {a} and {b} cannot move (hard anchors, or anchored to one or to a "
                f"decoration) and {where}: no settle can part them; move one of the anchors, "
                "or make one soft (hard = false)")
    if isinstance(limit, PinnedOutside):
        where = (f"{limit.past_edge_mm:.1f} mm past the page's edge" if limit.past_edge_mm > 0
                 else f"{limit.into_margin_mm:.1f} mm into the {margin_mm:.1f} mm print-safe "
                 "margin")
        if limit.decoration:
            return (f"decoration {name(limit.row)} stands {where}; decorations are never "
                    "moved: move it onto the page, or make it smaller")
        return (f"item {name(limit.row)} is pinned (a hard anchor, or anchored to one or to a "
                f"decoration) {where}: move its anchor inwards, or mark it `bleed = true` if it "
                "may reach the edge")
    if isinstance(limit, TooLarge):
        return _too_large_sentence(limit, name, page)
    if isinstance(limit, Stack):
        return _stack_sentence(limit, name, gutter_mm)
    if isinstance(limit, NoRoom):
        return _no_room_sentence(limit, name, gutter_mm)
    if isinstance(limit, PinnedStack):
        return _pinned_stack_sentence(limit, name, gutter_mm)
    if isinstance(limit, NoArrangement):
        return _no_arrangement_sentence(limit, name, gutter_mm)
    a, b = (name(row) for row in limit.rows)
    (side, above), (room_w, room_h) = limit.needs_mm, limit.room_mm
    fate = _fate(limit, "the widest gap they can keep is")
    return (f"items {a} and {b} cannot both fit with the {gutter_mm:g} mm gutter: side by side "
            f"they need {side:.1f} mm of the {room_w:.1f} mm inside the margins, one above the "
            f"other {above:.1f} mm of {room_h:.1f} mm; {fate}; make one smaller, or move it to "
            "another page")


def _companions(page, rows) -> tuple[str, str]:
    """How a sentence names the items that move rigidly with ``rows[0]``, and how to bring
    them closer: the members of a group have no dx and dy to change (check told a group's
    members to "bring its followers closer (their dx and dy)")."""
    lead = page.items[rows[0]] if page is not None else None
    if lead is not None and lead.group \
            and all(page.items[row].group == lead.group for row in rows[1:]):
        return (f'the other members of its group "{printable(lead.group)}"',
                "move the group's members closer together")
    return "the items following it", "bring the followers closer (their anchor dx and dy)"


def _too_large_sentence(limit: TooLarge, name, page) -> str:
    if page is not None and _past_lead_region(limit, page):
        return _chain_sentence(page, limit, name)
    size_word, _ = AXIS_WORDS[limit.axis]
    who = f"item {name(limit.rows[0])}"
    companions, closer = _companions(page, limit.rows)
    if len(limit.rows) > 1:
        others = ", ".join(name(row) for row in limit.rows[1:1 + SHOWN])
        more = f" and {len(limit.rows) - 1 - SHOWN} more" if len(limit.rows) > 1 + SHOWN else ""
        who += f" with {companions} ({others}{more}) is"
    else:
        who += " is"
    regions = sorted({page.items[row].region for row in limit.rows
                      if page.items[row].region}) if page is not None else []
    past_page = limit.extent_mm > limit.page_mm + 0.01
    if regions:
        # the members' regions are the walls that bind: "the print-safe margin" and "(the
        # page: 297 mm)" sent the user to the wrong knob, also for an item wider than the page
        # ("its room inside the margins is 75.7 mm" was the region's room)
        named = ", ".join(f'"{printable(region)}"' for region in regions)
        page = f" (more than the page's {limit.page_mm:g} mm)" if past_page else ""
        return (f"{who} {limit.extent_mm:.1f} mm {size_word}{page}, but the region(s) {named} "
                f"its items keep to, and the margins, leave it {limit.room_mm:.1f} mm: no "
                f"settle can fit it; make it smaller, {closer}, make the region larger, or take "
                "the items out of it")
    fate = "it cannot stay on the page" if past_page else "it cannot keep the print-safe margin"
    return (f"{who} {limit.extent_mm:.1f} mm {size_word}, but its room inside the margins "
            f"is {limit.room_mm:.1f} mm (the page: {limit.page_mm:g} mm): {fate}; make it "
            "smaller" + (f", or {closer}" if len(limit.rows) > 1 else ""))


def _fate(limit: Crossing | Stack | NoRoom | PinnedStack | NoArrangement, widest: str,
          overlap: str = "they overlap wherever they go on this page") -> str:
    if not limit.fits_page:
        return overlap
    if limit.widest_gap_mm < 0:
        return "they can be parted only by giving up the margin"
    return f"{widest} {limit.widest_gap_mm:.1f} mm"


def _row_words(axis: int) -> tuple[str, str, str]:
    """How a sentence tells items that must stand in a row along ``axis``: the size that
    rules out a pair across it, where they must stand, and the word for across."""
    size_word, _ = AXIS_WORDS[1 - axis]
    return (size_word, "one above another" if axis == 1 else "side by side",
            "beside" if axis == 1 else "above")


def _stack_sentence(limit: Stack, name, gutter_mm: float) -> str:
    who = _some([name(row) for row in limit.rows[:SHOWN]], len(limit.rows))
    size_word, place, beside = _row_words(limit.axis)
    along = "tall" if limit.axis == 1 else "wide"
    return (f"items {who} are each too {size_word} to stand {beside} another of them with the "
            f"{gutter_mm:g} mm gutter, so they must stand {place}, and that is "
            f"{limit.needs_mm:.1f} mm {along}, more than the {limit.room_mm:.1f} mm inside the "
            f"margins; {_fate(limit, 'the widest gap they can keep is at most')}; make one "
            "smaller, or move one to another page")


def _no_room_sentence(limit: NoRoom, name, gutter_mm: float) -> str:
    who = f"item {name(limit.rows[0])}"
    if len(limit.rows) > 1:
        who += f" with the items following it ({', '.join(name(row) for row in limit.rows[1:])})"
    pinned = _some([name(row) for row in limit.pinned[:SHOWN]], len(limit.pinned))
    fate = _fate(limit, "the widest gap it can keep from them is",
                 "it overlaps them wherever it goes on this page")
    return (f"{who} has no place inside the margins that keeps the {gutter_mm:g} mm gutter "
            f"from the items that cannot move ({pinned}); {fate}; move one of their anchors "
            "or make one soft (hard = false), make it smaller, or move it to another page")


def _pinned_stack_sentence(limit: PinnedStack, name, gutter_mm: float) -> str:
    who = _some([name(row) for row in limit.rows[:SHOWN]], len(limit.rows))
    pinned = _some([name(row) for row in limit.pinned[:SHOWN]], len(limit.pinned))
    size_word, place, beside = _row_words(limit.axis)
    passing = "beside" if limit.axis == 1 else "above or below"
    if not limit.pinned:  # items of several rooms (regions, or free), each in its own
        return (f"items {who} are too {size_word} to stand {beside} one another with the "
                f"{gutter_mm:g} mm gutter, each inside its region or the margins, so they "
                f"must stand {place}, and no such row of them fits in the "
                f"{limit.room_mm:.1f} mm they span; "
                f"{_fate(limit, 'the widest gap they can keep is at most')}; make one "
                "smaller, or move one to another page")
    return (f"items {who} are too {size_word} to stand {beside} one another with the "
            f"{gutter_mm:g} mm gutter, so they must stand {place}, and the items that cannot "
            f"move ({pinned}) leave no such row of the {limit.room_mm:.1f} mm inside the "
            f"margins: none of them passes {passing} those; "
            f"{_fate(limit, 'the widest gap they can keep is at most')}; move one of the "
            "anchors or make one soft (hard = false), make one smaller, or move one to another "
            "page")


def _no_arrangement_sentence(limit: NoArrangement, name, gutter_mm: float) -> str:
    who = _some([name(row) for row in limit.rows[:SHOWN]], len(limit.rows))
    width, height = limit.room_mm
    if limit.units:  # physics.unit_arrangements: around pinned items, with groups, regions
        around = (f" around the items that cannot move "
                  f"({_some([name(row) for row in limit.pinned[:SHOWN]], len(limit.pinned))})"
                  if limit.pinned else "")
        if not limit.proved:  # the search ran out of its budget on the way to the widest gap
            kept = (f"{limit.widest_gap_mm:.1f} mm apart" if limit.widest_gap_mm >= 0 else
                    f"{-limit.widest_gap_mm:.1f} mm into each other")
            fate = (f"a layout was found with them {kept}, and none keeps "
                    f"{limit.at_most_mm:.1f} mm; whether a gap in between fits, the search "
                    f"stopped before it could tell")
        elif limit.widest_gap_mm >= 0:
            fate = f"the widest gap they can all keep is {limit.widest_gap_mm:.1f} mm"
        elif limit.fits_page:
            fate = "they can be parted only by giving up the margin"
        else:
            fate = (f"they overlap wherever they go on this page, inside the margins by at "
                    f"least {-limit.widest_gap_mm:.1f} mm")
        advice = ("move one of the anchors or make one soft (hard = false), " if limit.pinned
                  else "")
        tried = ("every such arrangement was tried, groups moving as one" if limit.proved
                 else "every such arrangement was tried at the gutter, groups moving as one")
        return (f"items {who} cannot all stand {gutter_mm:g} mm apart{around}, each inside "
                f"its walls, whichever way each stands beside or above another and beside or "
                f"above those ({tried}); "
                f"{fate}; {advice}make one smaller, or move one to another page")
    return (f"items {who} cannot all stand {gutter_mm:g} mm apart in the {width:.1f} x "
            f"{height:.1f} mm inside the margins, whichever way each stands beside or above "
            f"another (every such arrangement was tried); "
            f"{_fate(limit, 'the widest gap they can all keep is')}; make one smaller, or "
            "move one to another page")
