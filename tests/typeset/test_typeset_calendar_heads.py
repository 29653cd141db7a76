"""The weekday heads of a calendar's panels print at one size whatever the month's number of
weeks, and smaller than the day numbers they stand over.  Before, a February of four weeks
and a May of six, in panels of the same size, had heads of 15.9 and 18.3 pt, and May's bold
heads were as large as its day numbers.  Read back from a real LuaLaTeX PDF."""

from __future__ import annotations

import pdfplumber
import pytest

from floatpage.model.calendar_month import month_weeks
from floatpage.model.document import CalendarItem, Page, Project
from floatpage.typeset import render_pdf
from typeset_pdfcheck import BoxPt, chars_in

MONTHS = [(2027, 2), (2027, 3), (2027, 5), (2027, 8)]  # 4, 5, 6 and 6 weeks


@pytest.fixture(scope="module")
def sizes(tmp_path_factory):
    assert sorted({len(month_weeks(year, month, "monday")) for year, month in MONTHS}) == [4, 5, 6]
    items = [CalendarItem(id=f"cal{month}", x=55 + 100 * (i % 2), y=55 + 100 * (i // 2),
                          w=90, h=80, year=year, month=month, font="sans")
             for i, (year, month) in enumerate(MONTHS)]
    out = tmp_path_factory.mktemp("heads") / "heads.pdf"
    render_pdf(Project(pages=[Page(id="p", size="A4", items=items)]), out)
    found = {}
    with pdfplumber.open(out) as pdf:
        for item in items:
            chars = chars_in(pdf.pages[0], BoxPt.of_item(item), margin_pt=1)
            heads = {round(c["size"], 2) for c in chars if c["text"].isalpha() and "Bold" in c["fontname"]
                     and c["size"] < 30 and c["text"] in "MonTueWedThuFriSatSun"}
            days = {round(c["size"], 2) for c in chars if c["text"].isdigit() and "Bold" not in c["fontname"]}
            found[item.month] = (heads, days)
    return found


def test_weekday_heads_have_one_size_in_every_month(sizes):
    heads = {size for month_heads, _ in sizes.values() for size in month_heads}
    assert len(heads) == 1, sizes


def test_weekday_heads_are_smaller_than_the_day_numbers(sizes):
    for month, (heads, days) in sizes.items():
        assert len(days) == 1, (month, days)
        assert max(heads) <= 0.85 * min(days), (month, heads, days)
