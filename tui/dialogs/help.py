"""Every key, grouped, from the same table the bindings and the command palette use."""

from __future__ import annotations

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical, VerticalScroll
from textual.screen import ModalScreen
from textual.widgets import Label, Static

from tui.keymap import COMMANDS, key_label


def help_text() -> str:
    groups: dict[str, list[str]] = {}
    for command in COMMANDS:
        groups.setdefault(command.group, []).append(
            f"  [b]{key_label(command.keys):<16}[/b] {command.help}")
    parts = []
    for group, lines in groups.items():
        parts.append(f"[b u]{group}[/]")
        parts.extend(lines)
    parts.append("")
    parts.append("[b u]Mouse[/]")
    parts.append("  [b]click[/b]            Select an item")
    parts.append("  [b]drag[/b]             Move it; the others make way")
    parts.append("")
    parts.append("Ctrl+P opens the command palette: every command above, by name.")
    return "\n".join(parts)


class HelpScreen(ModalScreen[None]):
    """Scrollable list of keys; Esc, q or ? closes it."""

    BINDINGS = [Binding("escape,q,question_mark,f1", "close", "Close")]

    def compose(self) -> ComposeResult:
        with Vertical(classes="dialog help"):
            yield Label("floatpage keys", classes="dialog-title")
            with VerticalScroll():
                yield Static(help_text(), id="help-text")
            yield Label("Esc closes · arrows scroll", classes="dialog-hint")

    def action_close(self) -> None:
        self.dismiss(None)
