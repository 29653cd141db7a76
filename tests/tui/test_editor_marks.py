"""Marks read as marks (issue 11): at 80x24 the album's follow-link `o` sat right after a
wrapped caption ("Daisyo"), and the flyer's anchor `+` covered its small pictures. Every
sample, at both sizes a terminal over SSH has: no mark touches a letter, none is on a
picture."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from floatpage.model.document import PictureItem
from floatpage.tui.page_painter import ANCHOR, LINK

from editor_helpers import editor, screen_of

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = sorted(path.parent.name for path in ROOT.glob("sample_projects/*/*.toml"))


def marks(canvas) -> dict[tuple[int, int], str]:
    """(col, row): char of every anchor or link mark and dot on the canvas."""
    return {(col, row): glyph.char for (row, col), glyph in canvas.glyphs.items()
            if (glyph.bg == ANCHOR and glyph.char in "+#") or (glyph.bg == LINK and glyph.char == "o")
            or (glyph.fg in (ANCHOR, LINK) and glyph.char == "\u00b7")}


def picture_cells(app) -> set[tuple[int, int]]:
    """The cells holding any pixel of a picture."""
    preview = screen_of(app).preview
    found = set()
    for item in app.session.page.items:
        if isinstance(item, PictureItem):
            x, y = app.session.engine.positions()[item.id]
            x0, y0, x1, y1 = preview.projection.rect(x, y, item.w, item.h)
            found |= {(col, row) for col in range(x0, x1) for row in range(y0 // 2, (y1 + 1) // 2)}
    return found


@pytest.mark.parametrize("size", [(80, 24), (100, 32)])
@pytest.mark.parametrize("sample", SAMPLES)
async def test_no_mark_glues_to_a_letter_or_hides_a_picture(tmp_path, sample, size):
    folder = tmp_path / sample
    shutil.copytree(ROOT / "sample_projects" / sample, folder)
    project = next(folder.glob("*.toml"))
    async with editor(project, size=size) as (app, pilot):
        for _page in app.session.project.pages[:2]:
            canvas = screen_of(app).preview.canvas
            drawn = marks(canvas)
            for (col, row), char in drawn.items():
                for side in (col - 1, col + 1):
                    glyph = canvas.glyph_at(side, row)
                    assert glyph is None or not glyph.char.isalnum(), \
                        (app.session.page.id, char, glyph.char, col, row)
            on_pictures = {cell: char for cell, char in drawn.items()
                           if cell in picture_cells(app) and char != "\u00b7"}
            assert not on_pictures, (app.session.page.id, on_pictures)
            await pilot.press("right_square_bracket")
            await pilot.pause()
