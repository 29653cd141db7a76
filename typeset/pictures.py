"""Make every picture something LuaLaTeX can read, at the resolution its rectangle needs.

PNG, JPEG and PDF go in as they are. WebP, GIF, BMP and TIFF are converted by
Pillow; a JPEG with an EXIF rotation is turned upright (TeX ignores EXIF); a
photo far sharper than 300 dpi at its printed size is downsampled so the PDF
stays small. Results live in a cache keyed by the file's content hash, so an
unchanged picture is converted once.

All pictures the engine reads sit in that cache folder under content-hash
names. The engine runs with `openin_any=p`, which refuses absolute paths and
hidden folders such as ~/.cache, so the .tex names each picture by its bare
file name: our compile finds it through TEXINPUTS, and a user compiling the
kept .tex by hand through `\\graphicspath`.
"""

from __future__ import annotations

import hashlib
import math
import os
from dataclasses import dataclass
from io import BytesIO
from pathlib import Path

from PIL import Image, ImageOps, UnidentifiedImageError

from floatpage.model.picture_files import (
    EXIF_ORIENTATION, QUARTER_TURNS, decode_warning, pdf_damage,
)
from floatpage.model.save import atomic_write
from floatpage.typeset.errors import RenderError

PRINT_DPI = 300
DOWNSAMPLE_ABOVE = 1.5  # only shrink pictures with more than 1.5x the pixels print needs
NATIVE = {"PNG": ".png", "JPEG": ".jpg"}
CONVERTED = {"WEBP", "GIF", "BMP", "TIFF"}
EXIF_RESOLUTION = (0x011A, 0x011B, 0x0128)  # XResolution, YResolution, ResolutionUnit
# TeX reads a picture's own size from its pixels and the resolution in its file (72 dpi when
# none), and stops with "Dimension too large" past 16,384 pt: a 20,000-pixel panorama, or a
# file that claims 1 dpi, cannot be placed as it is; below a few points (a 1-pixel strip) its
# scaling to the box is off by 0.5 pt. Such pictures are written again, TEX_MIN_PIXELS to
# TEX_MAX_PIXELS a side and with no resolution, so TeX reads them as pixels at 72 dpi.
TEX_MAX_PIXELS = 14_000
TEX_MIN_PIXELS = 16
TEX_NATURAL_PT = (float(TEX_MIN_PIXELS), float(TEX_MAX_PIXELS))
# A background covers its page; a picture whose shape is further than this from the page's
# would be scaled to many metres before the clip, so its middle is cut out first.
COVER_CROP_ABOVE = 8.0


def cache_dir() -> Path:
    """$FLOATPAGE_CACHE_DIR, else $XDG_CACHE_HOME/floatpage/pictures, else ~/.cache/..."""
    explicit = os.environ.get("FLOATPAGE_CACHE_DIR")
    if explicit:
        return Path(explicit).resolve()
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return (Path(base) / "floatpage" / "pictures").resolve()


@dataclass(frozen=True)
class PicturePlan:
    """What a source picture becomes: a file name in the cache and the work to make it."""

    source: Path
    cache_path: Path
    action: str              # "copy", "mend" (a damaged PDF), "convert", "rotate", "downsample"
    pixel_size: tuple[int, int]  # after rotation, cropping and downsampling; (0, 0) for PDF
    target_size: tuple[int, int] | None = None
    crop_box: tuple[int, int, int, int] | None = None  # (left, top, right, bottom), upright

    @property
    def aspect(self) -> float:
        w, h = self.pixel_size
        return w / h if w and h else 1.0


def print_pixels(w_mm: float, h_mm: float, dpi: int = PRINT_DPI) -> tuple[int, int]:
    return max(1, math.ceil(w_mm / 25.4 * dpi)), max(1, math.ceil(h_mm / 25.4 * dpi))


def resolutions_dpi(image: Image.Image) -> list[float]:
    """Every resolution the file claims (JFIF or pHYs, and EXIF), in dots per inch; TeX may
    read any of them, so each must give a size it can take."""
    found = [float(v) for v in image.info.get("dpi", ()) if isinstance(v, (int, float))]
    try:
        exif = image.getexif()
        unit = exif.get(EXIF_RESOLUTION[2], 2)
        for tag in EXIF_RESOLUTION[:2]:
            if tag in exif:
                found.append(float(exif[tag]) * (2.54 if unit == 3 else 1.0))
    except Exception:  # a broken EXIF block: TeX ignores it too
        pass
    return found or [72.0]


