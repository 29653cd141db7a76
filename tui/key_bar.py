"""The editor's footer: its keys as one line of text, drawn in the same frame as the key that
changed them.

Textual's Footer is a widget per key, rebuilt (unmounted and mounted again) a refresh after
the bindings change: about 80 ms on the shared build machine, and the footer was missing for
0.35-0.7 s after start and showed the old keys for 0.2-0.3 s after Tab over SSH (issue 11,
defect 6).  This bar reads the screen's active bindings (which the editor already fits to the
width by priority) when they change and only re-renders one line; a click runs the command
under the pointer, as a FooterKey does.
"""

from __future__ import annotations

from rich.text import Text
from textual import events
from textual.widget import Widget

PALETTE_LABEL = "palette"


class KeyBar(Widget):
    """One line: `key description ` per command, a group as `keys description `, the command
    palette at the right end."""

    ALLOW_SELECT = False
    COMPONENT_CLASSES = {"key-bar--key", "key-bar--description", "key-bar--disabled"}
    DEFAULT_CSS = """
    KeyBar {
        dock: bottom;
        height: 1;
        width: 1fr;
        color: $footer-foreground;
        background: $footer-background;
        .key-bar--key {
            color: $footer-key-foreground;
            background: $footer-key-background;
            text-style: bold;
        }
        .key-bar--description {
            color: $footer-description-foreground;
            background: $footer-description-background;
        }
        .key-bar--disabled {
            text-style: dim;
        }
    }
    """

    def __init__(self, *, id: str | None = None):
        super().__init__(id=id)
        self.units: list[tuple[str, str, str, bool]] = []  # (keys, description, action, enabled)
        self.spans: list[tuple[int, int, str]] = []  # (first cell, end cell, action) for clicks

    @property
    def actions(self) -> list[str]:
        """The actions shown, in order (for tests and the help text)."""
        return [action for _, _, action, _ in self.units]

    def on_mount(self) -> None:
        self.screen.bindings_updated_signal.subscribe(self, self.bindings_changed)
        self.read_bindings()

    def on_unmount(self) -> None:
        self.screen.bindings_updated_signal.unsubscribe(self)

    def bindings_changed(self, screen) -> None:
        if self.is_attached and screen is self.screen:
            self.read_bindings()

    def read_bindings(self) -> None:
        """Take the screen's active bindings: one unit per action (by its first key), a group's
        actions as one unit; re-render only if what is shown changed."""
        units: list[tuple[str, str, str, bool]] = []
        groups: dict[str, int] = {}
        seen: set[str] = set()
        for _, (_, binding, enabled, _) in self.screen.active_bindings.items():
            if not binding.show or binding.action in seen:
                continue
            seen.add(binding.action)
            key = self.app.get_key_display(binding)
            group = binding.group
            if group is not None and group.description in groups:
                at = groups[group.description]
                keys, description, action, was_enabled = units[at]
                units[at] = (keys + key, description, action, was_enabled or enabled)
                continue
            if group is not None:
                groups[group.description] = len(units)
            units.append((key, group.description if group else binding.description,
                          binding.action, enabled))
        if units != self.units:
            self.units = units
            self.refresh()

    def render(self) -> Text:
        key_style = self.get_component_rich_style("key-bar--key")
        description_style = self.get_component_rich_style("key-bar--description")
        dim = self.get_component_rich_style("key-bar--disabled")
        line = Text(no_wrap=True, overflow="crop")
        self.spans = []
        for keys, description, action, enabled in self.units:
            start = line.cell_len
            shade = dim if not enabled else None
            # spaces end runs rather than start them (SVG screenshots drop a run's leading one)
            line.append(f"{keys} ", key_style + shade if shade else key_style)
            line.append(f"{description} ", description_style + shade if shade else
                        description_style)
            self.spans.append((start, line.cell_len, action))
        palette = self.palette_text(key_style, description_style)
        room = self.size.width - line.cell_len - palette.cell_len
        if room >= 0 and palette.cell_len:
            line.append(" " * room)
            self.spans.append((line.cell_len, line.cell_len + palette.cell_len,
                               "app.command_palette"))
            line.append_text(palette)
        return line

    def palette_text(self, key_style, description_style) -> Text:
        if not self.app.ENABLE_COMMAND_PALETTE:
            return Text()
        entry = self.screen.active_bindings.get(self.app.COMMAND_PALETTE_BINDING)
        if entry is None:
            return Text()
        key = self.app.get_key_display(entry.binding)
        return Text.assemble(("▏ ", description_style), (f"{key} ", key_style),
                             (f"{PALETTE_LABEL} ", description_style))

    async def on_click(self, event: events.Click) -> None:
        for start, end, action in self.spans:
            if start <= event.x < end:
                event.stop()
                if action.startswith("app."):
                    await self.run_action(action)
                else:
                    await self.screen.run_action(action)
                return
