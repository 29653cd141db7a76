"""The page preview: a Line API widget over a cell grid rebuilt at most once per frame.

The screen hands it a PageView with `show(view)`; the widget paints it into a grid and
sends the changed cells to the terminal itself (`direct_paint`), or, when something else
may be over them, refreshes the changed regions through Textual. `render_line` reads the
rows' Strips, built when Textual asks for them. Mouse presses and drags go up as messages in
millimetres, so the screen never deals in cells.
"""

from __future__ import annotations

from dataclasses import dataclass

from textual import events
from textual.geometry import Region
from textual.message import Message
from textual.strip import Strip
from textual.widget import Widget

from floatpage.tui.cell_canvas import CellCanvas, StripCache
from floatpage.tui.direct_paint import DirectPainter
from floatpage.tui.page_painter import PagePainter, PageView
from floatpage.tui.projection import Projection


class PagePreview(Widget, can_focus=True):
    """The current page, fitted to the widget with its aspect ratio, in half-block pixels."""

    DEFAULT_CSS = """
    PagePreview {
        width: 1fr;
        height: 1fr;
        background: rgb(38, 38, 46);
    }
    """

    @dataclass
    class ItemPressed(Message):
        """The mouse went down on an item (item_id) or on empty page (None), at x, y in mm."""

        item_id: str | None
        x_mm: float
        y_mm: float

    @dataclass
    class ItemDragged(Message):
        """The pressed item is being dragged; its centre should go to x, y (mm)."""

        item_id: str
        x_mm: float
        y_mm: float

    @dataclass
    class DragEnded(Message):
        item_id: str

    def __init__(self, *, id: str | None = None):
        super().__init__(id=id)
        self.view: PageView | None = None
        self.projection: Projection | None = None
        self.canvas: CellCanvas | None = None  # the last frame's grid, kept for hit tests and tests
        self._cache = StripCache()
        self.direct = DirectPainter()
        self._drag: tuple[str, float, float] | None = None  # item id, grab offset x, y (mm)
        self.frames_drawn = 0
        self.unchanged_frames = 0  # frames in a row that changed no cell of the preview

    @property
    def dragging(self) -> bool:
        """Whether the mouse holds an item (a button down on it, not yet up)."""
        return self._drag is not None

    # -- drawing -------------------------------------------------------------------------

    def show(self, view: PageView) -> None:
        """Paint a view and refresh once."""
        self.view = view
        self.redraw()

    def redraw(self) -> None:
        if self.view is None:
            return
        width, height = self.size
        if width < 1 or height < 1:
            return
        page = self.view.page
        projection = Projection.fit(width, height, page.width_mm, page.height_mm)
        self.projection = projection
        canvas = PagePainter(projection).paint(self.view)
        self.canvas = canvas
        shape = (self._cache.rows, self._cache.cols)
        self._cache.update(canvas)
        self.frames_drawn += 1
        self.unchanged_frames = 0 if self._cache.changed else self.unchanged_frames + 1
        if shape != (canvas.rows, canvas.cols):
            self.refresh()
        elif self._cache.changed and not self.direct.paint(self, self._cache):
            self.refresh_changed_rows()

    def refresh_changed_rows(self) -> None:
        """Repaint only the cells that changed: a whole-preview refresh sent 13-19 KB a frame
        over SSH, although a moving item changes a few columns of a few rows (issue 11).
        Rows with the same changed columns go as one region."""
        run: tuple[int, int, int, int] | None = None  # first row, rows, first col, end col
        for row in sorted(self._cache.changed):
            spans = self._cache.changed[row]
            first, end = spans[0][0], spans[-1][1]  # Textual resends a line's run as one
            if run is not None and run[0] + run[1] == row and run[2:] == (first, end):
                run = (run[0], run[1] + 1, first, end)
                continue
            if run is not None:
                self.refresh(Region(run[2], run[0], run[3] - run[2], run[1]))
            run = (row, 1, first, end)
        if run is not None:
            self.refresh(Region(run[2], run[0], run[3] - run[2], run[1]))

    def on_resize(self, event: events.Resize) -> None:
        self.redraw()

    def render_line(self, y: int) -> Strip:
        if 0 <= y < self._cache.rows:
            return self._cache.strip(y)
        # A styled blank: Textual's NO_COLOR filter (Monochrome) reads every segment's style
        # and raised on an unstyled one, so the editor died with a traceback at start.
        return Strip.blank(self.size.width, self.rich_style)

    def strips(self) -> list[Strip]:
        """The preview's rows as Textual renders them."""
        return [self._cache.strip(row) for row in range(self._cache.rows)]

    def text_lines(self) -> list[str]:
        """The preview as plain text, row by row (for tests and for reading over SSH logs)."""
        return [strip.text for strip in self.strips()]

    # -- hit testing and the mouse ---------------------------------------------------------

    def item_at(self, col: int, row: int) -> str | None:
        """Topmost item under a cell, in painting order; None on empty page or outside it."""
        if self.view is None or self.projection is None:
            return None
        x_mm, y_mm = self.projection.mm_at(col, row)
        half_cell = 0.5 / self.projection.scale
        hits = []
        for item in self.view.page.items:
            x, y = self.view.positions.get(item.id, (item.x, item.y))
            if abs(x_mm - x) <= item.w / 2 + half_cell and abs(y_mm - y) <= item.h / 2 + half_cell:
                hits.append(item)
        if not hits:
            return None
        return max(hits, key=lambda item: (not item.decorative, item.z,
                                           self.view.page.items.index(item))).id

    def cell_centre_of(self, item_id: str) -> tuple[int, int]:
        """The cell under an item's centre (for tests that click on items)."""
        assert self.view is not None and self.projection is not None
        item = self.view.page.item(item_id)
        return self.projection.cell_of(*self.view.positions.get(item_id, (item.x, item.y)))

    def on_mouse_down(self, event: events.MouseDown) -> None:
        if self.projection is None or event.button != 1:
            return
        self.focus()
        item_id = self.item_at(event.x, event.y)
        x_mm, y_mm = self.projection.mm_at(event.x, event.y)
        self.post_message(self.ItemPressed(item_id, x_mm, y_mm))
        if item_id is not None and self.view is not None:
            item = self.view.page.item(item_id)
            x, y = self.view.positions.get(item_id, (item.x, item.y))
            self._drag = (item_id, x - x_mm, y - y_mm)
            self.capture_mouse()

    def on_mouse_move(self, event: events.MouseMove) -> None:
        if self._drag is None or self.projection is None:
            return
        item_id, grab_x, grab_y = self._drag
        x_mm, y_mm = self.projection.mm_at(event.x, event.y)
        self.post_message(self.ItemDragged(item_id, x_mm + grab_x, y_mm + grab_y))

    def on_mouse_up(self, event: events.MouseUp) -> None:
        if self._drag is None:
            return
        item_id = self._drag[0]
        self._drag = None
        self.release_mouse()
        self.post_message(self.DragEnded(item_id))
