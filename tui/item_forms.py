"""The forms for inserting and editing items, read off the model's own fields.

Every field a form shows carries its label (and, where the values are not what a person
reads, its choices) in its spec (model/key_specs.py, on model/document.py's dataclasses), and
is checked by the field's own check, so the editor shows, offers and accepts exactly what the
project file may hold, with the model's defaults.  Parsers turn what was typed into model
values or raise ValueError with a sentence for the user (the form shows it and stays open).
"""

from __future__ import annotations

import dataclasses
import itertools
import os
from pathlib import Path
from typing import Any, Callable

from floatpage.model.document import (
    ITEM_CLASSES, Background, BlockItem, CalendarItem, ItemBase, Page, PointAnchor, TextItem,
)
from floatpage.model.key_specs import HEX_COLOUR, colour as colour_check, keys_of
from floatpage.model.page_sizes import PAGE_SIZES_MM
from floatpage.tui.dialogs.form import Field, FieldError

INSERT_CHOICES = [("Text box", "text"), ("Picture…", "picture"), ("Colour block", "block"),
                  ("Calendar month", "calendar"), ("Background…", "background")]
BACKGROUND_CHOICES = [("A colour…", "color"), ("A picture…", "picture"),
                      ("None (plain paper)", "none")]
EDITED_CLASSES = (*ITEM_CLASSES.values(), PointAnchor)  # whose fields an edit form may hold


def form_fields(owner: Any, names: tuple[str, ...] | None = None, *,
                values: dict[str, Any] | None = None,
                choices: dict[str, tuple[tuple[str, Any], ...]] | None = None) -> list[Field]:
    """The form fields of ``owner`` (a model object, or a model class for its defaults): every
    labelled field in field order, or ``names`` in that order.  ``values`` overrides a shown
    value, ``choices`` gives the choices a field's spec cannot know (a page's regions); a
    field with neither a value to show nor its choices (region, on a page without any) is left
    out."""
    cls = owner if isinstance(owner, type) else type(owner)
    by_name = {f.name: f for f in dataclasses.fields(cls) if f.metadata.get("label")}
    wanted = names if names is not None else tuple(by_name)
    fields = []
    for name in wanted:
        f = by_name[name]
        options = (choices or {}).get(name, f.metadata.get("choices"))
        if name == "region" and not options:
            continue
        if values and name in values:
            value = values[name]
        elif isinstance(owner, type):
            value = f.default
        else:
            value = getattr(owner, name)
        kind = f.metadata["key"][0]
        widget = f.metadata.get("form") or ("bool" if kind == "bool" else
                                            "choice" if options else "line")
        shown = value if widget != "line" else ("" if value is None else
                                                f"{value:g}" if isinstance(value, float)
                                                else str(value))
        fields.append(Field(name, f.metadata["label"], widget, shown, tuple(options or ())))
    return fields


def field_words(cls: type, name: str) -> str:
    """How a message names the field: "the opacity" for "Opacity (0-1)"."""
    label = next(f.metadata["label"] for f in dataclasses.fields(cls) if f.name == name)
    return "the " + label.split(" (")[0].split(":")[0].lower()


def parse_form(owners: tuple[type, ...], values: dict[str, Any]) -> dict[str, Any]:
    """Model values from what was typed, each by its field's spec (the first of ``owners``
    that has it): numbers read and range-checked, colours written as the model writes them,
    choices and yes/no as they are; every value through the field's own check."""
    parsed = {}
    for name, raw in values.items():
        owner = next(cls for cls in owners if name in {f.name for f in dataclasses.fields(cls)})
        key = next(key for key in keys_of(owner) if key.name == name)
        words = field_words(owner, name)
        try:
            if key.kind == "int":
                value = whole(raw, words, owner, name)
            elif key.kind == "number":
                value = number(raw, words, owner, name)
            elif key.check is colour_check:
                value = colour(raw, words)
            elif isinstance(raw, str) and key.kind == "str" and name != "text":
                value = checked(owner, name, raw.strip(), words)
            else:
                value = checked(owner, name, raw, words)
        except ValueError as error:  # the form puts the cursor on the field it names
            raise FieldError(name, str(error)) from None
        parsed[name] = value
    return parsed


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
    return form_fields(TextItem, ("text",))


def parse_new_text(values: dict[str, Any]) -> dict[str, Any]:
    if not values["text"].strip():
        raise ValueError("type some text first")
    return parse_form((TextItem,), {"text": values["text"].strip()})


def new_block_fields(look: dict[str, Any] | None = None) -> list[Field]:
    """The colour to ask for, showing the one the new block takes (`insert_style`)."""
    return form_fields(BlockItem, ("color",),
                       values={"color": look["color"]} if look and "color" in look else None)


def parse_new_block(values: dict[str, Any]) -> dict[str, Any]:
    return parse_form((BlockItem,), values)


