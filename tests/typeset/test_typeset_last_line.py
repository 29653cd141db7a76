"""A card's message does not end on a lonely word: where greedy breaking left the last line
nearly empty ("Wishing you a year / full of sunshine, / flowers and good / friends."), the
lines are re-broken evenly at the same size, in the same number of lines, still inside the
box.  Read back from a real LuaLaTeX PDF."""

from __future__ import annotations

from itertools import groupby

import pdfplumber
import pytest

from floatpage.model.document import Page, Project, TextItem
from floatpage.typeset import render_pdf
from floatpage.typeset.fit import LONELY, Box, fit_text
from floatpage.typeset.fonts import metrics_for
from floatpage.typeset.text_layout import PT_PER_MM, face_for
from typeset_pdfcheck import BoxPt, chars_in, fill

MESSAGE = "Wishing you a year full of sunshine, flowers and good friends."
BOXES = [(36.0, 20.0), (42.0, 24.0), (48.0, 28.0)]  # mm; each left "friends." alone


@pytest.fixture(scope="module")
def read(tmp_path_factory):
    items = [TextItem(id=f"m{index}", x=35.0 + 55.0 * (index % 2), y=30.0 + 40.0 * (index // 2),
                      w=w, h=h, text=MESSAGE, font="serif", italic=True)
             for index, (w, h) in enumerate(BOXES)]
    out = tmp_path_factory.mktemp("lastline") / "message.pdf"
    render_pdf(Project(pages=[Page(id="p", size="A5", items=items)]), out)
    found = []
    with pdfplumber.open(out) as pdf:
        for item in items:
            box = BoxPt.of_item(item)
            chars = chars_in(pdf.pages[0], box, margin_pt=2)
            lines = [list(line) for _, line in groupby(sorted(chars, key=lambda c: (round(c["bottom"]), c["x0"])),
                                                     key=lambda c: round(c["bottom"]))]
            found.append((item, box, chars, lines))
    return found


def test_no_message_ends_on_a_lonely_word(read):
    for item, box, chars, lines in read:
        widths = [max(c["x1"] for c in line) - min(c["x0"] for c in line) for line in lines]
        assert len(lines) >= 3, item.id
        assert widths[-1] >= LONELY * max(widths), (item.id, ["".join(c["text"] for c in l) for l in lines])
        assert all(box.overflow(c) < 0.3 for c in chars), item.id
        assert fill(chars, box)[1] >= 0.97, item.id  # the height stays full


def test_size_and_line_count_stay_those_of_the_largest_fit(read):
    metrics = metrics_for(face_for("serif", False, True))
    for item, _, chars, lines in read:
        fit = fit_text(MESSAGE, Box(item.w * PT_PER_MM, item.h * PT_PER_MM), metrics)
        assert {round(c["size"], 2) for c in chars} == {round(fit.font_pt, 2)}, item.id
        assert len(lines) == len(fit.lines), item.id
