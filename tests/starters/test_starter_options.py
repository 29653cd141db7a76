"""Starter options: good values pass through, bad ones say what is allowed."""

import datetime

import pytest

from floatpage.model.errors import FloatpageError
from floatpage.starters.options import check_options


def test_year_defaults_to_next_year():
    options = check_options(year=None, first_weekday="monday", lang="en", orientation="portrait",
                            today=datetime.date(2026, 11, 21))
    assert options.year == 2027


def test_values_are_normalised():
    options = check_options(year=2030, first_weekday="Sunday", lang="DE", orientation="landscape")
    assert (options.year, options.first_weekday, options.lang, options.orientation) == \
        (2030, "sunday", "de", "landscape")


@pytest.mark.parametrize("field, value, says", [
    ("year", 0, "1 to 9999"),
    ("year", 10000, "1 to 9999"),
    ("year", True, "1 to 9999"),
    ("first_weekday", "funday", "monday, tuesday"),
    ("lang", "xx", "en, de, fr"),
    ("orientation", "sideways", "portrait or landscape"),
])
def test_bad_values_name_the_allowed_ones(field, value, says):
    values = dict(year=2027, first_weekday="monday", lang="en", orientation="portrait")
    values[field] = value
    with pytest.raises(FloatpageError, match=says):
        check_options(**values)
