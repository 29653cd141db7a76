"""Saving a settle by rewriting only the numbers that moved.

`floatpage settle` changes nothing in a project but its items' x and y.  Saving through
tomlkit first parses the whole file into an editable document: 7 s for a file of 2,000 items,
whose settle takes one.  So a settle's save rewrites, in the very text it was read from, the
values of the `x = ...` and `y = ...` lines that changed, each written as tomlkit writes a
number; every other byte (comments, spacing, line endings, key order) stays as it was.

Where the text is not laid out one key to a line under `[[pages.items]]` headers (an inline
item table, say), holds a multi-line string (whose lines could look like keys or headers), or
the project differs from what was read by more than positions, there is no patch and the
caller saves the full way (model.save.save_project).
"""

from __future__ import annotations

import re
import tomllib
from dataclasses import dataclass
from pathlib import Path

from floatpage.model.atomic_file import atomic_write
from floatpage.model.document import Project
from floatpage.model.locate import LineFinder
from floatpage.model.save import UTF8_BOM, mm, non_finite_numbers, same, save_project, \
    unchanged_on_disk

MULTILINE_STRING = re.compile(r'"""|\'\'\'')
PLAIN_NUMBER = re.compile(r"[+-]?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?")
VALUE = re.compile(r"^(?P<key>\s*(?P<name>[xy])\s*=\s*)(?P<value>[^\s#]+)(?P<rest>\s*(?:#.*)?)$")


@dataclass(frozen=True)
class Positions:
    """Each page's items as read: ids in order and centres, to tell what a settle moved."""

    pages: list[list[tuple[str, float, float]]]

    @classmethod
    def of(cls, project: Project) -> "Positions":
        return cls([[(item.id, item.x, item.y) for item in page.items] for page in project.pages])


def save_settled(project: Project, read: Positions) -> Path:
    """Save ``project``, which only a settle changed since it was read at ``read``, to the
    file it was read from: its moved positions patched into the text, else the full way."""
    text = patched_text(project, read)
    if text is None or project.path is None or non_finite_numbers(project):
        return save_project(project)
    data = text.encode("utf-8")
    if project.utf8_bom:
        data = UTF8_BOM + data
    if not unchanged_on_disk(project.path, data):
        atomic_write(project.path, data)
    project.source_text = text
    return project.path


def patched_text(project: Project, read: Positions) -> str | None:
    """The project's source text with the positions that moved since ``read`` rewritten as
    the full save writes them (to 0.01 mm, where they differ by as much), or None where only
    the full save can say it (see the module doc)."""
    text = project.source_text
    if text is None or project.parsed_source is not None or MULTILINE_STRING.search(text):
        return None  # a line of a multi-line string may look like `x = 10` or a header
    if [[item.id for item in page.items] for page in project.pages] != \
            [[item_id for item_id, _, _ in page] for page in read.pages]:
        return None
    lines = text.splitlines(keepends=True)
    finder = LineFinder(text)
    for page_index, (page, before) in enumerate(zip(project.pages, read.pages)):
        for item_index, (item, (_, old_x, old_y)) in enumerate(zip(page.items, before)):
            for name, old, new in (("x", old_x, mm(item.x)), ("y", old_y, mm(item.y))):
                if same(old, new):
                    continue
                number = finder.key_line(finder.item_line(page_index, item_index), name)
                patched = number and rewritten(lines[number - 1], name, old, new)
                if not patched:
                    return None
                lines[number - 1] = patched
    return "".join(lines)


def rewritten(line: str, name: str, old: float, new: float) -> str | None:
    """``line`` (``name = old``, perhaps with a comment) saying ``new`` instead, or None if the
    line is not such a line."""
    body = line.rstrip("\r\n")
    match = VALUE.match(body)
    if match is None or match["name"] != name or not holds(match["value"], old):
        return None
    if type(new) is float:  # noqa: E721 (bool and numpy floats take tomlkit's way)
        value = repr(new)  # what tomlkit.item(new).as_string() writes, without importing it
    else:
        import tomlkit

        value = tomlkit.item(new).as_string()
    return match["key"] + value + match["rest"] + line[len(body):]


def holds(token: str, value: float) -> bool:
    """Whether the TOML number ``token`` is ``value``: the line found is the key's own."""
    if PLAIN_NUMBER.fullmatch(token):  # as floatpage writes them: no parser needed
        return float(token) == float(value)
    try:
        parsed = tomllib.loads(f"v = {token}")["v"]
    except tomllib.TOMLDecodeError:
        return False
    return isinstance(parsed, (int, float)) and not isinstance(parsed, bool) \
        and float(parsed) == float(value)
