"""A mark French sets after a space (! ? ; : ») never starts a line alone, nor does « end one:
"Joyeux anniversaire !" in a narrow box printed its "!" alone on a third line (seen in
benchmarks/fresh_projects.py seed 7001).  Read back from a real LuaLaTeX PDF."""

from __future__ import annotations

from itertools import groupby

import pdfplumber
import pytest

from floatpage.model.document import Page, Project, TextItem
from floatpage.typeset import render_pdf
from typeset_pdfcheck import BoxPt, chars_in

TEXTS = {  # each in a box where breaking at every space would leave a mark alone on a line
    "joyeux": ("Joyeux anniversaire !", 22.13, 20.92, "sans"),
    "quote": ("« Bonjour » dit-il", 14.0, 30.0, "serif"),
    "colon": ("Attention : ouvert", 17.0, 30.0, "serif"),
}


@pytest.fixture(scope="module")
def lines(tmp_path_factory):
    items = [TextItem(id=name, x=30.0 + 45.0 * index, y=40.0, w=w, h=h, text=text, font=font)
             for index, (name, (text, w, h, font)) in enumerate(TEXTS.items())]
    out = tmp_path_factory.mktemp("marks") / "marks.pdf"
    render_pdf(Project(pages=[Page(id="p", size="A5", items=items)]), out)
    found = {}
    with pdfplumber.open(out) as pdf:
        for item in items:
            box = BoxPt.of_item(item)
            chars = sorted(chars_in(pdf.pages[0], box, margin_pt=2),
                           key=lambda c: (round(c["bottom"]), c["x0"]))
            found[item.id] = (box, chars, ["".join(c["text"] for c in line) for _, line in
                                           groupby(chars, key=lambda c: round(c["bottom"]))])
    return found


@pytest.mark.parametrize("name", list(TEXTS))
def test_a_french_mark_stays_with_its_word(lines, name):
    box, chars, read = lines[name]
    assert len(read) >= 2, read  # the box does break the text
    assert "".join(read) == TEXTS[name][0].replace(" ", ""), read  # nothing lost
    assert all(line not in ("!", "»", ":", "«") for line in read), read
    assert not read[-1].startswith(("!", "»", ":")) and not read[0].endswith("«"), read
    assert all(box.overflow(c) < 0.5 for c in chars)
