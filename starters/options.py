"""The options every starter takes, checked once so each builder can trust them."""

from __future__ import annotations

import datetime
from dataclasses import dataclass

from floatpage.model.document import WEEKDAYS
from floatpage.model.errors import FloatpageError
from floatpage.model.schema import CALENDAR_LANGUAGES

ORIENTATIONS = ("portrait", "landscape")


@dataclass(frozen=True)
class Options:
    """Validated starter options; `year` is always set (next year when the user gave none)."""

    year: int
    first_weekday: str = "monday"
    lang: str = "en"
    orientation: str = "portrait"


def check_options(*, year: int | None, first_weekday: str, lang: str, orientation: str,
                  today: datetime.date | None = None) -> Options:
    """Turn raw CLI values into Options, or raise FloatpageError saying what is allowed."""
    if year is None:
        year = (today or datetime.date.today()).year + 1
    if isinstance(year, bool) or not isinstance(year, int) or not 1 <= year <= 9999:
        raise FloatpageError(f"--year {year!r} is not a year floatpage can print (use 1 to 9999)")
    weekday = str(first_weekday).lower()
    if weekday not in WEEKDAYS:
        raise FloatpageError(f"--first-weekday {first_weekday!r} is not a weekday "
                             f"(use one of: {', '.join(WEEKDAYS)})")
    language = str(lang).lower()
    if language not in CALENDAR_LANGUAGES:
        raise FloatpageError(f"--lang {lang!r} is not supported "
                             f"(use one of: {', '.join(CALENDAR_LANGUAGES)})")
    if orientation not in ORIENTATIONS:
        raise FloatpageError(f"--orientation {orientation!r} is not an orientation "
                             f"(use portrait or landscape)")
    return Options(year=year, first_weekday=weekday, lang=language, orientation=orientation)