def tex_takes(size: tuple[int, int], dpis: list[float]) -> bool:
    low, high = TEX_NATURAL_PT
    return all(dpi > 0 and low <= side * 72.0 / dpi <= high for side in size for dpi in dpis)


def within(size: tuple[int, int], longest: int) -> tuple[int, int]:
    """The size scaled down to at most ``longest`` a side, each side at least TEX_MIN_PIXELS
    (the picture is stretched to its box anyway)."""
    scale = min(1.0, longest / max(size))
    return (max(TEX_MIN_PIXELS, round(size[0] * scale)),
            max(TEX_MIN_PIXELS, round(size[1] * scale)))


def middle_crop(size: tuple[int, int], aspect: float) -> tuple[int, int, int, int]:
    """The largest box of the given width/height ratio in the middle of a picture."""
    w, h = size
    if w / h > aspect:
        keep = max(1, round(h * aspect))
        return (w - keep) // 2, 0, (w - keep) // 2 + keep, h
    keep = max(1, round(w / aspect))
    return 0, (h - keep) // 2, w, (h - keep) // 2 + keep


def plan_picture(source: Path, w_mm: float, h_mm: float, label: str,
                 folder: Path | None = None, *, cover: bool = False) -> PicturePlan:
    """Decide (without writing anything) which cached file will stand for `source`.
    With ``cover`` (a page background), a picture of a very different shape is cropped to
    the box's shape first."""
    folder = folder or cache_dir()
    try:
        data = source.read_bytes()
    except OSError as error:
        raise RenderError(f'{label}: picture file "{source}" cannot be read: '
                          f"{error.strerror or error} (fix the path in the project file)") from None
    digest = hashlib.sha256(data).hexdigest()[:32]
    if data[:5] == b"%PDF-":
        if pdf_damage(source):  # LuaTeX reads no damaged PDF; qpdf mends what it can
            return PicturePlan(source, folder / f"{digest}-mended.pdf", "mend", (0, 0))
        return PicturePlan(source, folder / f"{digest}.pdf", "copy", (0, 0))
    try:
        with Image.open(source) as image:
            kind = image.format
            size = image.size
            orientation = image.getexif().get(EXIF_ORIENTATION, 1) if kind == "JPEG" else 1
            dpis = resolutions_dpi(image)
    except (UnidentifiedImageError, OSError) as error:
        raise RenderError(f'{label}: "{source}" is not a picture floatpage can read ({error}); '
                          "use PNG, JPEG, PDF, WebP, GIF, BMP or TIFF") from None
    if kind not in NATIVE and kind not in CONVERTED:
        raise RenderError(f'{label}: "{source}" is a {kind} picture; '
                          "use PNG, JPEG, PDF, WebP, GIF, BMP or TIFF")
    if orientation in QUARTER_TURNS:
        size = (size[1], size[0])
    ext = NATIVE.get(kind, ".png")
    aspect = w_mm / h_mm
    if cover and max(size[0] / size[1] / aspect, aspect * size[1] / size[0]) > COVER_CROP_ABOVE:
        box = middle_crop(size, aspect)
        cropped = (box[2] - box[0], box[3] - box[1])
        new = within(min(cropped, print_pixels(w_mm, h_mm), key=lambda s: s[0] * s[1]),
                     TEX_MAX_PIXELS)
        return PicturePlan(source, folder / f"{digest}-crop{box[0]}.{box[1]}.{box[2]}.{box[3]}"
                           f"-{new[0]}x{new[1]}{ext}", "downsample", new, new, box)
    plan = plan_at_print_size(source, folder, digest, kind, ext, size, orientation, w_mm, h_mm)
    written_again = plan.action != "copy"  # re-encoded without the file's resolution
    if not tex_takes(plan.pixel_size, [72.0] if written_again else dpis):
        new = within(plan.pixel_size, TEX_MAX_PIXELS)
        return PicturePlan(source, folder / f"{digest}-{new[0]}x{new[1]}-72dpi{ext}",
                           "downsample", new, new)
    return plan


