"""Pictures whose own size TeX cannot take: a 20,000-pixel panorama, a file claiming 1 dpi, a
1 x 60,000 strip.  Each stopped LuaLaTeX with "Dimension too large" (or "Division by 0"), as an
item and as a page background; now each lands on its rectangle, read back from the real PDF."""

from __future__ import annotations

import pdfplumber
import pytest
from PIL import Image

from floatpage.model.document import Background, Page, PictureItem, Project
from floatpage.typeset import render_pdf
from floatpage.typeset.pictures import TEX_MAX_PIXELS, plan_picture
from typeset_pdfcheck import BoxPt

PICTURES = {
    "panorama.png": lambda path: Image.new("RGB", (20_000, 100), "red").save(path),
    "one-dpi.png": lambda path: Image.new("RGB", (300, 200), "green").save(path, dpi=(1, 1)),
    "one-dpi.jpg": lambda path: Image.new("RGB", (300, 200), "blue").save(path, dpi=(1, 1)),
    "strip.png": lambda path: Image.new("L", (1, 60_000), 128).save(path),
}


@pytest.fixture(scope="module")
def rendered(tmp_path_factory):
    folder = tmp_path_factory.mktemp("picture-sizes")
    for name, make in PICTURES.items():
        make(folder / name)
    items = [PictureItem(id=name.replace(".", "-"), x=40 + 70 * (k % 2), y=40 + 50 * (k // 2),
                         w=50, h=30, path=name) for k, name in enumerate(PICTURES)]
    pages = [Page(id="items", size="A4", width_mm=210, height_mm=297, items=items)]
    pages += [Page(id=f"background-{name.replace('.', '-')}", size="A5", width_mm=148,
                   height_mm=210, background=Background(picture=name)) for name in PICTURES]
    project = Project(path=folder / "project.toml", pages=pages)
    out = folder / "out.pdf"
    render_pdf(project, out)  # raised LatexCompileError: Dimension too large
    return project, out


def fills(image, box: BoxPt) -> bool:
    """The image covers the box and meets it on one axis: it fills its frame, clipped
    (typeset.placed.framed_picture), or lands exactly on it."""
    covers = (image["x0"] <= box.x0 + 0.5 and image["x1"] >= box.x1 - 0.5
              and image["top"] <= box.top + 0.5 and image["bottom"] >= box.bottom - 0.5)
    across = abs(image["x0"] - box.x0) < 0.5 and abs(image["x1"] - box.x1) < 0.5
    down = abs(image["top"] - box.top) < 0.5 and abs(image["bottom"] - box.bottom) < 0.5
    return covers and (across or down)


def test_every_picture_lands_on_its_rectangle(rendered):
    project, out = rendered
    with pdfplumber.open(out) as pdf:
        images = pdf.pages[0].images
        assert len(images) == len(PICTURES)
        for item in project.pages[0].items:
            box = BoxPt.of_item(item)
            assert any(fills(image, box) for image in images), item.id


def test_every_background_covers_its_page_and_no_more_than_it_must(rendered):
    _, out = rendered
    with pdfplumber.open(out) as pdf:
        for page in pdf.pages[1:]:
            (image,) = page.images
            assert image["x0"] <= 0.5 and image["top"] <= 0.5
            assert image["x1"] >= page.width - 0.5 and image["bottom"] >= page.height - 0.5
            # Cropped to the page's shape first, not scaled to metres and clipped.
            assert image["x1"] - image["x0"] < 3 * page.width
            assert image["bottom"] - image["top"] < 3 * page.height


def test_pictures_tex_can_take_are_copied_as_they_are(tmp_path):
    Image.new("RGB", (4000, 3000), "red").save(tmp_path / "camera.jpg", dpi=(300, 300))
    plan = plan_picture(tmp_path / "camera.jpg", 400, 300, "camera", tmp_path / "cache")
    assert plan.action == "copy"


def test_the_panorama_is_written_again_within_what_tex_takes(rendered):
    project, _ = rendered
    plan = plan_picture(project.base_dir / "panorama.png", 50, 30, "panorama", cover=True)
    assert plan.action == "downsample" and max(plan.pixel_size) <= TEX_MAX_PIXELS
    with Image.open(plan.cache_path) as written:
        assert written.size == plan.pixel_size and "dpi" not in written.info
