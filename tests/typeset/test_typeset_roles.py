"""Texts of one role share one size: three price tags of a flyer, each fitted to its own box,
came out at three sizes.  A role's texts are set at the largest size at which every one of
them still fits, across the document's pages; a size set by hand (`size_pt`) is kept, and a
text that only fits below the legible minimum does not drag the others down.  Read back from
real LuaLaTeX PDFs with pdfplumber."""

from __future__ import annotations

import pdfplumber
import pytest

from floatpage.model import load_project, save_project
from floatpage.model.document import Page, Project, TextItem
from floatpage.typeset import render_pdf
from floatpage.typeset.fit import MIN_PT
from floatpage.typeset.render import text_fit_warnings
from floatpage.typeset.text_layout import face_for, fit_in_box
from typeset_pdfcheck import BoxPt, chars_in

# (id, text, w, h): the same role, boxes and texts of different lengths
PRICES = [("apples", "Apples\n€2.40", 36.0, 14.0), ("plant", "Potted plant\n€12.90", 30.0, 14.0),
          ("tea", "Teapot\n€24.50", 40.0, 16.0)]


def tags(role: str, page: int = 0) -> list[TextItem]:
    return [TextItem(id=f"{name}{page}", x=25.0 + 48.0 * index, y=40.0, w=w, h=h, text=text,
                     font="sans", bold=True, role=role)
            for index, (name, text, w, h) in enumerate(PRICES)]


def sizes_in(pdf_path, pages: list[Page]) -> dict[str, set[float]]:
    """Each item's set of character sizes in the PDF, in points."""
    found = {}
    with pdfplumber.open(pdf_path) as pdf:
        for pdf_page, page in zip(pdf.pages, pages):
            for item in page.items:
                chars = chars_in(pdf_page, BoxPt.of_item(item), margin_pt=2)
                assert chars, item.id
                found[item.id] = {round(c["size"], 2) for c in chars}
    return found


def own_size(item: TextItem) -> float:
    fit, _, _ = fit_in_box(item.text, face_for(item.font, item.bold, item.italic), item.w, item.h)
    return fit.font_pt


def test_texts_of_one_role_share_the_largest_size_at_which_all_fit(tmp_path):
    alone = Page(id="own", size="A5", items=tags(""))
    shared = Page(id="shared", size="A5", items=tags("price", 1))
    out = tmp_path / "prices.pdf"
    render_pdf(Project(pages=[alone, shared]), out)
    found = sizes_in(out, [alone, shared])
    own = [found[item.id] for item in alone.items]
    assert all(len(sizes) == 1 for sizes in own)
    assert len({next(iter(sizes)) for sizes in own}) == 3  # without a role: three sizes
    together = set().union(*(found[item.id] for item in shared.items))
    smallest = min(own_size(item) for item in alone.items)
    assert together == {round(smallest, 2)}  # with one: one, the tightest box's own


def test_a_role_spans_the_pages_and_a_size_set_by_hand_is_kept(tmp_path):
    first = Page(id="first", size="A5", items=tags("price", 1)[:1])
    hand = TextItem(id="hand", x=60.0, y=100.0, w=60.0, h=30.0, text="Teapot\n€24.50",
                    font="sans", bold=True, role="price", size_pt=9.5)
    second = Page(id="second", size="A5", items=tags("price", 2)[1:] + [hand])
    path = tmp_path / "two.toml"
    save_project(Project(pages=[first, second]), path)
    project = load_project(path)  # role and size_pt survive the file
    assert project.pages[1].item("hand").size_pt == 9.5
    assert project.pages[1].item("hand").role == "price"
    out = tmp_path / "two.pdf"
    render_pdf(project, out)
    found = sizes_in(out, project.pages)
    hand_sizes = found.pop("hand")
    assert hand_sizes == {9.5}
    smallest = min(own_size(item) for page in (first, second) for item in page.items
                   if item.id != "hand")
    assert set().union(*found.values()) == {round(smallest, 2)}
    assert smallest > 9.5 + 1  # the hand-set size did not pull the role down


def test_a_text_too_long_for_its_box_does_not_shrink_its_role(tmp_path):
    crammed = TextItem(id="crammed", x=70.0, y=120.0, w=20.0, h=8.0, role="price", font="sans",
                       text="A very long description that cannot fit a small tag at all " * 3)
    page = Page(id="p", size="A5", items=tags("price") + [crammed])
    out = tmp_path / "crammed.pdf"
    render_pdf(Project(pages=[page]), out)
    found = sizes_in(out, [page])
    assert max(found.pop("crammed")) < MIN_PT
    smallest = min(own_size(item) for item in tags(""))
    assert set().union(*found.values()) == {round(smallest, 2)}


def test_a_size_set_by_hand_that_does_not_fit_is_reduced_and_said(tmp_path):
    item = TextItem(id="big", x=60.0, y=60.0, w=30.0, h=10.0, text="Grand opening", size_pt=40.0)
    project = Project(pages=[Page(id="p", size="A5", items=[item])])
    warnings = text_fit_warnings(project)
    assert any('"big"' in w and "40 pt" in w for w in warnings), warnings
    out = tmp_path / "big.pdf"
    render_pdf(project, out)
    (sizes,) = sizes_in(out, project.pages).values()
    assert max(sizes) == round(own_size(item), 2) < 40.0


def test_a_row_of_one_role_stands_on_one_baseline_accents_or_not(tmp_path):
    """Tags of one size in a row of boxes of one height share their baselines: an accent on
    a capital ("Túlipas", "Éclair") lowered its tag's lines by 0.4 mm, as the ink block and not
    the lines' em boxes was centred in the box."""
    names = ["Queque\n3,20 €", "Túlipas\n4,50 €", "Éclair\n2,10 €", "Bule de chá\n24,50 €"]
    items = [TextItem(id=f"tag{index}", x=20.0 + 36.0 * index, y=50.0, w=34.0, h=14.0,
                      text=text, font="sans", bold=True, role="price")
             for index, text in enumerate(names)]
    out = tmp_path / "row.pdf"
    render_pdf(Project(pages=[Page(id="p", size="A5", items=items)]), out)
    with pdfplumber.open(out) as pdf:
        lines = []
        for item in items:
            chars = chars_in(pdf.pages[0], BoxPt.of_item(item), margin_pt=2)
            baselines = sorted({round(c["bottom"], 2) for c in chars})
            assert len(baselines) == 2, (item.id, baselines)  # two lines, each on one baseline
            lines.append(baselines)
    for depth in (0, 1):
        spread = max(b[depth] for b in lines) - min(b[depth] for b in lines)
        assert spread < 0.05, (depth, lines)
