"""The month checker itself: it passes a correct grid and catches each kind of mistake.

Without these, a checker that accepted anything would make the PDF tests pass for nothing.
"""

import calendar
import datetime

import pytest

from floatpage.model.document import WEEKDAYS
from starter_pdf_checks import DayMark, check_month, cluster

CELL = 20.0


def grid_marks(year, month, first_weekday, *, misplace=None, drop=None, extra=None):
    """Marks where a correct panel prints them; optionally one day moved, dropped or added."""
    start = WEEKDAYS.index(first_weekday)
    first_column = (datetime.date(year, month, 1).weekday() - start) % 7
    marks = []
    for day in range(1, calendar.monthrange(year, month)[1] + 1):
        if day == drop:
            continue
        row, column = divmod(first_column + day - 1, 7)
        if day == misplace:
            column = (column + 1) % 7
        marks.append(DayMark(day, 100 + column * CELL + (day >= 10) * 2.5, 300 + row * CELL))
    if extra:
        marks.append(DayMark(extra, 100, 300))
    return marks


@pytest.mark.parametrize("year, month", [(2027, 2), (2028, 2), (2000, 2), (2100, 2), (2027, 8)])
@pytest.mark.parametrize("first_weekday", ["monday", "sunday", "wednesday"])
def test_a_correct_panel_passes(year, month, first_weekday):
    check_month(grid_marks(year, month, first_weekday), year, month, first_weekday)


def test_a_day_in_the_wrong_column_fails():
    with pytest.raises(AssertionError, match="2027-03-10"):
        check_month(grid_marks(2027, 3, "monday", misplace=10), 2027, 3, "monday")


def test_the_wrong_first_weekday_fails():
    with pytest.raises(AssertionError, match="column"):
        check_month(grid_marks(2027, 3, "sunday"), 2027, 3, "monday")


def test_a_missing_day_fails():
    with pytest.raises(AssertionError, match="expected 1..31"):
        check_month(grid_marks(2027, 3, "monday", drop=17), 2027, 3, "monday")


def test_a_leap_day_in_a_common_year_fails():
    """A panel that printed 2028's February for 2100 (not a leap year) is caught."""
    with pytest.raises(AssertionError, match="expected 1..28"):
        check_month(grid_marks(2028, 2, "monday"), 2100, 2, "monday")


def test_a_day_printed_twice_fails():
    with pytest.raises(AssertionError, match="printed days"):
        check_month(grid_marks(2027, 4, "monday", extra=30), 2027, 4, "monday")


def test_cluster_splits_at_the_widest_gaps():
    assert cluster([1.0, 1.5, 10.0, 10.2, 30.0], 3) == {1.0: 0, 1.5: 0, 10.0: 1, 10.2: 1, 30.0: 2}
