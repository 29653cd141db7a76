"""The .tex itself: golden files (pure, no TeX), the fragment, the kept .tex, and warnings.

Update the golden files after reviewing a change with:
    FLOATPAGE_UPDATE_GOLDEN=1 .venv/bin/python -m pytest tests/typeset/test_typeset_tex_output.py
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pdfplumber
import pytest

from floatpage.model.document import Background, BlockItem, CalendarItem, Page, Project, TextItem
from floatpage.typeset import render_pdf, render_tex, text_fit_warnings

GOLDEN = Path(__file__).parent / "golden"


def golden_project() -> Project:
    return Project(title="Golden {card} 100%", pages=[
        Page(id="front", size="A6", width_mm=105, height_mm=148,
             background=Background(color="#FDF6E3"), items=[
                 BlockItem(id="band", x=52.5, y=20, w=105, h=16, color="#268bd2", opacity=0.5,
                           z=-1),
                 TextItem(id="title", x=52.5, y=20, w=90, h=12, text="Ta-da! #1 & $5",
                          font="display", bold=True, color="#ffffff"),
                 TextItem(id="body", x=52.5, y=90, w=80, h=60,
                          text="First line\nA second, longer line that wraps [sic] ~ok",
                          font="serif", italic=True)]),
        Page(id="march", items=[CalendarItem(id="cal", x=105, y=150, w=160, h=120, year=2027,
                                             month=3, first_weekday="sunday", language="it")]),
    ])


def check_golden(name: str, text: str) -> None:
    path = GOLDEN / name
    if os.environ.get("FLOATPAGE_UPDATE_GOLDEN") == "1":
        path.parent.mkdir(exist_ok=True)
        path.write_text(text, encoding="utf-8")
    assert path.is_file(), f"no golden file {path}; run with FLOATPAGE_UPDATE_GOLDEN=1"
    assert text == path.read_text(encoding="utf-8"), f"{name} changed; review, then update"


def test_standalone_tex_matches_golden():
    check_golden("card.tex", render_tex(golden_project()))


def test_fragment_matches_golden():
    fragment = render_tex(golden_project(), fragment=True)
    assert "\\documentclass" not in fragment and "\\begin{tikzpicture}" in fragment
    check_golden("card-fragment.tex", fragment)


def test_render_tex_is_pure():
    project = golden_project()
    assert render_tex(project) == render_tex(project)


def test_user_text_never_appears_unescaped():
    tex = render_tex(golden_project())
    assert r"\#1 \& \$5" in tex and "{[}sic{]}" in tex and r"\textasciitilde{}ok" in tex
    assert r"Golden \{card\} 100\%" in tex


def test_fragment_can_be_input_by_another_document(tmp_path):
    project = golden_project()
    render_pdf(project, tmp_path / "card.pdf", tex_out=tmp_path / "card.tex",
               fragment_out=tmp_path / "fragment.tex")
    assert (tmp_path / "card.tex").read_text() == render_tex(project)
    host = tmp_path / "host.tex"
    host.write_text("\\documentclass{article}\n\\usepackage{fontspec,xcolor,graphicx,tikz}\n"
                    "\\begin{document}\nHost text before.\n\n\\noindent\\input{fragment.tex}\n"
                    "\\end{document}\n")
    subprocess.run(["lualatex", "-interaction=nonstopmode", "-halt-on-error", "host.tex"],
                   cwd=tmp_path, check=True, stdout=subprocess.DEVNULL, timeout=120)
    with pdfplumber.open(tmp_path / "host.pdf") as pdf:
        text = "".join("".join(page.extract_text().split()) for page in pdf.pages)
    for expected in ["Hosttextbefore.", "Ta-da!#1&$5", "wraps[sic]~ok", "Marzo2027", "DomLun"]:
        assert expected in text


def test_kept_tex_compiles_by_hand(tmp_path):
    """The .tex kept with --tex is standalone: plain `lualatex card.tex` makes the same pages."""
    render_pdf(golden_project(), tmp_path / "card.pdf", tex_out=tmp_path / "card.tex")
    subprocess.run(["lualatex", "-interaction=nonstopmode", "-halt-on-error", "card.tex"],
                   cwd=tmp_path, check=True, stdout=subprocess.DEVNULL, timeout=120)
    with pdfplumber.open(tmp_path / "card.pdf") as pdf:
        assert len(pdf.pages) == 2


def test_fit_warnings_name_the_item_and_the_problem():
    project = Project(pages=[Page(id="p", items=[
        TextItem(id="crowded", x=20, y=20, w=10, h=5, text="word " * 300),
        TextItem(id="emoji", x=100, y=100, w=60, h=20, text="Hi 😀 中", font="serif"),
        TextItem(id="private", x=100, y=150, w=60, h=20, text="a\ue000b\U0010fffd", font="serif"),
        TextItem(id="fine", x=100, y=200, w=60, h=20, text="All good"),
        TextItem(id="long", x=100, y=250, w=12, h=40, text="Rindfleischetikettierung")])])
    warnings = text_fit_warnings(project)
    assert any('item "crowded"' in w and "below the 6 pt minimum" in w for w in warnings)
    # Emoji and CJK come from the fallback fonts; private-use characters have no font at all.
    assert not any('item "emoji"' in w for w in warnings)
    assert any('item "private"' in w and "U+E000" in w and "U+10FFFD" in w and "Pagella" in w
               for w in warnings)
    assert any('item "long"' in w and "broken across lines" in w for w in warnings)
    assert not any('"fine"' in w for w in warnings)
