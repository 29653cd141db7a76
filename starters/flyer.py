"""An A4 shop flyer: products with price tags anchored to their pictures, a title, a backdrop.

Each price tag follows its product picture by an item-to-item anchor, so however the physics
(or the user) moves a product, its price stays right under it. The header band is decorative:
fixed, and the title is hard-anchored on it so nothing pushes the shop's name off the band.
"""

from __future__ import annotations

from floatpage.model.document import (
    Background, BlockItem, ItemAnchor, PictureItem, PointAnchor, Project, TextItem,
)
from floatpage.starters.options import Options
from floatpage.starters.pictures import Picture
from floatpage.starters.placement import Region, edges_near_miss, grid, new_page
from floatpage.starters.words import phrase, price, product_name

PAGE_SIZE = "A4"
MARGIN_MM = 14.0
HEADER_H_MM = 58.0
FOOTER_H_MM = 18.0  # its text keeps the 5 mm print-safe margin below it
TAG_H_MM = 14.0
TAG_MIN_W_MM = 36.0
TAG_GAP_MM = 4.5  # below the product: past the 4 mm an eye reads as a near miss (physics.alignment)
MAX_PRODUCTS = 9
SLOT_GAMMA = 0.5  # products lean towards their grid slots, so the flyer keeps its rows
PAPER, GREEN, CREAM, RED, INK = "#fff8ea", "#2f6b4f", "#fff3d6", "#c0392b", "#2b2b2b"
BUNDLED = ["apples.png", "lemons.png", "sunflower.jpg", "coffee-mug.png", "teapot.png", "cupcake.png",
           "tulips.jpg", "potted-plant.png"]
# Prices of the bundled products, in cents; a user's own products start at placeholder prices.
PRICES = {"apples": 240, "lemons": 199, "coffee-mug": 850, "potted-plant": 1290, "teapot": 2450,
          "cupcake": 320, "sunflower": 590, "tulips": 450}


def price_tag(photo: PictureItem, name: str, cents: int, lang: str) -> TextItem:
    """Name and price under the product picture, following it."""
    dy = photo.h / 2 + TAG_GAP_MM + TAG_H_MM / 2
    # TAG_MIN_W_MM wide under a narrower product, but as wide as a product whose edges that
    # would leave a near miss (physics.alignment) from the tag's: a 28.5 mm bottle under a
    # 36 mm tag, 3.8 mm on each side, which no move of the snap closes.
    w = max(photo.w, TAG_MIN_W_MM)
    if edges_near_miss(w, photo.w):
        w = photo.w
    return TextItem(id=f"{photo.id}-price", x=photo.x, y=photo.y + dy, w=w, h=TAG_H_MM,
                    text=f"{name}\n{price(cents, lang)}", font="sans", bold=True, color=RED,
                    role="price", anchor=ItemAnchor(to=photo.id, dx=0.0, dy=dy))


def header(page, lang: str) -> list:
    W = page.width_mm
    title_y, subtitle_y = HEADER_H_MM * 0.42, HEADER_H_MM * 0.8
    return [
        BlockItem(id="header-band", x=W / 2, y=HEADER_H_MM / 2, w=W, h=HEADER_H_MM, color=GREEN,
                  decorative=True, z=-1, bleed=True),
        BlockItem(id="header-stripe", x=W / 2, y=HEADER_H_MM + 2.0, w=W, h=4.0, color="#f2b84b",
                  decorative=True, z=-1, bleed=True),
        TextItem(id="shop-title", x=W / 2, y=title_y, w=W - 40.0, h=26.0,
                 text=phrase("flyer_title", lang), font="display", bold=True, color=CREAM,
                 align="centre", anchor=PointAnchor(x=W / 2, y=title_y, hard=True)),
        TextItem(id="shop-subtitle", x=W / 2, y=subtitle_y, w=W - 60.0, h=10.0,
                 text=phrase("flyer_subtitle", lang), font="sans", italic=True, color=CREAM,
                 align="centre", anchor=PointAnchor(x=W / 2, y=subtitle_y, hard=True)),
    ]


def footer(page, lang: str) -> list:
    W, H = page.width_mm, page.height_mm
    y = H - FOOTER_H_MM / 2
    return [
        BlockItem(id="footer-band", x=W / 2, y=y, w=W, h=FOOTER_H_MM, color=GREEN, decorative=True, z=-1,
                  bleed=True),
        TextItem(id="shop-footer", x=W / 2, y=y, w=W - 30.0, h=7.0, text=phrase("flyer_footer", lang),
                 font="sans", color=CREAM, align="centre", anchor=PointAnchor(x=W / 2, y=y, hard=True)),
    ]


def build(options: Options, pictures: list[Picture]) -> Project:
    """One page: header, up to MAX_PRODUCTS products with their tags, footer."""
    page = new_page("flyer", PAGE_SIZE, options.orientation, background=Background(color=PAPER))
    page.items += header(page, options.lang)
    products = pictures[:MAX_PRODUCTS]
    region = Region(MARGIN_MM, HEADER_H_MM + 12.0, page.width_mm - MARGIN_MM,
                    page.height_mm - FOOTER_H_MM - 8.0)
    rects = grid(region, [p.aspect for p in products], fill=0.96, gap=6.0, below=TAG_GAP_MM + TAG_H_MM,
                 on_a_shelf=True)
    for index, (picture, (x, y, w, h)) in enumerate(zip(products, rects), start=1):
        photo = PictureItem(id=f"product-{index}", x=x, y=y, w=w, h=h, path=picture.path,
                            anchor=PointAnchor(x=x, y=y, gamma=SLOT_GAMMA))
        cents = PRICES.get(picture.stem, 100 * index + 99)
        page.items += [photo, price_tag(photo, product_name(picture.stem, options.lang), cents,
                                        options.lang)]
    page.items += footer(page, options.lang)
    return Project(title=phrase("flyer_title", options.lang), language=options.lang, pages=[page])
