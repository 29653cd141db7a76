"""The style a new item takes from the items beside it.

A text inserted on the shop flyer came in as a 94 mm box of large black serif among 36 mm
price tags in red bold sans, and a picture as an 84 mm photo among 35 mm ones (user-walk-11):
the user had to retype the font, the colour and the size of every new item.  As a layout
program's "new frame like this one", a new item takes its style from

- the selected item, where it is of the same kind (the user points at the one they want);
- else the style most of the page's items of that kind share, where at least two and more
  than half of them share it (a page of red price tags gives a red price tag; a page of one
  title and one message of two styles gives the defaults, for no style is the page's; so
  does a calendar page's one month name, 186 mm wide, which a note should not copy);
- else the model's defaults.

The style is the box's size and the look, never what ties the new item to others: a text's
role (every text of one role is set at one size, so a longer new text in the price role would
shrink every price), its set size in points, its group, region and anchor are left for the
user to give.  Decorations (a backdrop band) are a page's style only when selected.
"""

from __future__ import annotations

import math
import statistics
from collections import Counter
from typing import Any

from floatpage.model.document import ItemBase, Page

# The fields of each kind that make its look, besides the box's size.
LOOK_FIELDS: dict[str, tuple[str, ...]] = {
    "text": ("font", "color", "bold", "italic", "align"),
    "picture": (),
    "block": ("color", "opacity"),
    "calendar": ("font", "color", "first_weekday", "language"),
}


def look_of(item: ItemBase) -> tuple:
    return tuple(getattr(item, name) for name in LOOK_FIELDS[item.kind])


def style_model(kind: str, page: Page, selected: ItemBase | None) -> ItemBase | None:
    """The item whose style a new item of ``kind`` takes (see the module's docstring), or
    None for the defaults."""
    if selected is not None and selected.kind == kind:
        return selected
    alike = [item for item in page.items if item.kind == kind and not item.decorative]
    if not alike:
        return None
    look, count = Counter(look_of(item) for item in alike).most_common(1)[0]
    if count < 2 or 2 * count <= len(alike):  # one item is no style the page repeats
        return None
    return next(item for item in alike if look_of(item) == look)


def new_item_style(kind: str, page: Page, selected: ItemBase | None,
                   aspect: float | None = None) -> dict[str, Any]:
    """The fields a new item of ``kind`` takes from its model: the look and ``w``, ``h``.  A
    picture takes the size of the model picture's area, in its own file's shape (``aspect``,
    height / width), so a portrait photo beside landscape ones is as large, not as wide; with
    no selected picture, the median area of the page's pictures.  Empty: the defaults."""
    if kind == "picture":
        if selected is not None and selected.kind == "picture":
            area = selected.w * selected.h
        else:
            areas = [item.w * item.h for item in page.items
                     if item.kind == "picture" and not item.decorative]
            if len(areas) < 2:
                return {}
            area = statistics.median(areas)
        shape = aspect or 0.75
        w = math.sqrt(area / shape)
        return {"w": w, "h": w * shape}
    model = style_model(kind, page, selected)
    if model is None:
        return {}
    return {"w": model.w, "h": model.h,
            **{name: getattr(model, name) for name in LOOK_FIELDS[kind]}}
