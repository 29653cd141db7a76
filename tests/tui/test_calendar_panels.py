"""Calendar panels are whole (issue 11): every day of the month shows, in the cells the
panel has, and a panel too small for that says which month and days it holds."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from floatpage.tui.calendar_cells import cells, line_cells, month_lines, month_text
from floatpage.tui.page_painter import ANCHOR

from editor_helpers import editor, screen_of

ROOT = Path(__file__).resolve().parents[2]


def days_in(lines) -> list[int]:
    """The day numbers a layout shows: each shaded or plain piece's words, as numbers up to
    31 (a piece holds one day in the packed layouts, whose days touch)."""
    found = []
    for line in lines:
        for text, _shaded in line:
            found += [int(word) for word in text.split() if word.isdigit() and int(word) <= 31]
    return found


@pytest.mark.parametrize("year, month, first_weekday", [
    (2027, 1, "monday"), (2027, 2, "monday"), (2026, 2, "sunday"), (2027, 5, "monday"),
    (2028, 2, "monday"), (2027, 10, "sunday")])
def test_every_size_shows_every_day_once_or_says_the_month_and_its_days(year, month,
                                                                         first_weekday):
    text = month_text(year, month, first_weekday, "en")
    for cols in range(1, 41):
        for rows in range(1, 11):
            lines, whole = month_lines(text, cols, rows)
            if whole:
                assert len(lines) <= rows
                assert all(line_cells(line) <= cols for line in lines)
                assert days_in(lines) == list(range(1, text.days + 1)), (cols, rows, lines)
                for line in lines:  # where days touch, every other one is shaded
                    pieces = [(t, s) for t, s in line if t.strip().isdigit()]
                    for (a, shade_a), (b, shade_b) in zip(pieces, pieces[1:]):
                        if not a.endswith(" ") and not b.startswith(" ") and cells(a) == 2:
                            assert shade_a != shade_b
            else:
                assert len(lines) == 1 and lines[0][0][0] in (
                    f"{text.short_title} 1-{text.days}", text.short_title)
    # the largest panel gets the printed layout: title, weekday heads, weeks
    lines, whole = month_lines(text, 40, 10)
    assert whole and lines[0][0][0] == text.title and len(lines) == len(text.weeks) + 2


def preview_days(app, item_id: str) -> list[int]:
    """The day numbers the preview shows inside an item's cells, read from the canvas: each
    run of glyphs on one background, split at spaces."""
    preview = screen_of(app).preview
    canvas = preview.canvas
    item = app.session.page.item(item_id)
    x, y = app.session.engine.positions()[item_id]
    x0, y0, x1, y1 = preview.projection.rect(x, y, item.w, item.h)
    found = []
    for row in range(y0 // 2, (y1 + 1) // 2):
        words, word, background = [], "", None
        for col in range(x0, x1):
            glyph = canvas.glyph_at(col, row)
            char = glyph.char if glyph is not None else " "
            bg = glyph.bg if glyph is not None else None
            if bg == ANCHOR:  # the panel's own anchor, a digit on magenta: not a new day
                bg = background
            if bg != background or char == " ":
                words.append(word)
                word = ""
            background = bg
            word += char.strip()
        words.append(word)
        found += [int(w) for w in words if w.isdigit() and int(w) <= 31]
    return found


@pytest.mark.parametrize("size", [(80, 24), (100, 32)])
async def test_the_calendar_samples_month_is_whole_at_80x24_and_100x32(tmp_path, size):
    """At 80x24 the January panel stopped at the 17th: its 21 x 5 cells held the title, the
    heads and three weeks. Selected, its id takes a row more."""
    folder = tmp_path / "calendar-2027"
    shutil.copytree(ROOT / "sample_projects" / "calendar-2027", folder)
    async with editor(folder / "calendar-2027.toml", size=size) as (app, pilot):
        assert preview_days(app, "jan-month") == list(range(1, 32))
        app.session.select("jan-month")
        screen_of(app).after_edit()
        await pilot.pause()
        assert "jan-month" in "\n".join(screen_of(app).preview.text_lines())
        assert preview_days(app, "jan-month") == list(range(1, 32))
