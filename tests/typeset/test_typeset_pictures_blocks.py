"""Pictures, blocks, backgrounds, page sizes and z-order, read back from one real compile."""

from __future__ import annotations

from pathlib import Path

import pdfplumber
import pytest
from PIL import Image
from pdfminer.pdftypes import resolve1  # pdfplumber's own parser

from floatpage.model.document import Background, BlockItem, Page, PictureItem, Project
from floatpage.typeset import render_pdf
from floatpage.typeset.pictures import plan_picture
from typeset_pdfcheck import PT_PER_MM, BoxPt, edges_match

EXIF_ORIENTATION = 0x0112


def make_pictures(folder: Path) -> dict[str, str]:
    """One file per format LaTeX cannot read, one EXIF-rotated JPEG, one huge photo."""
    two_tone = Image.new("RGB", (200, 100), (220, 30, 30))
    two_tone.paste((30, 30, 220), (0, 50, 200, 100))  # top half red, bottom half blue
    files = {}
    for name, fmt in [("p.png", "PNG"), ("p.webp", "WEBP"), ("p.gif", "GIF"), ("p.bmp", "BMP"),
                      ("p.tiff", "TIFF"), ("p.jpg", "JPEG")]:
        two_tone.save(folder / name, fmt)
        files[name] = name
    exif = Image.Exif()
    exif[EXIF_ORIENTATION] = 6  # stored sideways: show it turned 90 degrees clockwise
    two_tone.save(folder / "rotated.jpg", "JPEG", exif=exif.tobytes())
    huge = Image.linear_gradient("L").resize((6000, 4000)).convert("RGB")
    huge.save(folder / "huge.jpg", "JPEG", quality=95)
    return files


