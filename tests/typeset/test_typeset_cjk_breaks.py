"""Chinese and Japanese break between characters, as they are written: a CJK paragraph in a
card's message box fills the box in several lines at a readable size, with no hyphen and no
space put between characters, and no line starts with closing punctuation.  Before, the
whole sentence was one "word": fitted on one line at about 5 pt, or split with a hyphen.
Read back from a real LuaLaTeX PDF with pdfplumber."""

from __future__ import annotations

import unicodedata
from itertools import groupby

import pdfplumber
import pytest

from floatpage.model.document import Page, Project, TextItem
from floatpage.typeset import render_pdf
from floatpage.typeset.break_points import NO_BREAK_BEFORE
from typeset_pdfcheck import BoxPt, chars_in

CHINESE = "祝你生日快乐，万事如意，身体健康，心想事成。愿你的每一天都充满阳光和欢笑。"
JAPANESE = "誕生日おめでとうございます。素敵な一年になりますように。「ありがとう」"
MIXED = "Happy 30th! 生日快乐，愿你的每一天都充满阳光。"


@pytest.fixture(scope="module")
def readback(tmp_path_factory):
    texts = {"zh": CHINESE, "ja": JAPANESE, "mixed": MIXED}
    items = [TextItem(id=name, x=60.0, y=30.0 + 50.0 * index, w=100.0, h=40.0, text=text,
                      font="serif")
             for index, (name, text) in enumerate(texts.items())]
    project = Project(title="cjk", pages=[Page(id="p", size="A5", items=items)])
    out = tmp_path_factory.mktemp("cjk") / "cjk.pdf"
    report = render_pdf(project, out)
    found = {}
    with pdfplumber.open(out) as pdf:
        for item in items:
            box = BoxPt.of_item(item)
            found[item.id] = (box, chars_in(pdf.pages[0], box, margin_pt=2))
    return texts, found, report


def nfkc(text: str) -> str:
    return unicodedata.normalize("NFKC", text)


def lines_of(chars):
    ordered = sorted(chars, key=lambda c: (round(c["bottom"]), c["x0"]))
    return ["".join(c["text"] for c in line)
            for _, line in groupby(ordered, key=lambda c: round(c["bottom"]))]


@pytest.mark.parametrize("name", ["zh", "ja", "mixed"])
def test_cjk_text_breaks_between_characters_and_fills_its_box(readback, name):
    texts, found, report = readback
    box, chars = found[name]
    lines = lines_of(chars)
    assert len(lines) >= 3, lines  # broken into lines, not squeezed onto one
    assert min(c["size"] for c in chars) >= 12.0  # 100 x 40 mm holds this at a readable size
    # no hyphen, no character lost (a font may map a character to its compatibility twin)
    assert nfkc("".join(lines)) == nfkc(texts[name].replace(" ", ""))
    assert all(line[0] not in NO_BREAK_BEFORE for line in lines[1:]), lines
    assert all(box.overflow(c) < 0.5 for c in chars)
    assert not any("broken across lines" in w for w in report.warnings), report.warnings
