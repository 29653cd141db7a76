"""Turn user text into TeX that can only ever print that text.

Escaping is the real defence: no TeX setting stops a control sequence from
reading a local file into the PDF, so user text must never form one. We do
not use PyLaTeX's `escape_latex`, which broke the compile on 29 of 195 hostile
strings; we do use its `NoEscape` marker, so templates escape by default.
"""

from __future__ import annotations

import unicodedata

from pylatex.utils import NoEscape

# One entry per character TeX treats specially (catcodes 0-8, 13, 14 and the
# brackets that a preceding macro could take as an optional argument).
ESCAPES: dict[str, str] = {
    "\\": r"\textbackslash{}",
    "{": r"\{",
    "}": r"\}",
    "$": r"\$",
    "&": r"\&",
    "#": r"\#",
    "%": r"\%",
    "_": r"\_",
    "^": r"\textasciicircum{}",
    "~": r"\textasciitilde{}",
    "[": "{[}",
    "]": "{]}",
    "\n": r"\\{}",
    # LuaTeX reads a literal U+FFFD as its own mark for invalid UTF-8 and stops with "String
    # contains an invalid utf-8 sequence"; the same character given by number prints as typed.
    "\ufffd": r"\char65533\relax{}",
}

LINE_BREAKS = {"\r\n": "\n", "\r": "\n", "\u2028": "\n", "\u2029": "\n", "\x85": "\n"}


def clean_text(text: str) -> str:
    """NFC-normalise, unify line breaks, turn tabs into spaces, drop control characters.

    What is left is text a person meant: letters, marks, spaces, newlines.
    """
    text = unicodedata.normalize("NFC", str(text))
    for old, new in LINE_BREAKS.items():
        text = text.replace(old, new)
    text = text.replace("\t", " ")
    return "".join(ch for ch in text if ch == "\n" or unicodedata.category(ch) not in ("Cc", "Cs")
                   and ch != "\ufeff")


def escape_latex(text: str) -> NoEscape:
    """Escape cleaned text character by character; a newline becomes a real line break."""
    return NoEscape("".join(ESCAPES.get(ch, ch) for ch in clean_text(text)))


def finalize(value: object) -> object:
    """Jinja's finalize hook: escape every substituted value unless it is already TeX."""
    if isinstance(value, NoEscape):
        return value
    if isinstance(value, bool) or value is None:
        raise TypeError(f"refusing to put {value!r} into a template; format it first")
    return escape_latex(str(value))
