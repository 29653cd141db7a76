"""How the user wrote a value or a table in a project file, so that a save keeps it so: a
literal or multi-line string, a Windows file's line breaks, a table written as dotted keys,
keys indented by hand (user-walk-13).  A save that rewrote these made a diff the user did not
ask for on every save, or crashed (dotted keys).  tomlkit's own items are read here; the save
(model.save) decides what changes.
"""

from __future__ import annotations

import re
from typing import Any

# tomlkit is imported inside the functions, as in model.save: `check`, `render` and a
# `settle` that patches positions into the text never load it.


def as_read(written: Any) -> Any:
    """The value of a tomlkit item as the loader (tomllib) read it. A multi-line string's
    line breaks are CRLF in a Windows file: tomlkit keeps them, tomllib reads LF, so every
    save of an unchanged CRLF project rewrote each such text as a one-line string with
    `\\n` in it (user-walk-13)."""
    value = written.unwrap() if hasattr(written, "unwrap") else written
    if isinstance(value, str) and "\r" in value and hasattr(written, "as_string"):
        import tomllib
        try:
            return tomllib.loads("v = " + written.as_string())["v"]
        except tomllib.TOMLDecodeError:
            return value
    return value


def in_written_form(written: Any, value: Any) -> Any:
    """``value``, a new string, in the form the user wrote the old one: literal `'...'` and
    multi-line `\"\"\"...\"\"\"` strings stay so (a word changed in a hand-written multi-line
    message came back as one line of `\\n`s), where the new words can be written that way
    and read back the same; else as tomlkit writes it."""
    from tomlkit.items import String, StringType
    if not isinstance(written, String) or not isinstance(value, str):
        return value
    import tomlkit
    import tomllib
    literal = written.type in (StringType.SLL, StringType.MLL)
    multiline = written.type in (StringType.MLB, StringType.MLL)
    for form in ((literal, multiline), (literal, True), (False, multiline)):
        try:
            candidate = tomlkit.string(value, literal=form[0], multiline=form[1])
            if form[1] and re.match(r'("""|\'\'\')\r?\n', written.as_string()):
                # the user's `"""` then a line break, which TOML drops: kept
                candidate = String(candidate.type, value, "\n" + candidate._original,
                                   candidate.trivia)
            if tomllib.loads("v = " + candidate.as_string())["v"] == value:
                return candidate
        except (ValueError, tomllib.TOMLDecodeError):  # tomlkit's InvalidStringError is one
            continue
    return value


def written_in_pieces(table: Table) -> bool:
    """Whether ``table`` is written in pieces rather than under one header: dotted keys
    (`physics.seed = 0`, `physics.alpha = 150.0`), which tomlkit reads as a proxy over the
    pieces with no body of its own. Every save of such a file, even a settle's, stopped with
    "internal error: AttributeError: 'dict' object has no attribute 'body'" (user-walk-13)."""
    from tomlkit.container import OutOfOrderTableProxy
    return isinstance(table, OutOfOrderTableProxy)


def written_entries(table: Table) -> list:
    """The (key, value) entries of ``table`` in the file's order, whether it is written
    under one header or in pieces (`written_in_pieces`, read through tomlkit's internal
    merged container, as bounded by pyproject.toml's tomlkit pin)."""
    if written_in_pieces(table):
        return table._internal_container.body
    return table.value.body


def indent_like_the_others(table: Table, key: str) -> None:
    """Indent an added key as the table's first key is (a tab, two spaces): the keys a save
    added to a table indented by hand stood at the line's start (user-walk-13)."""
    from tomlkit.items import AoT, InlineTable, Table as TableItem
    if isinstance(table, InlineTable) or key not in table.value:
        return
    indents = [item.trivia.indent for entry, item in table.value.body
               if entry is not None and entry.key != key
               and not isinstance(item, (TableItem, AoT)) and hasattr(item, "trivia")]
    added = table.value.item(key)
    if indents and hasattr(added, "trivia") and not indents[0].strip(" \t"):
        added.trivia.indent = indents[0]
