"""A starter's photo centred over a wider or narrower block (the calendar's month panel, the
card's greeting) is as wide as it, or clear of its edges: edges 0.5-4 mm apart are a near miss
(physics.alignment) the snap cannot close on both sides, and it slid the photo off centre."""

from __future__ import annotations

import pytest

from floatpage import starters
from floatpage.model import load_project
from floatpage.model.document import CalendarItem, PictureItem
from floatpage.physics.alignment import NEAR_MM
from floatpage.starters.options import Options
from floatpage.starters.pictures import Picture, bundled


def test_a_calendar_of_camera_photos_keeps_each_photo_as_wide_as_the_panel():
    project = starters.build("calendar", Options(year=2027), [Picture("pictures/a.jpg", 4, 3)])
    for page in project.pages:
        [photo] = [item for item in page.items if isinstance(item, PictureItem)]
        [panel] = [item for item in page.items if isinstance(item, CalendarItem)]
        assert photo.w == pytest.approx(panel.w)
        assert photo.x == pytest.approx(panel.x)


def test_a_settled_calendar_of_camera_photos_prints_them_centred(tmp_path):
    """`floatpage new calendar --photos` with 4:3 photos: each month's photo stays on the
    page's centre line (it slid 10.7 mm left, 178.6 mm wide over the 178 mm panel)."""
    photos = tmp_path / "photos"
    photos.mkdir()
    [source] = bundled(["autumn-forest.jpg"])  # 640 x 480
    (photos / source.name).write_bytes(source.read_bytes())
    starters.create("calendar", tmp_path / "cal.toml", photos=photos, year=2027, jobs=2)
    for page in load_project(tmp_path / "cal.toml").pages:
        [photo] = [item for item in page.items if isinstance(item, PictureItem)]
        assert photo.x == pytest.approx(page.width_mm / 2, abs=0.01), page.id


@pytest.mark.parametrize("shape", [(4, 3), (3, 2), (16, 9), (1, 1), (3, 4)])
def test_no_month_photo_stands_a_near_miss_inside_or_outside_the_panel(shape):
    project = starters.build("calendar", Options(year=2027), [Picture("pictures/a.jpg", *shape)])
    page = project.pages[0]
    [photo] = [item for item in page.items if isinstance(item, PictureItem)]
    [panel] = [item for item in page.items if isinstance(item, CalendarItem)]
    apart = abs(photo.w - panel.w) / 2
    assert apart < 0.01 or apart >= NEAR_MM, (photo.w, panel.w)


@pytest.mark.parametrize("shape", [(3, 2), (4, 3), (16, 9)])
def test_a_wide_picture_on_the_card_front_lines_up_with_the_greeting(shape):
    """It stood 3 mm inside the greeting's box on both sides: 1.00 near misses per item."""
    front = starters.build("card", Options(year=2027), [Picture("pictures/a.jpg", *shape)]).pages[0]
    picture, greeting = front.item("front-picture"), front.item("front-greeting")
    assert picture.left == pytest.approx(greeting.left)
    assert picture.left + picture.w == pytest.approx(greeting.left + greeting.w)


def test_a_flyer_tag_is_as_wide_as_a_product_a_near_miss_narrower():
    """Nine products of the sample pictures' shapes: a 28.5 mm bottle and a 32 mm candle under
    36 mm tags had both edges a near miss (3.8 and 2 mm) from their tags'."""
    shapes = [(640, 427), (640, 480), (400, 600), (640, 360), (300, 600), (500, 500),
              (640, 427), (450, 600), (640, 427)]
    page = starters.build("flyer", Options(year=2027),
                          [Picture(f"pictures/{n}.jpg", w, h) for n, (w, h) in enumerate(shapes)]).pages[0]
    widths = []
    for product in (item for item in page.items if isinstance(item, PictureItem)):
        tag = page.item(f"{product.id}-price")
        apart = abs(tag.w - product.w) / 2
        widths.append(product.w)
        assert apart <= 0.5 or apart >= NEAR_MM, (product.w, tag.w)
    assert any(28.0 < w < 35.0 for w in widths), widths  # the case is there
