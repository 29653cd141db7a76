"""The preview's changed cells straight to the terminal, past Textual's compositor.

A key's answer on the greeting card took 14-19 ms from key to flush, against 2x a trivial
Textual app's 5-6 ms over SSH (issue 11). Traced in the editor over a pty, most of it went
into carrying the moved photo's cells through Textual: building whole-row Strips (2 ms),
the compositor cutting and styling them (3 ms), rendering the segments to text (1 ms), and
the shadow screen parsing that text back into cells (2 ms), all on top of the painting
itself. The cells are known before any of that: the preview hands the changed columns of
each row to the driver's shadow screen (`ShadowScreen.paint`), which sends the ones the
terminal does not show, and Textual never hears of them.

Only when nothing else can be on those cells: the editor screen is the one shown (no dialog,
help or palette over it), no other widget overlaps the preview (a notification), the
driver follows the screen (it has written a frame since the last resize), and the preview
has the size Textual last laid out. Otherwise the preview asks Textual to refresh the
changed regions, as before. Either way the preview's Strips stay the truth that Textual
renders from whenever it repaints the preview itself (a dialog closing, a notification
going, a resize): the painted rows are marked stale in the widget's line cache.

Textual's compositor asks every widget for all its lines whenever it draws anything (a
widget's clip region is its parent's, so each overlaps any update): for the top bar's one
line it re-rendered the preview's stale rows, 3-5 ms, and threw them away. The editor
screen's update (`EditorScreen._on_timer_update`) hides them from Textual while it draws
only other widgets' cells (`stale_lines_hidden`), and they stay stale for the next update
that draws the preview.

The colours are turned into codes exactly as Textual's own `Strip.render` would, for the
terminal's colour system (truecolour, 256 colours), so the screen is the same either way
(tests/tui/test_editor_direct_paint.py compares it with Textual's own full repaint).
"""

from __future__ import annotations

from contextlib import contextmanager
from typing import Iterator

from rich.cells import cell_len
from rich.style import Style as RichStyle
from textual.geometry import Region
from textual.strip import Strip
from textual.widget import Widget

from floatpage.tui.cell_canvas import StripCache
from floatpage.tui.sgr_compactor import DEFAULT, SHOWN_ON_BLANKS, Style, apply_sgr

Run = tuple[int, int, str, Style]  # screen row, screen column, text, style


class DirectPainter:
    """Paints one widget's changed cells through the driver, when nothing else is on them."""

    def __init__(self):
        self._styles: dict[RichStyle, Style | None] = {}

    def paint(self, widget: Widget, cache: StripCache) -> bool:
        """Send `cache.changed` to the terminal; False (nothing sent) when it cannot be."""
        app = widget.app
        driver = app._driver
        paint_cells = getattr(driver, "paint_cells", None)
        if paint_cells is None or app.is_headless or not self.sole_owner(widget, cache):
            return False
        if not app._running or app._closed:  # as Textual's own `_display` checks: the writer
            return False                      # thread may be gone (its queue would fill up)
        color_system = app.console._color_system
        if color_system is None:
            return False
        region = widget.content_region
        runs: list[Run] = []
        for row, (first, end) in sorted(cache.changed.items()):
            col, segments = cache.segments(row, first, end)
            for segment in segments:
                style = self.terminal_style(segment.style, color_system)
                if style is None:
                    return False
                add_run(runs, region.y + row, region.x + col, segment.text, style)
                col += cell_len(segment.text)
        if not paint_cells(runs):
            return False
        offset = widget.content_offset
        for row, (first, end) in cache.changed.items():
            # what Textual cached of these lines is stale: rendered again when next asked
            widget._styles_cache.set_dirty(Region(offset.x, offset.y + row, widget.size.width, 1))
        return True

    @staticmethod
    def sole_owner(widget: Widget, cache: StripCache) -> bool:
        """The widget's cells are its own on the terminal: its screen is shown, laid out at
        the canvas's size, and no other widget overlaps it."""
        screen = widget.screen
        if screen is not widget.app.screen or not screen.is_current:
            return False
        if screen._layout_required or screen._repaint_required:
            return False  # Textual is about to repaint (or move) it anyway
        region = widget.content_region
        if (region.width, region.height) != (cache.cols, cache.rows) \
                or not screen.region.contains_region(region):
            return False
        ancestors = set(widget.ancestors_with_self)
        for other in screen._compositor.visible_widgets:
            if other not in ancestors and other.region.overlaps(region):
                return False
        return True

    def terminal_style(self, style: RichStyle | None, color_system) -> Style | None:
        """The terminal style Textual's output gives these cells (None: not followed)."""
        if style is None:
            return DEFAULT
        try:
            return self._styles[style]
        except KeyError:
            known = self._styles[style] = apply_sgr(DEFAULT,
                                                    Strip.render_ansi(style, color_system))
            return known


def draws_none_of(screen, widget: Widget) -> bool:
    """True when the screen's next update draws none of `widget`'s cells: nothing pending that
    repaints the whole screen (layout, scroll, repaint, recompose), and no widget to draw
    overlaps it, nor is it, nor contains it."""
    if screen._layout_required or screen._scroll_required or screen._repaint_required \
            or screen._recompose_required:
        return False
    region = widget.region
    return all(dirty is not widget and dirty is not screen and not dirty.region.overlaps(region)
               for dirty in screen._dirty_widgets)


@contextmanager
def stale_lines_hidden(widget: Widget) -> Iterator[None]:
    """While Textual draws only other widgets' cells, it takes the widget's lines as it last
    rendered them (stale where painted directly, and never shown): rendering them again is
    the work of the update that draws them."""
    dirty_lines = widget._styles_cache._dirty_lines
    held = set(dirty_lines)
    dirty_lines.clear()
    try:
        yield
    finally:
        dirty_lines.update(held)


def add_run(runs: list[Run], row: int, col: int, text: str, style: Style) -> None:
    """Append a run, or extend the last one when the terminal cannot tell the difference:
    blanks show only their background, so blanks next to text on the same background go in
    the text's style. A calendar's digits alternate with blank pixel cells, a run per cell,
    and each run costs the shadow screen as much as a dozen cells within one."""
    if runs:
        last_row, last_col, last_text, last_style = runs[-1]
        if last_row == row and last_col + cell_len(last_text) == col \
                and last_style.bg == style.bg \
                and not (last_style.flags | style.flags) & SHOWN_ON_BLANKS:
            if not text.strip(" ") and not last_style.flags ^ style.flags:
                runs[-1] = (row, last_col, last_text + text, last_style)
                return
            if not last_text.strip(" ") and not last_style.flags ^ style.flags:
                runs[-1] = (row, last_col, last_text + text, style)
                return
    runs.append((row, col, text, style))
