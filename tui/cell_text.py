"""Text for a grid of terminal cells: graphemes at their width, lines in visual order.

A terminal cell holds one narrow character; CJK and emoji take two, and a combining mark
takes none (it rides on the letter before it).  The preview used to print every wide
character as '?' and right-to-left text backwards (issue 11).  Here a text becomes cells:
graphemes with their widths, wrapped greedily by cells, each line put in visual order with
the typesetter's own bidi runs (`typeset.bidi`), so the preview reads as the PDF will.
"""

from __future__ import annotations

import unicodedata

from rich.cells import cell_len

from floatpage.merge.placeholders import TOKEN
from floatpage.typeset.bidi import base_direction, directional_runs, has_rtl, number_runs
from floatpage.typeset.break_points import pieces


def graphemes(text: str) -> list[str]:
    """Characters with the zero-width ones (marks, joiners, variation selectors) that follow
    them; control characters become '?' (a project's text must not drive the terminal)."""
    found: list[str] = []
    for char in text:
        if not char.isprintable() and char not in "\u200d\ufe0f":
            found.append("?")
        elif found and (cell_len(char) == 0 or unicodedata.combining(char)
                        or found[-1].endswith("\u200d")):
            found[-1] += char
        elif cell_len(char) == 0:
            continue  # a mark with nothing to ride on
        else:
            found.append(char)
    return found


def width(grapheme: str) -> int:
    return 2 if any(cell_len(char) == 2 for char in grapheme) else 1


def visual(line: str) -> str:
    """The line as it reads on paper: right-to-left runs reversed (numbers in them not),
    and the runs of a right-to-left line in reverse order."""
    if not has_rtl(line):
        return line
    base = base_direction(line)

    def shown(direction: str, text: str) -> str:
        if direction != "R":
            return text
        parts = [chunk if is_number else "".join(reversed(graphemes(chunk)))
                 for is_number, chunk in number_runs(text)]
        return "".join(reversed(parts))

    pieces = [shown(direction, text) for direction, text in directional_runs(line, base)]
    return "".join(reversed(pieces) if base == "R" else pieces)


def wrap_cells(text: str, cells: int) -> list[str]:
    """Greedy lines of at most ``cells`` cells, broken where the typesetter may break them
    (`break_points.pieces`: between words, and between Chinese or Japanese characters but
    never before a 。 or a small kana, nor before a French "!" set after a space); a piece
    longer than a line is broken.  The preview had its own rule, spaces only, and put a
    whole CJK sentence on the next line that the PDF began on this one.

    A merge template's ``{placeholder}`` is never broken (a narrow picture box read
    "pictures/{photo" over "}"): a piece longer than a line breaks beside it, and a
    placeholder wider than the line shows shortened, "{pho…}" (`placeholder_pieces`)."""
    lines: list[str] = []
    line, line_cells = "", 0
    for word, joined in placeholder_pieces(text.replace("\t", " ")):
        parts = graphemes(word)
        word_cells = sum(width(g) for g in parts)
        gap = 1 if line and not joined else 0
        if line_cells + gap + word_cells <= cells:
            line, line_cells = line + " " * gap + word, line_cells + gap + word_cells
            continue
        if line:
            lines.append(line)
            line, line_cells = "", 0
        for unit in units(word, cells):  # the word alone, broken where it must be
            unit_cells = sum(width(g) for g in graphemes(unit))
            if line_cells + unit_cells > cells and line:
                lines.append(line)
                line, line_cells = "", 0
            line, line_cells = line + unit, line_cells + unit_cells
    if line or not lines:
        lines.append(line)
    return [visual(one) for one in lines]


def placeholder_pieces(text: str) -> list[tuple[str, bool]]:
    """`break_points.pieces`, with the pieces of one ``{placeholder}`` that holds spaces
    ("{first name}") joined again into one; a lone "{" that nothing closes joins nothing."""
    found = pieces(text)
    out: list[tuple[str, bool]] = []
    index = 0
    while index < len(found):
        word, joined = found[index]
        index += 1
        if opens_placeholder(word):
            closing = next((later for later in range(index, len(found))
                            if closes_placeholder(found[later][0])), None)
            if closing is not None and not any(
                    "{" in found[between][0] for between in range(index, closing)):
                for later_word, later_joined in found[index:closing + 1]:
                    word += ("" if later_joined else " ") + later_word
                index = closing + 1
        out.append((word, joined))
    return out


def closes_placeholder(word: str) -> bool:
    """Whether a "}" in `word` comes before any "{" (it ends a placeholder begun before)."""
    close, open_ = word.find("}"), word.find("{")
    return close >= 0 and (open_ < 0 or close < open_)


def opens_placeholder(word: str) -> bool:
    """Whether `word` ends inside a ``{`` that a later ``}`` may close ("{{" is a brace)."""
    tokens = [match for match in TOKEN.finditer(word) if match.group(0) not in ("{{", "}}")]
    return bool(tokens) and tokens[-1].group(0) == "{"


def units(word: str, cells: int) -> list[str]:
    """What a word longer than a line may be broken into: its graphemes, but each whole
    ``{placeholder}`` one unit, cut to "{pla…}" when it is wider than ``cells``."""
    out: list[str] = []
    start = 0
    for match in TOKEN.finditer(word):
        if match.group(1) is None:
            continue  # a brace, "{{" or "}}": graphemes like any other
        out.extend(graphemes(word[start:match.start()]))
        out.append(shortened(match.group(0), cells))
        start = match.end()
    out.extend(graphemes(word[start:]))
    return out


def shortened(placeholder: str, cells: int) -> str:
    """The placeholder in at most ``cells`` cells: "{photo}", "{ph…}", "{…}", "…"."""
    parts = graphemes(placeholder)
    if sum(width(g) for g in parts) <= cells:
        return placeholder
    if cells < 3:
        return "\u2026"
    kept, used = [], 0
    for grapheme in parts[:-1]:
        if used + width(grapheme) > cells - 2:
            break
        kept.append(grapheme)
        used += width(grapheme)
    return "".join(kept) + "\u2026}"
