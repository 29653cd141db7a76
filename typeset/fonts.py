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
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

import uharfbuzz as hb

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
    """One font file: a family in one style; with a fallback chain for text it cannot set.

    `fallbacks` holds indices into `fallback_candidates(style)`, only the fonts this
    text needs, in candidate order, so luaotfload (which takes the first font of the
    chain that has a character) picks what `ChainMetrics` measured. A face without
    fallbacks uses the plain node renderer: Latin-only text pays nothing for them.
    """

    family: str
    style: str = "regular"
    fallbacks: tuple[int, ...] = ()
    harf: bool = False  # HarfBuzz mode: marks, right-to-left or fallback text

    @property
    def rich(self) -> bool:
        return bool(self.fallbacks) or self.harf

    @property
    def tex_command(self) -> str:
        """The `\\newfontface` command name, letters only as TeX requires."""
        chain = "".join("X" + letters_of(index) for index in self.fallbacks)
        return ("fpface" + self.family.capitalize() + self.style.capitalize()
                + ("H" if self.rich else "") + chain)

    @property
    def chain_key(self) -> str:
        return chain_key(self.family, self.style)

    @property
    def chain_name(self) -> str:
        return self.tex_command.lower()

    @property
    def fallback_specs(self) -> list[str]:
        """luaotfload font requests for the chain: HarfBuzz mode, the file by path."""
        specs = []
        for index in self.fallbacks:
            spec = fallback_candidates(self.chain_key)[index].spec
            script = script_of(self.chain_key, index)
            specs.append(spec + (f"script={script};" if script else ""))
        return specs

    @property
    def file_name(self) -> str:
        return TYPEFACES[self.family].files[self.style]

    @property
    def plain(self) -> "FaceKey":
        return FaceKey(self.family, self.style)

    @property
    def label(self) -> str:
        name = TYPEFACES[self.family].name
        return name if self.style == "regular" else f"{name} {self.style.replace('bolditalic', 'bold italic')}"


def letters_of(index: int) -> str:
    out = ""
    while True:
        out = chr(ord("a") + index % 26) + out
        index //= 26
        if not index:
            return out


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

    def __init__(self, path: Path, index: int = 0):
        self.path = Path(path)
        blob = hb.Blob.from_file_path(str(self.path))
        self.face = hb.Face(blob, index)
        self.font = hb.Font(self.face)
        self.upem = self.face.upem
        # PDF readers place a glyph's box from the FontDescriptor's Descent, which LuaTeX
        # writes as the hhea table's descender (not OS/2's, which HarfBuzz's font extents may
        # prefer), truncated to 1/1000 em; use exactly that number.
        hhea = self.face.reference_table("hhea").data
        descender = struct.unpack(">h", hhea[6:8])[0]
        self.descent_em = int(-descender * 1000 / self.upem) / 1000
        self._shaped: dict[str, tuple[float, Ink]] = {}
        self.em_extents: dict[str, tuple[float, float]] = {}  # word -> (above, below) baseline
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
        raised = min(0, *(p.y_offset for p in buffer.glyph_positions)) if buffer.glyph_positions else 0
        lifted = max(0, *(p.y_offset for p in buffer.glyph_positions)) if buffer.glyph_positions else 0
        # The em box PDF readers draw around each glyph moves with the glyph's offset.
        self.em_extents[word] = (1 - self.descent_em + lifted / self.upem,
                                 self.descent_em - raised / self.upem)
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


# ---- fallback: Debian's Noto fonts, for every script the three faces lack ----

NOTO_DIRS = (Path("/usr/share/fonts/truetype/noto"), Path("/usr/share/fonts/opentype/noto"))
FALLBACK_PACKAGES = "fonts-noto-core fonts-noto-cjk fonts-noto-color-emoji"
# Tried first, in this order: the general Latin/Greek/Cyrillic face, then the big scripts
# (CJK as Simplified Chinese, index 2 of the collection), then emoji; every other Noto
# face of the folder follows in name order, so rarer scripts are found too.
# The sans face tries Noto's sans faces first, the others Noto's serif faces.
# Symbols come before CJK: the CJK fonts draw ① and ➀ with one glyph, which the PDF's
# text layer can only name one way (➀), so ① must come from Noto Sans Symbols.
PREFERRED_SERIF = ("NotoSerif", "NotoSans", "NotoSansSymbols", "NotoSansSymbols2", "NotoSansMath",
                   "NotoSerifCJK-{Style}.ttc:2", "NotoNaskhArabic", "NotoSansArabic",
                   "NotoSerifHebrew", "NotoSansHebrew", "NotoSerifDevanagari",
                   "NotoSansDevanagari", "NotoSerifThai", "NotoSansThai", "NotoColorEmoji.ttf")
