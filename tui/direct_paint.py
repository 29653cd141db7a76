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
terminal's colour system (truecolour, 256 colours), after the App's line filters (NO_COLOR's
greys), so the screen is the same either way (tests/tui/test_editor_direct_paint.py compares
it with Textual's own full repaint).
"""

from __future__ import annotations

from contextlib import contextmanager
from typing import Callable, Iterator

from rich.cells import cell_len
from rich.segment import Segment
from rich.style import Style as RichStyle
from textual.color import Color
from textual.filter import LineFilter
from textual.geometry import Region
from textual.strip import Strip
from textual.widget import Widget

from floatpage.tui.cell_canvas import STYLES_KEPT, StripCache
from floatpage.tui.sgr_compactor import DEFAULT, SHOWN_ON_BLANKS, Style, apply_sgr

Run = tuple[int, int, str, Style]  # screen row, screen column, text, style


class DirectPainter:
    """Paints widgets' changed cells through the driver, when nothing else is on them.

    Inside `answer()` the cells of every widget painted go out together, in one write when
    the block ends: a key's answer (the moved item, then the top bar's "at 96, 175 mm") came
    in two writes 3-4 ms apart, the second through Textual's next screen update."""

    def __init__(self):
        self._styles: dict[RichStyle, Style | None] = {}
        self._cell_styles: dict[tuple, Style | None] = {}
        self._batch: list[tuple[list[Run], Callable[[], None], Callable[[], None]]] | None = None
        self._batch_app = None

    def paint(self, widget: Widget, cache: StripCache) -> bool:
        """Send `cache.changed` to the terminal; False (nothing sent) when it cannot be. Inside
        `answer()`, True means "to be sent", and Textual refreshes the rows should the block's
        write fail."""
        if not self.may_paint(widget, cache.cols, cache.rows):
            return False
        color_system = widget.app.console._color_system
        looks = LineLooks(tuple(widget.get_line_filters()), widget.background_colors[1])
        region = widget.content_region
        runs: list[Run] = []
        cell_style = self.cell_style
        for row, spans in sorted(cache.changed.items()):
            for first, end in spans:
                col, cell_runs = cache.runs(row, first, end)
                for text, cells, fg, bg, bold in cell_runs:
                    style = cell_style(cache, fg, bg, bold, color_system, looks)
                    if style is None:
                        return False
                    add_run(runs, region.y + row, region.x + col, text, style)
                    col += cells
        offset, width = widget.content_offset, widget.size.width
        rows = list(cache.changed)

        def sent() -> None:
            for row in rows:  # what Textual cached of these lines is stale: rendered again
                widget._styles_cache.set_dirty(Region(offset.x, offset.y + row, width, 1))

        refresh = getattr(widget, "refresh_changed_rows", widget.refresh)
        return self._send(widget.app, runs, sent, refresh)

    def paint_lines(self, widget: Widget) -> bool:
        """The widget's lines as Textual renders them (`Widget.render_lines`, which caches
        them for Textual's own repaints), sent in place of Textual's own update of them; the
        caller refreshes the widget only when this returns False (cannot be sent). Should the
        gathered write fail (`answer`), the widget is refreshed. For a line of text, the top
        bar (`PageBar.show` with `refresh=False`)."""
        region = widget.region
        if not self.may_paint(widget, region.width, region.height, content=False):
            return False
        color_system = widget.app.console._color_system
        runs: list[Run] = []
        for row, strip in enumerate(widget.render_lines(Region(0, 0, *region.size))):
            col = region.x
            for segment in strip:
                if segment.control:
                    return False
                style = self.terminal_style(segment.style, color_system)
                if style is None:
                    return False
                add_run(runs, region.y + row, col, segment.text, style)
                col += cell_len(segment.text)
        return self._send(widget.app, runs, lambda: None, widget.refresh)

    def may_paint(self, widget: Widget, cols: int, rows: int, content: bool = True) -> bool:
        """A terminal to paint on, whose cells of the widget are the widget's alone."""
        app = widget.app
        if getattr(app._driver, "paint_cells", None) is None or app.is_headless:
            return False
        if not app._running or app._closed:  # as Textual's own `_display` checks: the writer
            return False                      # thread may be gone (its queue would fill up)
        if app.console._color_system is None:
            return False
        return self.sole_owner(widget, cols, rows, content)

    def _send(self, app, runs: list[Run], sent: Callable[[], None],
              failed: Callable[[], None]) -> bool:
        if self._batch is not None and self._batch_app is app:
            self._batch.append((runs, sent, failed))
            return True
        if not app._driver.paint_cells(runs):
            return False
        sent()
        return True

    @contextmanager
    def answer(self, app) -> Iterator[None]:
        """Gather what is painted in the block, and send it in one write at its end; if the
        write cannot be made (the shadow screen lost track meanwhile), Textual draws it all."""
        if self._batch is not None:  # already gathering: the outer block sends
            yield
            return
        self._batch, self._batch_app = [], app
        try:
            yield
        finally:
            batch, self._batch, self._batch_app = self._batch, None, None
        if not batch:
            return
        driver = app._driver
        runs = [run for part, _, _ in batch for run in part]
        written = app._running and not app._closed and driver is not None \
            and driver.paint_cells(runs)
        for _, sent, failed in batch:
            (sent if written else failed)()

    @staticmethod
    def sole_owner(widget: Widget, cols: int, rows: int, content: bool = True) -> bool:
        """The widget's cells are its own on the terminal: its screen is shown, laid out at
        `cols` x `rows` (its content region's, or with `content=False` its whole region's),
        and no other widget overlaps it."""
        screen = widget.screen
        if screen is not widget.app.screen or not screen.is_current:
            return False
        if screen._layout_required or screen._repaint_required:
            return False  # Textual is about to repaint (or move) it anyway
        region = widget.content_region if content else widget.region
        if (region.width, region.height) != (cols, rows) \
                or not screen.region.contains_region(region):
            return False
        ancestors = set(widget.ancestors_with_self)
        for other in screen._compositor.visible_widgets:
            if other not in ancestors and other.region.overlaps(region):
                return False
        return True

    def cell_style(self, cache: StripCache, fg: int, bg: int, bold: bool,
                   color_system, looks: LineLooks) -> Style | None:
        """The terminal style of the preview's cells in these packed colours: the one its
        Rich style gives (`terminal_style`) once the App's line filters have passed over it,
        looked up by the colours without making it."""
        key = (fg, bg, bold, color_system, looks.key)
        try:
            return self._cell_styles[key]
        except KeyError:
            if len(self._cell_styles) >= STYLES_KEPT:  # a long session's pages of photos
                self._cell_styles.clear()
                self._styles.clear()
            style = looks.filtered(cache.style(fg, bg, bold))
            known = self._cell_styles[key] = self.terminal_style(style, color_system)
            return known

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


class LineLooks:
    """The App's line filters, as Textual passes every line it renders through them. With
    `NO_COLOR` set, Textual's Monochrome filter turns each colour grey; the cells painted here
    went out in full colour beside Textual's grey ones (a moved photo in colour on a grey
    page), so they pass through the same filters, with the widget's background as Textual
    gives it."""

    def __init__(self, filters: tuple[LineFilter, ...], background: Color):
        self.filters = filters
        self.background = background
        self.key = (tuple(id(one) for one in filters), background)

    def filtered(self, style: RichStyle) -> RichStyle | None:
        segments = [Segment(" ", style)]
        for one in self.filters:
            segments = one.apply(segments, self.background)
        return segments[0].style


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
