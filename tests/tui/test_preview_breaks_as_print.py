"""The preview breaks a line where the PDF does (user walk 5).

The preview wrapped at spaces only: "Happy 新年快乐" put its whole Chinese greeting on the
next line where the PDF began it on the first, a Japanese 。 could start a preview line, and
a French " !" went alone to the last line.  Both now follow `typeset.break_points.pieces`;
here the typesetter's own greedy breaking (`typeset.fit`, at one point per cell) and the
preview's must give the same lines.
"""

from __future__ import annotations

import pytest

from floatpage.model import Page, Project, TextItem, save_project
from floatpage.tui.cell_text import graphemes, width, wrap_cells
from floatpage.typeset.fit import Box, layout, paragraphs, segments_of

from editor_helpers import editor, preview_text


class CellMetrics:
    """A monospace face whose em is a terminal cell: a CJK character is two."""

    space_em = 1.0
    descent_em = 0.25

    def advance_em(self, word: str) -> float:
        return float(sum(width(g) for g in graphemes(word)))


TEXTS = ["Happy 新年快乐", "今日はいい天気ですね。明日もよろしくお願いします。",
         "あいう。えお", "「こんにちは」と言った", "ちょっとキャッシュ", "Joyeux anniversaire !",
         "« Bonne année » à tous", "Frohe Weihnachten und ein gutes neues Jahr",
         "生日快乐，祝你幸福！", "Love 愛 and ありがとう friends"]


def printed_lines(text: str, cells: int) -> list[str] | None:
    segments, _ = segments_of(paragraphs(text), CellMetrics(), None)
    found = layout(segments, 1.0, Box(float(cells), 1000.0), 1.2)
    return None if found is None else [line.text for line in found.lines]


@pytest.mark.parametrize("text", TEXTS)
def test_the_preview_breaks_lines_where_print_does(text):
    for cells in range(4, 30):
        printed = printed_lines(text, cells)
        if printed is not None:  # a piece wider than the line: print shrinks the font instead
            assert wrap_cells(text, cells) == printed, (text, cells)


def test_the_known_cases():
    assert wrap_cells("Happy 新年快乐", 10) == ["Happy 新年", "快乐"]
    assert wrap_cells("あいう。えお", 6) == ["あい", "う。え", "お"]  # no line starts with 。
    assert wrap_cells("Joyeux anniversaire !", 19) == ["Joyeux", "anniversaire !"]


async def test_the_editor_shows_a_chinese_greeting_begun_on_the_first_line(tmp_path):
    path = tmp_path / "card.toml"
    save_project(Project(pages=[Page(id="p", items=[
        TextItem(id="wish", x=105.0, y=100.0, w=34.0, h=30.0, text="Happy 新年快乐")])]),
        path)
    async with editor(path, size=(100, 40)) as (app, pilot):
        shown = preview_text(app)
        assert "Happy 新" in shown, shown
