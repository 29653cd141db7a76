"""One merge at a time per output folder.

Two merges into one folder at once (`make -j2` with two targets that share `out/`, a CI job
retried while the first still runs) wrote their reports through the same
`.floatpage-merge/report.partial`: the first run's rename took the second's rows, and the
second stopped with "out/report.csv: could not write it (No such file or directory)", after
typesetting every record; records of the same name would have replaced each other's PDFs.

The lock is `flock` on `.floatpage-merge/lock`, holding the owner's PID for the message, as
model.project_lock does for a project: the kernel drops it when the process dies, so a merge
killed outright never leaves the folder locked, and the file is never deleted.
"""

from __future__ import annotations

import errno
import os
from pathlib import Path

from floatpage.model.errors import FloatpageError
from floatpage.model.project_lock import WAIT_S, hold, let_go

LOCK = "lock"


def lock_output_folder(folder: Path, state_dir: Path, *, wait_s: float = WAIT_S) -> int | None:
    """Hold ``state_dir/lock`` for this process; the open descriptor, for ``unlock``.  Another
    merge holding it after ``wait_s`` seconds is refused, naming it.  None where no lock file
    can be made (a folder this user may not write: the first PDF says so)."""
    try:
        fd = os.open(state_dir / LOCK, os.O_RDWR | os.O_CREAT | os.O_CLOEXEC | os.O_NOFOLLOW
                     | os.O_NONBLOCK, 0o666)
    except OSError as error:
        if error.errno in (errno.EACCES, errno.EROFS, errno.EPERM):
            return None
        raise FloatpageError(f"{state_dir / LOCK}: cannot lock the output folder: "
                             f"{error.strerror} (it should be a small file floatpage makes; "
                             "remove it and try again)") from None
    holder = hold(fd, wait_s, "floatpage merge")
    if holder is not None:
        raise FloatpageError(f"{folder}: another merge is writing there ({holder}); wait for "
                             "it to finish, or name another output folder with -o")
    return fd


def unlock(fd: int | None) -> None:
    let_go(fd)
