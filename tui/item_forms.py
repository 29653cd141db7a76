"""The forms for inserting and editing items: which fields each kind has, and how to read them.

Parsers turn what was typed into model values or raise ValueError with a
sentence for the user (the form shows it and stays open). Values are checked
by the model's own field checks (model/key_specs.py), so the editor accepts
exactly what the loader accepts.
"""

from __future__ import annotations

import calendar
from typing import Any

from floatpage.model.document import (
    WEEKDAYS, Background, BlockItem, CalendarItem, Page, PictureItem, PointAnchor, TextItem,
)
from floatpage.model.page_sizes import PAGE_SIZES_MM
from floatpage.model.key_specs import CALENDAR_LANGUAGES, FONT_FAMILIES, HEX_COLOUR, keys_of
from floatpage.tui.dialogs.form import Field

MONTHS = tuple((calendar.month_name[number], number) for number in range(1, 13))
FONTS = tuple((name, name) for name in FONT_FAMILIES)
WEEKDAY_CHOICES = tuple((day.capitalize(), day) for day in WEEKDAYS)
LANGUAGES = tuple((code, code) for code in CALENDAR_LANGUAGES)
INSERT_CHOICES = [("Text box", "text"), ("Picture…", "picture"), ("Colour block", "block"),
                  ("Calendar month", "calendar"), ("Background…", "background")]
BACKGROUND_CHOICES = [("A colour…", "color"), ("A picture…", "picture"),
                      ("None (plain paper)", "none")]


def colour(text: str, what: str = "colour") -> str:
    """A colour as the model writes it, "#rrggbb"; the "#" may be left out when typing."""
    text = text.strip()
    written = text if text.startswith("#") else "#" + text
    if not HEX_COLOUR.match(written):
        raise ValueError(f'{what} must be written as #rrggbb, e.g. #1f77b4 (not "{text}")')
    return written.lower()


def checked(owner: type, name: str, value: Any, what: str) -> Any:
    """`value` if the model takes it for the field `owner.name`; else the model's own complaint
    (the loader's check, read off the field: the form keeps no second copy of a range)."""
    check = next(key.check for key in keys_of(owner) if key.name == name)
    complaint = check(value) if check is not None else None
    if complaint:
        raise ValueError(f"{what} {complaint}")
    return value


def number(text: str, what: str, owner: type, name: str) -> float:
    """A typed number for the model's field `owner.name`."""
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f'{what} must be a number (not "{text}")') from None
    return checked(owner, name, value, what)


def whole(text: str, what: str, owner: type, name: str) -> int:
    """A typed whole number for the model's field `owner.name`."""
    value = number(text, what, owner, name)
    if value != int(value):
        raise ValueError(f"{what} must be a whole number")
    return int(value)


# -- inserting ------------------------------------------------------------------------------

def new_text_fields() -> list[Field]:
    return [Field("text", "Text", "text", "")]


def parse_new_text(values: dict[str, Any]) -> dict[str, Any]:
    text = values["text"].strip()
    if not text:
        raise ValueError("type some text first")
    return {"text": checked(TextItem, "text", text, "the text")}


def new_block_fields() -> list[Field]:
    return [Field("color", "Colour (#rrggbb)", "line", "#4c8ed9")]


def parse_new_block(values: dict[str, Any]) -> dict[str, Any]:
    return {"color": colour(values["color"])}


def new_calendar_fields(year: int, month: int, language: str) -> list[Field]:
    return [Field("year", "Year", "line", str(year)),
            Field("month", "Month", "choice", month, MONTHS),
            Field("first_weekday", "Weeks start on", "choice", "monday", WEEKDAY_CHOICES),
            Field("language", "Language of the names", "choice", language, LANGUAGES)]


def parse_calendar(values: dict[str, Any]) -> dict[str, Any]:
    parsed = dict(values)
    parsed["year"] = whole(values["year"], "the year", CalendarItem, "year")
    return parsed


def background_colour_fields(current: str | None) -> list[Field]:
    return [Field("color", "Background colour (#rrggbb)", "line", current or "#fdf6e3")]


