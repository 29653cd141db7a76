"""Every key, grouped, from the same table the bindings and the command palette use."""

from __future__ import annotations

from rich.console import Group
from rich.table import Table
from rich.text import Text
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical, VerticalScroll
from textual.widgets import Label, Static

from floatpage.tui.dialogs.base import Dialog, Hint
from floatpage.tui.keymap import COMMANDS, key_label

MOUSE = (("click", "Select an item (or nothing, on empty paper)"),
         ("drag", "Move the item; the others make way"))
# Every mark the preview draws, and what it means (issue 11: they were explained nowhere).
MARKS = (("~name", "a decoration's id (shown with n): it sits behind and is never pushed"),
         ("+", "an item anchored to the page by a spring (magenta), at its anchor or, when "
               "that is under the item, beside it; on text, the letter there turns magenta"),
         ("#", "an item anchored to the page hard: it does not move (placed as +)"),
         ("· · ·", "the line from an item to its anchor, magenta; or to the item it follows, blue"),
         ("o", "the two ends of a follow link (blue), beside the follower and the item it "
               "follows"),
         ("(none)", "a small item with no free cell beside it goes without its + # o, rather "
                    "than have it hide the item or glue to a word; select it to see its anchor "
                    "in the top bar"),
         ("frame", "the selected item, framed in yellow, with its id"),
         ("- - group", "the selected item's group, dashed orange: it moves as one (G joins or leaves)"),
         ("- - guide", "a dashed cyan line across the page, while the selected item moves: an "
                       "alignment guide it sits on"),
         ("- - name", "a region, dashed green: its items stay inside it; its edges are guides"),
         ("1 2 3", "a calendar's days, every one of the month: where the panel is small, "
                   "without weekday columns, or two cells a day, every other day shaded"),
         ("…", "a text cut short: its box holds more than its cells show"),
         ("Jan 1-31", "a calendar panel too small to show its days: its month and days"),
         ("▀ ▄", "half-block pixels: each cell shows two rows of the page"))


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
    table.add_row(Text("Marks", style="bold underline"), "on the page, in the preview")
    for mark, meaning in MARKS:
        table.add_row(mark, meaning)
    return table


class HelpScreen(Dialog[None]):
    """Scrollable list of keys; Esc, q or ? closes it."""

    BINDINGS = [Binding("escape,q,question_mark,f1", "close", "Close")]

    def compose_dialog(self) -> ComposeResult:
        with Vertical(classes="dialog help"):
            yield Label("floatpage keys", classes="dialog-title dialog-head")
            with VerticalScroll():
                yield Static(Group(help_table(), Text(
                    "\nCtrl+P opens the command palette: every command above, by name.")),
                    id="help-text")
            yield Hint("Esc closes · arrows scroll", "Esc closes", classes="dialog-foot")

    def action_close(self) -> None:
        self.dismiss(None)
