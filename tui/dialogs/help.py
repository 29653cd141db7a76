"""Every key, grouped, from the same table the bindings and the command palette use."""

from __future__ import annotations

from rich.console import Group
from rich.table import Table
from rich.text import Text
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical, VerticalScroll
from textual.screen import ModalScreen
from textual.widgets import Label, Static

from floatpage.tui.keymap import COMMANDS, key_label

MOUSE = (("click", "Select an item (or nothing, on empty paper)"),
         ("drag", "Move the item; the others make way"))


def help_table() -> Table:
    """Two columns, keys and what they do, with a heading row per group."""
    table = Table.grid(padding=(0, 2))
    table.add_column(style="bold", no_wrap=True)
    table.add_column()
    group = None
    for command in COMMANDS:
        if command.group != group:
            group = command.group
            table.add_row(Text(group, style="bold underline"), "")
        table.add_row(key_label(command.keys), command.help)
    table.add_row(Text("Mouse", style="bold underline"), "")
    for gesture, meaning in MOUSE:
        table.add_row(gesture, meaning)
    return table


def help_plain_text() -> str:
    """The same content as plain lines (for tests and the command-line docs)."""
    lines = [f"{key_label(command.keys)}  {command.help}" for command in COMMANDS]
    return "\n".join(lines + [f"{gesture}  {meaning}" for gesture, meaning in MOUSE])


class HelpScreen(ModalScreen[None]):
    """Scrollable list of keys; Esc, q or ? closes it."""

    BINDINGS = [Binding("escape,q,question_mark,f1", "close", "Close")]

    def compose(self) -> ComposeResult:
        with Vertical(classes="dialog help"):
            yield Label("floatpage keys", classes="dialog-title")
            with VerticalScroll():
                yield Static(Group(help_table(), Text(
                    "\nCtrl+P opens the command palette: every command above, by name.")),
                    id="help-text")
            yield Label("Esc closes · arrows scroll", classes="dialog-hint")

    def action_close(self) -> None:
        self.dismiss(None)
