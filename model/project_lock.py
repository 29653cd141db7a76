"""One writer per project at a time: an advisory lock every writer (CLI and editor) takes.

Two `settle` runs at once both saved, and the second one's `.bak` held the first one's result,
so the text from before either run survived nowhere.  With the lock, the second writer waits a
moment (a `settle` takes about a second) and then refuses, naming the process that holds it.

The lock is `flock` on a hidden sidecar, `.NAME.lock` beside the real file (through symlinks),
holding the owner's PID for the message.  The kernel drops an flock when its process dies,
so a killed editor never leaves a project locked.  The sidecar is never deleted: deleting a
lock file lets a waiter lock an orphaned inode while a newcomer locks a fresh one.
"""

from __future__ import annotations

import errno
import fcntl
import os
import stat
import time
from pathlib import Path

from floatpage.model.errors import FloatpageError

WAIT_S = 2.0  # how long a second writer waits before it refuses
POLL_S = 0.05


class ProjectLockedError(FloatpageError):
    """Another process is writing this project."""


def lock_path_for(project: Path) -> Path:
    real = Path(os.path.realpath(project))
    return real.with_name(f".{real.name}.lock")


class ProjectLock:
    """``with ProjectLock(path):`` holds the project's lock for the block.

    Where no lock file can be made (a read-only folder), the lock is skipped: nobody can save
    there anyway, and the save says so clearly.
    """

    def __init__(self, project: str | Path, *, wait_s: float = WAIT_S, purpose: str = ""):
        self.project = Path(project)
        self.path = lock_path_for(self.project)
        self.wait_s = wait_s
        self.purpose = purpose
        self.fd: int | None = None

    def acquire(self) -> "ProjectLock":
        if not os.path.isfile(self.project):
            # Nothing to lock, and the load says why: a mistyped name left `.nope.toml.lock`
            # behind, and `settle /dev/zero` (as root) made /dev/.zero.lock.
            return self
        try:
            # O_NONBLOCK: a pipe put where the lock file belongs must not hang the open.
            fd = os.open(self.path, os.O_RDWR | os.O_CREAT | os.O_CLOEXEC | os.O_NOFOLLOW
                         | os.O_NONBLOCK, 0o666)
        except OSError as error:
            if error.errno in (errno.EACCES, errno.EROFS, errno.EPERM, errno.ENOENT):
                return self
            reason = "it is a symbolic link" if error.errno == errno.ELOOP else error.strerror
            raise FloatpageError(f"{self.path}: cannot lock the project: {reason} "
                                 "(it should be a small file floatpage makes; remove it and "
                                 "try again)") from None
        kind = file_kind(os.fstat(fd).st_mode)
        if kind:  # never write a PID into a device or a pipe
            os.close(fd)
            raise FloatpageError(f"{self.path}: cannot lock the project: it is a {kind}, not "
                                 "a lock file (remove it and try again)")
        holder = hold(fd, self.wait_s, self.purpose)
        if holder is not None:
            raise ProjectLockedError(f"{self.project}: {held_by(holder)}")
        self.fd = fd
        return self

    def release(self) -> None:
        let_go(self.fd)
        self.fd = None

    def __enter__(self) -> "ProjectLock":
        return self.acquire()

    def __exit__(self, *exc) -> None:
        self.release()


def hold(fd: int, wait_s: float, purpose: str) -> str | None:
    """Take the exclusive flock on the open lock file ``fd``, waiting up to ``wait_s``
    seconds for whoever holds it, and write this process's PID and ``purpose`` in it for the
    next waiter's message.  None once held; else who holds it, with ``fd`` closed.  (The
    project's lock and merge's output folder lock, merge.folder_lock, wait alike.)"""
    deadline = time.monotonic() + wait_s
    while True:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            break
        except BlockingIOError:
            if time.monotonic() >= deadline:
                holder = read_holder(fd)
                os.close(fd)
                return holder
            time.sleep(POLL_S)
    try:  # who holds it, for a waiter's message; a full disk refuses even these bytes,
        os.ftruncate(fd, 0)  # and what the holder writes next says so
        os.pwrite(fd, f"{os.getpid()} {purpose}\n".encode(), 0)
    except OSError:
        pass
    return None


def let_go(fd: int | None) -> None:
    """Empty the lock file (no stale PID for a reader) and give the lock up."""
    if fd is not None:
        try:
            os.ftruncate(fd, 0)
        except OSError:
            pass
        fcntl.flock(fd, fcntl.LOCK_UN)
        os.close(fd)


def file_kind(mode: int) -> str:
    """'' for a regular file, else what it is, in words."""
    if stat.S_ISREG(mode):
        return ""
    return ("device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode) else
            "pipe" if stat.S_ISFIFO(mode) else "socket" if stat.S_ISSOCK(mode) else "special file")


def held_by(holder: str) -> str:
    """What the one refused is told: an editor is closed by its user, any other writer (a
    `settle` of a long project) is waited for; "is being edited by PID 4242 (floatpage
    settle); close it there" sent a user looking for an editor there was none of."""
    if "floatpage" in holder and "floatpage edit" not in holder:
        return f"is being written by {holder}; wait for it to finish, then try again"
    return (f"is being edited by {holder}; close it there, or wait for it to finish, "
            "then try again")


def read_holder(fd: int) -> str:
    """'PID 1234 (floatpage edit)' from the lock file, or a vaguer phrase if it holds nothing."""
    try:
        words = os.pread(fd, 200, 0).decode("utf-8", "replace").split(maxsplit=1)
    except OSError:
        words = []
    if not words or not words[0].isdigit():
        return "another process"
    purpose = f" ({words[1].strip()})" if len(words) > 1 and words[1].strip() else ""
    return f"PID {words[0]}{purpose}"