def new_calendar_fields(year: int, month: int, language: str,
                        look: dict[str, Any] | None = None) -> list[Field]:
    """The month to ask for, with the first weekday and language the new panel takes from
    the page's panels (`insert_style`), else the project's language."""
    shown = {"year": year, "month": month, "language": language}
    shown |= {name: look[name] for name in ("first_weekday", "language") if name in (look or {})}
    return form_fields(CalendarItem, ("year", "month", "first_weekday", "language"),
                       values=shown)


def parse_calendar(values: dict[str, Any]) -> dict[str, Any]:
    return parse_form((CalendarItem,), values)


def background_colour_fields(current: str | None) -> list[Field]:
    return form_fields(Background, ("color",), values={"color": current or "#ffffff"})


def parse_background_colour(values: dict[str, Any]) -> Background:
    return Background(**parse_form((Background,), values))


PAGE_SIZE_CHOICES = [(f"{name}  ({w:g} × {h:g} mm)", name)
                     for name, (w, h) in PAGE_SIZES_MM.items()] + [("Custom…", "custom")]


def custom_size_fields(width_mm: float, height_mm: float) -> list[Field]:
    return form_fields(Page, ("width_mm", "height_mm"),
                       values={"width_mm": width_mm, "height_mm": height_mm})


def parse_custom_size(values: dict[str, Any]) -> dict[str, Any]:
    return parse_form((Page,), values)


# -- editing --------------------------------------------------------------------------------

def edit_fields(item, regions: tuple[str, ...] = ()) -> list[Field]:
    """The item's editable properties, kind first, then how the physics treats it (its
    anchor's gamma, decorative, its group, and its region where the page has ``regions``)."""
    own = [f for f in form_fields(item) if f.name not in BASE_FIELDS]
    anchor = form_fields(item.anchor) if isinstance(item.anchor, PointAnchor) else []
    region_choices = (("the whole page", ""),) + tuple((name, name) for name in regions)
    base = form_fields(item, BASE_FIELDS,
                       choices={"region": region_choices} if regions else None)
    return own + anchor + base


BASE_FIELDS = tuple(f.name for f in dataclasses.fields(ItemBase)
                    if f.metadata.get("label"))


def parse_edit(values: dict[str, Any]) -> dict[str, Any]:
    if "text" in values and not values["text"].strip():
        raise ValueError("a text box needs some text (delete the item instead)")
    return parse_form(EDITED_CLASSES, values)


def picture_edit_parser(current_path: str, resolve: Callable[[str], str]
                        ) -> Callable[[dict[str, Any]], dict[str, Any]]:
    """`parse_edit` for a picture: a path typed anew goes through ``resolve`` (the session's
    check of the file: a missing, unreadable or non-picture file is a sentence, and the form
    stays open); an unchanged path passes as it is, even while its file is missing, so a
    picture whose file is gone can still have its other fields edited."""
    def parse(values: dict[str, Any]) -> dict[str, Any]:
        parsed = parse_edit(values)
        if parsed.get("path", current_path) != current_path:
            try:
                parsed["path"] = resolve(parsed["path"])
            except ValueError as error:
                raise FieldError("path", str(error)) from None
        return parsed
    return parse


def group_fields(item, groups: tuple[str, ...]) -> list[Field]:
    known = f" (this page has {', '.join(groups)})" if groups else ""
    return [Field("group", f"Group name{known}; empty takes {item.id} out", "line", item.group)]


def parse_group(values: dict[str, Any]) -> str:
    return parse_form((TextItem,), values)["group"]


def export_fields(refused: str, suggested: str) -> list[Field]:
    """The one field of the export dialog: why the usual PDF cannot be written, and a name."""
    return [Field("name", f"{refused}\nExport to (a .pdf in the project's folder, or a path):",
                  "line", suggested)]


def free_pdf_name(project_file: Path) -> str:
    """A PDF name beside ``project_file`` that names nothing yet: NAME-export.pdf, then -2…"""
    stem = project_file.stem
    for count in itertools.count(1):
        name = f"{stem}-export{'' if count == 1 else f'-{count}'}.pdf"
        if not os.path.lexists(project_file.with_name(name)):
            return name
    raise AssertionError("unreachable")


def export_parser(folder: Path, check: Callable[[Path], None]) -> Callable[[dict], Path]:
    """Turn the typed name into the path to export to, relative to the project's ``folder``;
    ``check`` refuses a path render would refuse (ValueError: the dialog stays open)."""
    def parse(values: dict) -> Path:
        name = str(values["name"]).strip()
        if not name:
            raise ValueError("type a file name, e.g. card-print.pdf")
        if name.endswith(("/", os.sep)) or Path(name).name in ("", ".", ".."):
            # "." showed Python's own words: "PosixPath('.') has an empty name"
            raise ValueError(f"{name} names a folder; type a file name, e.g. "
                             f"{os.path.join(name, 'card-print.pdf')}")
        path = Path(name).expanduser()
        if path.suffix.lower() != ".pdf":
            path = path.with_name(path.name + ".pdf")
        path = path if path.is_absolute() else folder / path
        check(path)
        return path
    return parse
