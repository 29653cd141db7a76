"""Find the pictures a starter uses and copy them beside the project, so it is self-contained.

Picture paths in a project are relative to the project file. Copying the user's photos (or
the bundled ones) into a `pictures/` folder next to it means the project can be moved,
zipped or committed as one folder and still render.
"""

from __future__ import annotations

import filecmp
import os
import shutil
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from PIL import Image, UnidentifiedImageError

from floatpage.model.errors import FloatpageError
from floatpage.model.key_specs import PICTURE_SUFFIXES
from floatpage.model.picture_files import is_outside

PICTURES_DIR = "pictures"
# What the typesetter reads, but PDFs: a starter measures its photos' pixels.
ACCEPTED_SUFFIXES = tuple(suffix for suffix in PICTURE_SUFFIXES if suffix != ".pdf")
EXIF_ORIENTATION = 0x0112
ROTATED_ORIENTATIONS = (5, 6, 7, 8)  # EXIF values that turn the picture a quarter turn


@dataclass(frozen=True)
class Picture:
    """A picture a builder may place: its path relative to the project file and its shape."""

    path: str  # e.g. "pictures/sunflower.jpg"
    width_px: int
    height_px: int

    @property
    def aspect(self) -> float:
        """Width over height, as the picture will be shown (EXIF rotation applied)."""
        return self.width_px / self.height_px

    @property
    def stem(self) -> str:
        return Path(self.path).stem


def accepted_formats() -> str:
    return ", ".join(s.lstrip(".").upper() for s in ACCEPTED_SUFFIXES if s not in (".jpeg", ".tif"))


def bundled_dir() -> Path:
    """Folder of the pictures shipped inside the package (painted by tools/paint_sample_pictures.py)."""
    return Path(str(resources.files("floatpage.starters") / "bundled"))


def bundled(names: list[str]) -> list[Path]:
    folder = bundled_dir()
    paths = [folder / name for name in names]
    missing = [p.name for p in paths if not p.is_file()]
    if missing:
        raise FloatpageError(f"the bundled pictures {', '.join(missing)} are missing from {folder} "
                             "(reinstall floatpage, or run tools/paint_sample_pictures.py)")
    return paths


def displayed_size(path: Path) -> tuple[int, int] | None:
    """Pixel size as shown (EXIF quarter turns applied), or None if Pillow cannot read it."""
    try:
        with Image.open(path) as img:
            width, height = img.size
            if img.getexif().get(EXIF_ORIENTATION) in ROTATED_ORIENTATIONS:
                width, height = height, width
            return width, height
    except (UnidentifiedImageError, OSError, ValueError, Image.DecompressionBombError):
        return None


# The longest side of a photo a starter places, in shorts sides: a photo of 1 x 100,000 pixels
# became a box 0.0 mm tall, and `new album` saved a project its own loader refused ("h must
# be greater than 0").  A panorama of 20:1 is still 9 mm tall across an A4 page.
MOST_ELONGATED = 20.0


def usable_shape(size: tuple[int, int] | None) -> bool:
    """Whether a picture of ``size`` pixels (None: unreadable) can be a starter's photo."""
    return size is not None and max(size) <= MOST_ELONGATED * min(size)


def find_photos(folder: Path) -> list[Path]:
    """The readable pictures directly inside `folder`, in name order; raise if there are none."""
    folder = Path(folder).expanduser()
    if not folder.exists():
        raise FloatpageError(f"--photos {folder}: no such folder")
    if not folder.is_dir():
        raise FloatpageError(f"--photos {folder}: is a file, not a folder of pictures")
    candidates = sorted(p for p in folder.iterdir()
                        if p.is_file() and not p.name.startswith(".")
                        and p.suffix.lower() in ACCEPTED_SUFFIXES)
    readable = [p for p in candidates if usable_shape(displayed_size(p))]
    if not readable:
        found = f"{len(candidates)} picture file(s) but none could be read or used" \
            if candidates else "no picture files"
        raise FloatpageError(f"--photos {folder}: {found} (floatpage accepts {accepted_formats()})")
    return readable


# Picture formats a camera or phone writes that floatpage cannot read: left out of --photos
# with a word (other files, such as .xmp sidecars or notes, are passed over quietly).
OTHER_PICTURE_SUFFIXES = (".heic", ".heif", ".avif", ".jxl", ".dng", ".cr2", ".cr3", ".nef",
                          ".arw", ".orf", ".rw2", ".raf", ".psd", ".svg")


