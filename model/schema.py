"""What each table of a project file may hold: key, type, range and the advice to give.

Read off the model's dataclasses (`model.document`, whose fields carry their specs), so there
is one description of the model.  Only the file's own structure is written here: the top-level
keys and the `[files]` table, which name no model field one to one.  The loader walks a parsed
file against these lists and reports every problem at once, so a user fixes a file in one pass.
"""

from __future__ import annotations

from typing import Any

from floatpage.model.document import (
    ITEM_CLASSES, Background, ItemAnchor, ItemBase, Page, PhysicsSettings, PointAnchor, Region,
)
from floatpage.model.key_specs import (  # noqa: F401 - the vocabulary, for the loader's users
    CALENDAR_LANGUAGES, FONT_FAMILIES, HEX_COLOUR, MAX_TEXT_CHARS, MAX_TITLE_CHARS, Key,
    at_most_chars, keys_of, one_of,
)


def type_matches(kind: str, value: Any) -> bool:
    """TOML-level type test; bools are not numbers here, although Python says they are ints."""
    if kind == "bool":
        return isinstance(value, bool)
    if isinstance(value, bool):
        return False
    if kind == "int":
        return isinstance(value, int)
    if kind == "number":
        return isinstance(value, (int, float))
    if kind == "str":
        return isinstance(value, str)
    if kind == "table":
        return isinstance(value, dict)
    raise ValueError(kind)


TYPE_WORDS = {"int": "a whole number", "number": "a number", "bool": "true or false",
              "str": "a quoted string", "table": "a table"}

TOP_KEYS = [
    Key("format", "int", required=True),
    Key("title", "str", check=at_most_chars(MAX_TITLE_CHARS)),
    Key("language", "str", check=one_of(*CALENDAR_LANGUAGES)),
    Key("physics", "table"),
    Key("files", "table"),
    Key("pages", "array", required=True),
]
FILES_KEYS = [Key("allow_outside", "bool")]

PHYSICS_KEYS = keys_of(PhysicsSettings)
PAGE_KEYS = keys_of(Page)
BACKGROUND_KEYS = keys_of(Background)
_BASE = keys_of(ItemBase)
COMMON_ITEM_KEYS = [_BASE[0], Key("kind", "str", required=True), *_BASE[1:]]
KIND_KEYS = {kind: keys_of(cls, skip=tuple(key.name for key in _BASE))
             for kind, cls in ITEM_CLASSES.items()}
POINT_ANCHOR_KEYS = keys_of(PointAnchor)
ITEM_ANCHOR_KEYS = keys_of(ItemAnchor)
REGION_KEYS = keys_of(Region)


def complaints(obj: Any) -> list[tuple[str, str]]:
    """(field, what is wrong) for each value of a model object that its field's spec refuses:
    the loader's own checks, for objects built in code (the editor, merge) rather than read from
    a file. Nested tables (an item's anchor) are not walked."""
    found = []
    for key in keys_of(type(obj)):
        value = getattr(obj, key.name)
        if key.kind == "table" or value is None:
            continue
        if not type_matches(key.kind, value):
            found.append((key.name, f"must be {TYPE_WORDS[key.kind]}, not {value!r}"))
        elif key.check is not None and (complaint := key.check(value)):
            found.append((key.name, complaint))
    return found

