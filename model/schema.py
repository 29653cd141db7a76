"""What each table of a project file may hold: key, type, range and the advice to give.

The loader walks a parsed file against these specs and reports every problem
at once, so a user fixes a file in one pass rather than one error per run.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any, Callable

from floatpage.model.document import WEEKDAYS

HEX_COLOUR = re.compile(r"^#[0-9a-fA-F]{6}$")
CALENDAR_LANGUAGES = ("en", "de", "fr", "es", "it", "pt", "nl")
FONT_FAMILIES = ("serif", "sans", "display")

Check = Callable[[Any], "str | None"]


@dataclass(frozen=True)
class Key:
    """One allowed key: its TOML type, whether it must be present, and a value check."""

    name: str
    kind: str  # "int", "number", "bool", "str", "table"
    required: bool = False
    check: Check | None = None


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


def finite(value: float) -> str | None:
    return None if math.isfinite(value) else "must be a finite number"


def positive(value: float) -> str | None:
    return finite(value) or (None if value > 0 else "must be greater than 0")


def non_negative(value: float) -> str | None:
    return finite(value) or (None if value >= 0 else "must not be negative")


def positive_up_to(high: float) -> Check:
    def check(value: float) -> str | None:
        return positive(value) or (None if value <= high else f"must be at most {high:g}")
    return check


def at_most_chars(limit: int) -> Check:
    def check(value: str) -> str | None:
        if len(value) <= limit:
            return None
        return (f"holds {len(value)} characters, more than the {limit} it can hold; "
                "shorten it, or split a text over several boxes or pages")
    return check


def between(low: float, high: float) -> Check:
    def check(value: float) -> str | None:
        return finite(value) or (None if low <= value <= high else f"must be between {low} and {high}")
    return check


def one_of(*choices: str) -> Check:
    def check(value: str) -> str | None:
        return None if value in choices else "must be one of " + ", ".join(f'"{c}"' for c in choices)
    return check


def colour(value: str) -> str | None:
    return None if HEX_COLOUR.match(value) else 'must be a colour written as "#rrggbb", e.g. "#1f77b4"'


def item_id(value: str) -> str | None:
    if re.fullmatch(r"[A-Za-z0-9][A-Za-z0-9_.-]{0,63}", value):
        return None
    return "must be 1-64 letters, digits, '-', '_' or '.', starting with a letter or digit"


MAX_TITLE_CHARS = 1_000  # a title is PDF metadata; 200,000 characters overflowed TeX's line buffer

TOP_KEYS = [
    Key("format", "int", required=True),
    Key("title", "str", check=at_most_chars(MAX_TITLE_CHARS)),
    Key("language", "str", check=one_of(*CALENDAR_LANGUAGES)),
    Key("physics", "table"),
    Key("files", "table"),
    Key("pages", "array", required=True),
]

FILES_KEYS = [Key("allow_outside", "bool")]
MAX_TEXT_CHARS = 20_000  # a poster's worth; 1 MB of text drove LuaLaTeX to 2.5 GB

PHYSICS_KEYS = [
    Key("mode", "str", check=one_of("fast", "paper")),
    # Upper bounds keep the Euler update (4, 5) finite: alpha = dt = 1e308 overflows to inf,
    # then NaN, and a NaN written to the file loses the layout.
    Key("alpha", "number", check=positive_up_to(1e6)),
    Key("beta", "number", check=between(0.0, 1e6)),
    Key("delta", "number", check=between(0.0, 1.0)),
    Key("dt", "number", check=positive_up_to(1.0)),
    Key("steps_per_frame", "int", check=between(1, 100_000)),
    Key("distance", "str", check=one_of("euclidean", "axis")),
    Key("heat_decay", "number", check=between(0.0, 0.5)),
    Key("gutter_mm", "number", check=between(0.0, 100.0)),
    Key("seed", "int", check=between(0, 2**63 - 1)),
]

PAGE_KEYS = [
    Key("id", "str", required=True, check=item_id),
    Key("size", "str"),
    Key("orientation", "str", check=one_of("portrait", "landscape")),
    Key("width_mm", "number", check=between(10.0, 5000.0)),
    Key("height_mm", "number", check=between(10.0, 5000.0)),
    Key("background", "table"),
    Key("items", "array"),
]

BACKGROUND_KEYS = [Key("color", "str", check=colour), Key("picture", "str")]

COMMON_ITEM_KEYS = [
    Key("id", "str", required=True, check=item_id),
    Key("kind", "str", required=True),
    Key("x", "number", required=True, check=finite),
    Key("y", "number", required=True, check=finite),
    Key("w", "number", required=True, check=positive),
    Key("h", "number", required=True, check=positive),
    Key("z", "int"),
    Key("decorative", "bool"),
    Key("anchor", "table"),
]

KIND_KEYS = {
    "text": [
        Key("text", "str", check=at_most_chars(MAX_TEXT_CHARS)),
        Key("font", "str", check=one_of(*FONT_FAMILIES)),
        Key("color", "str", check=colour),
        Key("bold", "bool"),
        Key("italic", "bool"),
    ],
    "picture": [Key("path", "str", required=True), Key("lock_aspect", "bool"), Key("bleed", "bool")],
    "block": [Key("color", "str", check=colour), Key("opacity", "number", check=between(0.0, 1.0)),
              Key("bleed", "bool")],
    "calendar": [
        Key("year", "int", check=between(1, 9999)),
        Key("month", "int", check=between(1, 12)),
        Key("first_weekday", "str", check=one_of(*WEEKDAYS)),
        Key("language", "str", check=one_of(*CALENDAR_LANGUAGES)),
        Key("font", "str", check=one_of(*FONT_FAMILIES)),
        Key("color", "str", check=colour),
    ],
}

POINT_ANCHOR_KEYS = [
    Key("x", "number", required=True, check=finite),
    Key("y", "number", required=True, check=finite),
    Key("gamma", "number", check=between(0.0, 1.0)),
    Key("hard", "bool"),
]
ITEM_ANCHOR_KEYS = [
    Key("to", "str", required=True),
    Key("dx", "number", check=finite),
    Key("dy", "number", check=finite),
]
