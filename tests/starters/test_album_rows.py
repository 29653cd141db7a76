"""The album's rows are as tall as their photos need, and the height left is shared out evenly
(starters.even_rows): a page of tall photos over wide ones no longer leaves its lower third
empty, and the tall photos grow to their column's width."""

from __future__ import annotations

import copy

import pytest

from floatpage import starters
from floatpage.model import load_project
from floatpage.model.document import PictureItem
from floatpage.starters import album
from floatpage.starters.even_rows import even_rows, even_spaces, water_level
from floatpage.starters.options import Options
from floatpage.starters.pictures import Picture, bundled
from floatpage.starters.placement import Region

A4_COLUMN_MM = (210.0 - 2 * album.MARGIN_MM - 8.0) / 2 * 0.96  # two columns, as fill leaves them


def photos_of(page) -> list[PictureItem]:
    return [item for item in page.items if isinstance(item, PictureItem)]


def empty_bands(page) -> list[float]:
    """The empty heights a reader sees, top to bottom: from under the title (or the page's top
    edge) to the first block (a photo with its caption), between blocks, and to the page's
    bottom edge."""
    spans = {}
    for item in page.items:
        key = item.anchor.to if getattr(item.anchor, "to", None) else item.id
        top, bottom = item.y - item.h / 2, item.y + item.h / 2
        low, high = spans.get(key, (top, bottom))
        spans[key] = (min(low, top), max(high, bottom))
    bands, reached = [], 0.0
    for top, bottom in sorted(spans.values()):
        if top > reached + 1e-6:
            bands.append(top - reached)
        reached = max(reached, bottom)
    bands.append(page.height_mm - reached)
    return bands[1:] if any(item.id == "album-title" for item in page.items) else bands


def tall_over_wide() -> list[Picture]:
    return [Picture(f"pictures/{n}.jpg", w, h)
            for n, (w, h) in enumerate([(3, 4), (4, 5), (3, 2), (3, 2)])]


def test_a_row_of_wide_photos_under_tall_ones_takes_only_the_height_it_needs():
    """Equal rows left the wide photos small in a cell as tall as the tall ones', 34 mm empty
    over them and 38 mm under them (to the page's edge), 13 mm under the title: now the three
    spaces are one."""
    page = album.build(Options(year=2027), tall_over_wide()).pages[0]
    bands = empty_bands(page)
    assert len(bands) == 3, bands
    assert max(bands) - min(bands) < 1.0, bands
    assert min(bands) >= album.TITLE_GAP_MM


def test_tall_photos_grow_to_their_columns_width_where_the_page_has_the_height():
    """Held to half the page's height, the tall photos were 74 mm wide in 84 mm columns."""
    page = album.build(Options(year=2027), tall_over_wide()).pages[0]
    top_row = [photo for photo in photos_of(page) if photo.h > photo.w]
    assert len(top_row) == 2
    assert max(photo.w for photo in top_row) == pytest.approx(A4_COLUMN_MM)
    assert len({photo.h for photo in top_row}) == 1  # near shapes keep one height per row


def test_a_settled_mixed_album_keeps_its_even_spaces_and_is_a_fixed_point(tmp_path):
    """Made by `floatpage new album --photos` and settled: the physics keeps the shared-out
    spaces (within 3 mm), and settling again changes nothing."""
    from floatpage.model.layout import settle_project

    photos = tmp_path / "photos"
    photos.mkdir()
    for n, source in enumerate(bundled(["sunflower.jpg", "tulips.jpg", "alpine-dawn.jpg",
                                        "seaside.jpg"])):
        (photos / f"{n}-{source.name}").write_bytes(source.read_bytes())
    starters.create("album", tmp_path / "album.toml", photos=photos, year=2027)
    project = load_project(tmp_path / "album.toml")
    [page] = project.pages
    bands = empty_bands(page)
    assert max(bands) - min(bands) < 3.0, bands
    assert max(bands) < 30.0, bands  # equal rows left 13, 34 and 38 mm
    again = copy.deepcopy(project)
    settle_project(again)
    for before, after in zip(page.items, again.pages[0].items):
        assert (after.x, after.y) == pytest.approx((before.x, before.y), abs=0.01), before.id


