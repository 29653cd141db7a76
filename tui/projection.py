"""Where the page lands in the preview: millimetres to half-block pixels and back.

A terminal cell is about twice as tall as it is wide, so a half-block pixel
(one cell wide, half a cell tall) is close to square; one scale for both axes
keeps the page's aspect ratio. Only the preview converts between page
coordinates and cells; everything else speaks millimetres.
"""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class Projection:
    """The page's place in a cols x rows cell area. Pixels: x = column, y = half-row."""

    cols: int
    rows: int
    page_w_mm: float
    page_h_mm: float
    scale: float  # pixels per millimetre, both axes
    left: int  # page's left edge, in pixels from the widget's left
    top: int  # page's top edge, in pixels from the widget's top
    width: int  # page width in pixels
    height: int  # page height in pixels

    @classmethod
    def fit(cls, cols: int, rows: int, page_w_mm: float, page_h_mm: float,
            margin: int = 1) -> "Projection":
        """The largest page that fits with `margin` cells around it, centred."""
        cols, rows = max(cols, 1), max(rows, 1)
        room_w = max(cols - 2 * margin, 1)
        room_h = max(2 * (rows - 2 * margin), 1)
        scale = min(room_w / page_w_mm, room_h / page_h_mm)
        width = max(1, min(room_w, round(page_w_mm * scale)))
        height = max(1, min(room_h, round(page_h_mm * scale)))
        left = (cols - width) // 2
        top = (2 * rows - height) // 2
        return cls(cols, rows, page_w_mm, page_h_mm, scale, left, top, width, height)

    def to_pixels(self, x_mm: float, y_mm: float) -> tuple[float, float]:
        return self.left + x_mm * self.scale, self.top + y_mm * self.scale

    def rect(self, x_mm: float, y_mm: float, w_mm: float, h_mm: float) -> tuple[int, int, int, int]:
        """Pixel box (x0, y0, x1, y1), end-exclusive, of a rectangle centred at (x, y).

        Its size in pixels depends on the rectangle's size alone, not on where it is: with
        both edges rounded on their own, a moving picture grew and shrank by a pixel row, so
        it was scaled again and every one of its cells resent (one arrow on the greeting card
        drew its photo three times, 8 KB each over SSH; issue 11). At least one pixel each
        way, so the smallest item stays visible.
        """
        fx0, fy0 = self.to_pixels(x_mm - w_mm / 2, y_mm - h_mm / 2)
        x0, y0 = round(fx0), round(fy0)
        width = max(round(w_mm * self.scale), 1)
        height = max(round(h_mm * self.scale), 1)
        return x0, y0, x0 + width, y0 + height

    def cell_of(self, x_mm: float, y_mm: float) -> tuple[int, int]:
        """(column, row) of the cell holding a page point."""
        px, py = self.to_pixels(x_mm, y_mm)
        return math.floor(px), math.floor(py / 2)

    def mm_at(self, col: float, row: float) -> tuple[float, float]:
        """Page point under the middle of a cell (fractional cells allowed)."""
        return ((col + 0.5 - self.left) / self.scale, (2 * row + 1 - self.top) / self.scale)
