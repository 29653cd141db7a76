"""Place fitted lines on the page: baselines in mm, one run per line.

Shared by text items and calendar panels. Numbers are computed here, never
in the templates.
"""

from __future__ import annotations

import unicodedata
from dataclasses import dataclass

from pylatex.utils import NoEscape

from floatpage.model.key_specs import alignment_share
from floatpage.typeset.bidi import base_direction, line_markup
from floatpage.typeset.escape import clean_text, escape_latex
from floatpage.typeset.fit import MIN_PT, Box, TextFit, fit_text
from floatpage.typeset.fonts import (
    FaceKey, TYPEFACES, FontMetrics, chain_metrics_for, fallback_index, metrics_for, style_of)

MM_PER_PT = 25.4 / 72  # PostScript points: what PDF readers and `bp` in TeX use
PT_PER_MM = 72 / 25.4


@dataclass(frozen=True)
class Run:
    """One line of text, its baseline's left end at (x_mm, y_mm), or its right end if
    ``flush_right``.  A line set against the box's right edge is placed by that end: where
    HarfBuzz shapes it a little wider than the fitter measured (Thaana, Arabic: up to 3 pt),
    it then grows into the box rather than out of it."""

    x_mm: float
    y_mm: float
    text: str
    width_pt: float = 0.0
    direction: str = "L"  # the paragraph's: "R" when its first strong letter is right to left
    flush_right: bool = False

    @property
    def tex(self) -> NoEscape:
        """The line as TeX: escaped, its right-to-left runs marked for LuaTeX to reorder."""
        return line_markup(self.text, escape_latex, self.direction)


@dataclass(frozen=True)
class RunGroup:
    """Runs sharing a face, size and colour, so the .tex selects the font once."""

    face: FaceKey
    size_pt: float
    color: str  # "#rrggbb"
    runs: tuple[Run, ...]
    # merge (typeset.batch): the face is a font loaded at size_pt, scaled by this to its size
    scale: float | None = None


def face_for(family: str, bold: bool, italic: bool) -> FaceKey:
    return FaceKey(family if family in TYPEFACES else "serif", style_of(bold, italic))


def missing_glyph_warning(label: str, face: FaceKey, missing: list[str]) -> str:
    """Every character no font could set, each with its code point: the user can find them."""
    shown = ", ".join(f"'{ch}' (U+{ord(ch):04X})" for ch in missing)
    return (f"{label}: no installed font (neither {face.label} nor its fallbacks) has a glyph for "
            f"{shown}; they are left out (remove those characters, or install a font "
            f"that has them)")


RTL_CLASSES = ("R", "AL")
# Invisible characters that only steer breaking or direction (bidi.py sets directions): left
# out, since HarfBuzz gives them no width while LuaTeX's node mode prints a font's glyph.
STEERING = frozenset("\u200b\u200e\u200f\u2060\ufeff\u202a\u202b\u202c\u202d\u202e"
                     "\u2066\u2067\u2068\u2069\u00ad")


def is_variation_selector(char: str) -> bool:
    """U+FE00-FE0F and U+E0100-E01EF ask for a form of the character before them (emoji or
    text style, a CJK variant); a font without that form shows the plain one.  A selector no
    font has is left out silently: kept, it fell into the main face's run apart from its
    base and printed as a box."""
    code = ord(char)
    return 0xFE00 <= code <= 0xFE0F or 0xE0100 <= code <= 0xE01EF


def rich_text(text: str, face: FaceKey) -> tuple[str, FaceKey, list[str]]:
    """What will be printed, the face (with the fallback chain it needs), what cannot be.

    A character the face lacks goes to the first fallback font that has it; a space
    no font has becomes a plain space; an invisible format character no font has is left
    out silently, and so is a variation selector no font has (the plain form shows); any
    other character no font has is left out and reported.
    Base letters are kept whatever their marks do. Marks, right-to-left letters and
    fallback text switch the face to HarfBuzz mode, which shapes them and writes a
    text layer that gives back what was typed.
    """
    cleaned = clean_text(text)
    primary = metrics_for(face.plain)
    kept: list[str] = []
    missing: dict[str, None] = {}
    fallbacks: set[int] = set()
    harf = False
    for char in cleaned:
        if char in STEERING:  # HarfBuzz skips them, LuaTeX's node mode would print the glyph
            continue
        if char == "\n" or primary.has_char(char):
            kept.append(char)
            harf = harf or unicodedata.category(char).startswith("M") \
                or unicodedata.bidirectional(char) in RTL_CLASSES
            continue
        index = fallback_index(face.chain_key, char)
        category = unicodedata.category(char)
        if index is not None:
            fallbacks.add(index)
            kept.append(char)
        elif category == "Zs":
            kept.append(" ")
        elif category != "Cf" and not is_variation_selector(char):
            missing[char] = None
    chained = FaceKey(face.family, face.style, tuple(sorted(fallbacks)),
                      harf or bool(fallbacks))
    return "".join(kept), chained, list(missing)


