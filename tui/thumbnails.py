"""Small colour thumbnails of pictures, as arrays of half-block pixels.

Decoding a photo takes far longer than a frame, so each file is decoded once
(into a bounded working copy) and each (file, size) thumbnail is cached; a
changed file (new mtime) is read again.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import numpy as np

WORKING_SIZE = 256  # longest side of the decoded copy that thumbnails are cut from
LEVEL_STEP = 17  # 16 levels a channel (0, 17, ..., 255): neighbouring cells share colours more
# A box further than this from the picture's shape shows its middle, cropped, as the PDF
# prints it (typeset.placed.framed_picture); nearer, cells rounding the box's size would
# crop a picture of the very shape by a cell.
CROP_ABOVE = 0.05
PDF_DRAW_S = 5.0  # the longest pdftoppm may take to draw a PDF picture's thumbnail


@lru_cache(maxsize=64)
def _working_copy(path: str, mtime_ns: int):
    """The decoded copy, or None for a file the loader would refuse (the editor opens a
    project with such a picture, to mend it): a 200-megapixel PNG is never decoded here."""
    from PIL import Image, ImageOps

    from floatpage.model.picture_files import read_header

    header = read_header(Path(path))
    if header.problem:
        return None
    if header.kind == "PDF":
        return _pdf_working_copy(path)
    try:
        with Image.open(path) as image:
            image.draft("RGB", (WORKING_SIZE, WORKING_SIZE))  # JPEG: decode at reduced scale
            if image.format == "JPEG":  # turned upright as the PDF prints it: a phone's
                image = ImageOps.exif_transpose(image)  # portrait photo showed sideways
            image = image.convert("RGB")
            image.thumbnail((WORKING_SIZE, WORKING_SIZE))
            return image.copy()
    except Exception:  # a PDF, a JPEG cut short: remembered until the file changes, as a
        return None   # failure tried again every frame cost a header read and a decode


def _pdf_working_copy(path: str):
    """A PDF picture's first page, drawn by poppler's pdftoppm (installed with floatpage's
    LaTeX tools), or None where it cannot be: a shop's logo as a PDF showed as "unreadable
    pictures/logo.pdf" in the preview, as if the file were broken, while the PDF printed it."""
    import io
    import subprocess

    from PIL import Image

    try:
        drawn = subprocess.run(["pdftoppm", "-f", "1", "-l", "1", "-singlefile", "-png",
                                "-scale-to", str(WORKING_SIZE), path],
                               capture_output=True, timeout=PDF_DRAW_S, check=True).stdout
        with Image.open(io.BytesIO(drawn)) as image:
            return image.convert("RGB")
    except Exception:  # no pdftoppm, a PDF it cannot draw, too slow: the stand-in says so
        return None


@lru_cache(maxsize=512)
def _thumbnail(path: str, mtime_ns: int, width_px: int, height_px: int) -> np.ndarray:
    from PIL import Image

    from PIL import ImageOps

    image = _working_copy(path, mtime_ns)
    if image is None:
        raise ValueError(f"{path} is not a picture the editor shows")
    if abs(image.width / image.height / (width_px / height_px) - 1) > CROP_ABOVE:
        image = ImageOps.fit(image, (width_px, height_px), Image.Resampling.BOX)
    else:
        image = image.resize((width_px, height_px), Image.Resampling.BOX)
    # Fewer distinct colours: a photo's pixels each had a colour of their own, so every cell
    # of a moved picture cost both its colour codes over the link; with 16 levels a channel,
    # runs of equal cells (sky, walls) go as one code, and pure colours stay pure.
    levels = np.rint(np.asarray(image, dtype=np.float32) / LEVEL_STEP) * LEVEL_STEP
    pixels = levels.astype(np.uint8)
    pixels.setflags(write=False)
    return pixels


def thumbnail(path: Path, width_px: int, height_px: int) -> np.ndarray | None:
    """RGB pixels of shape (height_px, width_px, 3), or None if the file cannot be read."""
    if width_px < 1 or height_px < 1:
        return None
    try:
        mtime_ns = path.stat().st_mtime_ns
        return _thumbnail(str(path), mtime_ns, width_px, height_px)
    except Exception:  # missing, truncated, not a picture, a decompression bomb...
        return None  # ...the preview draws a placeholder instead; it never stops the editor
