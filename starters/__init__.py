"""Starters: the paper's case studies (section 6) as projects a user begins from.

Each kind has a module with a pure `build(options, pictures) -> Project` and the list of
bundled pictures it uses when the user brings none. `create` is the one entry point the CLI
calls (`floatpage new KIND PATH ...`): it checks the options, copies the pictures beside the
project, builds, settles with the physics and saves, refusing to overwrite anything.
"""

from __future__ import annotations

from pathlib import Path
from types import ModuleType

from floatpage.model.document import Project
from floatpage.model.errors import FloatpageError
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
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        pictures = copy_beside(sources, path.parent)
    except OSError as error:  # a folder no one may write in (/proc, read-only) was a crash
        where = error.filename or path.parent
        raise FloatpageError(f"{path}: cannot create the project there ({where}: "
                             f"{error.strerror}); choose a folder you can write to") from None
    project = module.build(options, pictures)
    project.path = path
    if settle:
        from floatpage.model.layout import settle_project  # the physics bridge; imported only when used

        settle_project(project, jobs=jobs)
    save_project(project, path)
    return project
