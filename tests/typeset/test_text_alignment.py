"""A text box's `align`: its lines set at the start of the text's direction (the default: left,
or right for Hebrew or Arabic), left, centred or right across the box, in the real PDF
(LuaLaTeX, read back with pdfplumber), in the project file and in the editor's preview."""

from __future__ import annotations

import pdfplumber
import pytest

from floatpage.model import Page, Project, TextItem, load_project, save_project
from floatpage.model.errors import ProjectFileError
from floatpage.typeset import render_pdf
from typeset_pdfcheck import BoxPt, chars_in

ALIGNMENTS = ("left", "centre", "right")
TOLERANCE_PT = 1.5  # a glyph's side bearing


def boxes(h: float = 16.0, alignments: tuple[str, ...] = ALIGNMENTS,
          text: str = "Opening hours\nMon") -> list[TextItem]:
    """Wide, low boxes, one per alignment, each with two lines of different lengths: the
    fitter sizes them by height, so the lines are far narrower than the box."""
    return [TextItem(id=f"t-{align}", x=105.0, y=60.0 + 60.0 * k, w=150.0, h=h,
                     text=text, font="sans", align=align)
            for k, align in enumerate(alignments)]


def line_ends(pdf_path, item: TextItem) -> list[tuple[float, float, BoxPt]]:
    """Each printed line's left and right end in the item's box (pt), with the box."""
    with pdfplumber.open(pdf_path) as pdf:
        box = BoxPt.of_item(item)
        lines: dict[int, list[dict]] = {}
        for char in chars_in(pdf.pages[0], box, 2.0):
            lines.setdefault(round(char["top"]), []).append(char)
        return [(min(c["x0"] for c in line), max(c["x1"] for c in line), box)
                for line in lines.values()]


def test_each_line_is_set_where_its_box_aligns_it(tmp_path):
    items = boxes()
    project = Project(title="align", pages=[Page(id="p", size="A4", items=items)])
    render_pdf(project, tmp_path / "align.pdf")
    with pdfplumber.open(tmp_path / "align.pdf") as pdf:
        page = pdf.pages[0]
        for item in items:
            box = BoxPt.of_item(item)
            chars = chars_in(page, box, 2.0)
            lines: dict[int, list[dict]] = {}
            for char in chars:
                lines.setdefault(round(char["top"]), []).append(char)
            assert len(lines) == 2, (item.align, sorted(lines))
            for line in lines.values():
                left = min(c["x0"] for c in line)
                right = max(c["x1"] for c in line)
                assert right - left < (box.x1 - box.x0) / 2  # far narrower than its box
                if item.align == "left":
                    assert abs(left - box.x0) < TOLERANCE_PT, (left, box)
                elif item.align == "right":
                    assert abs(box.x1 - right) < TOLERANCE_PT, (right, box)
                else:
                    assert abs((left + right) / 2 - (box.x0 + box.x1) / 2) < TOLERANCE_PT


def test_the_file_keeps_the_alignment_and_names_it_only_where_set(tmp_path):
    path = tmp_path / "align.toml"
    alignments = ("start", "left", "centre", "right")
    save_project(Project(title="align", pages=[Page(id="p", size="A4",
                                                    items=boxes(alignments=alignments))]), path)
    text = path.read_text()
    assert text.count("align = ") == 3, text  # start is the default: not written
    loaded = load_project(path)
    assert [item.align for item in loaded.pages[0].items] == list(alignments)


def test_right_to_left_text_starts_at_the_right_unless_told_otherwise(tmp_path):
    """Hebrew and Arabic read from the right, so by default their lines are set against the
    box's right edge, as a word processor sets them; "left" still sets them left, and Latin
    text by default stays left."""
    hebrew = "שעות פתיחה\nשני"
    items = (boxes(alignments=("start", "left"), text=hebrew)
             + [TextItem(id="latin", x=105.0, y=180.0, w=150.0, h=16.0,
                         text="Opening hours\nMon", font="sans")])
    assert items[0].align == items[2].align == "start"
    project = Project(title="rtl", pages=[Page(id="p", size="A4", items=items)])
    render_pdf(project, tmp_path / "rtl.pdf")
    for item in items:
        ends = line_ends(tmp_path / "rtl.pdf", item)
        assert len(ends) == 2, (item.id, ends)
        for left, right, box in ends:
            assert right - left < (box.x1 - box.x0) / 2
            if item.id == "t-start":
                assert abs(box.x1 - right) < TOLERANCE_PT, (item.id, right, box)
            else:
                assert abs(left - box.x0) < TOLERANCE_PT, (item.id, left, box)


def test_an_unknown_alignment_names_the_item_and_the_choices(tmp_path):
    path = tmp_path / "align.toml"
    save_project(Project(title="align", pages=[Page(id="p", size="A4", items=boxes())]), path)
    path.write_text(path.read_text().replace('align = "right"', 'align = "middle"'))
    with pytest.raises(ProjectFileError) as raised:
        load_project(path)
    message = str(raised.value)
    assert "t-right" in message and "middle" in message and "centre" in message, message


async def test_the_editor_preview_sets_the_lines_as_the_pdf_does(tmp_path):
    """In the preview each box's last line starts at its left, middle or right, as in the
    PDF (each box's line is told apart by its last letter)."""
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tui"))
    from editor_helpers import editor, item_pixel_box, screen_of

    items = boxes(h=36.0)  # rows enough for both lines at any offset from the cells
    for item, letter in zip(items, "XYZ"):
        item.text = f"Opening hours\nMon{letter}"
    path = tmp_path / "align.toml"
    save_project(Project(title="align", pages=[Page(id="p", size="A4", items=items)]), path)
    async with editor(path, size=(120, 40)) as (app, pilot):
        lines = screen_of(app).preview.text_lines()
        for item, letter in zip(app.session.page.items, "XYZ"):
            x0, _, x1, _ = item_pixel_box(app, item.id)
            row = next(row for row in lines if f"Mon{letter}" in row)
            start = row.index(f"Mon{letter}")
            end = start + 4
            if item.align == "left":
                assert start - x0 <= 1, (item.align, start, x0, x1)
            elif item.align == "right":
                assert x1 - end <= 1, (item.align, end, x0, x1)
            else:
                assert abs((start + end) / 2 - (x0 + x1) / 2) <= 1.5, (start, end, x0, x1)


async def test_the_editor_preview_starts_right_to_left_lines_at_the_right(tmp_path):
    """The preview sets a Hebrew box's lines against its right edge by default, as the PDF
    does, and a Latin box's against its left."""
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tui"))
    from editor_helpers import editor, item_pixel_box, screen_of

    items = [TextItem(id="hebrew", x=105.0, y=60.0, w=150.0, h=36.0, text="שלום\nשני",
                      font="sans"),
             TextItem(id="latin", x=105.0, y=140.0, w=150.0, h=36.0, text="Hello\nMon",
                      font="sans")]
    path = tmp_path / "rtl.toml"
    save_project(Project(title="rtl", pages=[Page(id="p", size="A4", items=items)]), path)
    async with editor(path, size=(120, 40)) as (app, pilot):
        lines = screen_of(app).preview.text_lines()
        x0, _, x1, _ = item_pixel_box(app, "hebrew")
        row = next(row for row in lines if "ינש" in row)  # shown as it reads: right to left
        assert x1 - (row.index("ינש") + 3) <= 1, (row, x0, x1)
        x0, _, x1, _ = item_pixel_box(app, "latin")
        row = next(row for row in lines if "Mon" in row)
        assert row.index("Mon") - x0 <= 1, (row, x0, x1)
