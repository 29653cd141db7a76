"""Pick one of a list: what to insert, which item to anchor to, quit or not, which page size."""

from __future__ import annotations

from typing import Generic, TypeVar

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.widgets import Label, OptionList
from textual.widgets.option_list import Option

from floatpage.tui.dialogs.base import Dialog, Hint


Value = TypeVar("Value")


class ChoiceDialog(Dialog[Value | None], Generic[Value]):
    """A title, an optional message and a list; Enter picks, Esc cancels (dismisses None).

    A choice whose value is None ("Keep editing") answers as Esc does."""

    BINDINGS = [Binding("escape", "cancel", "Cancel")]

    def __init__(self, title: str, choices: list[tuple[str, Value | None]], *, message: str = "",
                 highlighted: Value | None = None, dialog_id: str | None = None):
        super().__init__(id=dialog_id)
        self.title_text = title
        self.message = message
        self.choices = choices
        self.highlighted_value = highlighted

    def compose_dialog(self) -> ComposeResult:
        with Vertical(classes="dialog"):
            with Vertical(classes="dialog-head"):
                yield Label(self.title_text, classes="dialog-title", markup=False)
                if self.message:
                    yield Label(self.message, classes="dialog-message", markup=False)
            yield OptionList(*[Option(label, id=str(index))
                               for index, (label, _) in enumerate(self.choices)])
            yield Hint("Enter chooses · Esc cancels", "Esc cancels", classes="dialog-foot")

    def on_mount(self) -> None:
        options = self.query_one(OptionList)
        values = [value for _, value in self.choices]
        if self.highlighted_value in values:
            options.highlighted = values.index(self.highlighted_value)
        options.focus()

    def on_option_list_option_selected(self, event: OptionList.OptionSelected) -> None:
        event.stop()
        self.dismiss(self.choices[int(event.option.id)][1])

    def action_cancel(self) -> None:
        self.dismiss(None)
