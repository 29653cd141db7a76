"""What a picture file is, read from its header before anything trusts it.

A 48-byte PNG can claim 100000 x 100000 pixels, and decoding it takes 30 GB; a truncated JPEG
decodes to grey with no word from the TeX engine.  So `check`, `settle` and `render` all read
every picture's header here: its format, its pixel size against ``MAX_PIXELS``, and where the
file really is (a project's pictures stay inside its folder unless the user allows otherwise,
so a project cannot embed ~/.ssh/id_rsa.pdf and still renders after it moves machines).
Decoding, to find truncation, is left to `decode_warning`, which `check` and `render` call.
"""

from __future__ import annotations

import os
import re
import warnings
from dataclasses import dataclass
from pathlib import Path

MAX_PIXELS = 100_000_000  # 100 megapixels: a 40 x 40 cm print at 600 dpi is 15 Mpx
FORMATS = ("PNG", "JPEG", "WEBP", "GIF", "BMP", "TIFF")
FORMAT_WORDS = "PNG, JPEG, PDF, WebP, GIF, BMP or TIFF"


# Pillow warns above its 89.5-megapixel limit, as a Python warning with its own source path
# ("/.../PIL/Image.py:3593: DecompressionBombWarning: ... could be decompression bomb DOS
# attack"), which check, render and new printed for a 9,999 x 9,999 photo that floatpage's
# own limit, MAX_PIXELS, allows: every header is held to MAX_PIXELS before any decoding, so
# the warning says nothing the user can act on.
warnings.filterwarnings("ignore", message=r"Image size \(\d+ pixels\) exceeds limit",
                        category=RuntimeWarning)

MERGE_FIELD = re.compile(r"\{[^{}]+\}")
# A PDF picture's sides, in PDF units (1/72 in): 14,400 is PDF's own largest page (5.08 m;
# TeX stops at 16,322), and below one unit the scale to the item's size overflows TeX.
PDF_SIDE_UNITS = (1.0, 14_400.0)


EXIF_ORIENTATION = 0x0112
QUARTER_TURNS = (5, 6, 7, 8)  # EXIF orientations that turn the picture a quarter turn


def quarter_turned(image) -> bool:
    """Whether a JPEG's EXIF tag turns it a quarter turn (a broken EXIF block: no turn, as
    TeX ignores EXIF and typeset.pictures reads the same tag)."""
    try:
        return image.getexif().get(EXIF_ORIENTATION) in QUARTER_TURNS
    except Exception:
        return False


def quarter_turns(rotate) -> int:
    """A PDF page's /Rotate in quarter turns (an odd value: none)."""
    try:
        return int(rotate) // 90
    except (TypeError, ValueError):
        return 0


@dataclass(frozen=True)
class PictureHeader:
    """A picture as its header describes it; ``problem`` says why it cannot be used."""

    kind: str = ""  # "PDF" or a Pillow format name
    # as it prints: a JPEG whose EXIF tag turns it a quarter turn (every phone's portrait
    # photo, stored sideways) prints upright (typeset.pictures), its width and height swapped;
    # a PDF's first page is its crop box in PDF units, rounded, turned by its /Rotate
    size: tuple[int, int] = (0, 0)
    problem: str = ""
    hint: str = ""


def read_header(path: Path) -> PictureHeader:
    """Open the header only (no pixels are decoded), and judge what it claims."""
    if path.is_dir():
        return PictureHeader(problem="is a folder", hint="name a picture file inside it")
    if path.exists() and not path.is_file():
        return PictureHeader(problem="is not a regular file (a device or pipe)",
                             hint="name a picture file")
    if not path.is_file():
        return PictureHeader(problem="not found", hint="fix the path or copy the file there")
    try:
        with open(path, "rb") as handle:
            if handle.read(5) == b"%PDF-":
                return pdf_header(path)
    except OSError as error:
        return PictureHeader(problem=f"cannot be read: {error.strerror}", hint="check its permissions")
    from PIL import Image, UnidentifiedImageError  # only for a project with pictures

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", Image.DecompressionBombWarning)
            with Image.open(path) as image:
                kind, size = image.format or "", image.size
                if kind == "JPEG" and quarter_turned(image):
                    size = (size[1], size[0])
    except Image.DecompressionBombError as error:  # Pillow's own, far higher, limit
        claimed = re.search(r"\((\d+) pixels\)", str(error))
        return too_many_pixels(f"{int(claimed.group(1)) // 1_000_000:,} megapixels" if claimed
                               else "more pixels than Pillow will open")
    except (UnidentifiedImageError, OSError, ValueError, SyntaxError) as error:
        return PictureHeader(problem=f"is not a picture floatpage can read ({error})",
                             hint=f"use {FORMAT_WORDS}")
    if kind not in FORMATS:
        return PictureHeader(kind=kind, size=size, problem=f"is a {kind} picture",
                             hint=f"use {FORMAT_WORDS}")
    if size[0] < 1 or size[1] < 1:
        return PictureHeader(kind=kind, size=size, problem="has no pixels", hint="re-export it")
    if size[0] * size[1] > MAX_PIXELS:
        return too_many_pixels(f"{size[0]} x {size[1]} pixels, "
                               f"{size[0] * size[1] // 1_000_000:,} megapixels", kind, size)
    return PictureHeader(kind=kind, size=size)


