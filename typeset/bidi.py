"""Right-to-left runs for LuaTeX: which parts of a line are set right to left.

LuaTeX reorders text itself once it is told a run's direction (`\\textdir TRT`),
and luaotfload's HarfBuzz mode then shapes the run right to left. What it
cannot do is find the runs: that is the part of the Unicode bidirectional
algorithm done here, for one line without explicit embeddings:
- the line's direction is that of its first strong letter;
- in a left-to-right line, a right-to-left run goes from a right-to-left letter
  to the last one before the next left-to-right letter, taking the spaces,
  punctuation and numbers between them;
- in a right-to-left line, the same with the directions swapped;
- a number belongs to the run of the letter before it (rules W7 and N1), and inside
  a right-to-left run it stays left to right (2027 never reads 7202).
The fitter needs none of this: a line is as wide in either order.
"""

from __future__ import annotations

import unicodedata

from pylatex.utils import NoEscape

RTL = ("R", "AL")
NUMBER = ("EN", "AN")
NUMBER_JOINERS = ("CS", "ES", "ET")  # 1,000.5  +5  50% between or around digits


def strong(char: str) -> str | None:
    kind = unicodedata.bidirectional(char)
    if kind in RTL:
        return "R"
    if kind == "L":
        return "L"
    return None


def base_direction(text: str) -> str:
    for char in text:
        found = strong(char)
        if found:
            return found
    return "L"


def has_rtl(text: str) -> bool:
    return any(unicodedata.bidirectional(char) in RTL for char in text)


def directional_runs(line: str, base: str) -> list[tuple[str, str]]:
    """(direction, text) pieces in logical order: runs of the opposite direction between
    two of its strong letters, the rest in the base direction."""
    other = "R" if base == "L" else "L"
    kinds: dict[int, str] = {}
    previous = base
    for i, char in enumerate(line):
        kind = strong(char)
        if kind:
            kinds[i] = previous = kind
        elif previous == "L" and unicodedata.bidirectional(char) == "EN":
            kinds[i] = "L"  # a number after a left-to-right letter joins it ("Happy 30th, 2027")
        elif previous == "R" and unicodedata.bidirectional(char) in NUMBER:
            kinds[i] = "R"  # after a right-to-left letter, it is read within that run
    positions = sorted(kinds)
    runs: list[tuple[str, str]] = []
    start = 0
    index = 0
    while index < len(positions):
        first = positions[index]
        if kinds[first] != other or strong(line[first]) is None:
            index += 1
            continue
        last = first
        while index + 1 < len(positions) and kinds[positions[index + 1]] == other:
            index += 1
            last = positions[index]
        index += 1
        end = last + 1
        while end < len(line) and unicodedata.category(line[end]).startswith("M"):
            end += 1
        if first > start:
            runs.append((base, line[start:first]))
        runs.append((other, line[first:end]))
        start = end
    if start < len(line):
        runs.append((base, line[start:]))
    return runs


def number_runs(text: str) -> list[tuple[bool, str]]:
    """(is_number, text) pieces: digits with the separators between them kept together."""
    pieces: list[tuple[bool, str]] = []
    index = 0
    while index < len(text):
        char = text[index]
        if unicodedata.bidirectional(char) in NUMBER:
            end = index + 1
            while end < len(text):
                kind = unicodedata.bidirectional(text[end])
                if kind in NUMBER:
                    end += 1
                elif (kind in NUMBER_JOINERS and end + 1 < len(text)
                      and unicodedata.bidirectional(text[end + 1]) in NUMBER):
                    end += 2
                else:
                    break
            pieces.append((True, text[index:end]))
            index = end
        else:
            end = index + 1
            while end < len(text) and unicodedata.bidirectional(text[end]) not in NUMBER:
                end += 1
            pieces.append((False, text[index:end]))
            index = end
    return pieces


def rtl_markup(text: str, escape) -> str:
    """A right-to-left run with its numbers turned back to left to right."""
    inner = "".join("{\\textdir TLT " + escape(piece) + "}" if is_number else escape(piece)
                    for is_number, piece in number_runs(text))
    return "{\\textdir TRT " + inner + "}"


def line_markup(line: str, escape, base: str | None = None) -> NoEscape:
    """TeX for one line: escaped text, right-to-left runs wrapped in `\\textdir`."""
    if not has_rtl(line):
        return NoEscape(escape(line))
    base = base or base_direction(line)
    if base == "R":
        inner = "".join("{\\textdir TLT " + escape(piece) + "}" if direction == "L"
                        else rtl_markup(piece, escape)[len("{\\textdir TRT "):-1]
                        for direction, piece in directional_runs(line, "R"))
        return NoEscape("{\\textdir TRT " + inner + "}")
    return NoEscape("".join(rtl_markup(piece, escape) if direction == "R" else escape(piece)
                            for direction, piece in directional_runs(line, "L")))
