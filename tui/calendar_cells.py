"""A month panel in the cells it has: every day of the month, in the richest layout that fits.

The preview gives a calendar panel the cells its box covers: at 80x24 the calendar sample's
month is 21 cells by 4-5 rows, and the printed layout (title, weekday heads, up to six
weeks of three cells a day) was cut after its third week, at the 17th (issue 11: "calendar
panels are whole"). So a panel drops what it can spare, in this order, until every day fits:

1. the weekday heads, then the title;
2. the weekday columns: the days run on from 1 as text does;
3. the spaces between days: two cells a day, every other day shaded so "1011" reads as two
   (in weekday columns again first, then run on).

When even that does not fit, the panel says which month it is and which days it holds,
"Jan 1-31", or only "Jan" (cut at the panel's edge) in fewer cells. `?` in the editor says the same (dialogs.help).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

from floatpage.model.calendar_month import month_name, month_weeks, weekday_names
from floatpage.tui.cell_text import graphemes, width

Piece = tuple[str, bool]  # text, shaded (every other day, in the two-cell layouts)
Line = tuple[Piece, ...]


@dataclass(frozen=True)
class MonthText:
    """What the panel shows of a month: the title, the weekday heads and its weeks."""

    title: str
    short_title: str
    heads: tuple[str, ...]  # two letters each, from the first weekday
    weeks: tuple[tuple[int, ...], ...]  # seven days each, 0 outside the month

    @property
    def days(self) -> int:
        return max(max(week) for week in self.weeks)


@lru_cache(maxsize=256)
def month_text(year: int, month: int, first_weekday: str, language: str) -> MonthText | None:
    """None for a month the model cannot lay out (the panel then shows its raw numbers)."""
    try:
        name = month_name(month, language)
        heads = tuple(name[:2] for name in weekday_names(first_weekday, language))
        weeks = tuple(tuple(week) for week in month_weeks(year, month, first_weekday))
    except ValueError:
        return None
    return MonthText(f"{name} {year}", name[:3], heads, weeks)


def plain(text: str) -> Line:
    return ((text, False),)


def spaced_week(week: tuple[int, ...]) -> Line:
    return plain(" ".join(f"{day:2d}" if day else "  " for day in week))


def packed(days: list[int]) -> Line:
    """Two cells a day, no space between; every other day of the month shaded."""
    return tuple((f"{day:2d}" if day else "  ", bool(day) and day % 2 == 0) for day in days)


def packed_heads(heads: tuple[str, ...]) -> Line:
    return tuple((head, index % 2 == 1) for index, head in enumerate(heads))


def runs_of(days: int, per_line: int) -> list[list[int]]:
    numbers = list(range(1, days + 1))
    return [numbers[start:start + per_line] for start in range(0, days, per_line)]


def flow(month: MonthText, cols: int, cells_a_day: int) -> list[Line]:
    """The days from 1 on, as many to a line as fit, with no weekday columns."""
    if cells_a_day == 3:
        return [plain(" ".join(f"{day:2d}" for day in days))
                for days in runs_of(month.days, max((cols + 1) // 3, 1))]
    return [packed(days) for days in runs_of(month.days, max(cols // 2, 1))]


def layouts(month: MonthText, cols: int):
    """The candidate layouts, richest first, each a list of lines: spaced days before
    packed ones, and in each, weekday columns before a flow; the title and heads go first."""
    title, heads = plain(month.title), plain(" ".join(month.heads))
    spaced = [spaced_week(week) for week in month.weeks]
    yield [title, heads, *spaced]
    yield [title, *spaced]
    yield spaced
    yield [title, *flow(month, cols, 3)]
    yield flow(month, cols, 3)
    compact = [packed(list(week)) for week in month.weeks]
    yield [title, packed_heads(month.heads), *compact]
    yield [title, *compact]
    yield compact
    yield [title, *flow(month, cols, 2)]
    yield flow(month, cols, 2)


def cells(text: str) -> int:
    return sum(width(grapheme) for grapheme in graphemes(text))


def line_cells(line: Line) -> int:
    return sum(cells(text) for text, _shaded in line)


@lru_cache(maxsize=1024)
def month_lines(month: MonthText, cols: int, rows: int) -> tuple[tuple[Line, ...], bool]:
    """The richest layout of the whole month in cols x rows cells, and True; or, when no
    layout fits, the month's short name and day range ("Jan 1-31"), or only its name where
    the range does not fit either, and False. Cached: a frame asks for every panel's."""
    for lines in layouts(month, cols):
        if len(lines) <= rows and all(line_cells(line) <= cols for line in lines):
            return tuple(lines), True
    summary = f"{month.short_title} 1-{month.days}"
    return (plain(summary if cells(summary) <= cols else month.short_title),), False