@pytest.fixture(scope="module")
def rendered(tmp_path_factory):
    folder = tmp_path_factory.mktemp("pictures")
    make_pictures(folder)
    pictures = [PictureItem(id=f"pic-{name.replace('.', '-')}", x=30 + 45 * (i % 4),
                            y=30 + 40 * (i // 4), w=40, h=20, path=name, z=i)
                for i, name in enumerate(["p.png", "p.webp", "p.gif", "p.bmp", "p.tiff",
                                          "p.jpg"])]
    pictures.append(PictureItem(id="rotated", x=60, y=150, w=20, h=40, path="rotated.jpg", z=10))
    pictures.append(PictureItem(id="huge", x=140, y=150, w=60, h=40, path="huge.jpg", z=11))
    blocks = [  # drawn in ascending z, ties in file order: b, d, c, a
        BlockItem(id="a", x=40, y=40, w=30, h=20, color="#ff0000", z=2),
        BlockItem(id="b", x=60, y=50, w=30, h=20, color="#00ff00", z=0),
        BlockItem(id="c", x=80, y=60, w=30.5, h=21.25, color="#0000ff", z=1, opacity=0.5),
        BlockItem(id="d", x=100, y=70, w=17.3, h=9.9, color="#ffff00", z=0, decorative=True),
    ]
    project = Project(path=folder / "project.toml", pages=[
        Page(id="pictures", items=pictures),
        Page(id="blocks", size="A4", orientation="landscape", width_mm=297, height_mm=210,
             background=Background(color="#fff8e7"), items=blocks),
        Page(id="custom", size="custom", width_mm=127, height_mm=177.8,
             background=Background(picture="p.webp")),
    ])
    out = folder / "out.pdf"
    report = render_pdf(project, out)
    return project, out, report


def test_page_sizes(rendered):
    _, out, _ = rendered
    with pdfplumber.open(out) as pdf:
        sizes = [(p.width / PT_PER_MM, p.height / PT_PER_MM) for p in pdf.pages]
    assert sizes == [pytest.approx((210, 297), abs=0.01), pytest.approx((297, 210), abs=0.01),
                     pytest.approx((127, 177.8), abs=0.01)]


def test_every_picture_lands_on_its_rectangle(rendered):
    project, out, _ = rendered
    with pdfplumber.open(out) as pdf:
        images = pdf.pages[0].images
    items = project.pages[0].items
    assert len(images) == len(items)
    for item, image in zip(items, images):  # drawn in z order, which is file order here
        assert edges_match(image, BoxPt.of_item(item)) <= 0.5, item.id


def test_every_block_lands_on_its_rectangle_in_z_order(rendered):
    project, out, _ = rendered
    with pdfplumber.open(out) as pdf:
        rects = pdf.pages[1].rects
    page = project.pages[1]
    background, drawn = rects[0], rects[1:]
    assert edges_match(background, BoxPt(0, 0, page.width_mm * PT_PER_MM,
                                         page.height_mm * PT_PER_MM)) <= 0.5
    by_id = {item.id: item for item in page.items}
    order = ["b", "d", "c", "a"]
    assert len(drawn) == 4
    for item_id, rect in zip(order, drawn):
        assert edges_match(rect, BoxPt.of_item(by_id[item_id])) <= 0.5, item_id
    colours = [tuple(round(v) for v in rect["non_stroking_color"]) for rect in drawn]
    assert colours == [(0, 1, 0), (1, 1, 0), (0, 0, 1), (1, 0, 0)]


def test_block_opacity_reaches_the_pdf(rendered):
    _, out, _ = rendered
    with pdfplumber.open(out) as pdf:
        states = resolve1(resolve1(pdf.pages[1].page_obj.resources)["ExtGState"])
        assert any(abs(float(resolve1(state).get("ca", 1)) - 0.5) < 1e-6
                   for state in states.values())


def test_background_picture_covers_the_whole_page(rendered):
    _, out, _ = rendered
    with pdfplumber.open(out) as pdf:
        page = pdf.pages[2]
        (image,) = page.images
    # The picture is 2:1 and the page is taller than wide: it covers the height and is clipped.
    assert image["x0"] <= 0.5 and image["top"] <= 0.5
    assert image["x1"] >= page.width - 0.5 and image["bottom"] >= page.height - 0.5
    assert (image["bottom"] - image["top"]) == pytest.approx(page.height, abs=0.5)


def test_exif_rotation_is_applied(rendered):
    project, _, _ = rendered
    plan = plan_picture(project.base_dir / "rotated.jpg", 20, 40, "rotated")
    assert plan.action == "rotate" and plan.pixel_size == (100, 200)
    with Image.open(plan.cache_path) as upright:
        assert upright.size == (100, 200)
        red, blue = upright.getpixel((75, 100)), upright.getpixel((25, 100))
    assert red[0] > 150 and red[2] < 100      # the stored top (red) is now on the right
    assert blue[2] > 150 and blue[0] < 100


def test_huge_photo_is_downsampled_to_print_resolution(rendered):
    project, out, _ = rendered
    plan = plan_picture(project.base_dir / "huge.jpg", 60, 40, "huge")
    assert plan.action == "downsample"
    with Image.open(plan.cache_path) as small:
        w, h = small.size
    # 60 x 40 mm at 300 dpi is 709 x 473 px.
    assert 700 <= w <= 720 and 470 <= h <= 480
    assert out.stat().st_size < 1_000_000
    with pdfplumber.open(out) as pdf:
        srcsizes = [tuple(image["srcsize"]) for image in pdf.pages[0].images]
    assert (w, h) in srcsizes


@pytest.mark.parametrize("name", ["p.webp", "p.gif", "p.bmp", "p.tiff"])
def test_unreadable_formats_are_converted_into_the_cache(rendered, name):
    project, _, _ = rendered
    plan = plan_picture(project.base_dir / name, 40, 20, name)
    assert plan.action == "convert" and plan.cache_path.suffix == ".png"
    assert plan.cache_path.is_file()
    # Keyed by content: the same bytes under another name map to the same cache file.
    copy = project.base_dir / ("copy-" + name)
    copy.write_bytes((project.base_dir / name).read_bytes())
    assert plan_picture(copy, 40, 20, name).cache_path == plan.cache_path
