"""The Jinja environment for `latex_templates/`: TeX-safe delimiters, escape by default.

Templates write `\\VAR{value}` and `\\BLOCK{for ...}`; every substituted value is
escaped by the `finalize` hook unless it is PyLaTeX's `NoEscape`, which only
the filters below return. Numbers arrive computed and are only formatted here.

PyLaTeX is used for `NoEscape` only: the four packages are fixed `\\usepackage`
lines in page.tex.j2, next to what needs them, and PyLaTeX's `escape_latex` and
`generate_pdf` do not meet our needs (see typeset.escape and typeset.compile).
"""

from __future__ import annotations

import re
from importlib import resources
from pathlib import Path

import jinja2
from pylatex.utils import NoEscape

from floatpage.model.key_specs import HEX_COLOUR
from floatpage.typeset.escape import finalize

TEMPLATES = "floatpage.latex_templates"
SAFE_PATH = re.compile(r"^[A-Za-z0-9/._+-]+$")


def number(value: float, decimals: int = 4) -> NoEscape:
    """A plain decimal TeX accepts: no exponent, no '-0'."""
    text = f"{float(value):.{decimals}f}".rstrip("0").rstrip(".")
    return NoEscape("0" if text in ("-0", "") else text)


def tex_path(value: Path | str) -> NoEscape:
    """A file path for \\includegraphics or fontspec's Path; refuse anything TeX might parse."""
    text = str(value)
    if not SAFE_PATH.match(text):
        raise ValueError(f"path {text!r} has characters LaTeX cannot take in a file name")
    return NoEscape(text)


def color_name(value: str) -> NoEscape:
    """The xcolor name the preamble defines for "#rrggbb"."""
    return NoEscape("fp" + digits_of(value).lower())


def hex_digits(value: str) -> NoEscape:
    return NoEscape(digits_of(value).upper())


def digits_of(value: str) -> str:
    """The six hex digits of a colour written as the model writes it, "#rrggbb"."""
    if not isinstance(value, str) or not HEX_COLOUR.match(value):
        raise ValueError(f"colour {value!r} is not #rrggbb")
    return value[1:]


def control_sequence(name: str) -> NoEscape:
    """`\\name` for a command floatpage defines; letters only, so it is one control word."""
    if not re.fullmatch(r"[A-Za-z]+", name):
        raise ValueError(f"{name!r} is not a TeX control word")
    return NoEscape("\\" + name)


def lua_fallback(face) -> NoEscape:
    """luaotfload's fallback chain for a face, as a Lua call; only characters of file names."""
    specs = ", ".join(f'"{spec}"' for spec in face.fallback_specs)
    call = f'luaotfload.add_fallback("{face.chain_name}", {{{specs}}})'
    if not re.fullmatch(r'[A-Za-z0-9_./\-\[\]():;=", {}+]+', call):
        raise ValueError(f"font paths {face.fallback_specs!r} have characters LaTeX cannot take")
    return NoEscape(call)


def load_template(name: str) -> str:
    """A template's source, read as package data so an installed wheel needs no source tree."""
    return resources.files(TEMPLATES).joinpath(name).read_text(encoding="utf-8")


def make_environment() -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.FunctionLoader(load_template),
        block_start_string=r"\BLOCK{",
        block_end_string="}",
        variable_start_string=r"\VAR{",
        variable_end_string="}",
        comment_start_string=r"\#{",
        comment_end_string="}",
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=True,
        autoescape=False,
        undefined=jinja2.StrictUndefined,
        finalize=finalize,
    )
    env.filters.update(mm=number, bp=number, num=number, path=tex_path, color=color_name,
                       hex=hex_digits, cs=control_sequence,
                       lua_fallback=lua_fallback)
    return env
