"""What every dialog shares: it fits the terminal it is shown on.

A dialog's title sits at its top and its hint (and buttons) at its bottom, docked, so that
what lies between (a list, a form's fields) takes the height there is and scrolls: at
40 x 12 the choice dialogs showed three choices and no hint, at 20 x 6 none at all, and a
form showed 11 rows of fields on any terminal, however tall.  On a short or narrow terminal
the dialog drops its padding and its top and bottom borders (`app.tcss`: `-short`,
`-narrow`); below MIN_CELLS it says the terminal is too small and how large to make it,
rather than show a frame with nothing usable in it.
"""

from __future__ import annotations

from typing import TypeVar

from textual import events
from rich.cells import cell_len
from textual.app import ComposeResult
from textual.screen import ModalScreen
from textual.widgets import Label

MIN_CELLS = (20, 6)  # the smallest terminal a dialog can be used in: columns, rows
ROOMY_CELLS = (64, 16)  # from here on, dialogs keep their padding and full border

Answer = TypeVar("Answer")


class Hint(Label):
    """A dialog's one line of keys: the longest of its wordings that fits the width it has
    ("Esc cancels" alone at 20 columns, where the whole line wrapped to three rows and left a
    form no row for its fields)."""

    def __init__(self, *wordings: str, classes: str = ""):
        super().__init__(wordings[0], classes=f"dialog-hint {classes}".strip(), markup=False)
        self.wordings = wordings

    def render(self):
        width = self.content_region.width
        return next((words for words in self.wordings if cell_len(words) <= width),
                    self.wordings[-1])


class Dialog(ModalScreen[Answer]):
    """A modal screen whose subclasses yield their `.dialog` container from `compose_dialog`."""

    HORIZONTAL_BREAKPOINTS = [(0, "-too-narrow"), (MIN_CELLS[0], "-narrow"),
                              (ROOMY_CELLS[0], "-wide")]
    VERTICAL_BREAKPOINTS = [(0, "-too-short"), (MIN_CELLS[1], "-short"),
                            (ROOMY_CELLS[1], "-tall")]

    def compose(self) -> ComposeResult:
        yield Label(self.too_small_words(*self.app.size), classes="too-small", markup=False)
        yield from self.compose_dialog()

    def compose_dialog(self) -> ComposeResult:
        raise NotImplementedError

    @staticmethod
    def too_small_words(columns: int, rows: int) -> str:
        return (f"Terminal too small: make it {MIN_CELLS[0]} × {MIN_CELLS[1]} or more (now "
                f"{columns} × {rows}). Esc cancels.")

    def on_resize(self, event: events.Resize) -> None:
        self.query_one(".too-small", Label).update(self.too_small_words(*event.size))
        self.call_after_refresh(self.focus_when_shown)

    def focus_when_shown(self) -> None:
        """A dialog opened in a terminal too small for it gave its focus to a hidden widget,
        which refused it; made larger, the dialog showed with no widget taking keys (Enter
        and the arrows did nothing until Tab).  Its first field or list takes them now."""
        columns, rows = self.app.size
        if columns >= MIN_CELLS[0] and rows >= MIN_CELLS[1] and self.focused is None:
            self.focus_next()
