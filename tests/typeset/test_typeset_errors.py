"""Failures reach the user as the item and the log line, and never cost them their last PDF."""

from __future__ import annotations

from pathlib import Path

import pytest

from floatpage.model.document import Page, PictureItem, Project, TextItem
from floatpage.model.errors import FloatpageError
from floatpage.typeset import LatexCompileError, RenderError, compile_pdf, render_pdf
from floatpage.typeset.latex_log import errors_with_items, marker_at, parse_log

DATA = Path(__file__).parent / "data"


def test_parser_reads_a_saved_file_line_error_log():
    log = (DATA / "failed_picture.log").read_text()
    tex = (DATA / "failed_picture.tex").read_text()
    assert parse_log(log) == [(29, "error:  (file 7c417b3261bbfabf59ea488f5ff51c0f.pdf) "
                                    "(pdf inclusion): reading image failed")]
    labels = ['item "hello" on page "front"',
              'item "scan" on page "front" (picture file "broken.pdf")']
    (error,) = errors_with_items(log, tex, labels)
    assert error.item == labels[1] and error.line == 29
    assert str(error).startswith('item "scan" on page "front"')


def test_parser_reads_a_saved_bang_style_log():
    log = (DATA / "undefined_macro.log").read_text()
    tex = (DATA / "undefined_macro.tex").read_text()
    assert parse_log(log) == [(4, "Undefined control sequence.")]
    (error,) = errors_with_items(log, tex, ['item "greeting" on page "front"'])
    assert error.item == 'item "greeting" on page "front"'


def test_lines_outside_any_item_map_to_no_item():
    tex = "a\n% [fp:0] item x\nb\n% [fp:0] end\nc\n"
    assert marker_at(tex, 1) is None
    assert marker_at(tex, 3) == 0
    assert marker_at(tex, 5) is None


def broken_project(folder: Path) -> Project:
    (folder / "broken.pdf").write_bytes(b"%PDF-1.4\nthis is not really a pdf\n")
    return Project(path=folder / "p.toml", pages=[Page(id="front", items=[
        TextItem(id="hello", x=105, y=30, w=100, h=20, text="Hello"),
        PictureItem(id="scan", x=105, y=120, w=100, h=60, path="broken.pdf")])])


def good_project(folder: Path) -> Project:
    return Project(path=folder / "p.toml", pages=[Page(id="front", items=[
        TextItem(id="hello", x=105, y=30, w=100, h=20, text="Hello")])])


def test_a_failed_render_names_the_item_and_keeps_the_last_good_pdf(tmp_path):
    out = tmp_path / "card.pdf"
    render_pdf(good_project(tmp_path), out)
    good = out.read_bytes()
    with pytest.raises(LatexCompileError) as caught:
        render_pdf(broken_project(tmp_path), out)
    error = caught.value
    assert isinstance(error, FloatpageError)
    assert 'item "scan" on page "front" (picture file "broken.pdf")' in str(error)
    assert "reading image failed" in str(error)
    assert "Traceback" not in str(error) and "CalledProcessError" not in str(error)
    assert error.log_path is not None and error.log_path.is_file()
    assert out.read_bytes() == good
    assert not list(tmp_path.glob("*.floatpage-tmp"))
    render_pdf(good_project(tmp_path), out)      # success clears the stale log
    assert not error.log_path.exists()


def test_an_endless_loop_is_stopped_by_the_timeout(tmp_path):
    tex = "\\documentclass{article}\\begin{document}\\def\\x{\\x}\\x\\end{document}\n"
    with pytest.raises(LatexCompileError) as caught:
        compile_pdf(tex, tmp_path, timeout_s=3)
    assert "still running after 3 s" in str(caught.value)


def test_a_picture_that_is_not_a_picture_is_named(tmp_path):
    (tmp_path / "notes.png").write_text("not a png")
    project = Project(path=tmp_path / "p.toml", pages=[Page(id="front", items=[
        PictureItem(id="photo", x=50, y=50, w=40, h=30, path="notes.png")])])
    with pytest.raises(RenderError, match=r'item "photo" on page "front".*notes.png.*PNG, JPEG'):
        render_pdf(project, tmp_path / "out.pdf")
    assert not (tmp_path / "out.pdf").exists()


def test_missing_tex_says_what_to_install(tmp_path, monkeypatch):
    from floatpage.typeset import TexNotFoundError
    monkeypatch.setenv("PATH", str(tmp_path))  # an empty folder: no lualatex anywhere
    with pytest.raises(TexNotFoundError, match="not installed.*texlive-luatex"):
        render_pdf(good_project(tmp_path), tmp_path / "out.pdf")


@pytest.mark.parametrize("change, message", [  # the loader's own words (model/key_specs.py)
    ({"x": float("nan")}, '"x" must be a finite number'),
    ({"w": 0.0}, '"w" must be greater than 0'),
    ({"y": "ten"}, '"y" must be a number'),
    ({"color": "#fff}\\input{x}"}, 'must be a colour written as "#rrggbb"'),
    ({"text": "x" * 20_001}, '"text" holds 20001 characters'),
])
def test_bad_values_from_code_are_refused_with_the_item_named(tmp_path, change, message):
    item = TextItem(id="caption", x=50, y=50, w=40, h=10, text="Hi")
    for key, value in change.items():
        setattr(item, key, value)
    project = Project(pages=[Page(id="p", items=[item])])
    with pytest.raises(RenderError, match=message) as caught:
        render_pdf(project, tmp_path / "out.pdf")
    assert 'item "caption" on page "p"' in str(caught.value)


def test_a_new_pdf_is_readable_by_others_like_any_new_file(tmp_path):
    import os
    umask = os.umask(0o022)
    try:
        render_pdf(good_project(tmp_path), tmp_path / "card.pdf", tex_out=tmp_path / "card.tex")
    finally:
        os.umask(umask)
    assert (tmp_path / "card.pdf").stat().st_mode & 0o777 == 0o644
    assert (tmp_path / "card.tex").stat().st_mode & 0o777 == 0o644
