"""Replace a file so that a crash at any moment leaves the old version or the new one, never half.

The new bytes go to a hidden temporary file in the same folder, are flushed to disk, and are
renamed over the original: rename is atomic on POSIX.  Three cases need more than that:

- a symlinked project is saved *through* the link, to the real file, so the link survives and
  its target is not left stale;
- a hard-linked project (``st_nlink > 1``) is rewritten in place after the backup is safe,
  since a rename would split the links and leave the other names on the old text;
- a save killed half-way leaves its temporary file behind; the next save of the same file
  removes such leftovers at once when the process named in them is gone, else once they are
  older than ``STALE_AFTER_S``.
"""

from __future__ import annotations

import errno
import os
import secrets
import shutil
import stat
import time
from pathlib import Path

from floatpage.model.errors import FloatpageError

TEMPORARY_SUFFIX = ".floatpage-tmp"
STALE_AFTER_S = 60.0  # a save takes well under a second; older temporaries are leftovers


def write_chunks(handle, data: bytes, chunk: int = 1 << 16) -> None:
    """Write in chunks; a separate function so a test can interrupt a save midway."""
    for start in range(0, len(data), chunk):
        handle.write(data[start:start + chunk])


def real_target(path: Path) -> Path:
    """The file a save must change: through any symlinks, refusing what is not a regular file."""
    target = Path(os.path.realpath(path))
    if target.exists() and not target.is_file():
        raise FloatpageError(f"{path}: not saved, because it is not a regular file "
                             "(a folder, device or pipe); choose a file name")
    refuse_read_only(path, target)
    return target


def refuse_read_only(path: Path, target: Path) -> None:
    """Refuse to replace a file its permissions keep from being written.  The rename that makes
    a save atomic needs only the folder's permission, so a read-only (0444) project used to be
    replaced all the same, its protection gone."""
    if read_only(target):
        shown = path if Path(os.path.abspath(path)) == target else f"{path} (a link to {target})"
        held = held_by_system(target)
        if held:
            raise FloatpageError(f"{shown}: not saved, because {held}; the file is unchanged")
        if os.stat(target).st_mode & 0o222:  # writable, but not by this user: chmod u+w is
            raise FloatpageError(  # not theirs to run
                f"{shown}: not saved, because you may not write it (it belongs to "
                f"{owner_of(target)}); the file is unchanged (ask its owner, or write a copy)")
        raise FloatpageError(f"{shown}: not saved, because the file is read-only; the file is "
                             "unchanged (make it writable with `chmod u+w`, or write elsewhere)")


def held_by_system(path: Path) -> str:
    """Why a file whose permissions allow a write is refused all the same ('' if it is not):
    a read-only mount or the immutable flag.  They were told "it belongs to alice" (their own
    name), or to make it writable with chmod, which changes neither."""
    try:
        if os.statvfs(path).f_flag & os.ST_RDONLY:
            return ("its folder is on a read-only file system (a read-only mount, a CD or a "
                    "locked card); copy the project to a writable folder")
        status = os.stat(path)
    except OSError:
        return ""
    if status.st_mode & 0o200 and status.st_uid == os.geteuid():
        return ("the system keeps it from being written, although its permissions allow it "
                "(`lsattr` shows an immutable flag: `chattr -i` clears it)")
    return ""


def owner_of(path: Path) -> str:
    """The file's owner by name where there is one, else by number."""
    uid = os.stat(path).st_uid
    try:
        import pwd
        return pwd.getpwuid(uid).pw_name
    except (ImportError, KeyError):
        return f"user {uid}"


def read_only(path: Path) -> bool:
    """Whether an existing file may not be written: root passes every access test, so a file
    with no write bit at all counts as read-only for root too."""
    try:
        mode = os.stat(path).st_mode
    except OSError:
        return False  # a new file: the folder decides
    return mode & 0o222 == 0 or not os.access(path, os.W_OK)


def temporary_name(target: Path, extra: str = "") -> Path:
    return target.with_name(
        f".{target.name}.{os.getpid()}.{secrets.token_hex(4)}{TEMPORARY_SUFFIX}{extra}")


def process_alive(pid: int) -> bool:
    """Whether a process with this id runs (someone else's counts)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError, ValueError):
        return True  # alive but not ours, or no such number: never remove on a guess
    return True


def writer_pid(leftover: Path, target: Path) -> int | None:
    """The PID a temporary's name carries (`.NAME.PID.HEX.floatpage-tmp`), if it has one."""
    rest = leftover.name[len(target.name) + 2:]
    pid = rest.split(".", 1)[0]
    return int(pid) if pid.isdigit() else None


