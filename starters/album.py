"""Photo-album pages (paper, figure 6): the photos a page at a time, each with its caption.

A caption is anchored to its photo with an item-to-item anchor (section 4.5's extension), so
the two move as one while the physics spreads the photos, and the caption stays under its
picture whatever the user drags. Captions start as the file name made readable.
"""

from __future__ import annotations

from functools import lru_cache

from floatpage.model.document import Background, ItemAnchor, PictureItem, PointAnchor, Project, TextItem
from floatpage.model.page_sizes import page_dimensions
from floatpage.physics.guides import SNAP_MM
from floatpage.starters.options import Options
from floatpage.starters.pictures import Picture
from floatpage.starters.even_rows import even_rows
from floatpage.starters.placement import (
    Region, edges_near_miss, near_widths_as_one, new_page, one_height_per_row,
)
from floatpage.starters.words import phrase, readable

PAGE_SIZE = "A4"
MAX_PER_PAGE = 6
MIN_LONG_SIDE_MM = 72.0  # a photo in an album should be at least this long on its long side
MARGIN_MM = 14.0
CAPTION_H_MM = 8.0
CAPTION_GAP_MM = 4.5  # between a photo's lower edge and its caption: past the 4 mm an eye
# reads as a near miss (physics.alignment), as far as a line of caption text is tall
TITLE_H_MM = 20.0
TITLE_SHARE = 0.7  # of the page's width: the title's box, its words centred in it
TITLE_GAP_MM = 8.0  # at least this under the title, more where the page has height to share
PAPER, INK, ACCENT = "#f7f2ea", "#4a3f35", "#7a5230"
BUNDLED = ["alpine-dawn.jpg", "sunflower.jpg", "seaside.jpg", "autumn-forest.jpg", "tulips.jpg",
           "lake-sunset.jpg", "winter-pines.jpg", "daisy-meadow.jpg"]


def caption_for(photo: PictureItem, picture: Picture) -> TextItem:
    """The caption under `photo`, following it at a fixed offset."""
    dy = photo.h / 2 + CAPTION_GAP_MM + CAPTION_H_MM / 2
    w = max(photo.w, 40.0)
    dx = (w - photo.w) / 2  # flush left with the photo, also when the photo is narrower
    return TextItem(id=f"{photo.id}-caption", x=photo.x + dx, y=photo.y + dy, w=w, h=CAPTION_H_MM,
                    text=readable(picture.stem), font="serif", italic=True, color=INK,
                    role="caption", anchor=ItemAnchor(to=photo.id, dx=dx, dy=dy))


def photo_region(width: float, height: float, with_title: bool) -> Region:
    """From under the title (or the page's top) to the page's bottom, inside the side margins:
    the spaces above and below the rows are shared out with those between them, so the white
    a reader sees under the last row is as wide as between the rows (at least MARGIN_MM)."""
    return Region(MARGIN_MM, MARGIN_MM + TITLE_H_MM if with_title else 0.0, width - MARGIN_MM,
                  height)


def photo_rects(region: Region, pictures: list[Picture], with_title: bool,
                page_h_mm: float) -> list:
    """Each row as tall as its photos need, the height left shared out evenly (even_rows);
    each row's photos of near shapes at one height (placement.one_height_per_row), each
    column's of near widths at one width (placement.near_widths_as_one)."""
    return even_rows(region, [p.aspect for p in pictures], fill=0.96, gap=8.0,
                     below=CAPTION_GAP_MM + CAPTION_H_MM,
                     above=TITLE_GAP_MM if with_title else MARGIN_MM, under=MARGIN_MM,
                     cut=_one_height_then_width,
                     middle=(page_h_mm / 2, 2 * SNAP_MM))


def _one_height_then_width(rects: list, aspects: list[float]) -> list:
    return near_widths_as_one(one_height_per_row(rects, aspects), aspects)


FULL_WITHIN = 0.05  # pages whose photos cover up to this share of the page less count as full


