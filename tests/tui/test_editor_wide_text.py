"""Wide characters take two cells and right-to-left text reads right to left in the preview
(issue 11: they showed as '?' and backwards)."""

from __future__ import annotations

from floatpage.model import Page, Project, TextItem, save_project
from floatpage.tui.cell_text import graphemes, visual, wrap_cells

from editor_helpers import editor


def test_graphemes_keep_marks_and_joiners_with_their_letter():
    assert graphemes("e\u0301te\u0301") == ["e\u0301", "t", "e\u0301"]
    assert graphemes("\U0001F468\u200d\U0001F469 x") == ["\U0001F468\u200d\U0001F469", " ", "x"]
    assert graphemes("a\x1bb") == ["a", "?", "b"]


def test_lines_wrap_by_cells_and_read_in_visual_order():
    assert wrap_cells("日本語のテキスト", 6) == ["日本語", "のテキ", "スト"]
    assert visual("שלום 2027") == "2027 םולש"
    assert visual("Hello שלום world") == "Hello םולש world"


async def test_the_preview_draws_cjk_and_hebrew_readably(tmp_path):
    path = tmp_path / "card.toml"
    save_project(Project(pages=[Page(id="p", items=[
        TextItem(id="jp", x=60.0, y=60.0, w=90.0, h=30.0, text="日本 こんにちは"),
        TextItem(id="he", x=60.0, y=160.0, w=90.0, h=30.0, text="שלום")])]), path)
    async with editor(path) as (app, pilot):
        preview = app.editor.preview
        text = "\n".join(preview.text_lines())
        assert "日本" in text and "こんにちは" in text and "?" not in text
        assert "םולש" in text
        assert all(strip.cell_length == preview.size.width for strip in preview.strips())


def test_a_right_to_left_line_cut_short_keeps_its_beginning():
    """The "…" of a line cut short goes where the line ends: at the left of a Hebrew line,
    whose first word, at the right, is kept (user walk 5: it was cut off instead)."""
    from floatpage.tui.page_painter import cut_short
    line = wrap_cells("שלום עולם יפה מאוד", 9)[0]
    assert line == "םלוע םולש"
    assert cut_short(line, 6, True) == "…םולש"
    assert cut_short("Hello world", 6) == "Hello…"


async def test_the_preview_cuts_a_hebrew_text_at_its_left(tmp_path):
    path = tmp_path / "card.toml"
    save_project(Project(pages=[Page(id="p", items=[
        TextItem(id="he", x=105.0, y=100.0, w=40.0, h=9.0,
                 text="שלום עולם יפה מאוד וגם עוד מילים רבות מאוד")])]), path)
    async with editor(path) as (app, pilot):
        rows = [row for row in app.editor.preview.text_lines() if "םולש" in row]
        assert rows and rows[0].strip().startswith("…") and rows[0].strip().endswith("םולש")
