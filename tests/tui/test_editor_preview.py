"""The page preview, read back from the running app: fit, colours, thumbnails, labels, links."""

from __future__ import annotations

import pytest

from editor_helpers import editor, item_pixel_box, pixel, preview_text, screen_of, until
from floatpage.tui.page_painter import ANCHOR, LINK, PAPER, SELECTION, SURROUND
from floatpage.tui.projection import Projection
from floatpage.tui.thumbnails import thumbnail

async def test_page_fits_with_its_aspect_ratio_and_refits_on_resize(project_path):
    async with editor(project_path, size=(100, 40)) as (app, pilot):
        preview = screen_of(app).preview
        p = preview.projection
        # half-block pixels are square, so pixel width / height is the page's w / h (148 / 210)
        assert p.width / p.height == pytest.approx(148 / 210, rel=0.05)
        assert p.height == 2 * (preview.size.height - 2)  # the page is as tall as fits
        assert pixel(app, p.left + p.width // 2, p.top + 1) == PAPER
        assert pixel(app, 0, 0) == SURROUND
        await pilot.resize_terminal(160, 30)  # heard by the preview a few messages later
        assert await until(pilot, lambda: (preview.projection.cols, preview.projection.rows)
                           == (160, preview.size.height))
        q = preview.projection
        assert q.height == 2 * (preview.size.height - 2)
        assert q.width / q.height == pytest.approx(148 / 210, rel=0.05)


async def test_items_show_their_content_and_ids_only_when_asked(project_path):
    async with editor(project_path) as (app, pilot):
        text = preview_text(app)
        assert "Happy Birthday Anna" in text
        assert "March 2027" in text and "Mo Tu We Th Fr Sa Su" in text
        for item_id in ("photo", "block", "~band"):  # ids no longer print over the content
            assert item_id not in text
        await pilot.press("tab")  # the selected item shows its id
        await pilot.pause()
        assert app.session.selected_id in preview_text(app)
        await pilot.press("escape", "n")  # names for every item
        await pilot.pause()
        text = preview_text(app)
        for item_id in ("title", "photo", "caption", "block", "month", "~band"):
            assert item_id in text


async def test_items_are_drawn_in_their_colour(project_path):
    async with editor(project_path) as (app, pilot):
        x0, y0, x1, y1 = item_pixel_box(app, "block")
        assert pixel(app, (x0 + x1) // 2, y1 - 1) == (0x22, 0xAA, 0x44)


async def test_a_picture_shows_a_thumbnail_of_the_real_image(project_path):
    async with editor(project_path) as (app, pilot):
        x0, y0, x1, y1 = item_pixel_box(app, "photo")
        top = pixel(app, (x0 + x1) // 2, y0 + 2 + 1)  # below the label row
        bottom = pixel(app, (x0 + x1) // 2, y1 - 2)
        assert top[0] > 180 and top[2] < 80  # the red half
        assert bottom[2] > 180 and bottom[0] < 80  # the blue half


async def test_decorative_items_sit_behind_the_others(project_path):
    async with editor(project_path) as (app, pilot):
        x0, y0, x1, y1 = item_pixel_box(app, "month")
        band = (0xFF, 0xE0, 0x8A)
        inside_month = pixel(app, x1 - 2, y1 - 2)
        assert inside_month != band  # the calendar is drawn over the band
        bx0, by0, bx1, by1 = item_pixel_box(app, "band")
        assert pixel(app, bx0 + 1, by1 - 1) == band  # the band shows where nothing covers it


async def test_the_selected_item_is_framed(project_path):
    async with editor(project_path) as (app, pilot):
        x0, y0, x1, y1 = item_pixel_box(app, "block")
        assert pixel(app, x0 - 1, (y0 + y1) // 2) != SELECTION
        screen_of(app).selected_id = "block"
        await pilot.pause()
        assert pixel(app, x0 - 1, (y0 + y1) // 2) == SELECTION
        assert pixel(app, x1, (y0 + y1) // 2) == SELECTION


async def test_anchors_and_links_are_visible(project_path):
    async with editor(project_path) as (app, pilot):
        canvas = screen_of(app).preview.canvas
        preview = screen_of(app).preview
        col, row = preview.projection.cell_of(74.0, 170.0)  # the month's anchor point
        assert canvas.glyphs[(row, col)].bg == ANCHOR  # over the calendar's text: its letter
        screen_of(app).selected_id = "block"
        await pilot.press("a")  # a block shows no text: the anchor shows as '+', beside it
        x0, y0, x1, y1 = item_pixel_box(app, "block")  # (on it, it hid a cell of the block)
        pluses = [(col, row) for (row, col), glyph in preview.canvas.glyphs.items()
                  if glyph.char == "+" and glyph.bg == ANCHOR]
        beside = [(col, row) for col, row in pluses
                  if x0 - 1 <= col <= x1 and y0 // 2 - 1 <= row <= (y1 + 1) // 2
                  and not (x0 <= col < x1 and y0 // 2 <= row < (y1 + 1) // 2)]
        assert beside, (pluses, (x0, y0, x1, y1))
        ends = [g for g in preview.canvas.glyphs.values() if g.bg == LINK and g.char == "o"]
        assert len(ends) == 2  # caption follows photo: an 'o' at each end
        app.session.move_to("caption", 110.0, 190.0)  # far from its photo: a line between
        screen_of(app).redraw()
        link_dots = [g for g in preview.canvas.glyphs.values()
                     if g.fg == LINK and g.char == "\u00b7"]
        assert len(link_dots) >= 3


async def test_the_preview_fits_an_80_by_24_terminal(project_path):
    async with editor(project_path, size=(80, 24)) as (app, pilot):
        preview = screen_of(app).preview
        assert preview.size.height >= 15
        assert preview.projection.height >= 2 * (preview.size.height - 2)
        assert "Happy Birthday Anna" in preview_text(app)


def test_projection_round_trips_cells_and_millimetres():
    p = Projection.fit(100, 40, 210.0, 297.0)
    col, row = p.cell_of(105.0, 148.5)
    x, y = p.mm_at(col, row)
    assert abs(x - 105.0) <= 1 / p.scale and abs(y - 148.5) <= 2 / p.scale
    x0, y0, x1, y1 = p.rect(105.0, 148.5, 0.01, 0.01)
    assert x1 - x0 == 1 and y1 - y0 == 1  # the tiniest item stays one pixel


def test_thumbnails_are_cached_and_a_missing_file_is_none(tmp_path):
    from editor_helpers import paint_picture

    path = paint_picture(tmp_path / "p.png")
    first = thumbnail(path, 8, 6)
    assert first.shape == (6, 8, 3)
    assert thumbnail(path, 8, 6) is first
    assert thumbnail(tmp_path / "missing.png", 8, 6) is None


def test_a_moving_item_keeps_its_size_in_pixels():
    """Both edges rounded on their own made a moving picture a pixel taller or shorter now and
    then, so it was scaled again and every one of its cells resent (issue 11). Anywhere on
    the page, in steps of a twentieth of a millimetre, a 93 x 124 mm box is one size."""
    p = Projection.fit(98, 27, 127.0, 178.0)
    sizes = set()
    for step in range(400):
        x0, y0, x1, y1 = p.rect(50.0 + step / 20, 70.0 + step / 20, 93.0, 124.0)
        sizes.add((x1 - x0, y1 - y0))
    assert sizes == {(round(93.0 * p.scale), round(124.0 * p.scale))}


async def test_a_caption_a_cell_tall_shows_its_text_wherever_it_sits(tmp_path):
    """The photo album at 100 x 32, as opened: each photo's caption, a box about one cell
    tall, showed as a bare strip when it straddled two cell rows (four of five on page 1),
    since text went only on rows the box covers whole. Then one line goes on the row
    holding the box's top."""
    import shutil
    from pathlib import Path

    folder = tmp_path / "photo-album"
    shutil.copytree(Path(__file__).resolve().parents[2] / "sample_projects" / "photo-album",
                    folder)
    async with editor(folder / "photo-album.toml", size=(100, 32)) as (app, pilot):
        text = preview_text(app)
        captions = [item for item in app.session.page.items if item.id.endswith("-caption")]
        assert len(captions) == 5, [item.id for item in app.session.page.items]
        for caption in captions:
            assert caption.text in text, (caption.text, text)


async def test_a_merge_templates_picture_is_not_called_missing(tmp_path):
    """The merge sample's picture is `pictures/{photo}`, one per record: the preview said
    "missing pictures/{photo}", as for a file that is gone."""
    import shutil
    from pathlib import Path

    root = Path(__file__).resolve().parents[2]
    shutil.copytree(root / "sample_projects" / "merge-offers", tmp_path / "offers")
    async with editor(tmp_path / "offers" / "offer.toml", size=(100, 32)) as (app, pilot):
        text = " ".join(preview_text(app).split())
        assert "one per record:" in text and "{photo}" in text
        assert "missing" not in text


async def test_a_picture_that_is_there_but_cut_short_is_not_called_missing(tmp_path):
    """A JPEG cut short (a copy that stopped) prints, with render's warning that its pixels
    do not decode cleanly, but the preview said "missing pictures/sun.jpg" as if the file
    were gone, sending the user to look for it (user-walk-2)."""
    import shutil
    from pathlib import Path

    folder = tmp_path / "card"
    shutil.copytree(Path(__file__).resolve().parents[2] / "sample_projects" / "greeting-card",
                    folder)
    whole = (folder / "pictures" / "sunflower.jpg").read_bytes()
    (folder / "pictures" / "sunflower.jpg").write_bytes(whole[:3000])
    async with editor(folder / "greeting-card.toml", size=(100, 32)) as (app, pilot):
        text = " ".join(preview_text(app).split())
        assert "unreadable" in text and "missing" not in text


async def test_a_text_cut_short_ends_in_an_ellipsis(tmp_path):
    """At 80x24 the flyer's captions read "Sunfl" and "Coffe", as if that were all of them;
    a box that holds more text than its cells show ends its last line in "…"."""
    from floatpage.starters import create

    path = tmp_path / "flyer.toml"
    create("flyer", path)
    async with editor(path, size=(80, 24)) as (app, pilot):
        text = preview_text(app)
        for word in ("Sunflowers", "Coffee", "Lemons"):  # as far as its box's cells go
            assert any(word[:cut] + "\u2026" in text for cut in range(3, len(word))), (word, text)
        assert "Sunfl " not in text and "Coffe\n" not in text
