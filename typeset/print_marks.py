"""`render --print`: what a print shop asks of a PDF: bleed, crop marks, TrimBox and BleedBox.

A press prints on larger paper and trims it, and a cut is never exact to the millimetre. So
whatever reaches the edge of the finished page (a background, an item marked `bleed = true`,
any colour block that meets the edge, block or picture) is extended `bleed_mm` past it, crop marks outside the
bleed show where to cut, and the PDF says so itself: TrimBox is the finished page, BleedBox
the page with its bleed, MediaBox the sheet with room for the marks.  Inside the finished
page nothing moves, so the layout the physics settled is printed exactly.  An item meets the
edge unmarked when it is a decoration (decorations keep no margin), the margin gave way or
the user put it there; stopping at the trim, it left a sliver of background wherever the cut
strayed out, and print practice is that whatever touches the trim runs into the bleed.

A picture has no pixels past its own edges, so one that bleeds is scaled, proportions kept,
until it covers its frame grown into the bleed, and clipped to that frame (`covering`): its
edges away from the page's edge stay where they were, and what lies in the bleed is more of
the photo, never a stretched or mirrored copy.  The cost is a slight zoom inside the trim
(3 mm on a 60 mm photo: 5 %), which a print shop's own "extend to bleed" also pays.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from floatpage.typeset.calendar_panel import Rect
from floatpage.typeset.placed import PlacedBlock, PlacedDocument, PlacedPage, PlacedPicture

DEFAULT_BLEED_MM = 3.0  # the usual ask of print shops in Europe and North America
MARK_GAP_MM = 1.0  # crop marks start this far outside the bleed, so a cut never shows them
MARK_LENGTH_MM = 5.0
MM_TO_BP = 72.0 / 25.4
TOUCHING_MM = 0.05  # an edge this close to the page's edge meets it


@dataclass(frozen=True)
class PrintSetup:
    """Where the finished page sits on the sheet, and the marks around it (all in mm)."""

    bleed_mm: float
    slug_mm: float  # from the sheet's edge to the trim: bleed, gap and marks
    media_w_mm: float
    media_h_mm: float
    trim_box: tuple[float, float, float, float]  # PDF points, from the sheet's bottom left
    bleed_box: tuple[float, float, float, float]
    marks: tuple[tuple[float, float, float, float], ...]  # lines, in page mm (may be negative)


def print_setup(w_mm: float, h_mm: float, bleed_mm: float) -> PrintSetup:
    slug = bleed_mm + MARK_GAP_MM + MARK_LENGTH_MM + 1.0
    media_w, media_h = w_mm + 2 * slug, h_mm + 2 * slug

    def box(inset: float) -> tuple[float, float, float, float]:
        # PDF boxes count from the sheet's bottom-left corner, in points.
        return ((slug - inset) * MM_TO_BP, (slug - inset) * MM_TO_BP,
                (slug + w_mm + inset) * MM_TO_BP, (slug + h_mm + inset) * MM_TO_BP)

    start, end = bleed_mm + MARK_GAP_MM, bleed_mm + MARK_GAP_MM + MARK_LENGTH_MM
    marks = []
    for cx, sx in ((0.0, -1.0), (w_mm, 1.0)):
        for cy, sy in ((0.0, -1.0), (h_mm, 1.0)):
            marks.append((cx + sx * start, cy, cx + sx * end, cy))  # along the trim's top/bottom
            marks.append((cx, cy + sy * start, cx, cy + sy * end))  # along its left/right side
    return PrintSetup(bleed_mm, slug, media_w, media_h, box(0.0), box(bleed_mm), tuple(marks))


def extended(rect: Rect, w_mm: float, h_mm: float, bleed_mm: float, *, always: bool) -> Rect:
    """``rect`` pushed ``bleed_mm`` past every page edge it meets (every edge if ``always``)."""
    return Rect(rect.left_mm - bleed_mm if always or rect.left_mm <= TOUCHING_MM else rect.left_mm,
                rect.top_mm - bleed_mm if always or rect.top_mm <= TOUCHING_MM else rect.top_mm,
                rect.right_mm + bleed_mm if always or rect.right_mm >= w_mm - TOUCHING_MM
                else rect.right_mm,
                rect.bottom_mm + bleed_mm if always or rect.bottom_mm >= h_mm - TOUCHING_MM
                else rect.bottom_mm)


def covering(picture: PlacedPicture, target: Rect) -> PlacedPicture:
    """The picture scaled, proportions kept, to cover ``target``, and clipped to it; where
    it already covers it (a picture cropped to its frame), only the clip grows: the bleed
    shows the photo's own cropped margin and nothing inside the trim moves."""
    if (picture.left_mm <= target.left_mm and picture.top_mm <= target.top_mm
            and picture.left_mm + picture.w_mm >= target.right_mm
            and picture.top_mm + picture.h_mm >= target.bottom_mm):
        return replace(picture, clip=target)
    w, h = target.right_mm - target.left_mm, target.bottom_mm - target.top_mm
    scale = max(w / picture.w_mm, h / picture.h_mm)  # a PDF's too: as placed, never stretched
    new_w, new_h = picture.w_mm * scale, picture.h_mm * scale
    centre_x, centre_y = (target.left_mm + target.right_mm) / 2, (target.top_mm + target.bottom_mm) / 2
    return replace(picture, left_mm=centre_x - new_w / 2, top_mm=centre_y - new_h / 2, w_mm=new_w,
                   h_mm=new_h, clip=target)


def page_for_print(page: PlacedPage, bleed_mm: float) -> PlacedPage:
    w, h = page.w_mm, page.h_mm
    whole = Rect(-bleed_mm, -bleed_mm, w + bleed_mm, h + bleed_mm)
    background = []
    for placed in page.background:
        if isinstance(placed, PlacedBlock):
            background.append(replace(placed, rect=whole))
        elif isinstance(placed, PlacedPicture):
            background.append(covering(placed, whole))
        else:
            background.append(placed)
    items = []
    for placed in page.items:
        if isinstance(placed, PlacedBlock):
            # marked or not: see the module's docstring
            placed = replace(placed, rect=extended(placed.rect, w, h, bleed_mm, always=False))
        elif isinstance(placed, PlacedPicture):  # marked or not, as a block
            own = placed.clip or Rect(placed.left_mm, placed.top_mm, placed.left_mm + placed.w_mm,
                                      placed.top_mm + placed.h_mm)
            target = extended(own, w, h, bleed_mm, always=False)
            if target != own:
                placed = covering(placed, target)
        items.append(placed)
    return replace(page, background=background, items=items,
                   print_setup=print_setup(w, h, bleed_mm))


def for_print(document: PlacedDocument, bleed_mm: float) -> PlacedDocument:
    """The document as the print shop wants it (see the module's docstring)."""
    return replace(document, pages=[page_for_print(page, bleed_mm) for page in document.pages])
