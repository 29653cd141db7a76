"""Fitted text read back from a real LuaLaTeX PDF: inside its box, and filling it.

216 random boxes and texts (accents, very long words, one-word texts, long
paragraphs, LaTeX specials, forced line breaks) in all 12 faces, typeset in
ONE compile of a 12-page A3 document, then read back with pdfplumber.
"""

from __future__ import annotations

import random
import statistics
import subprocess

import numpy as np
import pdfplumber
import pytest
from PIL import Image

from floatpage.model.document import Page, Project, TextItem
from floatpage.typeset import render_pdf
from floatpage.typeset.escape import clean_text
from floatpage.typeset.placed import place_document
from typeset_pdfcheck import BoxPt, chars_in, fill

SEED = 20261121
PAGES, COLUMNS, ROWS = 12, 3, 6
CELL_W, CELL_H = 99.0, 70.0  # A3 is 297 x 420 mm

PLAIN = ("the of and light garden office final waffle fjord harbour quiet yellow music "
         "river morning window paper stone little evening journey friends summer").split()
ACCENTED = ("élan café naïve façade Ærøskøbing Ångström œuvre straße Müller señor "
            "coração São Éire Ôte Çà Über Zürich crème brûlée déjà-vu Łódź").split()
LONG_WORDS = ["Donaudampfschifffahrtsgesellschaftskapitänswitwe",
              "antidisestablishmentarianism", "Rindfleischetikettierungsüberwachungsaufgaben",
              "pneumonoultramicroscopicsilicovolcanoconiosis", "Llanfairpwllgwyngyll"]
SPECIALS = [r"50%", r"a_b", r"$5", r"#1", r"R&D", r"{x}", r"\relax", r"^2", r"~home",
            r"[opt]", r"\\", r"\input{x}", r"%comment", "x--y", "``q''"]


def random_text(rng: random.Random, kind: str) -> str:
    if kind == "one word":
        return rng.choice(PLAIN + ACCENTED + LONG_WORDS[:2])
    if kind == "accents":
        return " ".join(rng.choice(ACCENTED + PLAIN) for _ in range(rng.randint(2, 14)))
    if kind == "long word":
        words = [rng.choice(PLAIN) for _ in range(rng.randint(0, 6))]
        words.insert(rng.randint(0, len(words)), rng.choice(LONG_WORDS))
        return " ".join(words)
    if kind == "paragraph":
        words = [rng.choice(PLAIN + ACCENTED) for _ in range(rng.randint(60, 160))]
        for index in range(8, len(words), rng.randint(9, 17)):
            words[index] += "."
        return " ".join(words)
    if kind == "specials":
        return " ".join(rng.choice(SPECIALS + PLAIN) for _ in range(rng.randint(1, 12)))
    if kind == "lines":
        return "\n".join(" ".join(rng.choice(PLAIN) for _ in range(rng.randint(1, 4)))
                         for _ in range(rng.randint(2, 5)))
    raise ValueError(kind)


KINDS = ["one word", "accents", "long word", "paragraph", "specials", "lines"]


def random_project() -> Project:
    rng = random.Random(SEED)
    pages = []
    for page_index in range(PAGES):
        items = []
        for cell in range(COLUMNS * ROWS):
            column, row = cell % COLUMNS, cell // COLUMNS
            kind = KINDS[(page_index * COLUMNS * ROWS + cell) % len(KINDS)]
            w = rng.uniform(12, 90) if kind != "paragraph" else rng.uniform(35, 90)
            h = rng.uniform(6, 62) if kind != "paragraph" else rng.uniform(30, 62)
            items.append(TextItem(
                id=f"t{page_index}-{cell}", x=CELL_W * (column + 0.5), y=CELL_H * (row + 0.5),
                w=w, h=h, text=random_text(rng, kind),
                font=rng.choice(["serif", "sans", "display"]),
                bold=rng.random() < 0.4, italic=rng.random() < 0.4,
                color=rng.choice(["#000000", "#8b1e3f", "#1f77b4"])))
        pages.append(Page(id=f"p{page_index}", size="A3", width_mm=297.0, height_mm=420.0,
                          items=items))
    return Project(title="random boxes", pages=pages)