def pdf_header(path: Path) -> PictureHeader:
    """A PDF is usable when it opens and its first page has a size: a header followed by
    garbage passed `check` and stopped LuaLaTeX with "reading image failed"."""
    import pikepdf

    try:
        with pikepdf.open(path) as pdf:
            page = pdf.pages[0]
            # LuaTeX places the crop box (the media box when there is none)
            boxes = [[float(v) for v in page.mediabox], [float(v) for v in page.cropbox]]
            turned = quarter_turns(page.obj.get("/Rotate", 0)) % 2
    except Exception as error:  # pikepdf raises its own errors, and IndexError for no pages
        reason = str(error).splitlines()[0][:120] if str(error) else type(error).__name__
        return PictureHeader(kind="PDF", problem=f"is not a PDF floatpage can read ({reason})",
                             hint="export it again, or use PNG or JPEG")
    for box in boxes:
        if not (len(box) == 4 and box[2] - box[0] > 0 and box[3] - box[1] > 0):
            return PictureHeader(kind="PDF", problem="has a first page without a size",
                                 hint="export it again, or use PNG or JPEG")
    for box in boxes:
        sides = (box[2] - box[0], box[3] - box[1])
        if not PDF_SIDE_UNITS[0] <= min(sides) <= max(sides) <= PDF_SIDE_UNITS[1]:
            # a page past TeX's largest length stopped LuaLaTeX with "Dimension too large",
            # a speck of one with "Arithmetic overflow", after `check` had passed them
            mm = " x ".join(f"{side:,.0f}" if side >= 10 else f"{side:.2g}"
                            for side in (side * 25.4 / 72 for side in sides))
            return PictureHeader(kind="PDF", problem=f"has a first page of {mm} mm, a size TeX "
                                 "cannot place (0.35 mm to 5 m a side)",
                                 hint="export it again at the size it should print, or use "
                                      "PNG or JPEG")
    crop = boxes[1]
    size = (round(crop[2] - crop[0]), round(crop[3] - crop[1]))
    return PictureHeader(kind="PDF", size=(size[1], size[0]) if turned else size)


def pdf_damage(path: Path) -> str:
    """What qpdf had to mend to open a PDF ('' for a sound one): LuaTeX reads no damaged
    PDF ("reading image failed", after `check` had passed it), so render prints the mended
    copy (typeset.pictures) and `check` says so."""
    import pikepdf

    try:
        with pikepdf.open(path) as pdf:
            found = pdf.get_warnings()
    except Exception:  # noqa: BLE001 - unreadable: read_header has said so already
        return ""
    reasons = [re.sub(r"^\(offset \d+\):\s*", "", str(warning).removeprefix(f"{path}")
                      .lstrip(": ")).splitlines()[0][:120] for warning in found]
    telling = [reason for reason in reasons if reason != "file is damaged"]
    return (telling or reasons or [""])[0]


def too_many_pixels(what: str, kind: str = "", size: tuple[int, int] = (0, 0)) -> PictureHeader:
    return PictureHeader(kind=kind, size=size,
                         problem=f"is too large to lay out safely ({what}; the limit is "
                                 f"{MAX_PIXELS // 1_000_000} megapixels)",
                         hint="scale it down: print needs about 300 pixels per inch")


def decode_warning(path: Path) -> str:
    """Why the picture's pixels do not decode cleanly (truncated or corrupt), or ''.

    JPEGs decode at 1/8 scale (libjpeg's draft mode reads every byte but keeps few pixels),
    so even a 100-megapixel photo costs a few MB here; other formats are verified chunk by
    chunk (PNG's checksums) without decoding.
    """
    from PIL import Image

    try:
        with open(path, "rb") as handle:
            if handle.read(5) == b"%PDF-":  # no pixels: read_header opened it as a PDF
                damage = pdf_damage(path)
                return (f"the PDF is damaged ({damage}); a mended copy is printed: look at "
                        "it, or export the PDF again") if damage else ""
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            with Image.open(path) as image:
                if image.format == "JPEG":
                    image.draft("RGB", (max(1, image.size[0] // 8), max(1, image.size[1] // 8)))
                    image.load()
                else:
                    image.verify()
    except (OSError, ValueError, SyntaxError, Image.DecompressionBombError) as error:
        return f"its pixels do not decode cleanly ({error}); it may print grey or cut off"
    return ""


def names_a_field(text: str) -> bool:
    """Whether `text` holds a merge placeholder (`{column}`; `{{` and `}}` are braces)."""
    return MERGE_FIELD.search(text.replace("{{", "").replace("}}", "")) is not None


def fields_are_whole_names(relative: str) -> bool:
    """Whether a field is a whole part of the path, as a template names a picture by a
    column (`pictures/{photo}`, `{folder}/{id}.jpg`), not inside a file's name (`photo {1}.png`)."""
    for part in relative.replace("\\", "/").split("/"):
        stem = part.rsplit(".", 1)[0] if "." in part.lstrip(".") else part
        if names_a_field(part) and MERGE_FIELD.fullmatch(stem.strip()):
            return True
    return False


def is_merge_placeholder(relative: str, folder: Path | None = None) -> bool:
    """A template's picture path that a data column fills (`pictures/{photo}`). Given the
    project's ``folder``, a file that is there by that very name is a picture, not a
    placeholder: `photo {1}.png` passed `check` and `render` called it a merge template."""
    if MERGE_FIELD.search(relative) is None:
        return False
    return folder is None or not os.path.lexists(folder / relative)


def is_outside(picture: Path, folder: Path) -> bool:
    """Whether ``picture`` really lives outside ``folder`` (after every symlink is followed)."""
    real = os.path.realpath(picture)
    root = os.path.realpath(folder)
    return os.path.commonpath([real, root]) != root
