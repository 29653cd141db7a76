"""The order a reader meets the items on a page: rows from top to bottom, each left to right.

Tab walks the items in this order, so it must not jump around when two items
sit side by side at slightly different heights.
"""

from __future__ import annotations

from typing import Iterable, Protocol


class Box(Protocol):
    id: str
    x: float
    y: float
    h: float


def reading_order(items: Iterable[Box]) -> list[str]:
    """Item ids in reading order.

    Items are taken by their top edge; an item joins the current row when its
    centre lies above the bottom of the row's first item, so boxes that overlap
    vertically read left to right.
    """
    by_top = sorted(items, key=lambda item: (item.y - item.h / 2, item.x))
    rows: list[list[Box]] = []
    row_bottom = float("-inf")
    for item in by_top:
        if rows and item.y < row_bottom:
            rows[-1].append(item)
        else:
            rows.append([item])
            row_bottom = item.y + item.h / 2
    return [item.id for row in rows for item in sorted(row, key=lambda item: item.x)]


def step_through(order: list[str], current: str | None, step: int) -> str | None:
    """The id `step` places after `current` in `order`, wrapping; the first (or last) if none."""
    if not order:
        return None
    if current not in order:
        return order[0] if step > 0 else order[-1]
    return order[(order.index(current) + step) % len(order)]
