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
    numeric = number_flags(line)
    for i, char in enumerate(line):
        kind = strong(char)
        if kind:
            kinds[i] = previous = kind
        elif previous == "L" and unicodedata.bidirectional(char) == "EN":
            kinds[i] = "L"  # a number after a left-to-right letter joins it ("Happy 30th, 2027")
        elif previous == "R" and numeric[i]:
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


def number_flags(text: str) -> list[bool]:
    """For each character, whether it belongs to a number: digits, a single separator between
    two numbers (rule W4: 1,000.5 and 2027-11-24), and a sequence of terminators right before
    or after European digits (W5: 100%, $5; 20 °C keeps its °C apart, and so does an Arabic
    number's ٪, which W5 leaves to the letters around it)."""
    kinds = [unicodedata.bidirectional(char) for char in text]
    joined = [kind in NUMBER for kind in kinds]
    for index in range(1, len(text) - 1):
        if (kinds[index] in NUMBER_JOINERS and kinds[index - 1] in NUMBER
                and kinds[index + 1] in NUMBER):
            joined[index] = True
    index = 0
    while index < len(text):
        if kinds[index] != "ET" or joined[index]:
            index += 1
            continue
        end = index
        while end < len(text) and kinds[end] == "ET":
            end += 1
        if (index > 0 and kinds[index - 1] == "EN") or (end < len(text) and kinds[end] == "EN"):
            joined[index:end] = [True] * (end - index)
        index = end
    return joined


def number_runs(text: str) -> list[tuple[bool, str]]:
    """(is_number, text) pieces, numbers as `number_flags` finds them: in a right-to-left
    line "100%" printed "%100"."""
    pieces: list[tuple[bool, str]] = []
    for char, is_number in zip(text, number_flags(text)):
        if pieces and pieces[-1][0] == is_number:
            pieces[-1] = (is_number, pieces[-1][1] + char)
        else:
            pieces.append((is_number, char))
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