def plan_at_print_size(source: Path, folder: Path, digest: str, kind: str, ext: str,
                       size: tuple[int, int], orientation: int, w_mm: float, h_mm: float
                       ) -> PicturePlan:
    """The plan for a picture as it is: copied, converted, turned upright, or downsampled to
    what print needs."""
    target = print_pixels(w_mm, h_mm)
    scale = max(target[0] / size[0], target[1] / size[1])
    if scale * DOWNSAMPLE_ABOVE < 1:
        new = (max(1, round(size[0] * scale)), max(1, round(size[1] * scale)))
        return PicturePlan(source, folder / f"{digest}-{new[0]}x{new[1]}{ext}", "downsample",
                           new, new)
    if orientation not in (1, None):
        return PicturePlan(source, folder / f"{digest}-upright{ext}", "rotate", size)
    if kind in CONVERTED:
        return PicturePlan(source, folder / f"{digest}.png", "convert", size)
    return PicturePlan(source, folder / f"{digest}{ext}", "copy", size)


def materialize(plan: PicturePlan) -> Path:
    """Write the cached file if it is not there yet; return its path."""
    if plan.cache_path.exists():
        return plan.cache_path
    plan.cache_path.parent.mkdir(parents=True, exist_ok=True)
    if plan.action == "copy" and not (plan.cache_path.suffix == ".png"
                                      and decode_warning(plan.source)):
        atomic_write(plan.cache_path, plan.source.read_bytes(), backup=False)
        return plan.cache_path
    if plan.action == "copy":
        # A PNG cut short (or without its end chunk) stopped LuaTeX at the page's end with
        # "(writepng): reading chunk type failed", tied to no item; written again from the
        # rows it has, it prints as a cut-short JPEG does, and render warns of it by name
        # (render.picture_warnings), as it does of the JPEG.
        write_png_again(plan)
        return plan.cache_path
    if plan.action == "mend":
        import pikepdf

        out = BytesIO()
        with pikepdf.open(plan.source) as pdf:
            pdf.save(out, deterministic_id=True)
        atomic_write(plan.cache_path, out.getvalue(), backup=False)
        return plan.cache_path
    with Image.open(plan.source) as opened:
        opened.seek(0)  # the first frame of an animation
        image = ImageOps.exif_transpose(opened) if opened.format == "JPEG" else opened.copy()
    if plan.crop_box is not None:
        image = image.crop(plan.crop_box)
    if plan.target_size is not None:
        image = image.resize(plan.target_size, Image.Resampling.LANCZOS)
    out = BytesIO()
    if plan.cache_path.suffix == ".jpg":
        if image.mode not in ("RGB", "L", "CMYK"):
            image = image.convert("RGB")
        image.save(out, "JPEG", quality=90, optimize=False)
    else:
        if image.mode not in ("1", "L", "LA", "RGB", "RGBA", "I;16"):
            image = image.convert("RGBA" if "A" in image.mode or "transparency" in image.info
                                  else "RGB")
        image.save(out, "PNG")
    atomic_write(plan.cache_path, out.getvalue(), backup=False)
    return plan.cache_path


def write_png_again(plan: PicturePlan) -> None:
    """Write the PNG ``plan.source`` again from what Pillow can read of it (a file cut short
    keeps its first rows; the rest is left blank); OSError if not even that."""
    from PIL import ImageFile

    before = ImageFile.LOAD_TRUNCATED_IMAGES
    ImageFile.LOAD_TRUNCATED_IMAGES = True
    try:
        with Image.open(plan.source) as opened:
            opened.load()
            image = opened.copy()
    finally:
        ImageFile.LOAD_TRUNCATED_IMAGES = before
    if image.mode not in ("1", "L", "LA", "RGB", "RGBA", "I;16"):
        image = image.convert("RGBA" if "A" in image.mode or "transparency" in image.info
                              else "RGB")
    out = BytesIO()
    image.save(out, "PNG")
    atomic_write(plan.cache_path, out.getvalue(), backup=False)
