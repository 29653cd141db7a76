"""Month panels in the PDF: leap years, months starting on every weekday, every first weekday.

One project holds a page per case and is rendered once; each panel is then read back from
the PDF and checked against Python's calendar by starter_pdf_checks.check_month.
"""

from __future__ import annotations

import calendar
import datetime

import pytest

from floatpage.model.document import WEEKDAYS, CalendarItem, Project
from floatpage.model.schema import CALENDAR_LANGUAGES
from starter_pdf_checks import check_month, day_marks
from floatpage.starters.placement import new_page

LEAP_CASES = [(2027, 2, 28), (2028, 2, 29), (2100, 2, 28), (2000, 2, 29)]


def months_starting_on_each_weekday(year: int) -> list[tuple[int, int]]:
    """For weekday 0..6, the first month of `year` whose first day falls on it."""
    found: dict[int, tuple[int, int]] = {}
    for month in range(1, 13):
        found.setdefault(datetime.date(year, month, 1).weekday(), (year, month))
    return [found[weekday] for weekday in range(7)]


def cases() -> list[tuple[int, int, str, str]]:
    """(year, month, first_weekday, language): each first weekday and language used at least once."""
    months = [(y, m) for y, m, _ in LEAP_CASES] + months_starting_on_each_weekday(2027)
    return [(y, m, WEEKDAYS[k % 7], CALENDAR_LANGUAGES[k % len(CALENDAR_LANGUAGES)])
            for k, (y, m) in enumerate(months)]


def panels_project() -> Project:
    pages = []
    for year, month, first_weekday, lang in cases():
        page = new_page(f"p{year}-{month:02d}-{first_weekday}", "A4", "portrait")
        page.items.append(CalendarItem(id=f"{page.id}-month", x=105.0, y=148.5, w=170.0, h=120.0,
                                       year=year, month=month, first_weekday=first_weekday,
                                       language=lang))
        pages.append(page)
    return Project(title="month panels", pages=pages)


def test_the_cases_cover_every_start_day_and_first_weekday():
    starts = {datetime.date(y, m, 1).weekday() for y, m, _, _ in cases()}
    assert starts == set(range(7))
    assert {first for _, _, first, _ in cases()} == set(WEEKDAYS)
    assert [calendar.monthrange(y, m)[1] for y, m, _ in LEAP_CASES] == [d for _, _, d in LEAP_CASES]


@pytest.fixture(scope="module")
def rendered(render_once):
    return render_once("month-panels", panels_project)


@pytest.mark.parametrize("index", range(len(cases())))
def test_panel_prints_its_month(rendered, index):
    year, month, first_weekday, _ = cases()[index]
    page = rendered.project.pages[index]
    [panel] = [item for item in page.items if isinstance(item, CalendarItem)]
    assert (panel.year, panel.month, panel.first_weekday) == (year, month, first_weekday)
    check_month(day_marks(rendered.plumber.pages[index], panel), year, month, first_weekday)


@pytest.mark.parametrize("year, month, days", LEAP_CASES)
def test_february_has_the_right_last_day(rendered, year, month, days):
    index = next(k for k, case in enumerate(cases()) if case[:2] == (year, month))
    panel = rendered.project.pages[index].items[0]
    printed = {mark.day for mark in day_marks(rendered.plumber.pages[index], panel)}
    assert max(printed) == days
