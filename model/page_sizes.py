"""Named page sizes, in millimetres, portrait (width <= height)."""

from __future__ import annotations

import re

PAGE_SIZES_MM: dict[str, tuple[float, float]] = {
    "A3": (297.0, 420.0),
    "A4": (210.0, 297.0),
    "A5": (148.0, 210.0),
    "Letter": (215.9, 279.4),
    "5x7in": (127.0, 177.8),
    "5x8in": (127.0, 203.2),
    "4x6in": (101.6, 152.4),
    # A postcard's and a folded card's size in most of the world, and the long flyer that
    # fits an envelope: "A6" was refused with 'did you mean "A5"?', which prints twice as
    # large (user-walk-9). Last, so the editor's size list keeps its first places.
    "A6": (105.0, 148.0),
    "DL": (99.0, 210.0),
}
CUSTOM = "custom"


def canonical_size_name(name: str) -> str | None:
    """Map the spellings people use ("a4", "5x7 in", "letter") to the table's key, or None."""
    squashed = re.sub(r"\s+", "", name).lower()
    if squashed == CUSTOM:
        return CUSTOM
    for key in PAGE_SIZES_MM:
        if key.lower() == squashed:
            return key
    return None


def page_dimensions(size: str, orientation: str, width_mm: float | None = None,
                    height_mm: float | None = None) -> tuple[float, float]:
    """Width and height of a page in mm after orientation is applied."""
    if size == CUSTOM:
        # A custom page is exactly what the user typed; its orientation follows from it.
        if width_mm is None or height_mm is None:
            raise ValueError("a custom page needs width_mm and height_mm")
        return float(width_mm), float(height_mm)
    short, long_ = PAGE_SIZES_MM[size]
    return (long_, short) if orientation == "landscape" else (short, long_)
