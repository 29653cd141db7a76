"""The typefaces floatpage offers, where their files are, and how wide text is in them.

Every face is one OpenType file from Debian's TeX fonts. The same file is
measured here with HarfBuzz and loaded by path through fontspec, so the
widths the fitter computes are the widths LuaLaTeX typesets (they agreed
within 0.01 pt on this machine).
"""

from __future__ import annotations

import functools
import shutil
import struct
import subprocess
import unicodedata
from dataclasses import dataclass
from pathlib import Path

import uharfbuzz as hb

STYLES = ("regular", "bold", "italic", "bolditalic")
# Contextual alternates off, in HarfBuzz here and in fontspec (RawFeature=-calt): Fira
# Sans's calt turns "#&" into a lone swash ampersand, losing the "#" the user typed.
SHAPING_FEATURES = {"calt": False}


@dataclass(frozen=True)
class Typeface:
    """A family as the user names it ("serif"), its real name and its four files."""

    family: str
    name: str
    debian_package: str
    files: dict[str, str]  # style -> file name


TYPEFACES: dict[str, Typeface] = {
    "serif": Typeface("serif", "TeX Gyre Pagella", "fonts-texgyre", {
        "regular": "texgyrepagella-regular.otf", "bold": "texgyrepagella-bold.otf",
        "italic": "texgyrepagella-italic.otf", "bolditalic": "texgyrepagella-bolditalic.otf"}),
    "sans": Typeface("sans", "Fira Sans", "texlive-fonts-extra", {
        "regular": "FiraSans-Regular.otf", "bold": "FiraSans-Bold.otf",
        "italic": "FiraSans-Italic.otf", "bolditalic": "FiraSans-BoldItalic.otf"}),
    # A high-contrast Didone for headings. Not Playfair Display: its CFF outlines use 2048
    # units per em, and LuaTeX then writes a /Tf size and /W widths that make PDF readers
    # (pdfminer, poppler) see every glyph at 1000/2048 of its size, which breaks text
    # selection and search. All three faces here use 1000 units per em.
    "display": Typeface("display", "Old Standard", "texlive-fonts-extra", {
        "regular": "OldStandard-Regular.otf", "bold": "OldStandard-Bold.otf",
        "italic": "OldStandard-Italic.otf", "bolditalic": "OldStandard-BoldItalic.otf"}),
}

# Where Debian puts them, for when kpsewhich is missing (e.g. a machine that only measures).
FALLBACK_DIRS = (
    Path("/usr/share/texmf/fonts/opentype/public/tex-gyre"),
    Path("/usr/share/texlive/texmf-dist/fonts/opentype/public/fira"),
    Path("/usr/share/texlive/texmf-dist/fonts/opentype/public/oldstandard"),
)


def style_of(bold: bool, italic: bool) -> str:
    return ("bold" if bold else "") + ("italic" if italic else "") or "regular"


@dataclass(frozen=True)
class FaceKey:
    """One font file: a family in one style."""

    family: str
    style: str = "regular"

    @property
    def tex_command(self) -> str:
        """The `\\newfontface` command name, letters only as TeX requires."""
        return "fpface" + self.family.capitalize() + self.style.capitalize()

    @property
    def file_name(self) -> str:
        return TYPEFACES[self.family].files[self.style]

    @property
    def label(self) -> str:
        name = TYPEFACES[self.family].name
        return name if self.style == "regular" else f"{name} {self.style.replace('bolditalic', 'bold italic')}"


class FontNotFoundError(FileNotFoundError):
    pass


@functools.lru_cache(maxsize=None)
def font_paths() -> dict[str, Path]:
    """File name -> absolute path for every face, found once per process (one kpsewhich call)."""
    names = sorted({name for face in TYPEFACES.values() for name in face.files.values()})
    found: dict[str, Path] = {}
    if shutil.which("kpsewhich"):
        result = subprocess.run(["kpsewhich", *names], capture_output=True, text=True, check=False)
        for line in result.stdout.splitlines():
            path = Path(line.strip())
            if path.name in names:
                found.setdefault(path.name, path)
    for name in names:
        if name not in found:
            for folder in FALLBACK_DIRS:
                if (folder / name).is_file():
                    found[name] = folder / name
                    break
    return found


