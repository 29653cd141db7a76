"""Every editor command in one table: key, action, footer label and help text.

The screen's BINDINGS, the help screen and the command palette are all built
from this table, so a command can never be reachable one way and missing from
another. Keys avoid Ctrl+Shift combinations: terminals send them as plain Ctrl.
"""

from __future__ import annotations

from dataclasses import dataclass

from textual.binding import Binding
from textual.keys import format_key

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
    footer: str = "page"  # footer context: "item" (something selected), "page" (nothing) or "both"
    rank: int = 50  # footer order, left to right
    needs_item: bool = False
    priority: bool = False
    key_display: str | None = None

    @property
    def action_name(self) -> str:
        """The action without its parameters, as `check_action` receives it."""
        return self.action.split("(", 1)[0]

    @property
    def binding_id(self) -> str:
        """The binding's id, from the label ("Move far left" -> "move-far-left"): what a Textual
        keymap (`App.set_keymap`) names to give a command other keys."""
        return self.label.lower().replace(" ", "-")


def _move(keys: str, dx: int, dy: int, step: float, name: str) -> Command:
    first = keys.split(",")[0]
    large = first.startswith("shift+")
    display = "\u21e7" + format_key(first[6:]) if large else format_key(first)
    # priority: the App runs the binding as the key arrives, instead of handing the key to
    # the focused preview, which passes it up to the screen and the screen to the App, a turn
    # of the event loop each (about 1 ms of a key's answer, issue 11). Nothing on the editor
    # screen takes arrows itself; dialogs are screens of their own, whose keys these never
    # see; with nothing selected the binding is disabled and the key goes the usual way.
    return Command(keys, f"nudge({dx * step},{dy * step})", f"Move {name}",
                   f"Move the selected item {name} by {step:g} mm and anchor it there",
                   "Move and resize", footer="item", rank=16 if large else 2, needs_item=True,
                   priority=True, key_display=display)


def _resize(keys: str, fx: float, fy: float, label: str, how: str) -> Command:
    return Command(keys, f"resize({fx},{fy})", label, f"Make the selected item {how}",
                   "Move and resize", footer="item", rank=3, needs_item=True)


COMMANDS: tuple[Command, ...] = (
    Command("tab", "select_next", "Next", "Select the next item in reading order", "Select",
            footer="both", rank=1, priority=True),
    Command("shift+tab", "select_previous", "Previous",
            "Select the previous item in reading order", "Select", rank=17, priority=True),
    Command("escape", "select_none", "Deselect", "Clear the selection", "Select", footer="item",
            rank=17),
    _move("left,h", -1, 0, SMALL_STEP_MM, "left"),
    _move("right,l", 1, 0, SMALL_STEP_MM, "right"),
    _move("up,k", 0, -1, SMALL_STEP_MM, "up"),
    _move("down,j", 0, 1, SMALL_STEP_MM, "down"),
    _move("shift+left,H", -1, 0, LARGE_STEP_MM, "far left"),
    _move("shift+right,L", 1, 0, LARGE_STEP_MM, "far right"),
    _move("shift+up,K", 0, -1, LARGE_STEP_MM, "far up"),
    _move("shift+down,J", 0, 1, LARGE_STEP_MM, "far down"),
    _resize("plus,equals_sign", GROW, GROW, "Grow", "larger, keeping its shape"),
    _resize("minus", SHRINK, SHRINK, "Shrink", "smaller, keeping its shape"),
    _resize("greater_than_sign", GROW, 1, "Wider", "wider (a picture keeps its aspect ratio)"),
    _resize("less_than_sign", SHRINK, 1, "Narrower",
            "narrower (a picture keeps its aspect ratio)"),
    _resize("circumflex_accent", 1, GROW, "Taller", "taller (a picture keeps its aspect ratio)"),
    _resize("underscore", 1, SHRINK, "Shorter", "shorter (a picture keeps its aspect ratio)"),
    Command("i", "insert", "Insert", "Insert an item or a background (asks which)", "Insert",
            rank=2),
    Command("t", "insert_kind('text')", "Insert text",
            "Insert a text box, in the look and size of the selected text, or of most of the "
            "page's texts (its role is not taken)", "Insert", rank=2),
    Command("p", "insert_kind('picture')", "Insert picture",
            "Insert a picture from a file, as large as the selected picture, or as the page's "
            "pictures mostly are", "Insert", rank=2),
    Command("b", "insert_kind('block')", "Insert block",
            "Insert a colour block, in the colour and size of the selected block, or of most "
            "of the page's blocks", "Insert", rank=2),
    Command("c", "insert_kind('calendar')", "Insert calendar", "Insert a calendar month panel, "
            "in the look and size of the selected panel, or of the page's", "Insert", rank=2),
    Command("g", "insert_kind('background')", "Background",
            "Set the page background: a colour or a picture", "Insert", rank=2),
    Command("enter,e", "edit", "Edit", "Edit the selected item's text and properties "
            "(font, colour, gamma, decorative)", "Edit", footer="item", rank=4, needs_item=True),
    Command("d", "toggle_decorative", "Decorative",
            "Toggle decorative: a decoration sits behind and is never pushed", "Edit",
            footer="item", rank=15, needs_item=True),
    Command("delete,x", "delete", "Delete", "Delete the selected item", "Edit", footer="item",
            rank=5, needs_item=True),
    Command("a", "anchor_here", "Anchor", "Anchor the selected item to the point where it is",
            "Anchor", footer="item", rank=6, needs_item=True),
    Command("A", "anchor_to_item", "Anchor to item",
            "Anchor the selected item to another item, keeping their offset", "Anchor",
            footer="item", rank=6, needs_item=True),
    Command("u", "unanchor", "Unanchor", "Remove the selected item's anchor", "Anchor",
            footer="item", rank=6, needs_item=True),
    Command("G", "group", "Group", "Put the selected item in a group that moves as one "
            "(asks for its name; empty takes it out)", "Anchor", footer="item", rank=6,
            needs_item=True),
    Command("R", "region", "Region", "Make a region (around the selected item, which keeps "
            "inside it), or change or remove the selected item's region; with nothing "
            "selected, a new one (the page's top two-thirds) or one of the page's", "Anchor",
            footer="item", rank=6),
    Command("space", "toggle_pause", "Pause", "Pause or resume the physics", "Physics",
            footer="both", rank=9),
    Command("r", "reheat", "Reheat", "Reheat the physics so the items spread out again",
            "Physics", rank=14),
    Command("n", "toggle_labels", "Names",
            "Show every item's id on the preview, or only the selected item's", "Physics",
            rank=18),
    Command("v", "toggle_details", "Details",
            "Show the physics' and the layout's numbers in the status lines, or words again",
            "Physics", rank=18),
    Command("ctrl+z", "undo", "Undo", "Undo the last edit (positions too)", "History",
            footer="both", rank=10),
    Command("ctrl+y", "redo", "Redo", "Redo the edit you undid", "History",
            footer="both", rank=10),
    Command("right_square_bracket,pagedown", "switch_page(1)", "Next page",
            "Show the next page", "Pages", rank=3),
    Command("left_square_bracket,pageup", "switch_page(-1)", "Previous page",
            "Show the previous page", "Pages", rank=3),
    Command("N", "add_page", "Add page", "Add a page after this one", "Pages", rank=3),
    Command("D", "remove_page", "Remove page", "Remove this page (asks first)", "Pages", rank=3),
    Command("S", "page_size", "Page size", "Change the page size (asks: every page, or this one)", "Pages", rank=3),
    Command("o", "toggle_orientation", "Orientation",
            "Turn between portrait and landscape (asks: every page, or this one)", "Pages",
            rank=3),
    Command("ctrl+s", "save", "Save", "Save the project file (once room is found, "
            "where an insert or a new page size is still looking for it)", "File", footer="both",
            rank=11),
    Command("ctrl+e", "export_pdf", "Export",
            "Typeset the project into a PDF beside the project file", "File", footer="both",
            rank=12),
    Command("question_mark,f1", "help", "Help", "Show every key", "File", footer="both", rank=0),
    Command("q,ctrl+q", "quit", "Quit", "Quit, asking first if there are unsaved changes",
            "File", footer="both", rank=13, priority=True),
)

