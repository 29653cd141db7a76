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

One size is not yet one line: each box centred its own ink, so a tag whose first word has
an accented capital ("Túlipas") stood 0.4 mm lower than its neighbours in a row of one height.
The texts of a role centre one block instead (`RoleFits.block_of`): as tall above the first
baseline and below the last as the role's tallest ink, so boxes of one height and lines of
one count put their baselines on one line.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from floatpage.model.document import Project, TextItem
from floatpage.typeset.fit import TextFit
from floatpage.typeset.fonts import FaceKey
from floatpage.typeset.text_layout import face_for, fit_in_box

Fitted = tuple[TextFit, list[str], FaceKey]  # the fit, the characters no font has, the face


def fit_item(item: TextItem, sizes: dict[str, float]) -> Fitted:
    """The text fitted to its box, at most at its own or its role's size."""
    return fit_in_box(item.text, face_for(item.font, item.bold, item.italic), item.w, item.h,
                      max_pt=size_for(item, sizes))


def size_for(item: TextItem, sizes: dict[str, float]) -> float | None:
    """The size a text is set at, at most (None: fitted to its own box)."""
    if item.size_pt:
        return float(item.size_pt)
    return sizes.get(item.role) if item.role else None


def role_sizes(project: Project) -> dict[str, float]:
    """The size, in points, each role of the document is set at (only roles with a text that
    sets it)."""
    sizes: dict[str, float] = {}
    for page in project.pages:
        for item in page.items:
            if not isinstance(item, TextItem) or not item.role or item.size_pt:
                continue
            fit, _, _ = fit_item(item, {})
            if not fit.lines or fit.below_minimum or fit.broken_words:
                continue
            sizes[item.role] = min(sizes.get(item.role, fit.font_pt), fit.font_pt)
    return sizes


@dataclass
class RoleFits:
    """Every text of a document fitted, with its role's size and its role's block."""

    sizes: dict[str, float]
    fits: dict[int, Fitted] = field(default_factory=dict)  # by id() of the item
    blocks: dict[str, tuple[float, float]] = field(default_factory=dict)  # role -> em

    @classmethod
    def of(cls, project: Project) -> "RoleFits":
        found = cls(role_sizes(project))
        for page in project.pages:
            for item in page.items:
                if isinstance(item, TextItem):
                    fitted = found.fits[id(item)] = fit_item(item, found.sizes)
                    fit = fitted[0]
                    if found.sets_role_size(item, fit):
                        top, bottom = found.blocks.get(item.role, (0.0, 0.0))
                        found.blocks[item.role] = (max(top, fit.top_em),
                                                   max(bottom, fit.bottom_em))
        return found

    def sets_role_size(self, item: TextItem, fit: TextFit) -> bool:
        """Whether the text is set at its role's size (not by hand, nor smaller)."""
        size = self.sizes.get(item.role) if item.role and not item.size_pt else None
        return bool(fit.lines) and size is not None and abs(fit.font_pt - size) < 1e-6

    def fit_of(self, item: TextItem) -> Fitted:
        return self.fits.get(id(item)) or fit_item(item, self.sizes)

    def block_of(self, item: TextItem, fit: TextFit) -> tuple[float, float] | None:
        """The block (em above the first baseline, below the last) the text centres in its
        box: its role's, where it is set at its role's size; else its own ink (None)."""
        return self.blocks.get(item.role) if self.sets_role_size(item, fit) else None
