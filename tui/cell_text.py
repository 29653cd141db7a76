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
    whole CJK sentence on the next line that the PDF began on this one."""
    lines: list[str] = []
    line, line_cells = "", 0
    for word, joined in pieces(text.replace("\t", " ")):
        parts = graphemes(word)
        word_cells = sum(width(g) for g in parts)
        gap = 1 if line and not joined else 0
        if line_cells + gap + word_cells <= cells:
            line, line_cells = line + " " * gap + word, line_cells + gap + word_cells
            continue
        if line:
            lines.append(line)
            line, line_cells = "", 0
        for grapheme in parts:  # the word alone, broken where it must be
            if line_cells + width(grapheme) > cells and line:
                lines.append(line)
                line, line_cells = "", 0
            line, line_cells = line + grapheme, line_cells + width(grapheme)
    if line or not lines:
        lines.append(line)
    return [visual(one) for one in lines]
