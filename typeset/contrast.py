"""Text that is hard to read against what lies behind it: black words on a charcoal page, a
caption over the dark half of a photo.

Nothing in the layout looks at colour, so a user who puts a dark background behind the
default black text got a PDF of near-invisible words without a word said.  This reads the
placed page as it will print: under each line of each text (and each calendar panel) it
samples what is painted beneath, in paint order (paper, the page's background, then every
block and picture below the text, a block's opacity blended, a picture's own pixels), and
compares the text's colour with it by the WCAG 2 contrast ratio.  A text whose median
contrast is below what WCAG's level AA asks (4.5:1, or 3:1 for large text: 18 pt, or 14 pt
bold) is named in a note, as a blocky picture is: the user's colours are a choice, so it is
said, never changed.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from statistics import median

from floatpage.typeset.placed import (
    PlacedBlock, PlacedCalendar, PlacedDocument, PlacedPicture, PlacedText,
)
from floatpage.typeset.text_layout import MM_PER_PT

NORMAL_RATIO, LARGE_RATIO = 4.5, 3.0  # WCAG 2, level AA
LARGE_PT, LARGE_BOLD_PT = 18.0, 14.0
SAMPLES_PER_LINE = 9
MAX_LINES = 12  # sampled per text, spread over its lines
THUMB_PX = 256  # a picture is read at this size: enough for the colour behind a line

RGB = tuple[float, float, float]


def hex_rgb(colour: str) -> RGB:
    return tuple(int(colour[i:i + 2], 16) / 255 for i in (1, 3, 5))  # type: ignore[return-value]


def luminance(rgb: RGB) -> float:
    """WCAG 2's relative luminance of an sRGB colour (channels 0-1)."""
    def linear(c: float) -> float:
        return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4
    r, g, b = (linear(c) for c in rgb)
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def contrast(a: RGB, b: RGB) -> float:
    """WCAG 2's contrast ratio, 1 (none) to 21 (black on white)."""
    high, low = sorted((luminance(a), luminance(b)), reverse=True)
    return (high + 0.05) / (low + 0.05)


@lru_cache(maxsize=64)
def thumbnail(source: Path) -> object | None:
    """The picture upright, as RGBA, at most THUMB_PX a side; None where it cannot be read."""
    from PIL import Image, ImageOps

    try:
        with Image.open(source) as opened:
            opened.seek(0)
            image = ImageOps.exif_transpose(opened).convert("RGBA")
    except Exception:  # a PDF, or a file the render itself will name
        return None
    image.thumbnail((THUMB_PX, THUMB_PX))
    return image


def blend(top: RGB, under: RGB, alpha: float) -> RGB:
    return tuple(t * alpha + u * (1 - alpha) for t, u in zip(top, under))  # type: ignore


def inside(x: float, y: float, left: float, top: float, right: float, bottom: float) -> bool:
    return left <= x <= right and top <= y <= bottom


def colour_at(layers: list, x: float, y: float) -> RGB | None:
    """What is painted at (x, y) mm by ``layers`` (in paint order) on white paper; None where
    a layer's colour cannot be known (a PDF picture)."""
    colour: RGB = (1.0, 1.0, 1.0)
    for layer in layers:
        if isinstance(layer, PlacedBlock):
            r = layer.rect
            if inside(x, y, r.left_mm, r.top_mm, r.right_mm, r.bottom_mm):
                colour = blend(hex_rgb(layer.color), colour, layer.opacity)
        elif isinstance(layer, PlacedPicture):
            clip = layer.clip
            if clip is not None and not inside(x, y, clip.left_mm, clip.top_mm, clip.right_mm,
                                               clip.bottom_mm):
                continue
            if not inside(x, y, layer.left_mm, layer.top_mm, layer.left_mm + layer.w_mm,
                          layer.top_mm + layer.h_mm):
                continue
            image = thumbnail(layer.plan.source)
            if image is None:
                return None
            w, h = image.size
            u = min(w - 1, int((x - layer.left_mm) / layer.w_mm * w))
            v = min(h - 1, int((y - layer.top_mm) / layer.h_mm * h))
            *rgb, alpha = (c / 255 for c in image.getpixel((u, v)))
            colour = blend(tuple(rgb), colour, alpha)  # type: ignore[arg-type]
    return colour


@dataclass(frozen=True)
class Reading:
    """A text's colour, the median colour behind it and their contrast; and the sampled lines
    (numbered from 1 among ``lines``) whose own median contrast is below what is needed, with
    the colour behind the first of them."""

    text: RGB
    behind: RGB
    ratio: float
    needed: float
    faint_lines: tuple[int, ...] = ()
    lines: int = 0
    behind_faint: RGB | None = None


