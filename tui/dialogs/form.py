"""A small form: one line per field; the caller's parser turns the answers into values.

The parser raises ValueError with a sentence for the user; the form then stays
open and shows it, so a typo in a colour is a message, never a crash.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Generic, Literal, TypeVar

from textual.app import ComposeResult
from textual.binding import Binding
from textual.geometry import Region
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.widgets import Button, Checkbox, Input, Label, Select, TextArea

from floatpage.tui.dialogs.base import Dialog, Hint

FieldKind = Literal["line", "text", "choice", "bool"]


class MarkedCheckbox(Checkbox):
    """A checkbox whose state shows without colour. Textual's shows an "X" whether on or off,
    told apart by its colour alone; under NO_COLOR both came out the same grey, and a user
    could not see whether Bold was on (walk-14). There an unticked box is empty."""

    @property
    def _button(self):
        self.BUTTON_INNER = "X" if self.value or not self.app.no_color else " "
        return super()._button


class WordsField(TextArea):
    """A form's text field, whose cursor the form keeps in sight: the words wrap anew when
    the field is laid out or resized, which moves the cursor's row (on a loaded machine after
    the form had scrolled to it, so a 20 x 6 form showed the rows above it)."""

    def on_resize(self) -> None:
        # runs before TextArea's own _on_resize (this class comes first in the MRO), which
        # wraps the words anew: the cursor's row is known once it has run
        if isinstance(self.screen, FormDialog):
            self.call_later(self.screen.show_cursor)


@dataclass(frozen=True)
class Field:
    """One form field: a line of text, several lines, a choice or a yes/no."""

    name: str
    label: str
    kind: FieldKind
    value: Any
    choices: tuple[tuple[str, Any], ...] = ()


class FieldError(ValueError):
    """A parser's complaint about one field: the form shows it and puts the cursor there (a
    wrong width was reported while the cursor stayed in the height field)."""

    def __init__(self, field: str, message: str):
        super().__init__(message)
        self.field = field


Answer = TypeVar("Answer")
Parser = Callable[[dict[str, Any]], Answer]


class FormDialog(Dialog[Answer | None], Generic[Answer]):
    """Fields, an error line and OK / Cancel. Enter in a one-line field or Ctrl+S applies.

    It dismisses with what the parser made of the fields (its type is the parser's), or None.

    Compact widgets and a scrolling field list keep the buttons on screen at 80 x 24; the
    list takes the height the terminal has (see `Dialog`).
    """

    BINDINGS = [Binding("escape", "cancel", "Cancel"), Binding("ctrl+s", "apply", "Apply")]

    def __init__(self, title: str, fields: list[Field], parse: Parser[Answer], *,
                 dialog_id: str | None = None):
        super().__init__(id=dialog_id)
        self.title_text = title
        self.fields = fields
        self.parse = parse

    def compose_dialog(self) -> ComposeResult:
        with Vertical(classes="dialog form"):
            yield Label(self.title_text, classes="dialog-title dialog-head", markup=False)
            with VerticalScroll(classes="form-fields"):
                for field in self.fields:
                    yield from self._field(field)
            with Vertical(classes="dialog-foot"):
                yield Label("", id="form-error", classes="dialog-error", markup=False)
                multi_line = any(field.kind == "text" for field in self.fields)
                apply = "Ctrl+S" if multi_line else "Enter"
                yield Hint("Tab moves · " + ("Ctrl+S" if multi_line else "Enter or Ctrl+S")
                           + " applies · Esc cancels", f"{apply} applies · Esc cancels",
                           "Esc cancels")
                with Horizontal(classes="dialog-buttons"):
                    yield Button("OK", variant="primary", id="ok", compact=True)
                    yield Button("Cancel", id="cancel", compact=True)

    def _field(self, field: Field) -> ComposeResult:
        widget_id = f"field-{field.name}"
        if field.kind == "bool":
            yield MarkedCheckbox(field.label, value=bool(field.value), id=widget_id,
                                 compact=True)
            return
        yield Label(field.label, classes="field-label", markup=False)  # may hold a path
        if field.kind == "line":
            yield Input(str(field.value), id=widget_id, compact=True)
        elif field.kind == "text":
            yield WordsField(str(field.value), id=widget_id, tab_behavior="focus",
                             classes="field-text")
        else:
            yield Select(list(field.choices), value=field.value, allow_blank=False, id=widget_id,
                         compact=True)

    def on_mount(self) -> None:
        for widget in self.query("Input, TextArea"):
            widget.cursor_blink = getattr(self.app, "cursor_blink", True)
        # the form scrolls to the cursor itself (show_cursor): the focus's own scroll, which
        # shows the field's first row, came after it in some turns of the event loop and hid
        # the cursor of a 20 x 6 form again (tools/shuffled_loop.py)
        self.first_field().focus(scroll_visible=False)
        self.call_after_refresh(self._cursor_to_end)

    def first_field(self):
        return self.query(".form-fields > Input, .form-fields > TextArea, "
                          ".form-fields > Select, .form-fields > Checkbox").first()

    def _cursor_to_end(self) -> None:
        """Put each text field's cursor after its words, as a form field opens in every
        common editor: at their start (Textual's default), "Deine Anna" typed after a card's
        message landed before it (user-walk-9, user-walk-10).  A line field selects all its
        text on focus.  Once laid out (the field's wrapping is known only then), with the
        fields scrolled so the cursor shows: a 20 x 6 form shows one row of its 3."""
        for area in self.query(TextArea):
            area.move_cursor(area.document.end)
        self.show_cursor()

    def show_cursor(self) -> None:
        """Scroll the fields so that the focused text field's cursor shows (or the first
        field's, while the focus given it on mount is still on its way)."""
        area = self.focused or self.first_field()
        if not isinstance(area, TextArea):
            return
        fields = self.query_one(".form-fields", VerticalScroll)
        # where the cursor is in the fields' scrolled space, from the field's place in it and
        # the cursor's wrapped row (the screen offsets lag a scroll just asked for)
        row = area.wrapped_document.location_to_offset(area.cursor_location).y
        top = area.virtual_region.y + area.content_region.y - area.region.y
        fields.scroll_to_region(Region(0, top + row - int(area.scroll_y), 1, 1),
                                animate=False, immediate=True)

    def values(self) -> dict[str, Any]:
        """What the fields hold now, as typed."""
        values: dict[str, Any] = {}
        for field in self.fields:
            widget = self.query_one(f"#field-{field.name}")
            if isinstance(widget, TextArea):
                values[field.name] = widget.text
            else:
                values[field.name] = widget.value
        return values

    def typed(self) -> list[tuple[str, str]]:
        """(label, text) of each line or text field whose text was changed, as typed: what a
        lost terminal would lose (`tui.recovery` keeps it)."""
        typed = []
        for field in self.fields:
            if field.kind not in ("line", "text"):
                continue
            widget = self.query_one(f"#field-{field.name}")
            now = widget.text if isinstance(widget, TextArea) else widget.value
            if now != str(field.value):
                typed.append((field.label, now))
        return typed

    def action_apply(self) -> None:
        try:
            result = self.parse(self.values())
        except ValueError as error:
            self.query_one("#form-error", Label).update(str(error))
            if isinstance(error, FieldError):
                for widget in self.query(f"#field-{error.field}"):
                    widget.focus()
            return
        self.dismiss(result)

    def action_cancel(self) -> None:
        self.dismiss(None)

    def on_input_submitted(self, event: Input.Submitted) -> None:
        event.stop()
        self.action_apply()

    def on_button_pressed(self, event: Button.Pressed) -> None:
        event.stop()
        if event.button.id == "ok":
            self.action_apply()
        else:
            self.action_cancel()
