"""A picture in a frame of another shape fills it without distortion: scaled with its
proportions kept to cover the frame, centred, and clipped to it.  Stretched to the frame, a
3:2 photo in a tall box printed squashed by half.  Read back from a real PDF: the image as
drawn keeps its file's proportions, and the page's pixels show only its middle, inside the
frame; with `--print` a cropped picture at the page's edge bleeds with its own cropped part."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pdfplumber
import pytest
from PIL import Image

from floatpage.model import Background, Page, PictureItem, Project, TextItem, save_project
from floatpage.typeset.text_layout import PT_PER_MM

ROOT = Path(__file__).resolve().parents[2]
DPI = 100
RED, GREEN, BLUE, PAPER = (220, 0, 0), (0, 170, 0), (0, 0, 220), (255, 255, 255)
BLEED, SLUG = 3.0, 3.0 + 1.0 + 5.0 + 1.0  # typeset.print_marks: bleed, gap, mark, margin


def render(folder: Path, *extra: str) -> tuple[Path, Image.Image]:
    out = folder / ("print.pdf" if extra else "page.pdf")
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "render", "--no-settle",
                             *extra, str(folder / "frames.toml"), "-o", str(out)],
                            capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert result.returncode == 0, result.stderr
    stem = out.with_suffix("")
    subprocess.run(["pdftoppm", "-r", str(DPI), "-png", "-singlefile", str(out), str(stem)],
                   check=True)
    return out, Image.open(stem.with_suffix(".png")).convert("RGB")


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    folder = tmp_path_factory.mktemp("frames")
    stripes = Image.new("RGB", (300, 100), RED)  # 3:1, its thirds red, green and blue
    stripes.paste(GREEN, (100, 0, 200, 100))
    stripes.paste(BLUE, (200, 0, 300, 100))
    stripes.save(folder / "stripes.png")
    items = [PictureItem(id="square", x=25.0, y=40.0, w=50.0, h=50.0, path="stripes.png"),
             PictureItem(id="fitting", x=100.0, y=40.0, w=60.0, h=20.0, path="stripes.png")]
    page = Page(id="p", size="custom", width_mm=148.0, height_mm=105.0,
                background=Background(color="#ffffff"), items=items)
    save_project(Project(pages=[page]), folder / "frames.toml")
    return folder


def at(image: Image.Image, x_mm: float, y_mm: float, slug: float = 0.0) -> tuple[int, int, int]:
    scale = DPI / 25.4
    return image.getpixel((round((x_mm + slug) * scale), round((y_mm + slug) * scale)))


def test_a_picture_keeps_its_proportions_in_a_frame_of_another_shape(folder):
    out, page = render(folder)
    with pdfplumber.open(out) as pdf:
        square, fitting = pdf.pages[0].images  # in paint order
    drawn = (square["x1"] - square["x0"]) / (square["bottom"] - square["top"])
    assert drawn == pytest.approx(3.0, rel=0.01)  # the file's shape, not the frame's
    assert square["bottom"] - square["top"] == pytest.approx(50 * PT_PER_MM, abs=0.5)
    assert fitting["x1"] - fitting["x0"] == pytest.approx(60 * PT_PER_MM, abs=0.5)  # as it is
    # Only the middle third shows, inside the frame; the paper around it is bare.
    for x_mm in (1.0, 25.0, 49.0):
        assert at(page, x_mm, 40.0) == pytest.approx(GREEN, abs=10), x_mm
    assert at(page, 51.5, 40.0) == pytest.approx(PAPER, abs=10)
    assert at(page, 25.0, 13.5) == pytest.approx(PAPER, abs=10)
    assert at(page, 71.0, 40.0) == pytest.approx(RED, abs=10)  # the fitting one, whole
    assert at(page, 129.0, 40.0) == pytest.approx(BLUE, abs=10)


def test_a_cropped_picture_at_the_edge_bleeds_with_its_own_cropped_part(folder):
    _, sheet = render(folder, "--print", "--bleed", str(BLEED))
    assert at(sheet, -1.5, 40.0, SLUG) == pytest.approx(RED, abs=10)  # cropped off the page
    assert at(sheet, 1.0, 40.0, SLUG) == pytest.approx(GREEN, abs=10)  # inside: unchanged
    assert at(sheet, 49.0, 40.0, SLUG) == pytest.approx(GREEN, abs=10)
    assert at(sheet, -4.5, 40.0, SLUG) == pytest.approx(PAPER, abs=10)  # and no further


def test_a_text_listed_before_a_picture_it_meets_prints_over_it(tmp_path):
    """At one z, words print over pictures and blocks: a text listed first in the file, on a
    picture (a title on a photo, or a page too full to part them), printed hidden under it."""
    Image.new("RGB", (300, 200), (250, 230, 120)).save(tmp_path / "sand.png")
    photo = PictureItem(id="photo", x=60.0, y=50.0, w=90.0, h=60.0, path="sand.png")
    title = TextItem(id="title", x=60.0, y=50.0, w=60.0, h=16.0, text="MMMM", font="sans",
                     bold=True, color="#000000")
    save_project(Project(pages=[Page(id="p", size="A5", items=[title, photo])]),
                 tmp_path / "frames.toml")
    _, page = render(tmp_path)
    scale = DPI / 25.4
    darkest = min(sum(page.getpixel((x, y))) for x in range(round(35 * scale), round(85 * scale))
                  for y in range(round(45 * scale), round(55 * scale)))
    assert darkest < 150  # black glyphs show on the sand
