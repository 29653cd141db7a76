"""Faint text is named: black words on a charcoal page or on the dark half of a photo printed
without a word said.  `render` and `check` now note each text whose colour has too little
contrast (WCAG AA) with what is printed behind it.  The test renders a real PDF, reads each
text's colour from its glyphs (pdfplumber) and the colour behind it from the page's pixels
(pdftoppm), and checks the notes name exactly the texts whose printed contrast is too low."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pdfplumber
import pytest
from PIL import Image

from floatpage.model import Background, BlockItem, Page, PictureItem, Project, TextItem, save_project
from floatpage.typeset.contrast import NORMAL_RATIO, contrast
from floatpage.typeset.text_layout import PT_PER_MM

ROOT = Path(__file__).resolve().parents[2]
DPI = 100


def text(item_id: str, x: float, y: float, color: str) -> TextItem:
    return TextItem(id=item_id, x=x, y=y, w=40.0, h=6.0, text="Open every day", font="sans",
                    color=color)


@pytest.fixture(scope="module")
def rendered(tmp_path_factory):
    folder = tmp_path_factory.mktemp("contrast")
    photo = Image.new("RGB", (200, 100), (255, 255, 255))
    photo.paste((20, 20, 20), (0, 0, 100, 100))  # its left half dark
    photo.save(folder / "half.png")
    items = [text("dark", 40.0, 20.0, "#000000"), text("light", 40.0, 40.0, "#ffffff"),
             BlockItem(id="cream", x=105.0, y=30.0, w=70.0, h=30.0, color="#fdf4e6",
                       decorative=True, z=-1),
             text("on-block", 105.0, 30.0, "#000000"),
             PictureItem(id="half", x=70.0, y=100.0, w=120.0, h=60.0, path="half.png",
                         decorative=True, z=-1),
             text("on-dark-half", 40.0, 100.0, "#000000"),
             text("on-light-half", 100.0, 100.0, "#000000")]
    page = Page(id="p", size="A5", background=Background(color="#222222"), items=items)
    path = folder / "faint.toml"
    save_project(Project(pages=[page]), path)
    out = folder / "faint.pdf"
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "render", "--no-settle",
                             str(path), "-o", str(out)], capture_output=True, text=True, cwd=ROOT,
                            timeout=300)
    assert result.returncode == 0, result.stderr
    check = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "check", "--strict",
                            str(path)], capture_output=True, text=True, cwd=ROOT, timeout=300)
    subprocess.run(["pdftoppm", "-r", str(DPI), "-png", "-singlefile", str(out),
                    str(folder / "page")], check=True)
    return page, out, Image.open(folder / "page.png").convert("RGB"), result.stderr, check


def printed_contrast(item, pdf_page, picture: Image.Image) -> float:
    """The contrast of the item's glyphs' colour with the paper's colour 1 mm above its box,
    both as printed."""
    left, top = (item.x - item.w / 2) * PT_PER_MM, (item.y - item.h / 2) * PT_PER_MM
    right, bottom = left + item.w * PT_PER_MM, top + item.h * PT_PER_MM
    chars = [c for c in pdf_page.chars if left <= c["x0"] <= right and top <= c["top"] <= bottom]
    assert chars, item.id
    colour = chars[0]["non_stroking_color"]
    rgb = tuple(colour) if len(colour) == 3 else (colour[0],) * 3
    scale = DPI / 25.4
    behind = picture.getpixel((round(item.x * scale), round((item.y - item.h / 2 - 1.0) * scale)))
    return contrast(tuple(float(c) for c in rgb), tuple(c / 255 for c in behind))


def noted(messages: str) -> set[str]:
    return {line.split('"')[1] for line in messages.splitlines()
            if line.startswith("note: item") and "contrast" in line}


def test_the_notes_name_the_texts_too_faint_on_the_printed_page(rendered):
    page, out, picture, stderr, _ = rendered
    with pdfplumber.open(out) as pdf:
        faint = {item.id for item in page.items if isinstance(item, TextItem)
                 and printed_contrast(item, pdf.pages[0], picture) < NORMAL_RATIO}
    assert faint == {"dark", "on-dark-half"}  # black on #222, and on the photo's dark half
    assert noted(stderr) == faint


def test_check_says_it_too_and_a_faint_text_is_a_note_not_a_failure(rendered):
    *_, check = rendered
    assert check.returncode == 0, check.stdout
    assert noted(check.stdout) == {"dark", "on-dark-half"}


def test_a_text_whose_last_line_lies_over_a_dark_band_is_named(tmp_path):
    """Readable as a whole, not on every line: the flyer turned from A4 to DL left its prices
    2.7 mm into the dark footer band, and the median of the samples (the cream half) passed.
    A three-line text whose last line lies over a charcoal band is named, with the line; a
    text clear of the band is not; the PDF shows the last line's letters over the band."""
    items = [BlockItem(id="band", x=52.5, y=133.0, w=105.0, h=30.0, color="#222222",
                       decorative=True, z=-1),
             TextItem(id="prices", x=52.5, y=112.0, w=60.0, h=18.0,
                      text="Bread 2.40\nCroissant 1.20\nTart 3.10", font="sans",
                      color="#000000"),
             TextItem(id="title", x=52.5, y=30.0, w=60.0, h=18.0,
                      text="Bread 2.40\nCroissant 1.20\nTart 3.10", font="sans",
                      color="#000000")]
    page = Page(id="p", size="A6", background=Background(color="#fdf4e6"), items=items)
    path = tmp_path / "band.toml"
    save_project(Project(pages=[page]), path)
    check = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "check", "--strict",
                            str(path)], capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert check.returncode == 0, check.stdout  # a note, as for the faint texts
    named = [line for line in check.stdout.splitlines() if "of its text" in line]
    assert len(named) == 1 and '"prices"' in named[0] and "line 3 of 3" in named[0], check.stdout
    assert "#222222" in named[0]
    out = tmp_path / "band.pdf"
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "render",
                             "--no-settle", str(path), "-o", str(out)], capture_output=True,
                            text=True, cwd=ROOT, timeout=300)
    assert result.returncode == 0, result.stderr
    assert "line 3 of 3" in result.stderr
    with pdfplumber.open(out) as pdf:
        chars = pdf.pages[0].chars
    band_top_pt = (133.0 - 15.0) * PT_PER_MM
    last = [c for c in chars if c["text"] == "T" and c["top"] > 60.0 * PT_PER_MM]
    assert last and all(c["bottom"] > band_top_pt for c in last)  # "Tart" sits on the band
    first = [c for c in chars if c["text"] == "B" and c["top"] > 60.0 * PT_PER_MM]
    assert first and all(c["bottom"] < band_top_pt for c in first)  # "Bread" does not
