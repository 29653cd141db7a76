"""Where the preview puts a mark (`+` `#` anchors, `o` follow links) so that it reads as a mark.

A mark used to go on the cell of the point it marks: an anchor's `+` on the middle of the
picture it holds, which at 80x24 is a third of the flyer's small pictures; a link's `o` on a
caption's middle cell, which after a wrapped word is the cell right after it ("Daisyo",
issue 11). Now a mark takes the cell nearest its point among:

- the point's own cell, if it lies outside the marked item;
- the ring of cells just outside the item (its border), where no other item is;

and only a cell with no glyph on it or beside it, so it never glues to a word or another
mark. With no such cell, a large item (`INSIDE_MIN_CELLS` or more) takes the mark on the
point's cell inside it, where that cell and its sides hold no text; a smaller one goes
without, and `?` says so.
"""

from __future__ import annotations

import numpy as np

from floatpage.tui.cell_canvas import CellCanvas

Cells = tuple[int, int, int, int]  # col0, row0, col1, row1: the cells a box touches, ends out
INSIDE_MIN_CELLS = (6, 3)  # columns, rows: an item this large may carry its own mark inside


def touched_cells(box: tuple[int, int, int, int]) -> Cells:
    """The cells holding any pixel of an end-exclusive pixel box."""
    x0, y0, x1, y1 = box
    return x0, y0 // 2, max(x1, x0 + 1), max((y1 + 1) // 2, y0 // 2 + 1)


def occupancy(boxes, cols: int, rows: int) -> np.ndarray:
    """(rows, cols) bool: the cells some of the boxes (of cells) touch, built once a frame:
    testing every candidate cell against every item made the flyer's frame 6x dearer."""
    taken = np.zeros((rows, cols), dtype=bool)
    for col0, row0, col1, row1 in boxes:
        taken[max(row0, 0):max(row1, 0), max(col0, 0):max(col1, 0)] = True
    return taken


def inside(cells: Cells, col: int, row: int) -> bool:
    return cells[0] <= col < cells[2] and cells[1] <= row < cells[3]


def ring(cells: Cells) -> list[tuple[int, int]]:
    """The cells just outside a box of cells, all the way round."""
    col0, row0, col1, row1 = cells
    around = [(col, row) for col in range(col0 - 1, col1 + 1) for row in (row0 - 1, row1)]
    around += [(col, row) for row in range(row0, row1) for col in (col0 - 1, col1)]
    return around


def free(canvas: CellCanvas, col: int, row: int) -> bool:
    """On the canvas, with no glyph on the cell or on either side of it."""
    return 0 <= col < canvas.cols and 0 <= row < canvas.rows and all(
        canvas.glyph_at(c, row) is None for c in (col - 1, col, col + 1))


def beside_text(canvas: CellCanvas, col: int, row: int) -> bool:
    """A letter or digit on the cell or either side of it (a dot there would glue to it)."""
    for c in (col - 1, col, col + 1):
        glyph = canvas.glyph_at(c, row)
        if glyph is not None and glyph.char.isalnum():
            return True
    return False


def mark_cell(canvas: CellCanvas, own: Cells, target: tuple[int, int],
              taken: np.ndarray) -> tuple[int, int] | None:
    """The cell for a mark of the item on `own` cells pointing at `target` (the anchor's
    cell, or the followed item's), or None when the item should go without (see above).
    ``taken`` is the `occupancy` of the page's items (the marked one's own cells are never
    candidates, so its own part in it does not matter)."""
    tc, tr = target

    def distance(cell: tuple[int, int]) -> float:
        return (cell[0] - tc) ** 2 + (2 * (cell[1] - tr)) ** 2  # a cell is twice as tall

    candidates = ring(own)
    if not inside(own, tc, tr):
        candidates.append(target)
    candidates.sort(key=distance)  # nearest first, each tested only until one is found
    rows, cols = taken.shape
    for col, row in candidates:  # another item's cell first: the cheaper test, and the usual
        if 0 <= row < rows and 0 <= col < cols and not taken[row, col] \
                and free(canvas, col, row):
            return col, row
    col0, row0, col1, row1 = own
    if col1 - col0 >= INSIDE_MIN_CELLS[0] and row1 - row0 >= INSIDE_MIN_CELLS[1]:
        cell = (min(max(tc, col0), col1 - 1), min(max(tr, row0), row1 - 1))
        if free(canvas, *cell):
            return cell
    return None
