"""Hostile text: 200+ strings typeset in one compile; none breaks it, each reads back as typed.

The strings try every ASCII special character alone and in pairs, and the
classic attacks: \\input, \\write18, \\catcode, \\directlua, ^^ notation,
\\def loops, \\end{document}, unbalanced braces, control characters.
"""

from __future__ import annotations

import itertools
import string
import unicodedata
from pathlib import Path

import pdfplumber
import pytest

from floatpage.model.document import Page, Project, TextItem
from floatpage.typeset import render_pdf
from floatpage.typeset.escape import clean_text
from floatpage.typeset.fonts import ChainMetrics, FaceKey
from floatpage.typeset.text_layout import rich_text
from typeset_pdfcheck import BoxPt, chars_in

SPECIALS = "\\{}$&#%_^~[]"
ATTACKS = [
    r"\input{/etc/passwd}", r"\input /etc/passwd ", r"\include{/etc/hostname}",
    r"\write18{touch /tmp/floatpage-pwned}", r"\immediate\write18{id}",
    r"\catcode`\^=11 \catcode`\{=12", r"\catcode 92=12", r"\directlua{os.execute('id')}",
    r"\directlua{io.open('/tmp/floatpage-pwned','w')}", r"\luaexec{print(1)}",
    r"\def\x{\x}\x", r"\loop\iftrue\repeat", r"\end{document}", r"\begin{verbatim}",
    r"\makeatletter\@@input /etc/passwd", r"\csname input\endcsname{/etc/passwd}",
    r"\expandafter\input\string", r"\pdfobj file {/etc/passwd}", r"\special{pdf:x}",
    r"\openin5=/etc/passwd \read5 to\x", r"\newwrite\w\openout\w=/tmp/x",
    r"^^5cinput{/etc/passwd}", r"^^^^005cinput", r"^^M^^J^^I", r"^^7b^^7d",
    r"$\int_0^1 x\,dx$", r"$$x$$", r"\(x\)", r"\[x\]", r"#1#2##", r"\par\par",
    r"{{{{", r"}}}}", r"\iffalse", r"\fi\fi", r"\else", r"\relax\relax", r"\outer\def\y{}",
    r"\\\\\\", r"\\*[3pt]", r"\newline", r"\verb|x|", r"\url{http://x}", r"%%%%", r"% comment",
    r"~~~", r"``quotes''", r"--- -- -", r"!`?`", r"<<>>", r"a|b", r'"quoted"', r"'single'",
    r"\char92", r"\string\input", r"\detokenize{x}", r"\noexpand\x", r"\the\catcode92",
    r"\tikzset{every node/.style={red}}", r"\node at (0,0) {x};", r"]; \draw (0,0);",
    r"\color{red}", r"\fontsize{1000}{1}\selectfont", r"\font\x=cmr10 at 2000pt",
    r"\errmessage{boom}", r"\message{x}", r"\show\x", r"\batchmode", r"\scrollmode",
    r"\endinput", r"\dump", r"\end", r"\bye", r"\shipout\hbox{}", r"\global\let\par\relax",
    "tab\there", "nul\x00byte", "bell\x07", "esc\x1b[31mred", "del\x7f", "c1\x85next",
    "cr\rlf", "ls\u2028ps\u2029", "bom\ufeff", "nbsp\u00a0here", "soft\u00adhyphen",
]
UNICODE = ["naïve café", "Ærøskøbing Łódź", "Straße ẞ", "ﬁ ﬂ ligatures", "e\u0301 decomposed",
           "Ελληνικά", "Кириллица", "€ £ ¥ ¢", "„Anführung“ «guillemets»", "emoji 😀 here",
           "中文 text", "עברית", "…—–·•", "½ ¼ ¾", "№ ™ © ®", "private \ue000 use",
           # LuaTeX reads a literal U+FFFD as invalid UTF-8 and stopped the whole compile
           "mojibake \ufffd here", "\ufffd\ufffd5\ufffd", "noncharacter \ufffe \U0010ffff"]


def hostile_strings() -> list[str]:
    strings = [ch for ch in string.punctuation]
    strings += [f"a{ch}b" for ch in SPECIALS]
    strings += [f"{a}{b}" for a, b in itertools.product(SPECIALS, repeat=2)]
    strings += ATTACKS + UNICODE
    return strings


@pytest.fixture(scope="module")
def readback(tmp_path_factory):
    strings = hostile_strings()
    per_page, columns = 48, 4
    pages = []
    for start in range(0, len(strings), per_page):
        items = []
        for offset, text in enumerate(strings[start:start + per_page]):
            column, row = offset % columns, offset // columns
            items.append(TextItem(id=f"h{start + offset}", x=36 + 75 * column, y=17 + 33 * row,
                                  w=64, h=22, text=text, font="sans"))
        pages.append(Page(id=f"p{start // per_page}", size="A3", width_mm=297, height_mm=420,
                          items=items))
    project = Project(title=r"\input{/etc/passwd} 100% $hostile$", pages=pages)
    out = tmp_path_factory.mktemp("hostile") / "hostile.pdf"
    report = render_pdf(project, out)
    found = []
    with pdfplumber.open(out) as pdf:
        for page, pdf_page in zip(pages, pdf.pages):
            for item in page.items:
                chars = chars_in(pdf_page, BoxPt.of_item(item), margin_pt=8)
                found.append((item.text, "".join(c["text"] for c in chars)))
    return strings, found, report


def test_there_are_at_least_200_hostile_strings_and_none_broke_the_compile(readback):
    strings, found, report = readback
    assert len(strings) >= 200
    assert report.pages == len(found) // 48 + (1 if len(found) % 48 else 0)
    assert not Path("/tmp/floatpage-pwned").exists()


def is_colour_emoji(char: str) -> bool:
    """Colour emoji are pictures in the PDF (their text is checked by the multilingual tests)."""
    chain = ChainMetrics(rich_text(char, FaceKey("sans"))[1])
    return chain.font_of(char).path.name == "NotoColorEmoji.ttf"


def test_every_string_reads_back_as_typed_where_the_font_has_glyphs(readback):
    _, found, _ = readback
    """Compared without spaces (PDFs hold none; readers guess them from gaps), without
    invisible format characters (a soft hyphen prints nothing), and in NFKC form (the
    glyph for "ﬁ" is the "fi" ligature, which the PDF's ToUnicode spells "fi")."""
    wrong = []
    for typed, read in found:
        printable = rich_text(typed, FaceKey("sans"))[0]
        expected = "".join(ch for ch in printable if not ch.isspace()
                           and unicodedata.category(ch) != "Cf" and not is_colour_emoji(ch))
        expected = unicodedata.normalize("NFKC", expected)
        if unicodedata.normalize("NFKC", read.replace(" ", "")) != expected:
            wrong.append((typed, expected, read))
    assert not wrong, wrong[:5]


def test_characters_no_font_has_are_warned_about_by_item_and_code_point(readback):
    """Emoji and CJK come from the fallback fonts now; a private-use character has no font."""
    _, _, report = readback
    private = [w for w in report.warnings if "U+E000" in w]
    assert private and 'item "h' in private[0] and "Fira Sans" in private[0]
    assert not any("U+1F600" in w or "U+4E2D" in w for w in report.warnings)
