"""Fit a text to its box: the largest font size at which greedy line breaking fits it.

Pure: `fit_text(text, box, metrics) -> TextFit`. Lines are decided here and
emitted one by one, so LaTeX never re-breaks them.

Two boxes bound every glyph, and both must stay inside the item's rectangle:
- the em box PDF readers report (the advance width, from the descent below the
  baseline to one em above that): a line is one em tall and lines are `leading`
  em apart, so n lines are s * (1 + (n - 1) * leading) tall;
- the ink: an accent on a capital rises above the em box, an italic f leans out
  of its advance. The first line's ink may raise the top, the last line's the
  bottom, and each line's ends its width.
The fill is measured on the em boxes, so it falls below 1 only where ink sticks out.

Feasibility is monotone in the size for the em boxes (a larger size leaves a
narrower measure in em, so greedy breaking needs as many lines or more while
the box allows fewer); ink can break that in rare cases, and bisection then
still returns a size that fits.
"""

from __future__ import annotations

import math
from bisect import bisect_right
from dataclasses import dataclass
from typing import Protocol

from floatpage.typeset.break_points import clusters, pieces

LEADING = 1.2   # baseline distance / font size
MIN_PT = 6.0    # the smallest size we call legible; below it we warn
MAX_PT = 1000.0
FLOOR_PT = 0.25  # never go below this, even for text that does not fit at MIN_PT
PRECISION = 1e-6  # relative; the binding direction ends up this close to full


class Metrics(Protocol):
    space_em: float
    descent_em: float  # of the em box, below the baseline

    def advance_em(self, word: str) -> float: ...

    def ink_em(self, word: str): ...  # -> object with left, right, top, bottom (em)


@dataclass(frozen=True)
class Box:
    """A box's inner size in PostScript points (bp)."""

    w_pt: float
    h_pt: float


@dataclass(frozen=True)
class TextFit:
    font_pt: float
    lines: tuple[str, ...]
    line_widths_pt: tuple[float, ...]   # advance widths
    leading: float = LEADING
    broken_words: tuple[str, ...] = ()  # words split across lines to avoid overflowing
    below_minimum: bool = False         # the text only fits below MIN_PT
    top_em: float = 0.75                # first baseline below the block's top
    bottom_em: float = 0.25             # block's bottom below the last baseline
    line_offsets_pt: tuple[float, ...] = ()  # each line's origin right of the box's left edge

    @property
    def height_pt(self) -> float:
        if not self.lines:
            return 0.0
        return self.font_pt * (self.top_em + (len(self.lines) - 1) * self.leading + self.bottom_em)


@dataclass(frozen=True)
class _Line:
    text: str
    width: float   # advance width, em
    left: float    # ink left of the origin (<= 0 when it leans out), em
    right: float   # ink (or advance) right end, em
    top: float     # ink above the baseline, em
    bottom: float  # ink below the baseline, em


class _Segment:
    """Words that must start on a fresh line, with prefix sums for O(log n) greedy steps.
    A word with no glue before it (a CJK character after another) joins its line's text
    without a space."""

    __slots__ = ("words", "widths", "glues", "prefix", "inks")

    def __init__(self, words: list[str], widths: list[float], glues: list[float], inks: list):
        self.words, self.widths, self.glues, self.inks = words, widths, glues, inks
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

    def line(self, start: int, end: int, width: float) -> _Line:
        if start == end:
            return _Line("", 0.0, 0.0, 0.0, 0.0, 0.0)
        inks = self.inks[start:end]
        last_origin = width - self.widths[end - 1]
        text = self.words[start] + "".join(
            (" " if self.glues[index] else "") + self.words[index] for index in range(start + 1, end))
        return _Line(text, width, min(0.0, inks[0].left),
                     max(width, last_origin + inks[-1].right),
                     max(ink.top for ink in inks), max(ink.bottom for ink in inks))


class _EmInk:
    """Ink for metrics that know none: the em box itself."""

    def __init__(self, width: float, descent: float):
        self.left, self.right, self.top, self.bottom = 0.0, width, 1 - descent, descent


