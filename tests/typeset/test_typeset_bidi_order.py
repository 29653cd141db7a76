"""Right-to-left order read back from the real PDF and held against GNU FriBidi.

Each line mixes right-to-left letters with left-to-right words, numbers, brackets and signs.
It is typeset on one line through the real engine; pdfplumber gives the glyphs from left to
right, and FriBidi (libfribidi, an implementation of the Unicode bidi algorithm that
floatpage does not use) gives the order the line must show.  Brackets are compared as
brackets: a bracket set inside a right-to-left run is mirrored by HarfBuzz, so "(" drawn there
comes from a ")" and looks the same.  Lam-alef is avoided: its one ligature glyph copies as
two letters in typed order.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import unicodedata

import pdfplumber
import pytest

from floatpage.model.document import Page, Project, TextItem
from floatpage.typeset import render_pdf

LINES = [
    "abc אבג def", "אבג abc דהו", "Tel Aviv תל אביב 2027", "Price: 120 ₪ מחיר",
    "שלום (עולם) [1-2]", "א) 1. ב) 2.", "version 2.0 (הגרסה החדשה)", "חג שמח 2027",
    "Room 12B — חדר 12", "2027-11-24 תאריך", "abc 123 אבג 456 def", "«שלום» said Dan",
    "מזל טוב!", "עברית, English; עברית.", "(مرحبا [123] abc)", "عيد سعيد 2027",
    "ABC ١٢٣ 123 ۱۲۳", "−5 °C דרגה", "a 1 ב 2 c", "Love ❤ אהבה",
    # W5: a percent or currency sign belongs to its number ("100%" printed "%100")
    "100% אחוז", "50% off — הנחה 50%", "$5 לכל אחד", "מחיר: ₪100", "السعر ٥٠٪ فقط",
]
PAR_ON = 0x40  # FriBidi's "find the direction from the first strong letter"
BRACKETS = str.maketrans({b: "B" for b in "()[]{}<>«»"})


def fribidi_visual(text: str) -> str:
    """The line's characters in display order, left to right, as FriBidi orders them."""
    library = ctypes.CDLL(ctypes.util.find_library("fribidi") or "libfribidi.so.0")
    size = len(text)
    logical = (ctypes.c_uint32 * size)(*map(ord, text))
    visual = (ctypes.c_uint32 * size)()
    order = (ctypes.c_int * size)()
    direction = ctypes.c_uint32(PAR_ON)
    assert library.fribidi_log2vis(logical, size, ctypes.byref(direction), visual, None, order,
                                   None)
    return "".join(text[order[k]] for k in range(size))


def comparable(text: str) -> str:
    """Without spaces (a PDF holds none), presentation forms folded, brackets as brackets."""
    return unicodedata.normalize("NFKC", "".join(c for c in text if not c.isspace())
                                 ).translate(BRACKETS)


@pytest.fixture(scope="module")
def rendered(tmp_path_factory):
    items = [TextItem(id=f"line{k}", x=148, y=12 + 16 * k, w=280, h=11, text=text, font="sans")
             for k, text in enumerate(LINES)]
    out = tmp_path_factory.mktemp("bidi") / "bidi.pdf"
    render_pdf(Project(pages=[Page(id="p", size="A3", width_mm=297, height_mm=420,
                                   items=items)]), out)
    shown = {}
    with pdfplumber.open(out) as pdf:
        page = pdf.pages[0]
        for item in items:
            top, bottom = (item.y - item.h / 2) * 72 / 25.4, (item.y + item.h / 2) * 72 / 25.4
            glyphs = sorted((c for c in page.chars if top <= (c["top"] + c["bottom"]) / 2 <= bottom),
                            key=lambda c: c["x0"])
            shown[item.text] = "".join(c["text"] for c in glyphs)
    return shown


@pytest.mark.parametrize("line", LINES)
def test_a_mixed_line_shows_in_the_order_fribidi_gives(rendered, line):
    assert comparable(rendered[line]) == comparable(fribidi_visual(line))
