"""Placeholders in a merge template: `{column}` is replaced by the record's value.

Plain substitution and nothing more: no expressions, filters or logic, and the value is
inserted as it is (it is escaped for LaTeX later, like any text). `{{` and `}}` stand for
literal braces. A value is never scanned for placeholders again.
"""

from __future__ import annotations

import re
from typing import Mapping

TOKEN = re.compile(r"\{\{|\}\}|\{([^{}]*)\}|[{}]")


class PlaceholderError(ValueError):
    """A brace that opens or closes nothing, or an empty `{}`."""


def fields_in(text: str) -> list[str]:
    """The column names `text` asks for, in order of first use; PlaceholderError if malformed."""
    names: dict[str, None] = {}
    for match in TOKEN.finditer(text):
        token = match.group(0)
        if token in ("{{", "}}"):
            continue
        if token in ("{", "}"):
            raise PlaceholderError(f"a lone '{token}' at character {match.start() + 1}; write "
                                   f"'{token}{token}' for a brace, or '{{column}}' for a value")
        name = match.group(1).strip()
        if not name:
            raise PlaceholderError(f"an empty placeholder '{token}' at character "
                                   f"{match.start() + 1}; put a column name between the braces")
        names[name] = None
    return list(names)


def fill(text: str, values: Mapping[str, str]) -> str:
    """`text` with every placeholder replaced by its value (KeyError for a missing column)."""
    def replace(match: re.Match) -> str:
        token = match.group(0)
        if token == "{{":
            return "{"
        if token == "}}":
            return "}"
        return values[match.group(1).strip()]

    return TOKEN.sub(replace, text)
