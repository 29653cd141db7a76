"""Read a compiled PDF back: which glyphs fell in which box, and how full each box is."""

from __future__ import annotations

from dataclasses import dataclass

PT_PER_MM = 72 / 25.4


@dataclass(frozen=True)
class BoxPt:
    """An item's rectangle in PDF points, top-down like pdfplumber."""

    x0: float
    top: float
    x1: float
    bottom: float

    @classmethod
    def of_item(cls, item) -> "BoxPt":
        return cls((item.x - item.w / 2) * PT_PER_MM, (item.y - item.h / 2) * PT_PER_MM,
                   (item.x + item.w / 2) * PT_PER_MM, (item.y + item.h / 2) * PT_PER_MM)

    def holds_centre(self, obj, margin: float) -> bool:
        cx, cy = (obj["x0"] + obj["x1"]) / 2, (obj["top"] + obj["bottom"]) / 2
        return (self.x0 - margin <= cx <= self.x1 + margin
                and self.top - margin <= cy <= self.bottom + margin)

    def overflow(self, obj) -> float:
        """How far (pt) an object sticks out of the box; 0 when inside."""
        return max(0.0, self.x0 - obj["x0"], obj["x1"] - self.x1,
                   self.top - obj["top"], obj["bottom"] - self.bottom)


def chars_in(page, box: BoxPt, margin_pt: float) -> list[dict]:
    """Glyphs whose centre lies within `margin_pt` of the box, in content-stream order."""
    return [c for c in page.chars if box.holds_centre(c, margin_pt) and c["text"].strip()]


def fill(chars: list[dict], box: BoxPt) -> tuple[float, float]:
    """(width fill, height fill) of the glyphs' advance boxes."""
    if not chars:
        return 0.0, 0.0
    width = max(c["x1"] for c in chars) - min(c["x0"] for c in chars)
    height = max(c["bottom"] for c in chars) - min(c["top"] for c in chars)
    return width / (box.x1 - box.x0), height / (box.bottom - box.top)


def edges_match(obj, box: BoxPt) -> float:
    """Largest distance (pt) between an object's edges and the box's."""
    return max(abs(obj["x0"] - box.x0), abs(obj["x1"] - box.x1),
               abs(obj["top"] - box.top), abs(obj["bottom"] - box.bottom))
