"""Every editor command in one table: key, action, footer label and help text.

The screen's BINDINGS, the help screen and the command palette are all built
from this table, so a command can never be reachable one way and missing from
another. Keys avoid Ctrl+Shift combinations: terminals send them as plain Ctrl.
"""

from __future__ import annotations

from dataclasses import dataclass

from textual.binding import Binding

SMALL_STEP_MM = 2.0
LARGE_STEP_MM = 10.0
GROW = 1.1
SHRINK = 1 / 1.1


@dataclass(frozen=True)
class Command:
    """One thing the user can do. `keys` uses Textual's key names, comma-separated."""

    keys: str
    action: str
    label: str
    help: str
    group: str
    footer: bool = False
    needs_item: bool = False
    priority: bool = False

    @property
    def action_name(self) -> str:
        """The action without its parameters, as `check_action` receives it."""
        return self.action.split("(", 1)[0]


def _move(keys: str, dx: int, dy: int, step: float, name: str) -> Command:
    return Command(keys, f"nudge({dx * step},{dy * step})", f"Move {name}",
                   f"Move the selected item {name} by {step:g} mm; the others make way",
                   "Move and resize", needs_item=True)


COMMANDS: tuple[Command, ...] = (
    Command("tab", "select_next", "Next", "Select the next item in reading order", "Select",
            footer=True, priority=True),
    Command("shift+tab", "select_previous", "Previous", "Select the previous item in reading order",
            "Select", priority=True),
    Command("escape", "select_none", "Deselect", "Clear the selection", "Select"),
    _move("left,h", -1, 0, SMALL_STEP_MM, "left"),
    _move("right,l", 1, 0, SMALL_STEP_MM, "right"),
    _move("up,k", 0, -1, SMALL_STEP_MM, "up"),
    _move("down,j", 0, 1, SMALL_STEP_MM, "down"),
    _move("shift+left,H", -1, 0, LARGE_STEP_MM, "far left"),
    _move("shift+right,L", 1, 0, LARGE_STEP_MM, "far right"),
    _move("shift+up,K", 0, -1, LARGE_STEP_MM, "far up"),
    _move("shift+down,J", 0, 1, LARGE_STEP_MM, "far down"),
    Command("plus,equals_sign", f"resize({GROW},{GROW})", "Grow",
            "Make the selected item larger, keeping its shape", "Move and resize", needs_item=True),
    Command("minus", f"resize({SHRINK},{SHRINK})", "Shrink",
            "Make the selected item smaller, keeping its shape", "Move and resize", needs_item=True),
    Command("greater_than_sign", f"resize({GROW},1)", "Wider",
            "Make the selected item wider (a picture keeps its aspect ratio)", "Move and resize",
            needs_item=True),
    Command("less_than_sign", f"resize({SHRINK},1)", "Narrower",
            "Make the selected item narrower (a picture keeps its aspect ratio)", "Move and resize",
            needs_item=True),
    Command("circumflex_accent", f"resize(1,{GROW})", "Taller",
            "Make the selected item taller (a picture keeps its aspect ratio)", "Move and resize",
            needs_item=True),
    Command("underscore", f"resize(1,{SHRINK})", "Shorter",
            "Make the selected item shorter (a picture keeps its aspect ratio)", "Move and resize",
            needs_item=True),
    Command("i", "insert", "Insert", "Insert an item or a background (asks which)", "Insert",
            footer=True),
    Command("t", "insert_kind('text')", "Text", "Insert a text box", "Insert"),
    Command("p", "insert_kind('picture')", "Picture", "Insert a picture from a file", "Insert"),
    Command("b", "insert_kind('block')", "Block", "Insert a colour block", "Insert"),
    Command("c", "insert_kind('calendar')", "Calendar", "Insert a calendar month panel", "Insert"),
    Command("g", "insert_kind('background')", "Background",
            "Set the page background: a colour or a picture", "Insert"),
    Command("enter,e", "edit", "Edit", "Edit the selected item's text and properties "
            "(font, colour, gamma, decorative)", "Edit", footer=True, needs_item=True),
    Command("d", "toggle_decorative", "Decorative",
            "Toggle decorative: a decoration sits behind and is never pushed", "Edit",
            needs_item=True),
    Command("delete,x", "delete", "Delete", "Delete the selected item", "Edit", footer=True,
            needs_item=True),
    Command("a", "anchor_here", "Anchor", "Anchor the selected item to the point where it is",
            "Anchor", footer=True, needs_item=True),
    Command("A", "anchor_to_item", "Anchor to item",
            "Anchor the selected item to another item, keeping their offset", "Anchor",
            needs_item=True),
    Command("u", "unanchor", "Unanchor", "Remove the selected item's anchor", "Anchor",
            needs_item=True),
    Command("space", "toggle_pause", "Pause", "Pause or resume the physics", "Physics",
            footer=True),
    Command("r", "reheat", "Reheat", "Reheat the physics so the items spread out again",
            "Physics"),
    Command("ctrl+z", "undo", "Undo", "Undo the last edit (positions too)", "History",
            footer=True),
    Command("ctrl+y", "redo", "Redo", "Redo the edit you undid", "History"),
    Command("right_square_bracket,pagedown", "switch_page(1)", "Next page",
            "Show the next page", "Pages"),
    Command("left_square_bracket,pageup", "switch_page(-1)", "Previous page",
            "Show the previous page", "Pages"),
    Command("N", "add_page", "Add page", "Add a page after this one", "Pages"),
    Command("D", "remove_page", "Remove page", "Remove this page (asks first)", "Pages"),
    Command("S", "page_size", "Page size", "Change this page's size", "Pages"),
    Command("o", "toggle_orientation", "Orientation",
            "Switch this page between portrait and landscape", "Pages"),
    Command("ctrl+s", "save", "Save", "Save the project file", "File", footer=True),
    Command("ctrl+e", "export_pdf", "Export PDF",
            "Typeset the project into a PDF beside the project file", "File", footer=True),
    Command("question_mark,f1", "help", "Help", "Show every key", "File", footer=True),
    Command("q,ctrl+q", "quit", "Quit", "Quit, asking first if there are unsaved changes",
            "File", footer=True, priority=True),
)

ITEM_ACTIONS = frozenset(command.action_name for command in COMMANDS if command.needs_item)

KEY_NAMES = {
    "plus": "+", "equals_sign": "=", "minus": "-", "greater_than_sign": ">",
    "less_than_sign": "<", "circumflex_accent": "^", "underscore": "_",
    "right_square_bracket": "]", "left_square_bracket": "[", "question_mark": "?",
    "space": "Space", "escape": "Esc", "delete": "Del", "enter": "Enter", "tab": "Tab",
    "shift+tab": "Shift+Tab", "pagedown": "PgDn", "pageup": "PgUp",
}


def key_label(keys: str) -> str:
    """Keys as a person types them: 'plus,equals_sign' -> '+ ='."""
    def one(key: str) -> str:
        if key in KEY_NAMES:
            return KEY_NAMES[key]
        return "+".join(part.capitalize() if len(part) > 1 else part for part in key.split("+"))
    return " ".join(one(key) for key in keys.split(","))


def bindings() -> list[Binding]:
    """The editor screen's BINDINGS, built from COMMANDS."""
    return [Binding(command.keys, command.action, command.label, show=command.footer,
                    priority=command.priority) for command in COMMANDS]
