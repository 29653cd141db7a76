"""Each starter builds a valid project of the right shape (no physics, no TeX here)."""

from pathlib import Path

import pytest

from floatpage import starters
from floatpage.model import ItemAnchor, load_project, save_project
from floatpage.model.document import CalendarItem, PictureItem
from floatpage.model.page_sizes import page_dimensions
from floatpage.physics.alignment import NEAR_MM
from floatpage.starters.options import Options
from floatpage.starters.pictures import Picture, bundled, copy_beside


def build_saved(kind: str, tmp_path: Path, options: Options, sources=None):
    """Build `kind` into tmp_path, save it, and load it back through the validating loader."""
    module = starters.KINDS[kind]
    pictures = copy_beside(sources if sources is not None else bundled(module.BUNDLED), tmp_path)
    project = starters.build(kind, options, pictures)
    path = tmp_path / f"{kind}.toml"
    save_project(project, path)
    return project, load_project(path)


def non_decorative(page):
    return [item for item in page.items if not item.decorative]


def assert_inside(page, slack=0.01):
    for item in page.items:
        assert item.left >= -slack and item.top >= -slack, item.id
        assert item.left + item.w <= page.width_mm + slack, item.id
        assert item.top + item.h <= page.height_mm + slack, item.id


def assert_no_overlap(page):
    items = non_decorative(page)
    for n, a in enumerate(items):
        for b in items[n + 1:]:
            apart = (a.left + a.w <= b.left or b.left + b.w <= a.left or
                     a.top + a.h <= b.top or b.top + b.h <= a.top)
            assert apart, (a.id, b.id)


@pytest.mark.parametrize("kind", ["blank", "calendar", "card", "flyer"])
@pytest.mark.parametrize("orientation", ["portrait", "landscape"])
def test_every_starter_builds_a_loadable_tidy_project(kind, orientation, tmp_path):
    options = Options(year=2027, orientation=orientation)
    built, loaded = build_saved(kind, tmp_path, options)
    assert [p.id for p in loaded.pages] == [p.id for p in built.pages]
    ids = [item.id for page in loaded.pages for item in page.items]
    assert len(ids) == len(set(ids))
    for page in loaded.pages:
        width, height = page_dimensions(page.size, orientation)
        assert (page.width_mm, page.height_mm) == pytest.approx((width, height))
        assert page.orientation == orientation
        assert_inside(page)
        assert_no_overlap(page)  # the starting layout is already clean, before any physics
        for item in page.items:
            if isinstance(item, PictureItem):
                assert (tmp_path / item.path).is_file()


def test_calendar_has_a_page_per_month_with_panel_title_and_photos(tmp_path):
    options = Options(year=2028, first_weekday="sunday", lang="fr")
    _, project = build_saved("calendar", tmp_path, options)
    assert len(project.pages) == 12
    for month, page in enumerate(project.pages, start=1):
        [panel] = [i for i in page.items if isinstance(i, CalendarItem)]
        assert (panel.year, panel.month, panel.first_weekday, panel.language) == (2028, month, "sunday", "fr")
        assert page.item(f"{page.id}-title").text == starters.words.month_name(month, "fr")
        assert sum(isinstance(i, PictureItem) for i in page.items) >= 1
    assert project.pages[7].item("aug-title").text == "Août"


def test_calendar_uses_every_user_photo(tmp_path):
    photos = bundled(["apples.png", "lemons.png", "teapot.png", "cupcake.png", "tulips.jpg"] * 6)
    sources = []
    for n, source in enumerate(photos):  # 30 distinct file names
        target = tmp_path / "in" / f"{n:02d}-{source.name}"
        target.parent.mkdir(exist_ok=True)
        target.write_bytes(source.read_bytes() + bytes([n]))  # distinct content, still readable
        sources.append(target)
    project = starters.build("calendar", Options(year=2027), copy_beside(sources, tmp_path / "p"))
    used = {i.path for page in project.pages for i in page.items if isinstance(i, PictureItem)}
    assert len(used) == 30
    assert all(sum(isinstance(i, PictureItem) for i in p.items) == 3 for p in project.pages)


