"""Place fitted lines on the page: baselines in mm, one run per line.

Shared by text items and calendar panels. Numbers are computed here, never
in the templates.
"""

from __future__ import annotations

from dataclasses import dataclass

from floatpage.typeset.escape import clean_text
from floatpage.typeset.fit import MIN_PT, Box, TextFit, fit_text
from floatpage.typeset.fonts import FaceKey, TYPEFACES, FontMetrics, metrics_for, style_of

MM_PER_PT = 25.4 / 72  # PostScript points: what PDF readers and `bp` in TeX use
PT_PER_MM = 72 / 25.4


@dataclass(frozen=True)
class Run:
    """One line of text, its baseline's left end at (x_mm, y_mm)."""

    x_mm: float
    y_mm: float
    text: str
    width_pt: float = 0.0


@dataclass(frozen=True)
class RunGroup:
    """Runs sharing a face, size and colour, so the .tex selects the font once."""

    face: FaceKey
    size_pt: float
    color: str  # "#rrggbb"
    runs: tuple[Run, ...]


def face_for(family: str, bold: bool, italic: bool) -> FaceKey:
    return FaceKey(family if family in TYPEFACES else "serif", style_of(bold, italic))


def missing_glyph_warning(label: str, face: FaceKey, missing: list[str]) -> str:
    shown = ", ".join(f"'{ch}' (U+{ord(ch):04X})" for ch in missing[:12])
    more = f" and {len(missing) - 12} more" if len(missing) > 12 else ""
    return (f"{label}: the font {face.label} has no glyph for {shown}{more}; they are left out "
            f"(pick another font for this item, or remove those characters)")


def printable_text(text: str, metrics: FontMetrics) -> tuple[str, list[str]]:
    """The cleaned text without characters the font lacks, and those characters."""
    cleaned = clean_text(text)
    missing = metrics.missing_chars(cleaned)
    # Drop everything the font lacks, warned about or invisible, so HarfBuzz measures
    # exactly what LuaLaTeX (which drops such characters) prints.
    return "".join(ch for ch in cleaned if not metrics.lacks(ch)), missing


def place_lines(fit: TextFit, metrics: FontMetrics, left_mm: float, top_mm: float,
                h_mm: float, *, widths_mm: float | None = None, centre: bool = False) -> tuple[Run, ...]:
    """Runs for fitted lines: block centred vertically in the box, lines left-aligned
    (or centred in a box `widths_mm` wide)."""
    size = fit.font_pt
    spare_mm = max(0.0, h_mm - fit.height_pt * MM_PER_PT) / 2
    first_baseline_mm = top_mm + spare_mm + size * fit.top_em * MM_PER_PT
    runs = []
    offsets = fit.line_offsets_pt or (0.0,) * len(fit.lines)
    for index, (line, width_pt, offset_pt) in enumerate(zip(fit.lines, fit.line_widths_pt,
                                                            offsets)):
        x_mm = left_mm + offset_pt * MM_PER_PT
        if centre and widths_mm is not None:
            x_mm += max(0.0, widths_mm - width_pt * MM_PER_PT) / 2
        y_mm = first_baseline_mm + index * fit.leading * size * MM_PER_PT
        runs.append(Run(x_mm, y_mm, line, width_pt))
    return tuple(runs)


def fit_in_box(text: str, face: FaceKey, w_mm: float, h_mm: float) -> tuple[TextFit, list[str]]:
    """Fit cleaned text in a w x h mm box with the face's real metrics; also the missing chars."""
    metrics = metrics_for(face)
    printable, missing = printable_text(text, metrics)
    return fit_text(printable, Box(w_mm * PT_PER_MM, h_mm * PT_PER_MM), metrics), missing


def fit_warnings(label: str, face: FaceKey, fit: TextFit, missing: list[str]) -> list[str]:
    warnings = []
    if missing:
        warnings.append(missing_glyph_warning(label, face, missing))
    if fit.below_minimum and not fit.lines:
        warnings.append(f"{label}: the box is too small to hold this text at any size "
                        f"(enlarge the box or shorten the text)")
    elif fit.below_minimum:
        warnings.append(f"{label}: the text only fits at {fit.font_pt:.1f} pt, below the "
                        f"{MIN_PT:g} pt minimum (enlarge the box or shorten the text)")
    if fit.broken_words:
        words = ", ".join(f'"{w[:30]}"' for w in fit.broken_words[:3])
        warnings.append(f"{label}: {words} did not fit the box's width and "
                        f"{'was' if len(fit.broken_words) == 1 else 'were'} broken across lines "
                        f"(widen the box to keep words whole)")
    return warnings