def remove_stale_temporaries(target: Path, *, now: float | None = None) -> list[Path]:
    """Remove this file's temporaries left by a save that was killed: those whose writer no
    longer runs, at once, and any older than STALE_AFTER_S (a PID may have been reused)."""
    now = time.time() if now is None else now
    removed = []
    try:
        candidates = list(target.parent.glob(f".{glob_escape(target.name)}.*{TEMPORARY_SUFFIX}*"))
    except OSError:
        return removed
    for leftover in candidates:
        if not (leftover.name.endswith(TEMPORARY_SUFFIX)
                or leftover.name.endswith(TEMPORARY_SUFFIX + ".bak")):
            continue
        try:
            info = leftover.lstat()
            pid = writer_pid(leftover, target)
            dead = pid is not None and pid != os.getpid() and not process_alive(pid)
            if stat.S_ISREG(info.st_mode) and (dead or now - info.st_mtime > STALE_AFTER_S):
                leftover.unlink()
                removed.append(leftover)
        except OSError:
            pass
    return removed


def glob_escape(name: str) -> str:
    return "".join(f"[{c}]" if c in "*?[" else c for c in name)


SAVE_HINT = "check that the folder exists and is writable"
# A full disk was told to check that the folder exists and is writable.
SAVE_HINTS = {errno.ENOSPC: "the disk is full; free some space and save again: the file is "
                            "unchanged",
              errno.EDQUOT: "your disk quota is used up; free some space and save again: the "
                            "file is unchanged",
              errno.EROFS: "the folder is on a read-only file system; save to a writable folder",
              # a 240-byte name is a file, but not its temporary beside it (".NAME.PID.HEX"
              # plus the suffix): "check that the folder exists and is writable" misled
              errno.ENAMETOOLONG: "the file name is too long to save beside it safely; "
                                  "give the file a name of at most LONGEST_SAVED_NAME bytes"}
# The longest file name a save can keep its temporary and its .bak beside (255, most file
# systems' NAME_MAX, less temporary_name's additions).
LONGEST_SAVED_NAME = 255 - len(f"..{2 ** 22}.{'0' * 8}{TEMPORARY_SUFFIX}.bak")
SAVE_HINTS[errno.ENAMETOOLONG] = SAVE_HINTS[errno.ENAMETOOLONG].replace(
    "LONGEST_SAVED_NAME", str(LONGEST_SAVED_NAME))


def atomic_write(path: Path, data: bytes, *, backup: bool = True) -> None:
    """Replace the file at ``path`` with ``data``; keep the old version as NAME.bak if asked."""
    path = Path(path)
    target = real_target(path)
    remove_stale_temporaries(target)
    temporary: Path | None = None
    try:
        exists = target.exists()
        if exists and backup:
            keep_backup(target)
        if exists and target.stat().st_nlink > 1:
            write_in_place(target, data)
            return
        temporary = temporary_name(target)
        mode = stat.S_IMODE(target.stat().st_mode) if exists else 0o666  # the umask applies
        fd = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL, mode)
        with os.fdopen(fd, "wb") as handle:
            if exists:
                os.fchmod(handle.fileno(), mode)
            write_chunks(handle, data)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(temporary, target)
        temporary = None
        sync_folder(target.parent)
    except OSError as error:
        raise FloatpageError(f"{path}: could not save: {error.strerror or error}"
                             f" ({SAVE_HINTS.get(error.errno, SAVE_HINT)})") from None
    finally:  # also on Ctrl+C: no half-written temporary stays behind
        if temporary is not None:
            try:
                temporary.unlink()
            except OSError:
                pass


def keep_backup(target: Path) -> None:
    """Copy the current version to NAME.bak, itself atomically (a killed copy leaves no half .bak)."""
    backup_path = target.with_name(target.name + ".bak")  # a rename replaces a link, not its target
    try:
        mode = backup_path.lstat().st_mode
    except OSError:
        mode = None
    if mode is not None and not (stat.S_ISREG(mode) or stat.S_ISLNK(mode)):
        raise FloatpageError(f"{backup_path}: not saved, because the old version is kept "
                             "there and it is a folder, device or pipe (move it away and save "
                             "again)")
    copy = temporary_name(target, ".bak")
    try:
        shutil.copy2(target, copy)
        os.replace(copy, backup_path)
    except OSError:
        copy.unlink(missing_ok=True)
        raise


def write_in_place(target: Path, data: bytes) -> None:
    """Rewrite a hard-linked file through its own inode so every name sees the new text.
    Not atomic, which is why the backup is written first."""
    with open(target, "r+b") as handle:
        handle.truncate(0)
        write_chunks(handle, data)
        handle.flush()
        os.fsync(handle.fileno())


def sync_folder(folder: Path) -> None:
    """Flush the rename itself to disk; some filesystems refuse, which costs only durability."""
    try:
        dir_fd = os.open(folder, os.O_RDONLY)
        try:
            os.fsync(dir_fd)
        finally:
            os.close(dir_fd)
    except OSError:
        pass
