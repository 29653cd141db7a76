"""Undo and redo as whole-document snapshots.

A project is small (tens of items), so a copy per edit is cheap and makes
every edit undoable, positions included, without an inverse for each operation.
"""

from __future__ import annotations

import pickle
from dataclasses import dataclass

from floatpage.model.document import Page


@dataclass(frozen=True)
class Snapshot:
    """The editable state: every page (with positions), which page is shown, what is selected.

    The pages are kept pickled and unpickled only when asked for (an undo or redo): the first
    arrow press of a move takes a snapshot, and unpickling there was a third of the move's
    0.7-1.3 ms (issue 11: key to screen). Each `pages` is a fresh copy."""

    label: str
    pickled_pages: bytes
    page_index: int
    selected_id: str | None
    version: int = 0  # which document state this is, to tell whether it is the saved one

    @classmethod
    def take(cls, label: str, pages: list[Page], page_index: int,
             selected_id: str | None, version: int = 0) -> "Snapshot":
        return cls(label, pickle.dumps(pages, protocol=pickle.HIGHEST_PROTOCOL), page_index,
                   selected_id, version)

    @property
    def pages(self) -> list[Page]:
        return pickle.loads(self.pickled_pages)


class History:
    """Two stacks of snapshots; a new edit clears the redo stack."""

    def __init__(self, limit: int = 200):
        self.limit = limit
        self.undo_stack: list[Snapshot] = []
        self.redo_stack: list[Snapshot] = []
        self.dropped = 0  # edits older than the limit, no longer undoable (for "nothing to undo")

    def record(self, before: Snapshot) -> None:
        """Remember the state before an edit."""
        self.undo_stack.append(before)
        self.dropped += max(0, len(self.undo_stack) - self.limit)
        del self.undo_stack[:-self.limit]
        self.redo_stack.clear()

    def undo(self, current: Snapshot) -> Snapshot | None:
        """The state to return to, or None; `current` becomes redoable."""
        if not self.undo_stack:
            return None
        self.redo_stack.append(current)
        return self.undo_stack.pop()

    def redo(self, current: Snapshot) -> Snapshot | None:
        if not self.redo_stack:
            return None
        self.undo_stack.append(current)
        return self.redo_stack.pop()