def printable_text(text: str, metrics: FontMetrics) -> tuple[str, list[str]]:
    """The cleaned text without characters the font lacks, and those characters (no fallback)."""
    cleaned = clean_text(text)
    missing = metrics.missing_chars(cleaned)
    return "".join(ch for ch in cleaned if not metrics.lacks(ch)), missing


def place_lines(fit: TextFit, metrics: FontMetrics, left_mm: float, top_mm: float,
                h_mm: float, *, widths_mm: float | None = None, align: str = "start",
                block_em: tuple[float, float] | None = None) -> tuple[Run, ...]:
    """Runs for fitted lines: block centred vertically in the box, lines at the start of the
    text's direction, or set as ``align`` says (model.key_specs.alignment_share) in a box
    ``widths_mm`` wide.

    The block centred reaches from ``block_em``'s first (em above the first baseline) to its
    second (em below the last), by default the lines' own ink.  Texts of one role pass the
    role's (typeset.roles.role_blocks), so an accent on a capital ("Túlipas") no longer
    lowers one tag's baselines below its neighbours'; the text's own ink still stays inside
    its box."""
    direction = base_direction("".join(fit.lines))
    share = alignment_share(align, direction) if widths_mm is not None else 0.0
    size = fit.font_pt
    top_em, bottom_em = block_em or (fit.top_em, fit.bottom_em)
    between_mm = (len(fit.lines) - 1) * fit.leading * size * MM_PER_PT
    block_mm = (top_em + bottom_em) * size * MM_PER_PT + between_mm
    first_baseline_mm = top_mm + max(0.0, h_mm - block_mm) / 2 + size * top_em * MM_PER_PT
    lowest = top_mm + h_mm - size * fit.bottom_em * MM_PER_PT - between_mm  # its ink inside
    first_baseline_mm = max(min(first_baseline_mm, lowest), top_mm + size * fit.top_em * MM_PER_PT)
    runs = []
    offsets = fit.line_offsets_pt or (0.0,) * len(fit.lines)
    for index, (line, width_pt, offset_pt) in enumerate(zip(fit.lines, fit.line_widths_pt,
                                                            offsets)):
        x_mm = left_mm + offset_pt * MM_PER_PT
        y_mm = first_baseline_mm + index * fit.leading * size * MM_PER_PT
        if share == 1.0 and width_pt * MM_PER_PT <= widths_mm:
            runs.append(Run(left_mm + widths_mm, y_mm, line, width_pt, direction, True))
            continue
        if share:
            x_mm += max(0.0, widths_mm - width_pt * MM_PER_PT) * share
        runs.append(Run(x_mm, y_mm, line, width_pt, direction))
    return tuple(runs)


def fit_in_box(text: str, face: FaceKey, w_mm: float, h_mm: float, *,
               max_pt: float | None = None) -> tuple[TextFit, list[str], FaceKey]:
    """Fit text in a w x h mm box with the fonts that will set it, at most ``max_pt`` (a
    role's or the user's size: exactly that where it fits); also the missing chars and the
    face (with its fallback chain) to set it in."""
    printable, chained, missing = rich_text(text, face)
    metrics = chain_metrics_for(chained)
    box = Box(w_mm * PT_PER_MM, h_mm * PT_PER_MM)
    if max_pt is None:
        return fit_text(printable, box, metrics), missing, chained
    return fit_text(printable, box, metrics, max_pt=max_pt), missing, chained


# Ends every warning of a text that does not fit its box (`floatpage merge` fails the record).
DOES_NOT_FIT_HINT = "(enlarge the box or shorten the text)"


def fit_warnings(label: str, face: FaceKey, fit: TextFit, missing: list[str]) -> list[str]:
    warnings = []
    if missing:
        warnings.append(missing_glyph_warning(label, face, missing))
    if fit.below_minimum and not fit.lines:
        warnings.append(f"{label}: the box is too small to hold this text at any size "
                        f"{DOES_NOT_FIT_HINT}")
    elif fit.below_minimum:
        warnings.append(f"{label}: the text only fits at {fit.font_pt:.1f} pt, below the "
                        f"{MIN_PT:g} pt minimum {DOES_NOT_FIT_HINT}")
    if fit.broken_words:
        words = ", ".join(f'"{w[:30]}"' for w in fit.broken_words[:3])
        warnings.append(f"{label}: {words} did not fit the box's width and "
                        f"{'was' if len(fit.broken_words) == 1 else 'were'} broken across lines "
                        f"(widen the box to keep words whole)")
    return warnings
