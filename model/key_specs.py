"""What a key of a project file may hold, written once, on the model's own dataclass fields.

Each field of the document's dataclasses carries ``spec(kind, check)`` in its metadata:
its TOML type and the check its value must pass.  `model.schema` reads the key lists from
the fields, so the dataclasses (names, order, defaults) and what the loader accepts cannot
drift apart; the words a user sees for each rule live here too.  The vocabulary (colours,
languages, fonts, weekdays) is defined here once and imported by the typesetter and editor.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, fields
from typing import Any, Callable

HEX_COLOUR = re.compile(r"^#[0-9a-fA-F]{6}$")
CALENDAR_LANGUAGES = ("en", "de", "fr", "es", "it", "pt", "nl")
FONT_FAMILIES = ("serif", "sans", "display")
# where a text box sets its lines: the share of a line's spare width left of it; "start" (the
# default) is where the text's direction starts a line, left for Latin, right for Hebrew or
# Arabic, as a word processor sets a paragraph by default
ALIGNMENT_SHARES = {"left": 0.0, "centre": 0.5, "right": 1.0}
TEXT_ALIGNMENTS = ("start", *ALIGNMENT_SHARES)


def alignment_share(align: str, direction: str) -> float:
    """The share of a line's spare width left of it, for a box aligned ``align`` whose text
    runs in ``direction`` ("L" or "R", typeset.bidi.base_direction)."""
    if align == "start":
        return 1.0 if direction == "R" else 0.0
    return ALIGNMENT_SHARES[align]
WEEKDAYS = ("monday", "tuesday", "wednesday", "thursday", "friday", "saturday", "sunday")
# What the typesetter reads: JPEG, PNG and PDF go to LaTeX as they are, the rest are converted.
PICTURE_SUFFIXES = (".jpg", ".jpeg", ".png", ".pdf", ".webp", ".gif", ".bmp", ".tif", ".tiff")
MAX_TITLE_CHARS = 1_000  # a title is PDF metadata; 200,000 characters overflowed TeX's line buffer
MAX_TEXT_CHARS = 20_000  # a poster's worth; 1 MB of text drove LuaLaTeX to 2.5 GB
# A text's own size (`size_pt`): from the smallest a print shop still prints legibly (the
# typesetter's own floor for fitted text is lower, and warns) to the fitter's largest.
MIN_SET_PT, MAX_SET_PT = 4.0, 1000.0

Check = Callable[[Any], "str | None"]


@dataclass(frozen=True)
class Key:
    """One allowed key: its TOML type, whether it must be present, and a value check."""

    name: str
    kind: str  # "int", "number", "bool", "str", "table", "array"
    required: bool = False
    check: Check | None = None


def spec(kind: str, check: Check | None = None, *, required: bool = False,
         label: str | None = None, form: str | None = None,
         choices: tuple[tuple[str, Any], ...] | None = None) -> dict:
    """Field metadata: ``field(default=..., metadata=spec("number", positive))``.

    ``label`` puts the field in the editor's forms (tui.item_forms reads them off the fields,
    in field order), ``form`` names the widget when the kind alone does not say ("text": several
    lines), and ``choices`` are (shown, value) pairs where the values are not what a person
    reads (months by name); a ``one_of`` check gives its choices by itself."""
    return {"key": (kind, check, required), "label": label, "form": form,
            "choices": choices if choices is not None else getattr(check, "choices", None)}


def keys_of(cls, *, skip: tuple[str, ...] = ()) -> list[Key]:
    """The keys a dataclass's fields describe, in field order."""
    found = []
    for f in fields(cls):
        if "key" in f.metadata and f.name not in skip:
            kind, check, required = f.metadata["key"]
            found.append(Key(f.name, kind, required, check))
    return found


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


def zero_or_between(low: float, high: float) -> Check:
    """0 for "not set", else a value in [low, high]."""
    def check(value: float) -> str | None:
        if value == 0:
            return None
        return finite(value) or (None if low <= value <= high else
                                 f"must be 0 (fit the box) or between {low:g} and {high:g}")
    return check


def one_of(*choices: str) -> Check:
    def check(value: str) -> str | None:
        return None if value in choices else "must be one of " + ", ".join(f'"{c}"' for c in choices)
    check.choices = tuple((choice, choice) for choice in choices)  # type: ignore[attr-defined]
    return check


def colour(value: str) -> str | None:
    return None if HEX_COLOUR.match(value) else 'must be a colour written as "#rrggbb", e.g. "#1f77b4"'


def item_id(value: str) -> str | None:
    if re.fullmatch(r"[A-Za-z0-9][A-Za-z0-9_.-]{0,63}", value):
        return None
    return "must be 1-64 letters, digits, '-', '_' or '.', starting with a letter or digit"


def name_or_empty(value: str) -> str | None:
    """A region's or group's name on an item: an id, or "" for none."""
    return None if value == "" else item_id(value)
