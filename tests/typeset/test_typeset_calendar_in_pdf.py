"""Month panels read back from a real PDF: names in the panel's language, every day in its cell."""

from __future__ import annotations

import datetime

import pdfplumber
import pytest

from floatpage.model.calendar_month import month_name, weekday_names
from floatpage.model.document import WEEKDAYS, CalendarItem, Page, Project
from floatpage.typeset import render_pdf
from floatpage.typeset.calendar_panel import HEADS_SHARE, TITLE_SHARE
from typeset_pdfcheck import PT_PER_MM, BoxPt

PANELS = [  # (year, month, first weekday, language)
    (2027, 1, "monday", "en"), (2024, 2, "sunday", "de"), (1900, 3, "saturday", "fr"),
    (9999, 12, "wednesday", "es"), (2026, 8, "monday", "it"), (1, 1, "thursday", "pt"),
    (2000, 2, "tuesday", "nl"), (2031, 6, "friday", "en"),
]


def words_in(page, box: BoxPt) -> list[dict]:
    cropped = page.crop((box.x0 - 1, box.top - 1, box.x1 + 1, box.bottom + 1), strict=False)
    return cropped.extract_words(keep_blank_chars=False, use_text_flow=True)


@pytest.fixture(scope="module")
def panels(tmp_path_factory):
    items = [CalendarItem(id=f"cal{i}", x=55 + 100 * (i % 2), y=55 + 100 * (i // 2) % 400,
                          w=90, h=90, year=y, month=m, first_weekday=f, language=lang,
                          font=["serif", "sans", "display"][i % 3], color="#203040")
             for i, (y, m, f, lang) in enumerate(PANELS)]
    pages = [Page(id=f"p{n}", items=items[n * 4:(n + 1) * 4], size="A3", width_mm=297,
                  height_mm=420) for n in range(2)]
    for page in pages:
        for i, item in enumerate(page.items):
            item.x, item.y = 55 + 100 * (i % 2), 55 + 100 * (i // 2)
    out = tmp_path_factory.mktemp("calendar") / "calendar.pdf"
    render_pdf(Project(pages=pages), out)
    found = []
    with pdfplumber.open(out) as pdf:
        for page, pdf_page in zip(pages, pdf.pages):
            for item in page.items:
                found.append((item, words_in(pdf_page, BoxPt.of_item(item))))
    return found


def test_title_and_weekday_heads_are_in_the_panels_language(panels):
    for item, words in panels:
        text = " ".join(w["text"] for w in words)
        assert f"{month_name(item.month, item.language)} {item.year}" in text, item.id
        heads = " ".join(weekday_names(item.first_weekday, item.language))
        assert heads in text, item.id


def test_every_day_sits_in_its_weekday_column_and_week_row(panels):
    for item, words in panels:
        left, top = item.x - item.w / 2, item.y - item.h / 2
        grid_top = top + item.h * (TITLE_SHARE + HEADS_SHARE)
        col_w = item.w / 7
        first = datetime.date(item.year, item.month, 1)
        start = WEEKDAYS.index(item.first_weekday)
        offset = (first.weekday() - start) % 7
        days = [w for w in words if w["text"].isdigit() and w["top"] > grid_top * PT_PER_MM
                and int(w["text"]) <= 31]
        numbers = sorted(int(w["text"]) for w in days)
        assert numbers == list(range(1, len(numbers) + 1)) and numbers[-1] >= 28, item.id
        rows = len({round(w["top"]) for w in days})
        row_h = (item.h * (1 - TITLE_SHARE - HEADS_SHARE)) / rows
        for word in days:
            day = int(word["text"])
            date = datetime.date(item.year, item.month, day)
            column = (date.weekday() - start) % 7
            row = (offset + day - 1) // 7
            centre_x = (word["x0"] + word["x1"]) / 2 / PT_PER_MM
            centre_y = (word["top"] + word["bottom"]) / 2 / PT_PER_MM
            assert left + col_w * column < centre_x < left + col_w * (column + 1), (item.id, day)
            assert grid_top + row_h * row < centre_y < grid_top + row_h * (row + 1), (item.id, day)
