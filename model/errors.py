"""Errors a user can act on: each names the file, the line when known, the item and the fix.

The CLI and the editor print these as they are; a traceback is never the answer to bad input.
"""

from __future__ import annotations

import unicodedata
from dataclasses import dataclass
from pathlib import Path

MAX_PROBLEMS_SHOWN = 20
# Bidi overrides and isolates reorder what a terminal shows; a message must read as it is.
BIDI_CONTROLS = set("\u200e\u200f\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069")


def printable(text: str) -> str:
    """``text`` with control characters written as escapes (``\\x1b``, ``\\n``): a project file
    must not be able to put terminal escape sequences or fake lines into a message."""
    if text.isprintable():
        return text
    out = []
    for ch in text:
        if unicodedata.category(ch) in ("Cc", "Cs") or ch in BIDI_CONTROLS or ch in "\u2028\u2029":
            out.append(ch.encode("unicode_escape").decode("ascii"))
        else:
            out.append(ch)
    return "".join(out)


@dataclass(frozen=True)
class Problem:
    """One thing wrong with a project file, and what to do about it."""

    file: Path | None
    line: int | None
    where: str  # e.g. 'item "photo-1"' or 'page "front"' or '[physics]'
    message: str
    hint: str = ""

    def __str__(self) -> str:
        location = str(self.file) if self.file is not None else "<project>"
        if self.line is not None:
            location += f":{self.line}"
        text = f"{location}: {self.where + ': ' if self.where else ''}{self.message}"
        if self.hint:
            text += f" ({self.hint})"
        return printable(text)


class FloatpageError(Exception):
    """Base of every error that is the user's to fix; the CLI turns it into exit code 1."""


class ProjectFileError(FloatpageError):
    """A project file that cannot be read or is invalid; carries every problem found."""

    def __init__(self, problems: list[Problem]):
        self.problems = list(problems)
        super().__init__(summarize(self.problems))


def summarize(problems: list[Problem], limit: int = MAX_PROBLEMS_SHOWN) -> str:
    """The first ``limit`` problems, one per line, then how many more there are: a file with
    780 duplicate ids needs the first few lines and a count, not 780 lines."""
    lines = [str(problem) for problem in problems[:limit]]
    rest = len(problems) - limit
    if rest > 0:
        lines.append(f"… and {rest} more like this")
    return "\n".join(lines)
