"""One size per role: the texts of one role ("price", "caption", "month-name") share a size.

Each text box on its own is fitted to the largest size its box holds (typeset.fit), so three
prices side by side came out at 11.2, 13.7 and 9.8 pt, which reads as a mistake.  A designer
sets one size per paragraph style: the largest at which every box of that role still fits,
which is the smallest of their own fitted sizes (feasibility is monotone in the size).

The role spans the whole document, as a paragraph style does in a layout program: an album's
captions match from page to page and a calendar's month names from month to month (one
`floatpage merge` record is its own document).  Two kinds of text do not pull the others down:
one with its own size (`size_pt`), which keeps it, and one that only fits by breaking a word
or going below the legible minimum; that one warns, and is set at the role's size or smaller,
instead of shrinking every text of its role with it.
"""

from __future__ import annotations

from floatpage.model.document import Project, TextItem
from floatpage.typeset.text_layout import face_for, fit_in_box


def role_sizes(project: Project) -> dict[str, float]:
    """The size, in points, each role of the document is set at (only roles with a text that
    sets it)."""
    sizes: dict[str, float] = {}
    for page in project.pages:
        for item in page.items:
            if not isinstance(item, TextItem) or not item.role or item.size_pt:
                continue
            fit, _, _ = fit_in_box(item.text, face_for(item.font, item.bold, item.italic),
                                   item.w, item.h)
            if not fit.lines or fit.below_minimum or fit.broken_words:
                continue
            sizes[item.role] = min(sizes.get(item.role, fit.font_pt), fit.font_pt)
    return sizes


def size_for(item: TextItem, sizes: dict[str, float]) -> float | None:
    """The size a text is set at, at most (None: fitted to its own box)."""
    if item.size_pt:
        return float(item.size_pt)
    return sizes.get(item.role) if item.role else None
