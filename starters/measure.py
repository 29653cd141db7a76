"""Size short centred texts (titles, subtitles, footers, greetings) to their words.

The typesetter fills a text box and sets its lines left-aligned (paper, section 5). A title
in a box wider than its words therefore hugs the box's left edge. Narrowing the box to the
widest line the typesetter will set centres the text wherever the box is centred. The lines
come from the typesetter's own fitting (same font files, same HarfBuzz shaping), and a box
narrowed to its widest line still fits those lines at the same size.

Captions and price tags keep their picture's width: set flush left under it, their left edge
is the picture's, a line the eye follows down a column (and the one the alignment guides were
measured with); hugged and centred, each tag's edges fall a few mm from its neighbours'.
"""

from __future__ import annotations

from floatpage.model.document import TextItem

MM_PER_PT = 25.4 / 72
SLACK = 1.01  # a hair wider than the words, so rounding never forces another line break


def widest_line_mm(item: TextItem) -> float | None:
    """Width of the widest line the typesetter sets for `item` in its box, in mm.

    None when the fonts cannot be read (no TeX fonts installed): the caller keeps its box.
    """
    from floatpage.typeset.text_layout import face_for, fit_in_box

    try:
        fitted = fit_in_box(item.text, face_for(item.font, item.bold, item.italic), item.w, item.h)
    except Exception:  # noqa: BLE001 - failing to load fonts only means "don't measure"
        return None
    # Unpacked outside the try: a change of fit_in_box's result must fail loudly here, not
    # quietly leave every title left-aligned in a box wider than its words (as it once did).
    fit = fitted[0]
    if not fit.line_widths_pt:
        return None
    return max(fit.line_widths_pt) * MM_PER_PT * SLACK


def hug(item: TextItem, max_w: float | None = None) -> TextItem:
    """Narrow `item` about its centre to the lines it will show (its box is the widest allowed)."""
    if max_w is not None:
        item.w = max_w
    width = widest_line_mm(item)
    if width is not None:
        item.w = min(width, item.w)
    return item