def sample_points(placed) -> list[tuple[float, float, float, str, bool, int]]:
    """(x, y, size pt, colour, bold, line) under the text's lines: along each line, at its
    x-height; ``line`` numbers the sampled lines in reading order, from 1."""
    points = []
    line = 0
    for group in placed.groups:
        runs = group.runs
        step = max(1, -(-len(runs) // MAX_LINES))
        bold = "bold" in group.face.style
        for run in runs[::step]:
            line += 1
            width = run.width_pt * MM_PER_PT
            left = run.x_mm - width if run.flush_right else run.x_mm
            y = run.y_mm - 0.3 * group.size_pt * MM_PER_PT  # within the letters, above the baseline
            for index in range(SAMPLES_PER_LINE):
                x = left + width * (index + 0.5) / SAMPLES_PER_LINE
                points.append((x, y, group.size_pt, group.color, bold, line))
    return points


def reading(placed, layers: list) -> Reading | None:
    """The text's contrast as a whole (the median of its samples) and line by line: a text
    half over a dark band passed as a whole, its cream half the median, while its last line
    was unreadable in print (the flyer turned from A4 to DL: the prices 2.7 mm into the dark
    footer, user-walk-9)."""
    points = sample_points(placed)
    behind = [(colour_at(layers, x, y), size, colour, bold, line)
              for x, y, size, colour, bold, line in points]
    behind = [entry for entry in behind if entry[0] is not None]
    if not behind:
        return None
    ratios = sorted(((contrast(hex_rgb(colour), under), under, colour, size, bold, line)
                     for under, size, colour, bold, line in behind), key=lambda entry: entry[0])
    ratio, under, colour, size, bold, _ = ratios[len(ratios) // 2]
    large = any(s >= LARGE_PT or (b and s >= LARGE_BOLD_PT) for _, _, _, s, b, _ in ratios)
    needed = LARGE_RATIO if large else NORMAL_RATIO
    by_line: dict[int, list] = {}
    for entry in ratios:
        by_line.setdefault(entry[5], []).append(entry)
    faint = []
    for line, entries in sorted(by_line.items()):
        if median(entry[0] for entry in entries) < needed:
            faint.append((line, entries[len(entries) // 2][1]))
    return Reading(hex_rgb(colour), under, median(r[0] for r in ratios), needed,
                   tuple(line for line, _ in faint), max(by_line),
                   faint[0][1] if faint else None)


def hex_of(rgb: RGB) -> str:
    return "#" + "".join(f"{round(c * 255):02x}" for c in rgb)


def contrast_notes(document: PlacedDocument) -> list[str]:
    """A note for each text or calendar too faint against what lies behind it."""
    notes = []
    for page in document.pages:
        for index, placed in enumerate(page.items):
            if not isinstance(placed, (PlacedText, PlacedCalendar)):
                continue
            found = reading(placed, page.background + page.items[:index])
            if found is None or not found.faint_lines and found.ratio >= found.needed:
                continue
            if found.ratio >= found.needed:  # readable as a whole, not on every line
                noun = "text" if isinstance(placed, PlacedText) else "days and names"
                notes.append(f"{placed.label}: {lines_named(found)} of its {noun} "
                             f"({hex_of(found.text)}) lies over {hex_of(found.behind_faint)}, "
                             f"where the contrast is below the {found.needed:g}:1 that text "
                             "of its size needs to read easily (WCAG AA), while the rest "
                             f"reads on {hex_of(found.behind)}: move it clear of what lies "
                             "behind that part, or change its colour")
                continue
            what = ("its text ({}) with {} behind it" if isinstance(placed, PlacedText)
                    else "its days and names ({}) with {} behind them")
            notes.append(f"{placed.label}: the contrast of "
                         f"{what.format(hex_of(found.text), hex_of(found.behind))} is "
                         f"{found.ratio:.1f}:1, below the {found.needed:g}:1 that text of its "
                         "size needs to read easily (WCAG AA): change its colour or what lies "
                         "behind it")
    return notes


def lines_named(found: Reading) -> str:
    """"line 3 of 3", "lines 1 and 2 of 5", "3 of its 12 sampled lines"."""
    faint = found.faint_lines
    if found.lines > MAX_LINES - 1 or len(faint) > 2:
        return f"{len(faint)} of {found.lines} sampled lines"
    if len(faint) == 1:
        return f"line {faint[0]} of {found.lines}"
    return f"lines {faint[0]} and {faint[1]} of {found.lines}"
