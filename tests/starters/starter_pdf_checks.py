"""Read a rendered PDF back and check it: page sizes, and the days of every month panel.

The month check is independent of the typesetter's own month grid: the expected weekday of
each day comes from Python's `datetime`, and the columns are found from where the numbers
actually landed on the page (the six widest horizontal gaps between day numbers separate the
seven columns), so a panel that puts a day under the wrong weekday fails.
"""

from __future__ import annotations

import calendar
import datetime
from dataclasses import dataclass

from floatpage.model.document import WEEKDAYS

PT_PER_MM = 72 / 25.4
SIZE_TOLERANCE_PT = 0.5


@dataclass(frozen=True)
class DayMark:
    """A day number as printed: its value and the centre of its glyphs, pt from the top left."""

    day: int
    x: float
    y: float


def page_sizes_pt(pdf) -> list[tuple[float, float]]:
    """(width, height) of each page of a pdfplumber PDF, in pt."""
    return [(float(page.width), float(page.height)) for page in pdf.pages]


def assert_page_sizes(pdf, pages) -> None:
    """Every PDF page has its model page's size, within half a point."""
    sizes = page_sizes_pt(pdf)
    assert len(sizes) == len(pages), f"{len(sizes)} PDF pages for {len(pages)} project pages"
    for (w_pt, h_pt), page in zip(sizes, pages):
        assert abs(w_pt - page.width_mm * PT_PER_MM) <= SIZE_TOLERANCE_PT, page.id
        assert abs(h_pt - page.height_mm * PT_PER_MM) <= SIZE_TOLERANCE_PT, page.id


def day_marks(plumber_page, item) -> list[DayMark]:
    """Day numbers (1..31) printed inside the item's rectangle on a pdfplumber page."""
    left, top = item.left * PT_PER_MM, item.top * PT_PER_MM
    right, bottom = left + item.w * PT_PER_MM, top + item.h * PT_PER_MM
    marks = []
    for word in plumber_page.extract_words(keep_blank_chars=False, use_text_flow=False):
        x, y = (word["x0"] + word["x1"]) / 2, (word["top"] + word["bottom"]) / 2
        if not (left <= x <= right and top <= y <= bottom):
            continue
        text = word["text"]
        if text.isdigit() and 1 <= int(text) <= 31:
            marks.append(DayMark(int(text), x, y))
    return marks


def cluster(values: list[float], groups: int) -> dict[float, int]:
    """Index (0 = smallest) of the group each value falls in, split at the widest gaps."""
    ordered = sorted(set(values))
    if len(ordered) < groups:
        raise AssertionError(f"only {len(ordered)} distinct positions for {groups} groups")
    gaps = sorted(range(1, len(ordered)), key=lambda k: ordered[k] - ordered[k - 1], reverse=True)
    cuts = sorted(gaps[:groups - 1])
    index, result = 0, {}
    for k, value in enumerate(ordered):
        if index < len(cuts) and k == cuts[index]:
            index += 1
        result[value] = index
    return result


def check_month(marks: list[DayMark], year: int, month: int, first_weekday: str) -> None:
    """Each day of the month printed once, in its weekday's column and its week's row.

    Raises AssertionError naming the first day out of place.
    """
    days_in_month = calendar.monthrange(year, month)[1]
    printed = sorted(mark.day for mark in marks)
    assert printed == list(range(1, days_in_month + 1)), \
        f"{year}-{month:02d}: printed days {printed}, expected 1..{days_in_month}"
    start = WEEKDAYS.index(first_weekday)
    first_column = (datetime.date(year, month, 1).weekday() - start) % 7
    rows = (first_column + days_in_month + 6) // 7
    column_of = cluster([m.x for m in marks], 7)
    row_of = cluster([m.y for m in marks], rows)
    for mark in marks:
        weekday = datetime.date(year, month, mark.day).weekday()
        want_column = (weekday - start) % 7
        want_row = (first_column + mark.day - 1) // 7
        assert column_of[mark.x] == want_column, (
            f"{year}-{month:02d}-{mark.day:02d} ({WEEKDAYS[weekday]}) printed in column "
            f"{column_of[mark.x] + 1}, expected column {want_column + 1} of a {first_weekday}-first week")
        assert row_of[mark.y] == want_row, (
            f"{year}-{month:02d}-{mark.day:02d} printed in week row {row_of[mark.y] + 1}, "
            f"expected row {want_row + 1}")
