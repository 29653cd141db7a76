"""Choose a picture file: a tree of the project's folder showing only pictures, or a typed path."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Iterable

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.widgets import DirectoryTree, Input, Label

from floatpage.model.key_specs import PICTURE_SUFFIXES
from floatpage.model.picture_files import read_header
from floatpage.tui.dialogs.base import Dialog, Hint



def resolved(path: Path) -> Path:
    return Path(os.path.realpath(path))


class PictureTree(DirectoryTree):
    """Folders and picture files only; hidden files stay hidden, and so do the project's own
    PDFs (``outputs``): offered beside the pictures, the card's own card.pdf went in as a
    picture of itself, and the next export refused to write over one of its inputs."""

    def __init__(self, path: Path, *, outputs: frozenset[Path] = frozenset(), **kwargs):
        self.outputs = outputs
        super().__init__(path, **kwargs)

    def filter_paths(self, paths: Iterable[Path]) -> Iterable[Path]:
        return [path for path in paths if not path.name.startswith(".")
                and (path.is_dir() or (path.suffix.lower() in PICTURE_SUFFIXES
                                       and resolved(path) not in self.outputs))]


class PictureDialog(Dialog[Path | None]):
    """Dismisses with the chosen file's path, or None."""

    BINDINGS = [Binding("escape", "cancel", "Cancel")]

    def __init__(self, folder: Path, title: str = "Insert a picture", *,
                 dialog_id: str | None = "picture-dialog", outputs: Iterable[Path] = ()):
        """``outputs``: the PDFs the project is exported to, which are no pictures for it."""
        super().__init__(id=dialog_id)
        self.folder = folder
        self.outputs = frozenset(resolved(path) for path in outputs)
        self.title_text = title

    def compose_dialog(self) -> ComposeResult:
        with Vertical(classes="dialog picture"):
            yield Label(self.title_text, classes="dialog-title dialog-head", markup=False)
            yield PictureTree(self.folder, outputs=self.outputs, id="picture-tree")
            with Vertical(classes="dialog-foot"):
                yield Label("…or type a path (relative to the project folder):",
                            classes="field-label")
                yield Input(placeholder="photos/sunset.jpg", id="picture-path")
                yield Label("", id="picture-error", classes="dialog-error", markup=False)
                yield Hint("Enter chooses · Tab moves · Esc cancels", "Esc cancels")

    def on_mount(self) -> None:
        self.query_one(Input).cursor_blink = getattr(self.app, "cursor_blink", True)
        self.query_one(PictureTree).focus()

    def on_directory_tree_file_selected(self, event: DirectoryTree.FileSelected) -> None:
        event.stop()
        self.dismiss(Path(event.path))

    def on_input_submitted(self, event: Input.Submitted) -> None:
        event.stop()
        typed = event.value.strip()
        path = (self.folder / Path(typed).expanduser()) if typed else None
        if path is None:
            self.query_one("#picture-error", Label).update(
                "type a path, e.g. pictures/photo.jpg, or pick a file in the tree above")
            return
        if not path.is_file():  # where it looked, in full, and what to do
            header = read_header(path)
            self.query_one("#picture-error", Label).update(
                f"{path.absolute()} {header.problem}: {header.hint}, or pick a file in the "
                "tree above")
            return
        if path.suffix.lower() not in PICTURE_SUFFIXES:
            self.query_one("#picture-error", Label).update(
                "not a picture (use " + ", ".join(PICTURE_SUFFIXES) + ")")
            return
        if resolved(path) in self.outputs:
            self.query_one("#picture-error", Label).update(
                f"{path.name} is this project's own PDF (Ctrl+E writes it): a page cannot "
                "show itself, and the next export would have to write over a picture it "
                "reads; export to another file, or pick a picture")
            return
        header = read_header(path)  # a text named .jpg: the loader would refuse the project
        if header.problem:
            self.query_one("#picture-error", Label).update(f"{path.name} {header.problem}")
            return
        self.dismiss(path)

    def action_cancel(self) -> None:
        self.dismiss(None)
