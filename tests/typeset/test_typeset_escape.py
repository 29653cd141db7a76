"""The escape table, one character at a time, and the cleaning that comes before it."""

import pytest
from pylatex.utils import NoEscape

from floatpage.typeset.escape import clean_text, escape_latex, finalize


@pytest.mark.parametrize("char, tex", [
    ("\\", r"\textbackslash{}"),
    ("{", r"\{"),
    ("}", r"\}"),
    ("$", r"\$"),
    ("&", r"\&"),
    ("#", r"\#"),
    ("%", r"\%"),
    ("_", r"\_"),
    ("^", r"\textasciicircum{}"),
    ("~", r"\textasciitilde{}"),
    ("[", "{[}"),
    ("]", "{]}"),
    ("\n", r"\\{}"),
])
def test_each_special_character_has_its_escape(char, tex):
    assert escape_latex(char) == tex
    assert escape_latex(f"a{char}b") == f"a{tex}b"


@pytest.mark.parametrize("char", list("<>|\"'`-!?@*+=/:;.,()") + ["é", "ß", "€", "\u00a0"])
def test_harmless_characters_pass_through(char):
    assert escape_latex(char) == char


def test_no_backslash_survives_except_as_our_own_commands():
    hostile = r"\input{/etc/passwd}\write18{ls}\catcode`\^=11 \directlua{io.open('x')}"
    escaped = escape_latex(hostile)
    # Every backslash now starts one of the table's commands, never a user's word.
    allowed = (r"\textbackslash{}", r"\{", r"\}", r"\textasciicircum{}", r"\%", r"\$")
    rest = escaped
    for command in allowed:
        rest = rest.replace(command, "")
    assert "\\" not in rest


def test_clean_text_normalises_and_drops_controls():
    assert clean_text("e\u0301") == "é"                       # NFC
    assert clean_text("a\r\nb\rc\u2028d") == "a\nb\nc\nd"      # one kind of newline
    assert clean_text("a\tb") == "a b"
    assert clean_text("a\x00b\x07c\x1bd\x7fe\x85f\ufeffg") == "abcde\nfg"
    assert clean_text("\ud800x") == "x"                        # lone surrogate


def test_finalize_escapes_everything_but_noescape():
    assert finalize("50%") == r"50\%"
    assert finalize(NoEscape(r"\relax")) == r"\relax"
    assert finalize(3.5) == "3.5"
    with pytest.raises(TypeError):
        finalize(None)
