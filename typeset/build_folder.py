"""The temporary folder one engine run works in, and the clean-up of those a killed run left.

A render killed with SIGKILL cannot remove its own folder, so folders are named after their
process (`floatpage-build-PID-…`) and every render first removes those whose process is gone.
"""

from __future__ import annotations

import contextlib
import os
import re
import shutil
import tempfile
from pathlib import Path
from typing import Iterator

from floatpage.model.atomic_file import process_alive

PREFIX = "floatpage-build-"
NAME = re.compile(re.escape(PREFIX) + r"(\d+)-")


def remove_stale_build_folders(parent: Path | None = None) -> list[Path]:
    """Remove build folders of processes that no longer run; return what was removed."""
    parent = Path(parent or tempfile.gettempdir())
    removed = []
    try:
        entries = list(parent.iterdir())
    except OSError:
        return removed
    for entry in entries:
        found = NAME.match(entry.name)
        if not found or entry.is_symlink() or not entry.is_dir():
            continue
        if int(found.group(1)) != os.getpid() and not process_alive(int(found.group(1))):
            shutil.rmtree(entry, ignore_errors=True)
            removed.append(entry)
    return removed


@contextlib.contextmanager
def build_folder() -> Iterator[str]:
    """A fresh build folder for this process, removed afterwards (and by the next run if not)."""
    remove_stale_build_folders()
    with tempfile.TemporaryDirectory(prefix=f"{PREFIX}{os.getpid()}-") as folder:
        yield folder