def left_out_photos(folder: Path) -> list[tuple[Path, str]]:
    """The pictures in `folder` that `find_photos` passes over, each with why: `new album
    --photos` of 20 photos, two of them cut short and one an iPhone's .HEIC, made an album of
    17 without a word."""
    left = []
    for path in sorted(Path(folder).expanduser().iterdir()):
        if not path.is_file() or path.name.startswith("."):
            continue
        suffix = path.suffix.lower()
        size = displayed_size(path) if suffix in ACCEPTED_SUFFIXES else None
        if suffix in ACCEPTED_SUFFIXES and size is None:
            left.append((path, "it cannot be read as a picture (damaged, or not what its name "
                               "says)"))
        elif suffix in ACCEPTED_SUFFIXES and not usable_shape(size):
            left.append((path, f"it is {size[0]} × {size[1]} pixels, its long side more "
                               f"than {MOST_ELONGATED:g} times its short one: too thin a strip "
                               "to lay out (crop it)"))
        elif suffix in OTHER_PICTURE_SUFFIXES:
            left.append((path, f"floatpage reads {accepted_formats()}; convert it to JPG or PNG"))
        elif suffix == ".pdf":  # a logo among the photos was left out without a word
            left.append((path, "a PDF is no photo for the starter to lay out; a logo or a "
                               "drawing goes in with `p` in the editor (or as a picture's "
                               "path), drawn at its own shape"))
    return left


def copy_beside(sources: list[Path], project_dir: Path,
                made: list[Path] | None = None) -> list[Picture]:
    """Copy each source into project_dir/pictures/ and describe it; one Picture per source.

    A file already there with the same content is reused; a different file with the same name
    gets a numbered name (photo-2.jpg), so nothing the user has is overwritten.  Each folder
    and file this call creates is appended to ``made`` before it is written, so a `new` that
    fails later (or is interrupted mid-copy) can take back exactly those (starters.create).
    """
    target_dir = project_dir / PICTURES_DIR
    made = [] if made is None else made
    if target_dir.is_symlink() and is_outside(target_dir, project_dir):
        # the copies went through the link, and the project saved named pictures its own
        # loader then refused as "outside the project folder"
        raise FloatpageError(f"{target_dir}: is a symbolic link to {os.readlink(target_dir)}, "
                             "outside the project's folder, and a new project keeps its "
                             "pictures inside it; remove the link, or create the project in "
                             "another folder")
    if not os.path.lexists(target_dir):  # a file named `pictures` is the user's: never made
        made.append(target_dir)
    target_dir.mkdir(parents=True, exist_ok=True)
    placed: dict[Path, Picture] = {}
    pictures = []
    for source in sources:
        source = Path(source)
        if source.resolve() not in placed:
            target = free_name(source, target_dir)
            if not target.exists():
                made.append(target)
                shutil.copyfile(source, target)
            size = displayed_size(target)
            if size is None:
                raise FloatpageError(f"{source}: cannot be read as a picture "
                                     f"(floatpage accepts {accepted_formats()})")
            placed[source.resolve()] = Picture(f"{PICTURES_DIR}/{target.name}", *size)
        pictures.append(placed[source.resolve()])
    return pictures


def utf8_name(name: str) -> str:
    """`name` as UTF-8 can hold it: a file named in another encoding (`caf\xe9.png` from an
    old Latin-1 camera card) reaches Python with surrogate escapes, which the project file
    cannot hold (`new album` ended in an internal error); each byte that is no UTF-8 becomes _."""
    return os.fsencode(name).decode("utf-8", errors="replace").replace("\ufffd", "_")


def free_name(source: Path, target_dir: Path) -> Path:
    """Where to put `source` in target_dir: its own name, an identical file's name, or name-N."""
    stem, suffix = utf8_name(source.stem), source.suffix.lower()
    if suffix == ".jpeg":
        suffix = ".jpg"
    for n in range(1, 10_000):
        candidate = target_dir / (f"{stem}{suffix}" if n == 1 else f"{stem}-{n}{suffix}")
        if not os.path.lexists(candidate):
            return candidate
        # A symlink there is the user's: one that leads nowhere took the copy through it, out
        # of the project (and a failed `new` then deleted the link); only a regular file that
        # holds this very picture is reused.
        if candidate.is_symlink() or not candidate.is_file():
            continue
        if candidate.resolve() == source.resolve() or filecmp.cmp(candidate, source, shallow=False):
            return candidate
    raise FloatpageError(f"{target_dir}: too many pictures named {stem}")