def test_card_is_five_by_eight_inches_front_and_inside(tmp_path):
    _, project = build_saved("card", tmp_path, Options(year=2027, lang="de"))
    assert [p.id for p in project.pages] == ["front", "inside"]
    for page in project.pages:
        assert page.size == "5x8in"
        assert (page.width_mm, page.height_mm) == pytest.approx((127.0, 203.2))
        assert any(isinstance(i, PictureItem) for i in page.items)
    assert project.page("front").item("front-greeting").text == "Alles Gute zum Geburtstag!"


def test_album_takes_photos_a_page_at_a_time_with_anchored_captions(tmp_path):
    names = starters.album.BUNDLED + ["rolling-hills.jpg", "night-sky.jpg"]  # 10 photos
    _, project = build_saved("album", tmp_path, Options(year=2027), bundled(names))
    photos = [i for p in project.pages for i in p.items if isinstance(i, PictureItem)]
    assert [Path(p.path).name for p in photos] == names  # each once, in the order given
    assert len(project.pages) >= -(-10 // starters.album.MAX_PER_PAGE)
    for page in project.pages:
        on_page = [i for i in page.items if isinstance(i, PictureItem)]
        assert 1 <= len(on_page) <= starters.album.MAX_PER_PAGE
        for photo in on_page:
            assert max(photo.w, photo.h) >= starters.album.MIN_LONG_SIDE_MM or len(on_page) == 1
            caption = page.item(f"{photo.id}-caption")
            assert isinstance(caption.anchor, ItemAnchor) and caption.anchor.to == photo.id
            assert caption.anchor.dx == pytest.approx(caption.x - photo.x)
            assert caption.anchor.dy == pytest.approx(caption.y - photo.y)
            assert caption.top >= photo.top + photo.h  # under the photo, not on it
            assert caption.text == Path(photo.path).stem.replace("-", " ").capitalize()


def test_album_pages_take_fewer_photos_when_they_would_shrink():
    """Wide photos go six to a portrait page at a good size; squares would shrink, so fewer."""
    wide = [Picture(f"pictures/w{n}.jpg", 3, 2) for n in range(12)]
    square = [Picture(f"pictures/s{n}.jpg", 1, 1) for n in range(12)]
    per_page = lambda pictures: [sum(isinstance(i, PictureItem) for i in p.items)
                                 for p in starters.build("album", Options(year=2027), pictures).pages]
    assert max(per_page(wide)) == starters.album.MAX_PER_PAGE
    assert max(per_page(square)) < starters.album.MAX_PER_PAGE
    assert sum(per_page(square)) == 12


def test_flyer_price_tags_follow_their_products(tmp_path):
    _, project = build_saved("flyer", tmp_path, Options(year=2027))
    [page] = project.pages
    assert (page.size, page.width_mm, page.height_mm) == ("A4", 210.0, 297.0)
    products = [i for i in page.items if isinstance(i, PictureItem)]
    assert len(products) == len(starters.flyer.BUNDLED)
    for product in products:
        tag = page.item(f"{product.id}-price")
        assert isinstance(tag.anchor, ItemAnchor) and tag.anchor.to == product.id
        assert "€" in tag.text
        assert tag.top >= product.top + product.h
    assert any(i.decorative for i in page.items)
    assert page.background is not None and page.background.color


def test_flyer_products_stand_on_one_line_per_row_so_their_tags_line_up(tmp_path):
    """Products of eight shapes: each row's pictures share their bottom edge, so the tags under
    them share a line (centred in their cells, a square beside a tall one left its tag 4-9 mm
    off its neighbours', which no move of the snap could line up)."""
    shapes = [(1, 1), (3, 4), (4, 3), (2, 3), (3, 2), (1, 1), (9, 16), (4, 5)]
    project = starters.build("flyer", Options(year=2027),
                             [Picture(f"pictures/{n}.jpg", w, h) for n, (w, h) in enumerate(shapes)])
    [page] = project.pages
    products = [i for i in page.items if isinstance(i, PictureItem)]
    rows: dict[float, list[PictureItem]] = {}
    for product in products:  # a row is the products whose boxes overlap it vertically
        row = next((key for key in rows if abs(key - product.y) < product.h / 2), product.y)
        rows.setdefault(row, []).append(product)
    assert len(rows) == 2
    for row in rows.values():
        assert len({round(product.y + product.h / 2, 9) for product in row}) == 1, row
        # on one line, boxes of near heights would have tops 1-4 mm apart: one height, or
        # tops no near miss apart
        heights = sorted(product.h for product in row)
        for low, high in zip(heights, heights[1:]):
            assert high == low or high - low >= NEAR_MM, heights
    tags = {round(page.item(f"{product.id}-price").y, 9) for product in products}
    assert len(tags) == len(rows)


def test_flyer_columns_of_near_widths_share_one_width():
    """The shipped flyer's products: an apple 35 mm wide over a teapot 39 mm wide had edges
    2 mm apart, and the snap pushed such columns 4-8 mm out of line.  Each column of near widths
    is cut to one, where the row's tops allow it; here every column."""
    products = starters.build("flyer", Options(year=2027), [
        Picture(f"pictures/{n}.jpg", w, h) for n, (w, h) in enumerate(
            [(1, 1), (10, 9), (3, 4), (1, 1), (1, 1), (9, 11), (4, 5), (9, 11)])]).pages[0].items
    photos = [item for item in products if isinstance(item, PictureItem)]
    columns: dict[float, list[float]] = {}
    for photo in photos:
        columns.setdefault(round(photo.x, 6), []).append(photo.w)
    assert len(columns) == 4, columns
    for widths in columns.values():
        assert len(set(widths)) == 1, columns


def test_album_columns_of_near_widths_keep_the_rows_one_height():
    """The album's rows of one height come first: a column is cut to one width only where no
    row loses its one height (3:2 and 4:3 photos cannot have both)."""
    pictures = [Picture(f"pictures/{n}.jpg", w, h)
                for n, (w, h) in enumerate([(3, 4), (3, 2), (4, 5), (3, 2)])]
    page = starters.build("album", Options(year=2027), pictures).pages[0]
    photos = [item for item in page.items if isinstance(item, PictureItem)]
    left = [photo for photo in photos if photo.x < page.width_mm / 2]
    assert len(left) == 2 and left[0].w == left[1].w  # the tall 3:4 cut to the 4:5's width


def test_the_shipped_flyer_tags_line_up_along_each_row():
    """The sample as settled (physics, no-overlap pass and snap): each row's tags on one line."""
    path = Path(__file__).resolve().parents[2] / "sample_projects" / "shop-flyer" / "shop-flyer.toml"
    page = load_project(path).pages[0]
    tags = [item for item in page.items if item.id.endswith("-price")]
    lines = sorted({round(tag.y, 2) for tag in tags})
    assert len(lines) == 2, lines


def test_each_month_panel_is_the_right_month():
    """The builder's panels, checked against Python's calendar: every month once, in order."""
    project = starters.build("calendar", Options(year=2100), [Picture("pictures/a.jpg", 4, 3)])
    panels = [i for p in project.pages for i in p.items if isinstance(i, CalendarItem)]
    assert [(p.year, p.month) for p in panels] == [(2100, m) for m in range(1, 13)]


def test_album_rows_of_near_shapes_share_one_height_and_line_up():
    """A 3:2 photo beside a 4:3 one would keep edges 2-4 mm apart, a near miss no move can
    close; the album cuts such a row to one height.  A tall photo beside a wide one keeps its
    size instead of shrinking to a stamp."""
    def rows(pictures):
        page = starters.build("album", Options(year=2027), pictures).pages[0]
        by_row: dict[float, list[PictureItem]] = {}
        for photo in (i for i in page.items if isinstance(i, PictureItem)):
            by_row.setdefault(photo.y, []).append(photo)
        return list(by_row.values())

    shapes = [(3, 2), (4, 3), (4, 3), (3, 2)]
    near = rows([Picture(f"pictures/{n}.jpg", w, h) for n, (w, h) in enumerate(shapes)])
    assert [len(row) for row in near] == [2, 2]
    for row in near:
        assert row[0].h == row[1].h
        assert sorted(p.w / p.h for p in row) == pytest.approx([4 / 3, 1.5])
    shapes = [(3, 2), (3, 4), (3, 4), (3, 2)]
    apart = rows([Picture(f"pictures/{n}.jpg", w, h) for n, (w, h) in enumerate(shapes)])
    assert [len(row) for row in apart] == [2, 2]
    for row in apart:
        assert max(p.h for p in row) > 1.2 * min(p.h for p in row)
