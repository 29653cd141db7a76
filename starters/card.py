"""A 5x8 in greeting card (paper, figure 6): a front page and an inside page.

The front carries a big picture and the greeting; the inside a message, a smaller picture and
a signature. Coloured bands are decorative, so the physics leaves them where they are and the
content floats over them, as in the paper's prototype.
"""

from __future__ import annotations

from model.document import Background, BlockItem, PictureItem, PointAnchor, Project, TextItem
from starters.options import Options
from starters.pictures import Picture
from starters.measure import hug
from starters.placement import fit, new_page
from starters.words import phrase

PAGE_SIZE = "5x8in"
BUNDLED = ["sunflower.jpg", "tulips.jpg"]
CREAM, WARM, ROSE, INK = "#fdf4e6", "#f2b84b", "#c4473a", "#3b3027"


def band(item_id: str, page, top: float, height: float, colour: str, opacity: float) -> BlockItem:
    """A full-width decorative strip, behind everything else."""
    return BlockItem(id=item_id, x=page.width_mm / 2, y=top + height / 2, w=page.width_mm, h=height,
                     color=colour, opacity=opacity, decorative=True, z=-1)


def front(options: Options, picture: Picture):
    page = new_page("front", PAGE_SIZE, options.orientation, background=Background(color=CREAM))
    W, H = page.width_mm, page.height_mm
    page.items.append(band("front-band", page, H * 0.72, H * 0.28, WARM, 0.55))
    title_h = H * 0.12
    title_y = H - 12.0 - title_h / 2
    w, h = fit(picture.aspect, W - 26.0, title_y - title_h / 2 - 22.0)
    page.items.append(PictureItem(id="front-picture", x=W / 2, y=12.0 + h / 2, w=w, h=h,
                                  path=picture.path))
    page.items.append(hug(TextItem(id="front-greeting", x=W / 2, y=title_y, w=W - 20.0, h=title_h,
                                   text=phrase("card_front", options.lang), font="display",
                                   color=ROSE, bold=True,
                                   anchor=PointAnchor(x=W / 2, y=title_y, gamma=1.0)), W - 20.0))
    return page


def inside(options: Options, picture: Picture):
    page = new_page("inside", PAGE_SIZE, options.orientation, background=Background(color="#fffaf2"))
    W, H = page.width_mm, page.height_mm
    page.items.append(band("inside-band", page, 0.0, 10.0, WARM, 0.55))
    message_h = H * 0.22
    page.items.append(TextItem(id="inside-message", x=W / 2, y=20.0 + message_h / 2, w=W - 28.0,
                               h=message_h, text=phrase("card_message", options.lang), font="serif",
                               italic=True, color=INK))
    signature_y = H - 16.0
    page.items.append(hug(TextItem(id="inside-signature", x=W * 0.6, y=signature_y, w=W * 0.55,
                                   h=12.0, text=phrase("card_signature", options.lang), font="serif",
                                   italic=True, color=ROSE,
                                   anchor=PointAnchor(x=W * 0.6, y=signature_y, gamma=1.0)), W * 0.55))
    top, bottom = 20.0 + message_h + 8.0, signature_y - 14.0
    w, h = fit(picture.aspect, W * 0.62, bottom - top)
    page.items.append(PictureItem(id="inside-picture", x=W / 2, y=(top + bottom) / 2, w=w, h=h,
                                  path=picture.path))
    return page


def build(options: Options, pictures: list[Picture]) -> Project:
    """The front uses the first picture, the inside the second (or the first again)."""
    first = pictures[0]
    second = pictures[1] if len(pictures) > 1 else first
    return Project(title="Greeting card", language=options.lang,
                   pages=[front(options, first), inside(options, second)])
