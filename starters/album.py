"""Photo-album pages (paper, figure 6): the photos a page at a time, each with its caption.

A caption is anchored to its photo with an item-to-item anchor (section 4.5's extension), so
the two move as one while the physics spreads the photos, and the caption stays under its
picture whatever the user drags. Captions start as the file name made readable.
"""

from __future__ import annotations

from model.document import Background, ItemAnchor, PictureItem, PointAnchor, Project, TextItem
from starters.options import Options
from starters.pictures import Picture
from starters.measure import hug
from starters.placement import Region, grid, new_page
from starters.words import phrase, readable

PAGE_SIZE = "A4"
PHOTOS_PER_PAGE = 4
MARGIN_MM = 14.0
CAPTION_H_MM = 8.0
CAPTION_GAP_MM = 1.5  # between a photo's lower edge and its caption
TITLE_H_MM = 20.0
PAPER, INK, ACCENT = "#f7f2ea", "#4a3f35", "#7a5230"
BUNDLED = ["alpine-dawn.jpg", "sunflower.jpg", "seaside.jpg", "autumn-forest.jpg", "tulips.jpg",
           "lake-sunset.jpg", "winter-pines.jpg", "daisy-meadow.jpg"]


def caption_for(photo: PictureItem, picture: Picture) -> TextItem:
    """The caption under `photo`, following it at a fixed offset."""
    dy = photo.h / 2 + CAPTION_GAP_MM + CAPTION_H_MM / 2
    w = max(photo.w, 40.0)
    return hug(TextItem(id=f"{photo.id}-caption", x=photo.x, y=photo.y + dy, w=w, h=CAPTION_H_MM,
                        text=readable(picture.stem), font="serif", italic=True, color=INK,
                        anchor=ItemAnchor(to=photo.id, dx=0.0, dy=dy)), w)


def album_page(number: int, pictures: list[Picture], options: Options, with_title: bool):
    page = new_page(f"page-{number}", PAGE_SIZE, options.orientation, background=Background(color=PAPER))
    W, H = page.width_mm, page.height_mm
    top = MARGIN_MM
    if with_title:
        y = MARGIN_MM + TITLE_H_MM / 2
        page.items.append(hug(TextItem(id="album-title", x=W / 2, y=y, w=W * 0.7, h=TITLE_H_MM,
                                       text=phrase("album_title", options.lang), font="display",
                                       color=ACCENT, bold=True,
                                       anchor=PointAnchor(x=W / 2, y=y, gamma=1.0)), W * 0.7))
        top += TITLE_H_MM + 8.0
    region = Region(MARGIN_MM, top, W - MARGIN_MM, H - MARGIN_MM)
    rects = grid(region, [p.aspect for p in pictures], fill=0.96, gap=8.0,
                 below=CAPTION_GAP_MM + CAPTION_H_MM)
    for index, (picture, (x, y, w, h)) in enumerate(zip(pictures, rects), start=1):
        photo = PictureItem(id=f"p{number}-photo-{index}", x=x, y=y, w=w, h=h, path=picture.path)
        page.items += [photo, caption_for(photo, picture)]
    return page


def build(options: Options, pictures: list[Picture]) -> Project:
    """One page per PHOTOS_PER_PAGE photos, in the order given; the first page has a title."""
    chunks = [pictures[i:i + PHOTOS_PER_PAGE] for i in range(0, len(pictures), PHOTOS_PER_PAGE)]
    pages = [album_page(n, chunk, options, with_title=(n == 1)) for n, chunk in enumerate(chunks, 1)]
    return Project(title=phrase("album_title", options.lang), language=options.lang, pages=pages)