def paragraphs(text: str) -> list[list[tuple[str, bool]]]:
    """The pieces of each line of `text` (`break_points.pieces`: a word, or a CJK character,
    and whether it is joined to the one before); a newline always breaks."""
    text = text.strip(" \n")
    if not text:
        return []
    return [pieces(line) for line in text.split("\n")]


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


def segments_of(paras: list[list[tuple[str, bool]]], metrics: Metrics, break_limit_em: float | None
                ) -> tuple[list[_Segment], tuple[str, ...]]:
    """Build segments; with a limit, words wider than it are broken and each piece gets its line."""
    space = metrics.space_em
    descent = getattr(metrics, "descent_em", 0.25)
    ink_of = getattr(metrics, "ink_em", None)
    segments: list[list[tuple[str, bool]]] = []  # (word, joined to the one before: no space)
    broken = []
    for para in paras:
        current: list[tuple[str, bool]] = []
        for word, joined in para:
            if break_limit_em is not None and metrics.advance_em(word) > break_limit_em:
                parts = break_word(word, break_limit_em, metrics)
                if len(parts) > 1:
                    broken.append(word)
                    current.append((parts[0], joined))
                    segments.append(current)
                    segments.extend([(part, False)] for part in parts[1:-1])
                    current = [(parts[-1], False)]
                    continue
            current.append((word, joined))
        segments.append(current)
    built = []
    for pairs in segments:
        words = [word for word, _ in pairs]
        widths = [metrics.advance_em(word) for word in words]
        inks = [ink_of(word) if ink_of else _EmInk(width, descent)
                for word, width in zip(words, widths)]
        glues = [0.0] + [0.0 if joined else space for _, joined in pairs[1:]]
        built.append(_Segment(words, widths, glues, inks))
    return built, tuple(broken)


@dataclass(frozen=True)
class _Layout:
    lines: list[_Line]
    top: float     # em above the first baseline
    bottom: float  # em below the last baseline


def layout(segments: list[_Segment], size_pt: float, box: Box, leading: float,
           descent: float = 0.25) -> _Layout | None:
    """All lines at `size_pt`, or None if their em boxes or their ink do not fit the box."""
    limit = box.w_pt / size_pt
    height = box.h_pt / size_pt
    max_lines = (height - 1) / leading + 1 + 1e-9  # the em boxes alone
    lines: list[_Line] = []
    for segment in segments:
        found = segment.breaks(limit)
        if found is None:
            return None
        for start, end, width in found:
            line = segment.line(start, end, width)
            if line.right - line.left > limit * (1 + 1e-12):
                return None  # ink leans out of the box's side
            lines.append(line)
        if len(lines) > max_lines:
            return None
    top = max(1 - descent, lines[0].top)
    bottom = max(descent, lines[-1].bottom)
    if top + (len(lines) - 1) * leading + bottom > height * (1 + 1e-12):
        return None
    return _Layout(lines, top, bottom)


def largest_size(segments, box: Box, leading: float, descent: float, low: float, high: float
                 ) -> float | None:
    """Largest size in [low, high] at which the segments fit, or None if not even `low` does."""
    if layout(segments, high, box, leading, descent) is not None:
        return high
    if layout(segments, low, box, leading, descent) is None:
        return None
    while high / low > 1 + PRECISION:
        middle = math.sqrt(low * high)
        if layout(segments, middle, box, leading, descent) is None:
            high = middle
        else:
            low = middle
    return low


LONELY = 0.4  # a last line shorter than this share of the longest line looks left behind
HEIGHT_BINDS = 0.99  # the lines fill this share of the box's height: the width has room
EVEN_MAX_WORDS = 120  # re-break paragraphs up to this long (the search is quadratic)


