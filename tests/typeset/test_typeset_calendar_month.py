"""The month grid and names in model.calendar_month (shared with the editor)."""

import calendar
import datetime

import pytest

from floatpage.model.calendar_month import (
    LANGUAGES, month_name, month_weeks, weekday_names, weekend_columns,
)
from floatpage.model.document import WEEKDAYS


@pytest.mark.parametrize("year", [1, 1582, 1900, 2000, 2024, 2027, 9999])
@pytest.mark.parametrize("first", WEEKDAYS)
def test_every_day_sits_under_its_weekday(year, first):
    for month in (1, 2, 12):
        weeks = month_weeks(year, month, first)
        days = [d for week in weeks for d in week if d]
        assert days == list(range(1, calendar.monthrange(year, month)[1] + 1))
        assert all(len(week) == 7 for week in weeks) and 4 <= len(weeks) <= 6
        start = WEEKDAYS.index(first)
        for week in weeks:
            for column, day in enumerate(week):
                if day:
                    assert datetime.date(year, month, day).weekday() == (start + column) % 7


def test_february_2026_starting_sunday():
    weeks = month_weeks(2026, 2, "sunday")  # 1 Feb 2026 is a Sunday
    assert weeks[0] == [1, 2, 3, 4, 5, 6, 7]
    assert len(weeks) == 4


def test_names_in_each_language():
    assert month_name(3, "de") == "März"
    assert month_name(8, "fr") == "Août"
    assert weekday_names("sunday", "en") == ("Sun", "Mon", "Tue", "Wed", "Thu", "Fri", "Sat")
    assert weekday_names("monday", "nl", abbreviated=False)[0] == "Maandag"
    assert weekday_names("monday", "es")[5] == "Sá"
    for language in LANGUAGES:
        assert len({month_name(m, language) for m in range(1, 13)}) == 12
        assert len(set(weekday_names("monday", language))) == 7


def test_weekend_columns_follow_the_first_weekday():
    assert weekend_columns("monday") == (5, 6)
    assert weekend_columns("sunday") == (0, 6)
    assert weekend_columns("saturday") == (0, 1)


def test_bad_input_is_refused():
    with pytest.raises(ValueError):
        month_weeks(0, 1)
    with pytest.raises(ValueError):
        month_weeks(2027, 13)
    with pytest.raises(ValueError):
        weekday_names("funday")
