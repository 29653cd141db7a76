"""Read a LuaLaTeX log: find the errors and say which item each came from.

With `-file-line-error` an error reads `./main.tex:123: message`. The .tex
brackets every item between `% [fp:N] label` and `% [fp:N] end` comments, so
a line number leads back to the item the user knows.
"""

from __future__ import annotations

import re

from floatpage.typeset.errors import LogError

FILE_LINE = re.compile(r"^(?P<file>[^\s:][^:]*):(?P<line>\d+): (?P<message>.*)$")
BANG = re.compile(r"^! (?P<message>.*)$")
MARKER = re.compile(r"^% \[fp:(?P<n>\d+)\] (?P<rest>.*)$")


def parse_log(log: str, main_file: str = "main.tex") -> list[tuple[int | None, str]]:
    """(line, message) for each error; messages include their continuation line when cut."""
    errors: list[tuple[int | None, str]] = []
    lines = log.splitlines()
    for index, line in enumerate(lines):
        match = FILE_LINE.match(line)
        if match and match.group("file").lstrip("./").endswith(main_file.lstrip("./")):
            message = match.group("message").strip()
            following = lines[index + 1].strip() if index + 1 < len(lines) else ""
            if following and not following.startswith(("l.", "See ", "Type ", "!")) \
                    and len(line) >= 79:
                message += following  # TeX wraps log lines at 79 characters
            if "==> Fatal error occurred" not in message:
                errors.append((int(match.group("line")), message))
            continue
        match = BANG.match(line)
        if match and not any(m == match.group("message") for _, m in errors):
            number = None
            for later in lines[index + 1:index + 12]:
                found = re.match(r"^l\.(\d+) ", later)
                if found:
                    number = int(found.group(1))
                    break
            message = match.group("message").strip()
            if message and "==> Fatal error occurred" not in message \
                    and not any(m.startswith(message) for _, m in errors):
                errors.append((number, message))
    return errors


def marker_at(tex: str, line_number: int) -> int | None:
    """The item marker number enclosing a 1-based .tex line, or None outside any item."""
    lines = tex.splitlines()
    for index in range(min(line_number, len(lines)) - 1, -1, -1):
        match = MARKER.match(lines[index])
        if match:
            return None if match.group("rest") == "end" else int(match.group("n"))
    return None


def errors_with_items(log: str, tex: str, labels: list[str]) -> list[LogError]:
    """Parsed errors, each tied to the item label its .tex line lies in."""
    out = []
    for line, message in parse_log(log):
        item = None
        if line is not None:
            marker = marker_at(tex, line)
            if marker is not None and marker < len(labels):
                item = labels[marker]
        out.append(LogError(line, plain_words(message), item))
    return out


PNG_READER = re.compile(r"\((?:read|write)png\)")


def plain_words(message: str) -> str:
    """LuaTeX's own words, with what to do where they leave the user lost: a PNG that libpng
    refuses (a chunk of a kind it does not know) read "(readpng): internal error"."""
    if PNG_READER.search(message):
        message = message.replace("internal error", "the PNG could not be read")
        message += ("; the file is damaged or of a kind LuaTeX does not read: open it and "
                    "save it again as PNG or JPEG")
    return message