def even_breaks(segment: _Segment, limit: float, count: int) -> list[tuple[int, int, float]] | None:
    """`count` lines within `limit` em whose slack is as even as can be (least sum of squared
    slack, the last line included), or None."""
    words = len(segment.widths)
    prefix, glues = segment.prefix, segment.glues
    inf = float("inf")
    best = [[inf] * (words + 1) for _ in range(count + 1)]
    back = [[0] * (words + 1) for _ in range(count + 1)]
    best[0][0] = 0.0
    for line in range(1, count + 1):
        for end in range(line, words + 1):
            for start in range(end - 1, line - 2, -1):
                width = prefix[end] - prefix[start] - glues[start]
                if width > limit:
                    break
                cost = best[line - 1][start] + (limit - width) ** 2
                if cost < best[line][end]:
                    best[line][end], back[line][end] = cost, start
    if best[count][words] == inf:
        return None
    out, end = [], words
    for line in range(count, 0, -1):
        start = back[line][end]
        out.append((start, end, prefix[end] - prefix[start] - glues[start]))
        end = start
    return out[::-1]


def without_lonely_last_line(found: _Layout, segments, size: float, box: Box, leading: float,
                             descent: float) -> _Layout:
    """The same lines at the same size, re-broken as evenly as they go when greedy breaking
    left a paragraph's last line nearly empty ("Wishing you a year / full of sunshine, /
    flowers and good / friends." becomes "... / flowers and / good friends."), as a
    typesetter re-breaks by hand.  Box, size and line count do not change.  Only where the
    lines fill the box's height: where its width binds the size, evening the lines out would
    leave the box's sides empty instead."""
    height = (found.top + (len(found.lines) - 1) * leading + found.bottom) * size
    if height < HEIGHT_BINDS * box.h_pt:
        return found
    limit = box.w_pt / size
    lines: list[_Line] = []
    changed = False
    for segment in segments:
        greedy = segment.breaks(limit)
        if greedy is None:
            return found
        widest = max(width for _, _, width in greedy)
        if (len(greedy) >= 2 and greedy[-1][2] < LONELY * widest
                and len(segment.widths) <= EVEN_MAX_WORDS):
            even = even_breaks(segment, limit, len(greedy))
            if even is not None and even != greedy:
                greedy, changed = even, True
        for start, end, width in greedy:
            line = segment.line(start, end, width)
            if line.right - line.left > limit * (1 + 1e-12):
                return found  # ink would lean out of the box's side
            lines.append(line)
    if not changed or len(lines) != len(found.lines):
        return found
    top = max(1 - descent, lines[0].top)
    bottom = max(descent, lines[-1].bottom)
    if top + (len(lines) - 1) * leading + bottom > box.h_pt / size * (1 + 1e-12):
        return found
    return _Layout(lines, top, bottom)


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
    descent = getattr(metrics, "descent_em", 0.25)
    high = max(min(max_pt, box.h_pt), FLOOR_PT)
    low = min(min_pt, high)
    segments, broken = segments_of(paras, metrics, None)
    size = largest_size(segments, box, leading, descent, low, high)
    below = False
    if size is None:
        segments, broken = segments_of(paras, metrics, box.w_pt / min_pt)
        size = largest_size(segments, box, leading, descent, low, high)
        if size is None:
            below = True
            size = largest_size(segments, box, leading, descent, FLOOR_PT, low)
            if size is None:  # a box too small for anything: break at the floor size
                segments, broken = segments_of(paras, metrics, box.w_pt / FLOOR_PT)
                size = largest_size(segments, box, leading, descent, FLOOR_PT, low) or FLOOR_PT
    size = math.floor(size * 1e4) / 1e4  # the .tex carries 4 decimals; never round up
    found = layout(segments, size, box, leading, descent)
    if found is None:  # nothing fits even at the floor: report it, print nothing
        return TextFit(size, (), (), leading, broken, True)
    found = without_lonely_last_line(found, segments, size, box, leading, descent)
    return TextFit(size, tuple(line.text for line in found.lines),
                   tuple(line.width * size for line in found.lines), leading, broken, below,
                   found.top, found.bottom, tuple(-line.left * size for line in found.lines))