@pytest.mark.parametrize("orientation", ["portrait", "landscape"])
def test_photos_are_large_and_never_smaller_than_the_albums_least(orientation):
    """Photos of every shape: each page's photos stay at least MIN_LONG_SIDE_MM long, inside
    the margins, with rows of near shapes at one height."""
    shapes = [(4, 3), (3, 4), (1, 1), (16, 9), (2, 3), (3, 2), (1, 2), (4, 5), (3, 2), (2, 3)]
    project = album.build(Options(year=2027, orientation=orientation),
                          [Picture(f"pictures/{n}.jpg", w, h) for n, (w, h) in enumerate(shapes)])
    assert sum(len(photos_of(page)) for page in project.pages) == len(shapes)
    for page in project.pages:
        photos = photos_of(page)
        for photo in photos:
            assert max(photo.w, photo.h) >= album.MIN_LONG_SIDE_MM or len(photos) == 1
            assert photo.left >= album.MARGIN_MM - 1e-6
            assert photo.left + photo.w <= page.width_mm - album.MARGIN_MM + 1e-6
        assert min(empty_bands(page)) >= -1e-6


def test_mixed_photos_are_shared_out_over_the_pages_not_left_one_alone():
    """The sixteen sample pictures (mixed shapes) in name order: filling each page in turn gave
    4, 5, 6 and one photo alone on the last page; four to a page keeps every page as full."""
    aspects = [(640, 427), (640, 480), (400, 600), (640, 360), (300, 600), (500, 500),
               (640, 427), (450, 600), (640, 427), (427, 600), (600, 400), (640, 400),
               (640, 427), (480, 640), (480, 600), (427, 640)]
    project = album.build(Options(year=2027),
                          [Picture(f"pictures/{n:02d}.jpg", w, h) for n, (w, h) in enumerate(aspects)])
    assert [len(photos_of(page)) for page in project.pages] == [4, 4, 4, 4]


def test_wide_photos_still_go_six_to_a_page_rather_than_four_to_emptier_pages():
    """Eight wide photos on portrait pages: four to a page would leave both pages three
    quarters empty (the photos held by the column's width), six and two fill both."""
    project = album.build(Options(year=2027), [Picture(f"pictures/{n}.jpg", 3, 2) for n in range(8)])
    assert [len(photos_of(page)) for page in project.pages] == [6, 2]


def test_water_level_keeps_the_rows_that_need_less():
    assert water_level([50.0, 200.0, 200.0], 250.0) == pytest.approx(100.0)
    assert water_level([50.0, 60.0], 200.0) == float("inf")
    assert water_level([80.0, 80.0], 100.0) == pytest.approx(50.0)


def test_even_spaces_share_out_what_is_left_and_keep_each_least():
    assert even_spaces(40.0, [0.0, 8.0, 0.0]) == pytest.approx([40 / 3] * 3)
    assert even_spaces(12.0, [0.0, 8.0, 0.0]) == pytest.approx([2.0, 8.0, 2.0])
    assert even_spaces(20.0, [8.0, 0.0]) == pytest.approx([10.0, 10.0])
    assert even_spaces(10.0, [8.0, 0.0]) == pytest.approx([8.0, 2.0])


def test_even_rows_gives_a_wide_row_its_need_and_the_tall_rows_the_rest():
    rects = even_rows(Region(0, 0, 100, 250), [0.5, 2.0, 0.5], fill=1.0, gap=0.0)
    # one column keeps the most area here: heights 100, 50, 100 (the wide row its need)
    assert [h for _, _, _, h in rects] == pytest.approx([100.0, 50.0, 100.0])
    assert [y for _, y, _, _ in rects] == pytest.approx([50.0, 125.0, 200.0])


def test_the_title_lines_up_with_a_photo_centred_under_it_at_a_near_width():
    """Three wide photos and two tall ones: the first page's two wide photos, one above the
    other, came out 149.6 mm wide under the 147 mm title box (1.60 near misses per item)."""
    shapes = [(640, 427)] * 3 + [(427, 640), (427, 600)]
    project = album.build(Options(year=2027),
                          [Picture(f"pictures/{n}.jpg", w, h) for n, (w, h) in enumerate(shapes)])
    page = project.pages[0]
    title = page.item("album-title")
    centred = [p for p in photos_of(page) if abs(p.x - page.width_mm / 2) < 1e-6]
    assert centred, "the case is there: a photo centred under the title"
    for photo in centred:
        apart = abs(title.w - photo.w) / 2
        assert apart <= 0.5 or apart >= 4.0, (title.w, photo.w)