PREFERRED_SANS = ("NotoSans", "NotoSerif", "NotoSansSymbols", "NotoSansSymbols2", "NotoSansMath",
                  "NotoSansCJK-{Style}.ttc:2", "NotoSansArabic", "NotoNaskhArabic",
                  "NotoSansHebrew", "NotoSerifHebrew", "NotoSansDevanagari",
                  "NotoSerifDevanagari", "NotoSansThai", "NotoSerifThai", "NotoColorEmoji.ttf")


@dataclass(frozen=True)
class Candidate:
    path: Path
    index: int = 0

    @property
    def spec(self) -> str:
        sub = f"({self.index})" if self.path.suffix == ".ttc" else ""
        return f"[{self.path}]{sub}:mode=harf;"


def noto_file(stem: str, style: str) -> Candidate | None:
    """The file of a Noto family in this style, else its regular one."""
    index = 0
    if ":" in stem:
        stem, number = stem.split(":")
        index = int(number)
    styles = {"regular": ["Regular"], "bold": ["Bold", "Regular"], "italic": ["Italic", "Regular"],
              "bolditalic": ["BoldItalic", "Bold", "Italic", "Regular"]}[style]
    for folder in NOTO_DIRS:
        if "{Style}" in stem or "." in stem:
            for name in styles:
                path = folder / stem.replace("{Style}", name)
                if path.is_file():
                    return Candidate(path, index)
            continue
        for name in styles:
            for ext in (".ttf", ".otf"):
                path = folder / f"{stem}-{name}{ext}"
                if path.is_file():
                    return Candidate(path, index)
    return None


def chain_key(family: str, style: str) -> str:
    """Which candidate list a face uses: its Noto kind and style, e.g. "sans:bold"."""
    return ("sans:" if family == "sans" else "serif:") + style


@functools.lru_cache(maxsize=None)
def fallback_candidates(key: str) -> tuple[Candidate, ...]:
    """Every fallback font for a chain key, in the order the chain tries them."""
    kind, style = key.split(":")
    found: dict[Candidate, None] = {}
    for stem in PREFERRED_SANS if kind == "sans" else PREFERRED_SERIF:
        candidate = noto_file(stem, style)
        if candidate is not None:
            found[candidate] = None
    stems = sorted({path.name.split("-")[0] for folder in NOTO_DIRS if folder.is_dir()
                    for path in folder.glob("Noto*-Regular.[to]tf")})
    for stem in stems:
        candidate = noto_file(stem, style)
        if candidate is not None:
            found[candidate] = None
    return tuple(found)


@functools.lru_cache(maxsize=None)
def candidate_metrics(key: str, index: int) -> "FontMetrics":
    """A fallback font's metrics, with the descent PDF readers will see for it.

    LuaTeX describes a TrueType font loaded in HarfBuzz mode by its letters: the
    Descent it writes is the depth of "p" (Noto Sans: 240/1000) and 0 in a font
    without Latin letters (Noto Sans Thaana), whatever the font's own tables say;
    readers hang each glyph's em box from that (measured with pdfminer here).
    """
    candidate = fallback_candidates(key)[index]
    metrics = FontMetrics(candidate.path, candidate.index)
    if metrics.face.reference_table("CFF ").data:
        return metrics  # CFF outlines (the CJK fonts): the hhea descender, as for the faces
    depth = metrics.ink_em("p").bottom if metrics.has_char("p") and metrics.has_char("h") else 0.0
    metrics.descent_em = int(depth * 1000) / 1000
    metrics._shaped.clear()
    metrics.em_extents.clear()
    return metrics


