"""Typesetting: fit texts to their boxes, write TikZ-positioned LaTeX, compile one reproducible PDF."""

from floatpage.typeset.compile import compile_pdf
from floatpage.typeset.errors import LatexCompileError, LogError, RenderError, TexNotFoundError
from floatpage.typeset.escape import clean_text, escape_latex
from floatpage.typeset.fit import Box, TextFit, fit_text
from floatpage.typeset.render import RenderReport, render_pdf, render_tex, text_fit_warnings

__all__ = [
    "render_tex", "render_pdf", "text_fit_warnings", "RenderReport", "RenderError",
    "LatexCompileError", "LogError", "TexNotFoundError", "compile_pdf", "escape_latex",
    "clean_text", "fit_text", "Box", "TextFit",
]
