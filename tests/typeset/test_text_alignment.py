"""A text box's `align`: its lines set left, centred or right across the box, in the real PDF
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


def boxes(h: float = 16.0) -> list[TextItem]:
    """Three wide, low boxes, one per alignment, each with two lines of different lengths:
    the fitter sizes them by height, so the lines are far narrower than the box."""
    return [TextItem(id=f"t-{align}", x=105.0, y=60.0 + 60.0 * k, w=150.0, h=h,
                     text="Opening hours\nMon", font="sans", align=align)
            for k, align in enumerate(ALIGNMENTS)]


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
    save_project(Project(title="align", pages=[Page(id="p", size="A4", items=boxes())]), path)
    text = path.read_text()
    assert text.count("align = ") == 2, text  # left is the default: not written
    loaded = load_project(path)
    assert [item.align for item in loaded.pages[0].items] == list(ALIGNMENTS)


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
