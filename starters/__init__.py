"""Starters: the paper's case studies (section 6) as projects a user begins from.

Each kind has a module with a pure `build(options, pictures) -> Project` and the list of
bundled pictures it uses when the user brings none. `create` is the one entry point the CLI
calls (`floatpage new KIND PATH ...`): it checks the options, copies the pictures beside the
project, builds, settles with the physics and saves, refusing to overwrite anything.
"""

from __future__ import annotations

import os
from pathlib import Path
from types import ModuleType

from floatpage.model.document import Project
from floatpage.model.errors import FloatpageError
from floatpage.model.atomic_file import LONGEST_SAVED_NAME
from floatpage.model.save import save_project
from floatpage.starters import album, blank, calendar, card, flyer
from floatpage.starters.options import Options, check_options
from floatpage.starters.pictures import Picture, accepted_formats, bundled, copy_beside, find_photos

KINDS: dict[str, ModuleType] = {
    "blank": blank, "calendar": calendar, "card": card, "album": album, "flyer": flyer,
}

__all__ = ["KINDS", "Options", "Picture", "build", "create", "check_options"]


def starter(kind: str) -> ModuleType:
    try:
        return KINDS[kind]
    except KeyError:
        raise FloatpageError(f"unknown starter {kind!r} (choose one of: {', '.join(KINDS)})") from None


def build(kind: str, options: Options, pictures: list[Picture]) -> Project:
    """The project of `kind`, unsettled and unsaved; `pictures` are already beside the project."""
    return starter(kind).build(options, pictures)


def check_target(path: Path) -> Path:
    """The project file must be a new .toml file; never overwrite what the user has."""
    path = Path(path).expanduser()
    if path.suffix.lower() != ".toml":
        raise FloatpageError(f"{path}: a project file name ends in .toml (e.g. {path.name or 'project'}.toml)")
    if len(os.fsencode(path.name)) > LONGEST_SAVED_NAME:
        # 256 bytes ended in "internal error: OSError: File name too long"; 240 copied the
        # pictures, then could not save (its temporary's name is longer still)
        raise FloatpageError(f"{path}: the file name is {len(os.fsencode(path.name))} bytes "
                             f"long; a project file's name may have at most "
                             f"{LONGEST_SAVED_NAME} (choose a shorter name)")
    if path.exists() or path.is_symlink():
        raise FloatpageError(f"{path}: already exists; floatpage new never overwrites a file "
                             "(choose another name, or delete it first)")
    if path.parent.exists() and not path.parent.is_dir():
        raise FloatpageError(f"{path.parent}: is a file, not a folder")
    return path


def create(kind: str, path: Path, *, year: int | None = None, photos: Path | None = None,
           first_weekday: str = "monday", lang: str = "en", orientation: str = "portrait",
           settle: bool = True, jobs: int = 1) -> Project:
    """Build a starter project at `path`, settle it (its pages in `jobs` processes, see
    model.page_pool), save it and return it.

    With `photos` the pictures in that folder are used, otherwise the bundled ones; either way
    they are copied into a `pictures/` folder beside the project, so the folder is complete.
    Raises FloatpageError for an unknown kind, bad options, a photos folder without readable
    pictures, or a path that already exists.
    """
    module = starter(kind)
    options = check_options(year=year, first_weekday=first_weekday, lang=lang, orientation=orientation)
    path = check_target(Path(path))
    sources = find_photos(Path(photos)) if photos is not None else bundled(module.BUNDLED)
    made: list[Path] = []  # what this call created, in order: taken back if it fails
    try:
        try:
            made += missing_folders(path.parent)
            path.parent.mkdir(parents=True, exist_ok=True)
            pictures = copy_beside(sources, path.parent, made)
        except OSError as error:  # a folder no one may write in (/proc, read-only) was a crash
            where = error.filename or path.parent
            raise FloatpageError(f"{path}: cannot create the project there ({where}: "
                                 f"{error.strerror}); choose a folder you can write to") from None
        project = module.build(options, pictures)
        project.path = path
        if settle:
            from floatpage.model.layout import settle_project  # the physics bridge; imported only when used

            settle_project(project, jobs=jobs)
        made.append(path)
        save_project(project, path)
    except BaseException:
        # A failed (or interrupted: Ctrl+C while settling) `new album` left its copied
        # pictures/ behind, and a second try then numbered every photo name-2.jpg.
        take_back(made)
        raise
    return project


def missing_folders(folder: Path) -> list[Path]:
    """The folders `mkdir(parents=True)` would create for ``folder``, outermost first."""
    missing = []
    folder = Path(folder)
    while not folder.exists() and not folder.is_symlink() and folder != folder.parent:
        missing.append(folder)
        folder = folder.parent
    return missing[::-1]


def take_back(made: list[Path]) -> None:
    """Remove what `create` made, newest first: the files, then each folder once empty (a
    folder that holds anything else, put there meanwhile, stays)."""
    for path in reversed(made):
        try:
            if path.is_dir() and not path.is_symlink():
                path.rmdir()
            else:
                path.unlink(missing_ok=True)
        except OSError:
            pass