ITEM_ACTIONS = frozenset(command.action_name for command in COMMANDS if command.needs_item)
# Keys of the commands that need a selected item: pressed with none, they say so (defect 13).
ITEM_KEYS = {key: command for command in COMMANDS if command.needs_item
             for key in command.keys.split(",")}

def key_label(keys: str) -> str:
    """Keys as a person types them, each named by Textual's format_key as the footer names it,
    modifiers spelled out: 'plus,equals_sign' -> '+ =', 'shift+left,H' -> 'Shift+← H'."""
    def one(key: str) -> str:
        *modifiers, name = key.split("+")
        return "+".join([modifier.capitalize() for modifier in modifiers] + [format_key(name)])
    return " ".join(one(key) for key in keys.split(","))


FOOTER_GROUPS = {
    "Insert": Binding.Group("Insert", compact=True),
    "Anchor": Binding.Group("Anchor", compact=True),
    "History": Binding.Group("Undo/Redo", compact=True),
    "Pages": Binding.Group("Page", compact=True),
}
FAR_GROUP = Binding.Group("Far", compact=True)
MOVE_GROUP = Binding.Group("Move", compact=True)
SIZE_GROUP = Binding.Group("Size", compact=True)


def footer_group(command: Command) -> Binding.Group | None:
    """The footer shows related keys as one group ("←→↑↓ Move") so that, with only the commands
    that make sense in the moment (see `in_footer`), every command appears in the footer; the
    help screen spells each one out."""
    if command.group == "Move and resize":
        if command.action_name == "nudge":
            return FAR_GROUP if command.rank == 16 else MOVE_GROUP
        return SIZE_GROUP
    return FOOTER_GROUPS.get(command.group)


def bindings() -> list[Binding]:
    """The editor screen's BINDINGS, built from COMMANDS: every command shows in the footer."""
    return [Binding(command.keys, command.action, command.label, show=True,
                    priority=command.priority, group=footer_group(command),
                    key_display=command.key_display, id=command.binding_id)
            for command in COMMANDS]


COMMAND_BY_ACTION = {command.action: command for command in COMMANDS}


def in_footer(action: str, item_selected: bool) -> bool:
    """Whether a binding's action shows in the footer in this context (unknown ones do)."""
    command = COMMAND_BY_ACTION.get(action)
    if command is None or command.footer == "both":
        return True
    return command.footer == ("item" if item_selected else "page")


def footer_rank(action: str) -> int:
    command = COMMAND_BY_ACTION.get(action)
    return command.rank if command is not None else 99
