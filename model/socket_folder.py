"""A folder for the pools' fork-server socket whose path a Unix socket can hold.

Both pools (a pooled settle, `merge` on this machine) start their workers from
multiprocessing's fork server, which listens on a Unix socket made in a folder under $TMPDIR:
`$TMPDIR/pymp-XXXXXXXX/listener-XXXXXXXX`, 32 bytes more than $TMPDIR itself. A socket's path
holds at most 107 bytes on Linux and 103 on macOS, so under a TMPDIR longer than about 70
bytes (a CI job's workspace, a build system's sandbox, macOS's /var/folders/...) every pool
failed at its first worker: `merge` ended in "internal error: OSError: AF_UNIX path too long"
(found when the test suite ran under pytest-xdist, whose folders are longer), and a pooled
settle fell back to one process without a word. Python 3.13 picks a shorter folder itself;
3.11 and 3.12 do not, so `fit_socket_folder` does the same before a pool starts.
"""

from __future__ import annotations

import multiprocessing.util
import os
import tempfile
import threading

SUN_PATH_MAX = 104  # macOS's 104 bytes with the closing NUL; Linux allows 108
SOCKET_NAME_BYTES = len("/pymp-XXXXXXXX/listener-XXXXXXXX")
SHORT_FOLDERS = ("/tmp", "/var/tmp", "/dev/shm")
_fitting = threading.Lock()  # tempfile.tempdir is the whole process's: one swap at a time


def fit_socket_folder() -> None:
    """Before a fork-server pool starts: if $TMPDIR is too long for its socket, give
    multiprocessing its folder (made once per process, removed at exit) under a short one.
    Nothing else's temporary files move; without a short folder the pool fails as before,
    and its callers say so."""
    base = tempfile.gettempdir()
    if len(os.fsencode(base)) + SOCKET_NAME_BYTES < SUN_PATH_MAX:
        return
    short = next((folder for folder in SHORT_FOLDERS
                  if os.path.isdir(folder) and os.access(folder, os.W_OK | os.X_OK)), None)
    if short is None:
        return
    with _fitting:
        kept = tempfile.tempdir
        tempfile.tempdir = short  # get_temp_dir makes its folder under this once, and keeps it
        try:
            multiprocessing.util.get_temp_dir()
        finally:
            tempfile.tempdir = kept