def parse_background_colour(values: dict[str, Any]) -> Background:
    return Background(color=colour(values["color"]))


PAGE_SIZE_CHOICES = [(f"{name}  ({w:g} × {h:g} mm)", name)
                     for name, (w, h) in PAGE_SIZES_MM.items()] + [("Custom…", "custom")]


def custom_size_fields(width_mm: float, height_mm: float) -> list[Field]:
    return [Field("width_mm", "Width (mm)", "line", f"{width_mm:g}"),
            Field("height_mm", "Height (mm)", "line", f"{height_mm:g}")]


def parse_custom_size(values: dict[str, Any]) -> dict[str, Any]:
    return {"width_mm": number(values["width_mm"], "the width", Page, "width_mm"),
            "height_mm": number(values["height_mm"], "the height", Page, "height_mm")}


# -- editing --------------------------------------------------------------------------------

def edit_fields(item, regions: tuple[str, ...] = ()) -> list[Field]:
    """The item's editable properties, kind first, then how the physics treats it (its
    anchor's gamma, decorative, its group, and its region where the page has ``regions``)."""
    fields: list[Field] = []
    if isinstance(item, TextItem):
        fields += [Field("text", "Text", "text", item.text),
                   Field("font", "Font", "choice", item.font, FONTS),
                   Field("color", "Colour (#rrggbb)", "line", item.color),
                   Field("bold", "Bold", "bool", item.bold),
                   Field("italic", "Italic", "bool", item.italic)]
    elif isinstance(item, PictureItem):
        fields += [Field("lock_aspect", "Keep the picture's aspect ratio", "bool",
                         item.lock_aspect)]
    elif isinstance(item, BlockItem):
        fields += [Field("color", "Colour (#rrggbb)", "line", item.color),
                   Field("opacity", "Opacity (0-1)", "line", f"{item.opacity:g}")]
    elif isinstance(item, CalendarItem):
        fields += new_calendar_fields(item.year, item.month, item.language)
        fields[2] = Field("first_weekday", "Weeks start on", "choice", item.first_weekday,
                          WEEKDAY_CHOICES)
        fields += [Field("font", "Font", "choice", item.font, FONTS),
                   Field("color", "Colour (#rrggbb)", "line", item.color)]
    if isinstance(item.anchor, PointAnchor):
        fields.append(Field("gamma", "Anchor gamma: 0 loose … 1 rigid", "line",
                            f"{item.anchor.gamma:g}"))
    fields.append(Field("decorative", "Decorative (behind, never pushed)", "bool",
                        item.decorative))
    fields.append(Field("group", "Group (items of one group move as one; empty: none)", "line",
                        item.group))
    if regions:
        fields.append(Field("region", "Keep inside region", "choice", item.region,
                            (("the whole page", ""),) + tuple((name, name) for name in regions)))
    return fields


def group_fields(item, groups: tuple[str, ...]) -> list[Field]:
    known = f" (this page has {', '.join(groups)})" if groups else ""
    return [Field("group", f"Group name{known}; empty takes {item.id} out", "line", item.group)]


def parse_group(values: dict[str, Any]) -> str:
    return checked(TextItem, "group", values["group"].strip(), "a group name")


def parse_edit(values: dict[str, Any]) -> dict[str, Any]:
    parsed = dict(values)
    if "color" in parsed:
        parsed["color"] = colour(parsed["color"])
    if "opacity" in parsed:
        parsed["opacity"] = number(parsed["opacity"], "the opacity", BlockItem, "opacity")
    if "gamma" in parsed:
        parsed["gamma"] = number(parsed["gamma"], "gamma", PointAnchor, "gamma")
    if "year" in parsed:
        parsed["year"] = whole(parsed["year"], "the year", CalendarItem, "year")
    if "group" in parsed:
        parsed["group"] = checked(TextItem, "group", parsed["group"].strip(), "a group name")
    if "text" in parsed:
        if not parsed["text"].strip():
            raise ValueError("a text box needs some text (delete the item instead)")
        checked(TextItem, "text", parsed["text"], "the text")
    return parsed
