"""Fit a text to its box: the largest font size at which greedy line breaking fits it.

Pure: `fit_text(text, box, metrics) -> TextFit`. Lines are decided here and
emitted one by one, so LaTeX never re-breaks them. The vertical model is the
em box PDF readers report for every glyph: a line is one em tall and the
lines are `leading` em apart, so n lines are s * (1 + (n - 1) * leading) tall.

Feasibility is monotone in the size (a larger size leaves a narrower measure
in em, and greedy breaking then needs as many lines or more, while the box
allows fewer), so bisection finds the largest feasible size.
"""

from __future__ import annotations

import math
import unicodedata
from bisect import bisect_right
from dataclasses import dataclass
from typing import Protocol

LEADING = 1.2   # baseline distance / font size
MIN_PT = 6.0    # the smallest size we call legible; below it we warn
MAX_PT = 1000.0
FLOOR_PT = 0.25  # never go below this, even for text that does not fit at MIN_PT
PRECISION = 1e-6  # relative; the binding direction ends up this close to full


class Metrics(Protocol):
    space_em: float

    def advance_em(self, word: str) -> float: ...


@dataclass(frozen=True)
class Box:
    """A box's inner size in PostScript points (bp)."""

    w_pt: float
    h_pt: float


@dataclass(frozen=True)
class TextFit:
    font_pt: float
    lines: tuple[str, ...]
    line_widths_pt: tuple[float, ...]
    leading: float = LEADING
    broken_words: tuple[str, ...] = ()  # words split across lines to avoid overflowing
    below_minimum: bool = False         # the text only fits below MIN_PT

    @property
    def height_pt(self) -> float:
        if not self.lines:
            return 0.0
        return self.font_pt * (1 + (len(self.lines) - 1) * self.leading)


class _Segment:
    """Words that must start on a fresh line, with prefix sums for O(log n) greedy steps."""

    __slots__ = ("words", "widths", "glues", "prefix")

    def __init__(self, words: list[str], widths: list[float], glues: list[float]):
        self.words, self.widths, self.glues = words, widths, glues
        self.prefix = [0.0]
        for glue, width in zip(glues, widths):
            self.prefix.append(self.prefix[-1] + glue + width)

    def breaks(self, limit: float) -> list[tuple[int, int, float]] | None:
        """Greedy lines as (start, end, width_em) within `limit` em, or None if a word is too wide."""
        words = len(self.widths)
        if words == 0:
            return [(0, 0, 0.0)]
        prefix, glues, out, start = self.prefix, self.glues, [], 0
        while start < words:
            end = bisect_right(prefix, limit + prefix[start] + glues[start], start + 1) - 1
            if end <= start:
                return None
            out.append((start, end, prefix[end] - prefix[start] - glues[start]))
            start = end
        return out


def paragraphs(text: str) -> list[list[str]]:
    """Words of each line of `text`; a newline always breaks, runs of spaces are one space."""
    text = text.strip(" \n")
    if not text:
        return []
    return [[word for word in line.split(" ") if word] for line in text.split("\n")]


def clusters(word: str) -> list[str]:
    """Characters with their combining marks, so a break never separates an accent."""
    out: list[str] = []
    for char in word:
        if out and unicodedata.combining(char):
            out[-1] += char
        else:
            out.append(char)
    return out


def break_word(word: str, limit_em: float, metrics: Metrics) -> list[str]:
    """Split a too-wide word into hyphenated pieces no wider than `limit_em`."""
    pieces, current = [], ""
    for cluster in clusters(word):
        if current and metrics.advance_em(current + cluster + "-") > limit_em:
            pieces.append(current + "-")
            current = cluster
        else:
            current += cluster
    pieces.append(current)
    return pieces


def segments_of(paras: list[list[str]], metrics: Metrics, break_limit_em: float | None
                ) -> tuple[list[_Segment], tuple[str, ...]]:
    """Build segments; with a limit, words wider than it are broken and each piece gets its line."""
    space = metrics.space_em
    segments, broken = [], []
    for words in paras:
        current: list[str] = []
        for word in words:
            if break_limit_em is not None and metrics.advance_em(word) > break_limit_em:
                pieces = break_word(word, break_limit_em, metrics)
                if len(pieces) > 1:
                    broken.append(word)
                    current.append(pieces[0])
                    segments.append(current)
                    segments.extend([piece] for piece in pieces[1:-1])
                    current = [pieces[-1]]
                    continue
            current.append(word)
        segments.append(current)
    built = []
    for words in segments:
        widths = [metrics.advance_em(word) for word in words]
        built.append(_Segment(words, widths, [0.0] + [space] * (len(words) - 1)))
    return built, tuple(broken)


def layout(segments: list[_Segment], size_pt: float, box: Box, leading: float):
    """All lines at `size_pt` as (segment, start, end, width_em), or None if they do not fit."""
    limit = box.w_pt / size_pt
    max_lines = (box.h_pt / size_pt - 1) / leading + 1 + 1e-9
    lines = []
    for segment in segments:
        found = segment.breaks(limit)
        if found is None:
            return None
        lines.extend((segment, start, end, width) for start, end, width in found)
        if len(lines) > max_lines:
            return None
    return lines


def largest_size(segments, box: Box, leading: float, low: float, high: float) -> float | None:
    """Largest size in [low, high] at which the segments fit, or None if not even `low` does."""
    if layout(segments, high, box, leading) is not None:
        return high
    if layout(segments, low, box, leading) is None:
        return None
    while high / low > 1 + PRECISION:
        middle = math.sqrt(low * high)
        if layout(segments, middle, box, leading) is None:
            high = middle
        else:
            low = middle
    return low


def fit_text(text: str, box: Box, metrics: Metrics, *, leading: float = LEADING,
             min_pt: float = MIN_PT, max_pt: float = MAX_PT) -> TextFit:
    """The largest size (and its lines) at which `text` fits `box`, breaking words only if needed.

    1. Whole words, sizes from min_pt up.  2. If a word is wider than the box at
    min_pt, break such words at min_pt and try again.  3. If it still does not fit
    (too much text), go below min_pt, down to FLOOR_PT, and say so.
    """
    paras = paragraphs(text)
    if not paras or box.w_pt <= 0 or box.h_pt <= 0:
        return TextFit(0.0, (), (), leading)
    high = max(min(max_pt, box.h_pt), FLOOR_PT)
    segments, broken = segments_of(paras, metrics, None)
    size = largest_size(segments, box, leading, min(min_pt, high), high)
    below = False
    if size is None:
        segments, broken = segments_of(paras, metrics, box.w_pt / min_pt)
        size = largest_size(segments, box, leading, min(min_pt, high), high)
        if size is None:
            below = True
            size = largest_size(segments, box, leading, FLOOR_PT, min(min_pt, high)) or FLOOR_PT
            if layout(segments, size, box, leading) is None:  # a box too small for anything
                segments, broken = segments_of(paras, metrics, box.w_pt / FLOOR_PT)
    size = math.floor(size * 1e4) / 1e4  # the .tex carries 4 decimals; never round up
    lines = layout(segments, size, box, leading) or layout(segments, FLOOR_PT, box, leading) or []
    texts = tuple(" ".join(segment.words[start:end]) for segment, start, end, _ in lines)
    widths = tuple(width * size for _, _, _, width in lines)
    return TextFit(size, texts, widths, leading, broken, below)