def font_path(face: FaceKey) -> Path:
    path = font_paths().get(face.file_name)
    if path is None:
        package = TYPEFACES[face.family].debian_package
        raise FontNotFoundError(f"font file {face.file_name} ({face.label}) not found; "
                                f"install the Debian package {package}")
    return path


@dataclass(frozen=True)
class Ink:
    """A word's ink box in em: left and right of its origin, above (top) and below (bottom)
    the baseline. An accent on a capital reaches above the em box PDF readers report."""

    left: float
    right: float
    top: float
    bottom: float


class FontMetrics:
    """Shaped widths of words in one font file, in em, plus the em box's descent.

    Widths scale linearly with size (no hinting in PDF), so each word is shaped
    once, at the font's units per em, and cached.
    """

    def __init__(self, path: Path):
        self.path = Path(path)
        blob = hb.Blob.from_file_path(str(self.path))
        self.face = hb.Face(blob)
        self.font = hb.Font(self.face)
        self.upem = self.face.upem
        # PDF readers place a glyph's box from the FontDescriptor's Descent, which LuaTeX
        # writes as the hhea table's descender (not OS/2's, which HarfBuzz's font extents may
        # prefer), truncated to 1/1000 em; use exactly that number.
        hhea = self.face.reference_table("hhea").data
        descender = struct.unpack(">h", hhea[6:8])[0]
        self.descent_em = int(-descender * 1000 / self.upem) / 1000
        self._shaped: dict[str, tuple[float, Ink]] = {}
        self.space_em = self.advance_em(" ")

    def shape(self, word: str) -> tuple[float, "Ink"]:
        """Advance width and ink box of `word` as HarfBuzz shapes it (ligatures, kerning), in em."""
        known = self._shaped.get(word)
        if known is not None:
            return known
        buffer = hb.Buffer()
        buffer.add_str(word)
        buffer.guess_segment_properties()
        hb.shape(self.font, buffer, SHAPING_FEATURES)
        pen = 0
        left = right = top = bottom = None
        for info, position in zip(buffer.glyph_infos, buffer.glyph_positions):
            extents = self.font.get_glyph_extents(info.codepoint)
            if extents is not None and (extents.width or extents.height):
                x0 = pen + position.x_offset + extents.x_bearing
                y0 = position.y_offset + extents.y_bearing
                left = x0 if left is None else min(left, x0)
                right = x0 + extents.width if right is None else max(right, x0 + extents.width)
                top = y0 if top is None else max(top, y0)
                low = -(y0 + extents.height)
                bottom = low if bottom is None else max(bottom, low)
            pen += position.x_advance
        scale = 1 / self.upem
        if left is None:  # nothing visible, e.g. a space
            ink = Ink(0.0, 0.0, 0.0, 0.0)
        else:
            ink = Ink(left * scale, right * scale, top * scale, bottom * scale)
        known = (pen * scale, ink)
        self._shaped[word] = known
        return known

    def advance_em(self, word: str) -> float:
        """Advance width of `word`, in em: what TeX moves the pen by."""
        return self.shape(word)[0]

    def ink_em(self, word: str) -> "Ink":
        """Where the word's glyphs put ink, in em from its origin on the baseline."""
        return self.shape(word)[1]

    def has_char(self, char: str) -> bool:
        return self.font.get_nominal_glyph(ord(char)) is not None

    def missing_chars(self, text: str) -> list[str]:
        """Visible characters of `text` this font has no glyph for, in order of appearance.

        Invisible format characters (zero-width space, joiners, marks of direction) are
        not reported: a font without them prints exactly what the user sees anyway.
        """
        missing: dict[str, None] = {}
        for char in text:
            if char not in " \n" and char not in missing and not self.has_char(char) \
                    and unicodedata.category(char) != "Cf":
                missing[char] = None
        return list(missing)

    def lacks(self, char: str) -> bool:
        """True for a character the engine would drop: no glyph in this font."""
        return char not in " \n" and not self.has_char(char)


@functools.lru_cache(maxsize=None)
def metrics_for(face: FaceKey) -> FontMetrics:
    """One FontMetrics per face per process: loading and shaping caches are worth keeping."""
    return FontMetrics(font_path(face))
