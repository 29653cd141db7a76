"""`render --print`: the real PDF has TrimBox and BleedBox where the page is, the background
and every block or picture that meets the page's edge reach into the bleed, other items do
not, and crop marks stand outside the bleed.  Read back with pdfplumber and with pixels from pdftoppm."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pdfplumber
import pytest
from PIL import Image

from floatpage.model import Background, BlockItem, Page, PictureItem, Project, save_project

ROOT = Path(__file__).resolve().parents[2]
BLEED = 3.0
SLUG = BLEED + 1.0 + 5.0 + 1.0  # typeset.print_marks: bleed, gap, mark length, margin
W, H = 100.0, 140.0
DPI = 150
MM_TO_BP = 72 / 25.4


@pytest.fixture(scope="module")
def printed(tmp_path_factory):
    folder = tmp_path_factory.mktemp("print")
    Image.new("RGB", (200, 100), (250, 200, 0)).save(folder / "sun.png")
    Image.new("RGB", (100, 100), (120, 60, 200)).save(folder / "moon.png")
    tall = Image.new("RGB", (100, 300), (0, 160, 0))  # green, its top quarter red
    tall.paste((200, 0, 0), (0, 0, 100, 75))
    tall.save(folder / "tall.png")
    page = Page(id="p", size="custom", width_mm=W, height_mm=H, background=Background(color="#ff0000"),
                items=[BlockItem(id="left", x=10.0, y=30.0, w=20.0, h=20.0, color="#0000ff", bleed=True),
                       BlockItem(id="right", x=90.0, y=30.0, w=20.0, h=20.0, color="#00ff00"),
                       BlockItem(id="band", x=50.0, y=100.0, w=100.0, h=10.0, color="#ffff00",
                                 decorative=True, z=-1),
                       PictureItem(id="moon", x=90.0, y=70.0, w=20.0, h=20.0, path="moon.png"),
                       PictureItem(id="tall", x=5.0, y=70.0, w=10.0, h=30.0, path="tall.png"),
                       PictureItem(id="sun", x=50.0, y=130.0, w=40.0, h=20.0, path="sun.png",
                                   bleed=True)])
    path = folder / "card.toml"
    save_project(Project(title="Print", pages=[page]), path)
    out = folder / "card.pdf"
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "render", "--no-settle",
                             "--print", "--bleed", str(BLEED), str(path), "-o", str(out)],
                            capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert result.returncode == 0, result.stderr
    subprocess.run(["pdftoppm", "-r", str(DPI), "-png", "-singlefile", str(out), str(folder / "sheet")],
                   check=True)
    return out, Image.open(folder / "sheet.png").convert("RGB")


def pixel(image: Image.Image, x_mm: float, y_mm: float) -> tuple[int, int, int]:
    """The colour at a point given in the finished page's mm (origin at the trim's top left)."""
    scale = DPI / 25.4
    return image.getpixel((round((x_mm + SLUG) * scale), round((y_mm + SLUG) * scale)))


def test_the_pdf_says_where_to_trim_and_how_far_the_bleed_goes(printed):
    out, _ = printed
    with pdfplumber.open(out) as pdf:
        boxes = pdf.pages[0].page_obj.attrs  # as written: from the sheet's bottom-left corner
        media, trim, bleed = ([float(v) for v in boxes[name]]
                              for name in ("MediaBox", "TrimBox", "BleedBox"))
    assert media == pytest.approx([0, 0, (W + 2 * SLUG) * MM_TO_BP, (H + 2 * SLUG) * MM_TO_BP], abs=0.05)
    assert trim == pytest.approx([SLUG * MM_TO_BP, SLUG * MM_TO_BP, (SLUG + W) * MM_TO_BP,
                                  (SLUG + H) * MM_TO_BP], abs=0.01)
    assert bleed == pytest.approx([(SLUG - BLEED) * MM_TO_BP, (SLUG - BLEED) * MM_TO_BP,
                                   (SLUG + W + BLEED) * MM_TO_BP, (SLUG + H + BLEED) * MM_TO_BP], abs=0.01)


def test_the_background_and_bleed_items_reach_into_the_bleed_and_no_further(printed):
    _, sheet = printed
    assert pixel(sheet, -1.5, 47.0) == pytest.approx((255, 0, 0), abs=8)  # background in the bleed
    assert pixel(sheet, -4.5, 47.0) == pytest.approx((255, 255, 255), abs=8)  # white beyond it
    assert pixel(sheet, -1.5, 30.0) == pytest.approx((0, 0, 255), abs=8)  # the bleed block
    assert pixel(sheet, 50.0, 141.5) == pytest.approx((250, 200, 0), abs=8)  # the bleed picture
    assert pixel(sheet, 50.0, 131.0) == pytest.approx((250, 200, 0), abs=8)
    assert pixel(sheet, 30.0, 30.0) == pytest.approx((255, 0, 0), abs=8)  # the page is unchanged


def test_a_block_that_meets_the_page_edge_bleeds_marked_or_not(printed):
    """An unmarked block flush with the edge (a decorative band, or one the margin gave way
    for) reaches into the bleed on the edges it meets, and only those: stopping at the trim,
    a cut a hair outside it showed a line of background.  Inside the page nothing moves."""
    _, sheet = printed
    assert pixel(sheet, 101.5, 30.0) == pytest.approx((0, 255, 0), abs=8)  # the right edge
    assert pixel(sheet, 91.0, 30.0) == pytest.approx((0, 255, 0), abs=8)
    assert pixel(sheet, 79.0, 30.0) == pytest.approx((255, 0, 0), abs=8)  # its inner edge stays
    assert pixel(sheet, 90.0, 18.5) == pytest.approx((255, 0, 0), abs=8)
    for x_mm in (-1.5, 101.5):  # the band: both sides it meets
        assert pixel(sheet, x_mm, 100.0) == pytest.approx((255, 255, 0), abs=8)
    assert pixel(sheet, -4.5, 100.0) == pytest.approx((255, 255, 255), abs=8)  # and no further
    assert pixel(sheet, 50.0, 93.5) == pytest.approx((255, 0, 0), abs=8)  # its height is kept
    assert pixel(sheet, 50.0, 106.5) == pytest.approx((255, 0, 0), abs=8)


def test_an_unmarked_picture_that_meets_the_page_edge_bleeds_with_more_of_itself(printed):
    """A picture flush with the edge and not marked `bleed` reaches into the bleed too
    (stopping at the trim, a cut a hair outside it showed a sliver of paper).  It is scaled
    with its proportions kept and clipped to its frame grown into the bleed: its other edges
    stay where the layout put them, and the picture is not stretched to the new frame.  The
    tall picture (10 x 30 mm, its top quarter red) meets the left edge: 13 mm wide in print,
    so 39 mm tall centred on its own middle, its red ending at 70 - 19.5 + 9.75 = 60.25 mm
    (stretched to 13 x 30 mm it would end at 62.5)."""
    _, sheet = printed
    assert pixel(sheet, 101.5, 70.0) == pytest.approx((120, 60, 200), abs=8)  # the moon, right
    assert pixel(sheet, 50.0, 70.0) == pytest.approx((255, 0, 0), abs=8)
    assert pixel(sheet, 90.0, 58.5) == pytest.approx((255, 0, 0), abs=8)  # its top edge stays
    assert pixel(sheet, -1.5, 75.0) == pytest.approx((0, 160, 0), abs=8)  # the tall one, left
    assert pixel(sheet, -4.5, 75.0) == pytest.approx((255, 255, 255), abs=8)  # and no further
    assert pixel(sheet, 10.6, 75.0) == pytest.approx((255, 0, 0), abs=8)  # its right edge stays
    assert pixel(sheet, 5.0, 54.4) == pytest.approx((255, 0, 0), abs=8)  # so do top and bottom
    assert pixel(sheet, 5.0, 85.6) == pytest.approx((255, 0, 0), abs=8)
    assert pixel(sheet, 5.0, 59.5) == pytest.approx((200, 0, 0), abs=8)  # red, cut at 60.25
    assert pixel(sheet, 5.0, 61.2) == pytest.approx((0, 160, 0), abs=8)  # green: not stretched


def test_crop_marks_stand_outside_the_bleed_at_every_corner(printed):
    _, sheet = printed
    scale = DPI / 25.4
    for corner_x, corner_y, out_x, out_y in ((0, 0, -1, -1), (W, 0, 1, -1), (0, H, -1, 1), (W, H, 1, 1)):
        along = corner_x + out_x * (BLEED + 3.5)  # half way along the horizontal mark
        darkest = min(sum(sheet.getpixel((round((along + SLUG) * scale), round((corner_y + SLUG) * scale) + dy)))
                      for dy in (-1, 0, 1))
        assert darkest < 400, (corner_x, corner_y)
        assert pixel(sheet, corner_x + out_x * (BLEED + 0.5), corner_y) == pytest.approx((255, 255, 255), abs=8)


def test_without_print_the_pdf_is_the_page_alone(tmp_path):
    path = tmp_path / "card.toml"
    save_project(Project(pages=[Page(id="p", size="custom", width_mm=W, height_mm=H,
                                     background=Background(color="#ff0000"))]), path)
    out = tmp_path / "card.pdf"
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "render", str(path), "-o", str(out)],
                            capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert result.returncode == 0, result.stderr
    with pdfplumber.open(out) as pdf:
        boxes = pdf.pages[0].page_obj.attrs
    assert [float(v) for v in boxes["MediaBox"]] == pytest.approx([0, 0, W * MM_TO_BP, H * MM_TO_BP], abs=0.05)
    assert "TrimBox" not in boxes
