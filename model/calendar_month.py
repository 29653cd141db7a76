"""The month grid and the localised month and day names of a calendar panel.

Pure and dependency-free so the typesetter and the editor's preview draw the
same weeks. Names come from a table rather than the system locale: locales
are often missing on a print machine, and the PDF must not depend on them.
"""

from __future__ import annotations

import calendar

from floatpage.model.key_specs import CALENDAR_LANGUAGES as LANGUAGES, WEEKDAYS

MONTH_NAMES: dict[str, tuple[str, ...]] = {
    "en": ("January", "February", "March", "April", "May", "June", "July", "August",
           "September", "October", "November", "December"),
    "de": ("Januar", "Februar", "März", "April", "Mai", "Juni", "Juli", "August",
           "September", "Oktober", "November", "Dezember"),
    "fr": ("Janvier", "Février", "Mars", "Avril", "Mai", "Juin", "Juillet", "Août",
           "Septembre", "Octobre", "Novembre", "Décembre"),
    "es": ("Enero", "Febrero", "Marzo", "Abril", "Mayo", "Junio", "Julio", "Agosto",
           "Septiembre", "Octubre", "Noviembre", "Diciembre"),
    "it": ("Gennaio", "Febbraio", "Marzo", "Aprile", "Maggio", "Giugno", "Luglio", "Agosto",
           "Settembre", "Ottobre", "Novembre", "Dicembre"),
    "pt": ("Janeiro", "Fevereiro", "Março", "Abril", "Maio", "Junho", "Julho", "Agosto",
           "Setembro", "Outubro", "Novembro", "Dezembro"),
    "nl": ("Januari", "Februari", "Maart", "April", "Mei", "Juni", "Juli", "Augustus",
           "September", "Oktober", "November", "December"),
}

# Monday first, as WEEKDAYS is.
DAY_NAMES: dict[str, tuple[str, ...]] = {
    "en": ("Monday", "Tuesday", "Wednesday", "Thursday", "Friday", "Saturday", "Sunday"),
    "de": ("Montag", "Dienstag", "Mittwoch", "Donnerstag", "Freitag", "Samstag", "Sonntag"),
    "fr": ("Lundi", "Mardi", "Mercredi", "Jeudi", "Vendredi", "Samedi", "Dimanche"),
    "es": ("Lunes", "Martes", "Miércoles", "Jueves", "Viernes", "Sábado", "Domingo"),
    "it": ("Lunedì", "Martedì", "Mercoledì", "Giovedì", "Venerdì", "Sabato", "Domenica"),
    "pt": ("Segunda-feira", "Terça-feira", "Quarta-feira", "Quinta-feira", "Sexta-feira",
           "Sábado", "Domingo"),
    "nl": ("Maandag", "Dinsdag", "Woensdag", "Donderdag", "Vrijdag", "Zaterdag", "Zondag"),
}

# The short forms printed calendars of each language use as column heads.
DAY_ABBREVIATIONS: dict[str, tuple[str, ...]] = {
    "en": ("Mon", "Tue", "Wed", "Thu", "Fri", "Sat", "Sun"),
    "de": ("Mo", "Di", "Mi", "Do", "Fr", "Sa", "So"),
    "fr": ("Lun", "Mar", "Mer", "Jeu", "Ven", "Sam", "Dim"),
    "es": ("Lu", "Ma", "Mi", "Ju", "Vi", "Sá", "Do"),
    "it": ("Lun", "Mar", "Mer", "Gio", "Ven", "Sab", "Dom"),
    "pt": ("Seg", "Ter", "Qua", "Qui", "Sex", "Sáb", "Dom"),
    "nl": ("Ma", "Di", "Wo", "Do", "Vr", "Za", "Zo"),
}


def weekday_index(first_weekday: str) -> int:
    """0 for "monday" ... 6 for "sunday" (Python's calendar numbering)."""
    try:
        return WEEKDAYS.index(first_weekday)
    except ValueError:
        raise ValueError(f"first_weekday must be one of {', '.join(WEEKDAYS)}, not {first_weekday!r}")


def language_or_english(language: str) -> str:
    return language if language in MONTH_NAMES else "en"


def month_name(month: int, language: str = "en") -> str:
    if not 1 <= month <= 12:
        raise ValueError(f"month must be 1-12, not {month}")
    return MONTH_NAMES[language_or_english(language)][month - 1]


def weekday_names(first_weekday: str = "monday", language: str = "en", *,
                  abbreviated: bool = True) -> tuple[str, ...]:
    """The seven column heads, starting at first_weekday."""
    table = DAY_ABBREVIATIONS if abbreviated else DAY_NAMES
    names = table[language_or_english(language)]
    start = weekday_index(first_weekday)
    return names[start:] + names[:start]


def month_weeks(year: int, month: int, first_weekday: str = "monday") -> list[list[int]]:
    """Rows of seven day numbers (0 = a cell outside the month), 4 to 6 rows.

    Python's proleptic Gregorian calendar covers years 1-9999, the range the
    project file allows.
    """
    if not 1 <= year <= 9999:
        raise ValueError(f"year must be 1-9999, not {year}")
    if not 1 <= month <= 12:
        raise ValueError(f"month must be 1-12, not {month}")
    weeks = calendar.Calendar(firstweekday=weekday_index(first_weekday))
    return [list(week) for week in weeks.monthdayscalendar(year, month)]


def weekend_columns(first_weekday: str = "monday") -> tuple[int, ...]:
    """Column indexes of Saturday and Sunday, for panels that tint the weekend."""
    start = weekday_index(first_weekday)
    return tuple(sorted((day - start) % 7 for day in (5, 6)))