@pytest.fixture(scope="module")
def typeset(tmp_path_factory):
    project = random_project()
    out = tmp_path_factory.mktemp("fit") / "boxes.pdf"
    report = render_pdf(project, out)
    document = place_document(project)
    lines = {}
    for page in document.pages:
        for placed in page.items:
            lines[placed.item_id] = [run.text for g in placed.groups for run in g.runs]
    results = []
    with pdfplumber.open(out) as pdf:
        assert len(pdf.pages) == PAGES == report.pages
        for page, pdf_page in zip(project.pages, pdf.pages):
            for item in page.items:
                box = BoxPt.of_item(item)
                chars = chars_in(pdf_page, box, margin_pt=4 * 72 / 25.4)
                results.append((item, box, chars, lines[item.id]))
    return results, report, out


def test_there_are_enough_boxes_of_every_kind(typeset):
    results, *_ = typeset
    assert len(results) >= 200
    texts = [item.text for item, *_ in results]
    assert any(w in t for t in texts for w in LONG_WORDS)
    assert any("\\" in t for t in texts) and any("%" in t for t in texts)
    assert sum(1 for t in texts if " " not in t and "\n" not in t) >= 20
    assert sum(1 for t in texts if len(t.split()) >= 60) >= 20


def test_every_glyph_lies_inside_its_box(typeset):
    results, *_ = typeset
    worst = max(((box.overflow(c), item.id, c["text"]) for item, box, chars, _ in results
                 for c in chars), default=(0.0, "", ""))
    assert worst[0] <= 0.25, f"glyph {worst[2]!r} of {worst[1]} overflows by {worst[0]:.3f} pt"


def test_the_pdf_holds_exactly_the_fitted_lines(typeset):
    """LaTeX did not re-break, drop or add anything: the glyphs spell the lines we emitted."""
    results, *_ = typeset
    for item, _, chars, lines in results:
        expected = "".join(lines).replace(" ", "")
        assert "".join(c["text"] for c in chars) == expected, item.id
        unbroken = [line for line in lines]
        if not any(line.endswith("-") for line in unbroken):
            assert "".join(unbroken).replace(" ", "") == \
                clean_text(item.text).replace(" ", "").replace("\n", "")


def test_text_fills_its_box_in_the_binding_direction(typeset):
    results, *_ = typeset
    fills = sorted(max(fill(chars, box)) for item, box, chars, _ in results)
    median = statistics.median(fills)
    fifth_percentile = fills[int(0.05 * len(fills))]
    assert median >= 0.99, median
    assert fifth_percentile >= 0.97, fifth_percentile


def test_one_engine_run_for_all_pages(typeset):
    _, report, _ = typeset
    assert report.pages == PAGES
    assert report.engine_seconds < report.seconds


def test_no_ink_outside_any_box(typeset, tmp_path):
    """Rasterise the pages and look for ink outside the boxes: this sees accents above
    capitals and italic overhangs, which the PDF's advance boxes do not."""
    results, _, out = typeset
    dpi = 100
    px_per_pt = dpi / 72
    subprocess.run(["pdftoppm", "-gray", "-r", str(dpi), str(out), str(tmp_path / "page")],
                   check=True, timeout=300)
    pages = sorted(tmp_path.glob("page-*.pgm"))
    assert len(pages) == PAGES
    slack_px = 0.25 * px_per_pt + 1.5  # the 0.25 pt allowance plus anti-aliasing
    by_page: dict[int, list[BoxPt]] = {}
    for item, box, *_ in results:
        by_page.setdefault(int(item.id[1:].split("-")[0]), []).append(box)
    for index, path in enumerate(pages):
        ink = np.asarray(Image.open(path)) < 200
        allowed = np.zeros_like(ink)
        for box in by_page[index]:
            x0 = max(0, int(np.floor(box.x0 * px_per_pt - slack_px)))
            y0 = max(0, int(np.floor(box.top * px_per_pt - slack_px)))
            x1 = int(np.ceil(box.x1 * px_per_pt + slack_px))
            y1 = int(np.ceil(box.bottom * px_per_pt + slack_px))
            allowed[y0:y1, x0:x1] = True
        stray = np.argwhere(ink & ~allowed)
        assert len(stray) == 0, f"page {index}: ink outside every box at (row, col) {stray[:5]}"
