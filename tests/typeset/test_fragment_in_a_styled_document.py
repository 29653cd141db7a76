"""A fragment `\\input` by a LaTeX document of one's own keeps its looks whatever TikZ styles
that document sets for its own pictures (user-walk-8). Real LuaLaTeX, real PDFs, compared
as pixels."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from PIL import Image, ImageChops

from floatpage.model.document import BlockItem, Page, PictureItem, Project, TextItem
from floatpage.typeset import render_pdf

HOST = r"""\documentclass{article}
\usepackage[a5paper,margin=10mm]{geometry}
\usepackage{fontspec,xcolor,graphicx,tikz}
%s
\pagestyle{empty}
\begin{document}
\noindent\input{fragment.tex}
\end{document}
"""
# A document's own house style: every node framed, every picture drawn at half scale
STYLES = (r"\tikzset{every node/.style={draw=red, line width=2pt, fill=yellow},"
          r" every picture/.style={scale=0.5}, every path/.style={draw=blue},"
          r" every scope/.style={rotate=10}}")


def compiled_page(folder: Path, styles: str) -> Image.Image:
    (folder / "host.tex").write_text(HOST % styles)
    subprocess.run(["lualatex", "-interaction=nonstopmode", "-halt-on-error", "host.tex"],
                   cwd=folder, check=True, stdout=subprocess.DEVNULL, timeout=180)
    subprocess.run(["pdftoppm", "-r", "60", "-png", "-singlefile", "host.pdf", "host"],
                   cwd=folder, check=True, timeout=60)
    return Image.open(folder / "host.png").convert("RGB")


def test_a_documents_own_tikz_styles_do_not_reach_the_fragments_items(tmp_path):
    """`\\tikzset{every node/.style={draw=red}}` in the host framed every picture of the
    flyer in red; `every picture/.style={scale=.5}` would have moved every item."""
    picture = tmp_path / "pictures" / "photo.png"
    picture.parent.mkdir()
    Image.new("RGB", (60, 40), (30, 120, 200)).save(picture)
    project = Project(path=tmp_path / "card.toml", title="Styled", pages=[
        Page(id="front", size="custom", width_mm=100, height_mm=80, items=[
            PictureItem(id="photo", x=30, y=30, w=45, h=30, path="pictures/photo.png"),
            BlockItem(id="block", x=75, y=30, w=30, h=30, color="#22aa44"),
            TextItem(id="title", x=50, y=65, w=80, h=12, text="Open 8:00-20:00; now!")])])
    render_pdf(project, tmp_path / "card.pdf", fragment_out=tmp_path / "fragment.tex")
    plain = compiled_page(tmp_path, "")
    styled = compiled_page(tmp_path, STYLES)
    assert plain.size == styled.size
    assert ImageChops.difference(plain, styled).getbbox() is None


def test_the_documents_language_adds_no_space_before_the_fragments_colons(tmp_path):
    """A French document (polyglossia) set the flyer's "8:00-20:00" as "8 :00-20 :00": its
    rule puts a space before every colon, semicolon and exclamation mark, and the fragment's
    lines, fitted without them, grew past their boxes."""
    project = Project(path=tmp_path / "card.toml", title="Horaires", pages=[
        Page(id="front", size="custom", width_mm=100, height_mm=40, items=[
            TextItem(id="hours", x=50, y=20, w=90, h=14, text="Open 8:00-20:00; now!")])])
    render_pdf(project, tmp_path / "card.pdf", fragment_out=tmp_path / "fragment.tex")
    plain = compiled_page(tmp_path, "")
    french = compiled_page(tmp_path, r"\usepackage{polyglossia}\setdefaultlanguage{french}")
    assert ImageChops.difference(plain, french).getbbox() is None


# babel's shorthands as its German makes them ("a is ä, "s is ß), and one as its Turkish does
# (= active, which TikZ's options are full of), from babel's core, installed everywhere
SHORTHANDS = (r"\usepackage[english]{babel}"
              r"\useshorthands*{"+'"'+r"}\defineshorthand{"+'"'+r"a}{\"a}"
              r"\defineshorthand{"+'"'+r"s}{\ss}"
              r"\useshorthands*{=}\defineshorthand{=}{\textbf{!}}")


def test_the_documents_shorthands_leave_the_fragments_words_as_typed(tmp_path):
    """user-walk-12b: in a German document (babel) the fragment's `"Offen"` printed `Öffen"`,
    `"a"o` printed `äö` and `"s` printed `ß`: words the user typed, changed, in lines fitted
    without those changes."""
    project = Project(path=tmp_path / "card.toml", title="Kurz", pages=[
        Page(id="front", size="custom", width_mm=100, height_mm=40, items=[
            TextItem(id="sign", x=50, y=20, w=90, h=14, text='"Offen" "a"o "s x=y')])])
    render_pdf(project, tmp_path / "card.pdf", fragment_out=tmp_path / "fragment.tex")
    plain = compiled_page(tmp_path, "")
    german = compiled_page(tmp_path, SHORTHANDS)
    assert ImageChops.difference(plain, german).getbbox() is None


@pytest.mark.parametrize("engine", ["pdflatex", "xelatex"])
def test_another_engine_is_told_the_fragment_needs_lualatex(tmp_path, engine):
    """pdfLaTeX and XeLaTeX stopped at "Undefined control sequence \\directlua", which says
    nothing of what to do."""
    project = Project(path=tmp_path / "card.toml", title="Engine", pages=[
        Page(id="front", size="custom", width_mm=60, height_mm=30, items=[
            TextItem(id="t", x=30, y=15, w=50, h=10, text="Hello")])])
    render_pdf(project, tmp_path / "card.pdf", fragment_out=tmp_path / "fragment.tex")
    (tmp_path / "host.tex").write_text(r"""\documentclass{article}
\usepackage{xcolor,graphicx,tikz}
\begin{document}
\input{fragment.tex}
\end{document}
""")
    run = subprocess.run([engine, "-interaction=nonstopmode", "host.tex"], cwd=tmp_path,
                         stdout=subprocess.DEVNULL, timeout=180)
    log = (tmp_path / "host.log").read_text(errors="replace")
    assert run.returncode != 0
    assert "This fragment needs LuaLaTeX (compile this document" in log
    assert "Undefined control sequence" not in log
