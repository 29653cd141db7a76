"""Where `render` may write: new paths and regular files that are none of its inputs.

`render card.toml -o card.toml` once replaced the project with the PDF, `-o /dev/full` (as
root) turned a device into a regular file, and `--tex` onto a symlink replaced the link.
Every output is checked here before the engine runs, so a refused render has written nothing.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path
from typing import Iterable

from floatpage.model.atomic_file import (
    SAVE_HINT, SAVE_HINTS, held_by_system, owner_of, read_only, real_target, temporary_name,
)
from floatpage.model.document import Project
from floatpage.model.project_lock import lock_path_for
from floatpage.typeset.errors import RenderError


def kind_of(mode: int) -> str:
    if stat.S_ISLNK(mode):
        return "a symbolic link"
    if stat.S_ISDIR(mode):
        return "a folder"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    if stat.S_ISFIFO(mode):
        return "a pipe"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "not a regular file"


def project_inputs(project: Project) -> list[Path]:
    """Every file the render reads: the project file and its pictures."""
    inputs = [project.path] if project.path is not None else []
    for page in project.pages:
        if page.background is not None and page.background.picture:
            inputs.append(project.base_dir / page.background.picture)
        inputs += [project.base_dir / item.path for item in page.items if item.kind == "picture"]
    return inputs


def project_companions(project: Project) -> list[tuple[Path, str]]:
    """The files floatpage keeps beside the real project file, each with what it holds: a
    PDF written over one (`-o card.toml.bak`) lost the only copy of the text before a settle,
    or an editor's unsaved edits."""
    if project.path is None:
        return []
    real = Path(os.path.realpath(project.path))
    return [(real.with_name(real.name + ".bak"), "the project's backup"),
            (lock_path_for(real), "the project's lock"),
            (real.with_name(f".{real.name}.recover"),  # tui/recovery.py's recovery_path
             "the editor's unsaved edits")]


def same_file(a: Path, b: Path) -> bool:
    try:
        return os.path.samefile(a, b)
    except OSError:
        return os.path.realpath(a) == os.path.realpath(b)


def check_outputs(outputs: Iterable[Path | None], inputs: Iterable[Path],
                  kept: Iterable[tuple[Path, str]] = ()) -> None:
    """Refuse any output that is not a new path or a regular file, that is an input, that is
    a file floatpage keeps beside the project (``kept``: path and what it holds), or that
    another output also names; the message says which and what to do."""
    chosen: list[Path] = []
    kept = list(kept)
    inputs = [Path(p) for p in inputs]
    for output in outputs:
        if output is None:
            continue
        output = Path(output)
        try:
            mode = os.lstat(output).st_mode
        except FileNotFoundError:
            mode = None
        except OSError as error:
            raise RenderError(f"{output}: cannot be written: {error.strerror}") from None
        if mode is None and not output.parent.is_dir():
            raise RenderError(f"{output}: the folder {output.parent} does not exist; "
                              "create it first, or name another place")
        if mode is not None and not stat.S_ISREG(mode):
            raise RenderError(f"{output}: will not write there, because it is {kind_of(mode)}; "
                              "name a new file or a regular file")
        for source in inputs:
            if mode is not None and same_file(output, source) or \
                    os.path.realpath(output) == os.path.realpath(source):
                raise RenderError(f"{output}: will not write there, because it is an input of "
                                  f"this render ({source}); choose another output name")
        for companion, holds in kept:
            if os.path.realpath(output) == os.path.realpath(companion):
                raise RenderError(f"{output}: will not write there, because it holds {holds}; "
                                  "choose another output name")
        for earlier in chosen:
            if os.path.realpath(output) == os.path.realpath(earlier):
                raise RenderError(f"{output}: named for two outputs; give each its own name")
        # after the input tests, so `-o card.toml` on a read-only project is not told to
        # make the project writable
        if mode is not None and read_only(output):
            held = held_by_system(output)
            if held:
                raise RenderError(f"{output}: will not write there, because {held}")
            if mode & 0o222:  # writable by its owner, who is someone else
                raise RenderError(f"{output}: will not write there, because you may not write "
                                  f"it (it belongs to {owner_of(output)}); name another file")
            raise RenderError(f"{output}: will not write there, because the file is read-only; "
                              "make it writable (`chmod u+w`) or name another file")
        refuse_unwritable_folder(output)
        chosen.append(output)


def refuse_unwritable_folder(output: Path) -> None:
    """Make and remove, beside ``output``, the temporary a save makes there (atomic_write): a
    folder that takes no new file (`-o /proc/x.pdf`, a read-only mount, a full disk's quota)
    failed only once the whole document had been typeset, seconds later.  Permission bits
    alone do not tell: root passes every access test, and /proc refuses root."""
    temporary = temporary_name(real_target(output))
    try:
        os.close(os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600))
    except OSError as error:
        hint = SAVE_HINTS.get(error.errno, SAVE_HINT)
        raise RenderError(f"{output}: cannot be written: {error.strerror or error} ({hint})"
                          ) from None
    try:
        os.unlink(temporary)
    except OSError:
        pass
