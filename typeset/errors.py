"""Render errors a user can act on; each says which file or item, and what to do."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from floatpage.model.errors import FloatpageError


class RenderError(FloatpageError):
    """The PDF could not be made; the message names the item or file and the fix."""


class TexNotFoundError(RenderError):
    """The TeX engine is not installed."""


class EngineDidNotStart(RenderError):
    """LuaLaTeX ended, with an exit code of its own, before it wrote a log: the TeX
    installation is at fault (a format or texmf.cnf it cannot find), not the document. A
    merge stops at once on it rather than failing every record, each after its chunk had
    been halved down to it."""


@dataclass(frozen=True)
class LogError:
    """One error from the LaTeX log: the .tex line, the message, and the item it came from."""

    line: int | None
    message: str
    item: str | None = None  # e.g. 'item "photo" on page "front"'

    def __str__(self) -> str:
        where = self.item or (f"line {self.line} of the .tex" if self.line else "the document")
        line = f" (.tex line {self.line})" if self.item and self.line else ""
        return f"{where}: {self.message}{line}"


class LatexCompileError(RenderError):
    """LuaLaTeX stopped with an error; `errors` are parsed from the log at `log_path`."""

    def __init__(self, log_path: Path | None, errors: list[LogError], summary: str = ""):
        self.log_path = log_path
        self.errors = list(errors)
        lines = [summary or "LaTeX could not typeset the document:"]
        lines += [f"  {error}" for error in self.errors] or ["  (no error line found in the log)"]
        if log_path is not None:
            lines.append(f"  full log: {log_path}")
        super().__init__("\n".join(lines))
