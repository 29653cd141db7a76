"""A 5x8 in greeting card (paper, figure 6): a front page and an inside page.

The front carries a big picture and the greeting; the inside a message, a smaller picture and
a signature. Coloured bands are decorative, so the physics leaves them where they are and the
content floats over them, as in the paper's prototype.
"""

from __future__ import annotations

from floatpage.model.document import Background, BlockItem, PictureItem, PointAnchor, Project, TextItem
from floatpage.starters.options import Options
from floatpage.starters.pictures import Picture
from floatpage.starters.placement import Region, fit, new_page
from floatpage.starters.words import phrase

PAGE_SIZE = "5x8in"
BUNDLED = ["sunflower.jpg", "tulips.jpg"]
CREAM, WARM, ROSE, INK = "#fdf4e6", "#f2b84b", "#c4473a", "#3b3027"
GREETING_SIDE_MM = 10.0  # the front's greeting (and a wide picture above it) from the sides


def band(item_id: str, x: float, y: float, w: float, h: float) -> BlockItem:
    """A decorative strip of warm colour, behind everything else. Every band meets the page's
    edge, so it bleeds: `render --print` carries it past the trim (no white hairline)."""
    return BlockItem(id=item_id, x=x, y=y, w=w, h=h, color=WARM, opacity=0.55, decorative=True, z=-1,
                     bleed=True)


def picture_in(item_id: str, picture: Picture, region: Region) -> PictureItem:
    """The picture as large as `region` allows, centred in it."""
    w, h = fit(picture.aspect, region.width, region.height)
    x, y = region.centre
    return PictureItem(id=item_id, x=x, y=y, w=w, h=h, path=picture.path)


def anchored_text(item_id: str, text: str, x: float, y: float, w: float, h: float, **style) -> TextItem:
    """A short text held near (x, y) by a spring, its lines centred in its box."""
    return TextItem(id=item_id, x=x, y=y, w=w, h=h, text=text, align="centre",
                    anchor=PointAnchor(x=x, y=y, gamma=1.0), **style)


def front(options: Options, picture: Picture):
    """Portrait: picture above, greeting on a band below. Landscape: picture left, band right."""
    page = new_page("front", PAGE_SIZE, options.orientation, background=Background(color=CREAM))
    W, H = page.width_mm, page.height_mm
    greeting = dict(font="display", color=ROSE, bold=True)
    text = phrase("card_front", options.lang)
    if options.orientation == "portrait":
        band_h, title_h = H * 0.28, H * 0.12
        title_y = H - 12.0 - title_h / 2
        # The picture's sides are the greeting's: a wide picture 3 mm inside the greeting's box
        # left a near miss on both edges (physics.alignment) that no move could close.
        side = GREETING_SIDE_MM
        page.items += [band("front-band", W / 2, H - band_h / 2, W, band_h),
                       picture_in("front-picture", picture, Region(side, 12.0, W - side, H - band_h - 10.0)),
                       anchored_text("front-greeting", text, W / 2, title_y, W - 2 * side, title_h, **greeting)]
    else:
        band_w = W * 0.42
        x = W - band_w / 2
        page.items += [band("front-band", x, H / 2, band_w, H),
                       picture_in("front-picture", picture, Region(12.0, 12.0, W - band_w - 10.0, H - 12.0)),
                       anchored_text("front-greeting", text, x, H / 2, band_w - 14.0, H * 0.36, **greeting)]
    return page


def inside(options: Options, picture: Picture):
    """The message, a picture and the signature; side by side on a landscape card."""
    page = new_page("inside", PAGE_SIZE, options.orientation, background=Background(color="#fffaf2"))
    W, H = page.width_mm, page.height_mm
    page.items.append(band("inside-band", W / 2, 5.0, W, 10.0))
    # The signature is not of the message's role: its box is a short line, and "Com carinho,
    # Sam" in it would have set the whole message at 27 pt where its own box holds 37.
    message = dict(text=phrase("card_message", options.lang), font="serif", italic=True, color=INK,
                   role="message")
    signature = phrase("card_signature", options.lang)
    signature_style = dict(font="serif", italic=True, color=ROSE)
    signature_y = H - 16.0
    if options.orientation == "portrait":
        message_h = H * 0.22
        page.items += [
            TextItem(id="inside-message", x=W / 2, y=20.0 + message_h / 2, w=W - 28.0, h=message_h,
                     **message),
            anchored_text("inside-signature", signature, W * 0.6, signature_y, W * 0.55, 12.0,
                          **signature_style),
            picture_in("inside-picture", picture,
                       Region(W * 0.19, 20.0 + message_h + 8.0, W * 0.81, signature_y - 14.0)),
        ]
    else:
        column = W * 0.46
        page.items += [
            TextItem(id="inside-message", x=12.0 + column / 2, y=H * 0.42, w=column, h=H * 0.42,
                     **message),
            anchored_text("inside-signature", signature, 12.0 + column / 2, signature_y, column, 11.0,
                          **signature_style),
            picture_in("inside-picture", picture, Region(W * 0.56, 20.0, W - 12.0, H - 12.0)),
        ]
    return page


def build(options: Options, pictures: list[Picture]) -> Project:
    """The front uses the first picture, the inside the second (or the first again)."""
    first = pictures[0]
    second = pictures[1] if len(pictures) > 1 else first
    return Project(title="Greeting card", language=options.lang,
                   pages=[front(options, first), inside(options, second)])