@functools.lru_cache(maxsize=None)
def script_of(key: str, index: int) -> str | None:
    """The script tag ("arab", "deva", "mong") of a fallback font made for one script.

    luaotfload's HarfBuzz mode otherwise shapes a fallback font's text with the main
    face's script (Latin): Arabic comes out backwards inside `\\textdir TRT`, Mongolian
    unjoined. Fonts for Latin with Greek and Cyrillic (Noto Serif, Noto Sans) and
    emoji get none, and HarfBuzz guesses per run as the fitter does.
    """
    metrics = candidate_metrics(key, index)
    words: Counter[str] = Counter()
    sample: dict[str, int] = {}
    for code in metrics.face.unicodes:
        if code < 0x250:
            continue
        try:
            word = unicodedata.name(chr(code)).split()[0]
        except ValueError:
            continue
        words[word] += 1
        sample.setdefault(word, code)
    if not words:
        return None
    word, count = words.most_common(1)[0]
    if word in ("LATIN", "GREEK", "CYRILLIC", "COMBINING") or count < sum(words.values()) / 3:
        return None
    buffer = hb.Buffer()
    buffer.add_str(chr(sample[word]))
    buffer.guess_segment_properties()
    tag = str(buffer.script).lower()
    return tag if tag.isalpha() and len(tag) == 4 and tag not in ("zyyy", "zinh", "zzzz") else None


def fallback_index(key: str, char: str) -> int | None:
    """The first fallback font (index) with a glyph for `char`, or None."""
    for index in range(len(fallback_candidates(key))):
        if candidate_metrics(key, index).has_char(char):
            return index
    return None


class ChainMetrics:
    """Widths of text set in a face plus its fallback chain, as luaotfload sets it.

    Each character goes to the first font of [face, *chain] that has it; runs of one
    font are shaped by HarfBuzz in that font (its own script and direction), so
    Arabic joins and Devanagari conjuncts are measured as the engine sets them.
    """

    def __init__(self, face: FaceKey):
        self.face = face
        self.primary = metrics_for(face.plain)
        self.fonts = [self.primary] + [candidate_metrics(face.chain_key, i) for i in face.fallbacks]
        self.descent_em = self.primary.descent_em
        self.space_em = self.primary.space_em
        self._shaped: dict[str, tuple[float, Ink]] = {}

    def font_of(self, char: str) -> "FontMetrics":
        for font in self.fonts:
            if font.has_char(char):
                return font
        return self.primary

    def shape(self, word: str) -> tuple[float, Ink]:
        known = self._shaped.get(word)
        if known is not None:
            return known
        runs: list[tuple[FontMetrics, str]] = []
        for char in word:
            font = self.font_of(char)
            if runs and runs[-1][0] is font:
                runs[-1] = (font, runs[-1][1] + char)
            else:
                runs.append((font, char))
        pen, left, right, top, bottom = 0.0, None, None, None, None
        for font, text in runs:
            width, ink = font.shape(text)
            above, below = font.em_extents[text]
            if font is not self.primary or above > 1 - self.descent_em + 1e-9 \
                    or below > self.descent_em + 1e-9:
                # A fallback font's em box (its own descent) or a raised mark's is what
                # PDF readers report; it must stay in the box like ink does.
                ink = Ink(min(ink.left, 0.0), max(ink.right, width), max(ink.top, above),
                          max(ink.bottom, below))
            if ink.right > ink.left or ink.top > ink.bottom:
                left = pen + ink.left if left is None else min(left, pen + ink.left)
                right = pen + ink.right if right is None else max(right, pen + ink.right)
                top = ink.top if top is None else max(top, ink.top)
                bottom = ink.bottom if bottom is None else max(bottom, ink.bottom)
            pen += width
        known = (pen, Ink(0.0, 0.0, 0.0, 0.0) if left is None else Ink(left, right, top, bottom))
        self._shaped[word] = known
        return known

    def advance_em(self, word: str) -> float:
        return self.shape(word)[0]

    def ink_em(self, word: str) -> Ink:
        return self.shape(word)[1]


@functools.lru_cache(maxsize=256)
def chain_metrics_for(face: FaceKey) -> "FontMetrics | ChainMetrics":
    return ChainMetrics(face) if face.rich else metrics_for(face)
