"""Errors a user can act on: each names the file, the line when known, the item and the fix.

The CLI and the editor print these as they are; a traceback is never the answer to bad input.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path


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
        return text


class FloatpageError(Exception):
    """Base of every error that is the user's to fix; the CLI turns it into exit code 1."""


class ProjectFileError(FloatpageError):
    """A project file that cannot be read or is invalid; carries every problem found."""

    def __init__(self, problems: list[Problem]):
        self.problems = list(problems)
        super().__init__("\n".join(str(p) for p in self.problems))