def paginate(pictures: list[Picture], width: float, height: float) -> list[list[Picture]]:
    """Split the photos into pages, in order: as few pages as show every photo large; of
    those splits, one whose emptiest page is as full as can be (within FULL_WITHIN), then the
    most even counts, then the largest photos together.

    A page may take up to MAX_PER_PAGE photos whose grid keeps every photo's long side at least
    MIN_LONG_SIDE_MM, so wide photos share a page six at a time while tall ones, which would
    shrink more, go four or fewer.  Filling each page in turn counted the pages, but left the
    last with what remained: 16 photos of mixed shapes went 4, 5 and 6 to a page and the last
    alone, where 4 to a page keeps every page as full; and an even split alone would spread 8
    wide photos 4 and 4 over pages three quarters empty, where 6 and 2 fill both.
    """
    @lru_cache(maxsize=None)
    def cover(start: int, count: int) -> float | None:
        """The share of the page the photos cover, None if they cannot share one page."""
        region = photo_region(width, height, with_title=start == 0)
        rects = photo_rects(region, pictures[start:start + count], start == 0, height)
        if count > 1 and min(max(w, h) for _, _, w, h in rects) < MIN_LONG_SIDE_MM:
            return None
        return sum(w * h for _, _, w, h in rects) / (width * height)

    total, pages, start = len(pictures), 0, 0
    while start < total:  # the fewest pages: each takes the most it can
        start += next(count for count in range(min(MAX_PER_PAGE, total - start), 0, -1)
                      if cover(start, count))
        pages += 1
    levels = sorted({found for start in range(total)
                     for count in range(1, min(MAX_PER_PAGE, total - start) + 1)
                     if (found := cover(start, count))})
    low, high = 0, len(levels) - 1  # the fullest emptiest page some split has
    while low < high:
        middle = (low + high + 1) // 2
        if _split(total, pages, 1, MAX_PER_PAGE, cover, levels[middle]):
            low = middle
        else:
            high = middle - 1
    least_cover = levels[low] - FULL_WITHIN
    for spread in range(MAX_PER_PAGE):  # the most even counts, then the largest photos
        found = [split for least in range(1, MAX_PER_PAGE - spread + 1)
                 if (split := _split(total, pages, least, least + spread, cover, least_cover))]
        if found:
            counts = max(found)[1]
            bounds = [sum(counts[:k]) for k in range(len(counts) + 1)]
            return [pictures[a:b] for a, b in zip(bounds, bounds[1:])]
    raise AssertionError("unreachable: the fullest emptiest page's split has some spread")


def _split(total: int, pages: int, least: int, most: int, cover,
           least_cover: float) -> tuple[float, tuple[int, ...]] | None:
    """(the photos' cover summed over the pages, the counts) of the split of ``total``
    photos over ``pages`` pages, in order, each page from ``least`` to ``most`` photos that can
    share it (``cover(start, count)``) and cover at least ``least_cover`` of it, whose photos
    cover the most; None if there is none."""
    @lru_cache(maxsize=None)
    def rest(start: int, left: int) -> tuple[float, tuple[int, ...]] | None:
        if left == 0:
            return (0.0, ()) if start == total else None
        best = None
        for count in range(min(most, total - start), least - 1, -1):
            on_page = cover(start, count)
            if on_page is None or on_page < least_cover:
                continue
            tail = rest(start + count, left - 1)
            if tail is not None and (best is None or on_page + tail[0] > best[0] + 1e-12):
                best = (on_page + tail[0], (count,) + tail[1])
        return best

    return rest(0, pages)


def title_width(width: float, rects: list) -> float:
    """The title's box: 0.7 of the page's width, or a photo's width where a photo centred
    under it is nearly as wide (edges 0.5-4 mm apart, a near miss: physics.alignment).  Two
    wide photos 149.6 mm wide under a 147 mm title left 1.60 near misses per item."""
    found = width * TITLE_SHARE
    for x, _, w, _ in rects:
        if abs(x - width / 2) < 1e-6 and edges_near_miss(w, found):
            return w
    return found


def album_page(number: int, pictures: list[Picture], options: Options, with_title: bool):
    page = new_page(f"page-{number}", PAGE_SIZE, options.orientation, background=Background(color=PAPER))
    W, H = page.width_mm, page.height_mm
    rects = photo_rects(photo_region(W, H, with_title), pictures, with_title, H)
    if with_title:
        y = MARGIN_MM + TITLE_H_MM / 2
        page.items.append(TextItem(id="album-title", x=W / 2, y=y, w=title_width(W, rects),
                                   h=TITLE_H_MM, text=phrase("album_title", options.lang),
                                   font="display", color=ACCENT, bold=True, align="centre",
                                   anchor=PointAnchor(x=W / 2, y=y, gamma=1.0)))
    for index, (picture, (x, y, w, h)) in enumerate(zip(pictures, rects), start=1):
        photo = PictureItem(id=f"p{number}-photo-{index}", x=x, y=y, w=w, h=h, path=picture.path)
        page.items += [photo, caption_for(photo, picture)]
    return page


def build(options: Options, pictures: list[Picture]) -> Project:
    """Pages of photos in the order given (see paginate); the first page has a title."""
    width, height = page_dimensions(PAGE_SIZE, options.orientation)
    chunks = paginate(pictures, width, height)
    pages = [album_page(n, chunk, options, with_title=(n == 1)) for n, chunk in enumerate(chunks, 1)]
    return Project(title=phrase("album_title", options.lang), language=options.lang, pages=pages)
