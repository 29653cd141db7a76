"""Unsaved edits outlive a lost terminal, the way nano's `.save` files do.

When the editor's terminal goes away (SIGHUP, end of input) or it is told to stop (SIGTERM),
it writes the project as edited so far to `.NAME.toml.recover` beside the real project (never
over the project itself) and exits at once: a dead terminal must not keep it spinning, and a
terminal that is gone cannot show a question.  The next `floatpage edit` of the project finds
the recovery file and offers to restore or discard it.
"""

from __future__ import annotations

import importlib
import os
import signal
import threading
from pathlib import Path
from typing import Callable

from floatpage.model.atomic_file import atomic_write
from floatpage.model.project_file import load_project
from floatpage.model.save import dump_project

EXIT_HANGUP = 128 + signal.SIGHUP
EXIT_TERMINATED = 128 + signal.SIGTERM
LEAVE_WITHIN_S = 0.8  # the watchdog's wait: the whole exit stays under a second


def recovery_path(project_path: str | Path) -> Path:
    real = Path(os.path.realpath(project_path))
    return real.with_name(f".{real.name}.recover")


def write_recovery(session) -> Path | None:
    """Write the session's unsaved project to its recovery file; None when nothing is unsaved."""
    if not session.unsaved or session.project.path is None:
        return None
    try:
        session.sync_positions()
    except Exception:  # noqa: BLE001 - mid-step numbers: the model's last positions will do
        pass
    path = recovery_path(session.project.path)
    atomic_write(path, dump_project(session.project).encode("utf-8"), backup=False)
    return path


def pending_recovery(project_path: str | Path) -> Path | None:
    path = recovery_path(project_path)
    return path if path.is_file() else None


def load_recovered(project_path: str | Path, *, allow_outside_files: bool = False):
    """The project as the recovery file holds it, to be saved under the project's own name."""
    project = load_project(recovery_path(project_path), allow_outside_files=allow_outside_files,
                           missing_pictures_ok=True)
    project.path = Path(project_path)
    return project


def discard_recovery(project_path: str | Path) -> None:
    recovery_path(project_path).unlink(missing_ok=True)


class HangupGuard:
    """Signal handlers that save unsaved edits to the recovery file and leave promptly.

    SIGHUP (and end of input, which the driver turns into SIGHUP) means the terminal is gone:
    write the recovery file and exit with no attempt to restore a screen nobody sees. SIGTERM
    asks the app to exit normally, with a watchdog that ends the process after LEAVE_WITHIN_S
    should a terminal that stopped reading hold the exit up.
    """

    def __init__(self, session, exit_app: Callable[[], None]):
        self.session = session
        self.exit_app = exit_app

    def install(self) -> None:
        # What write_recovery needs is imported now, not in the handler: tomlkit is imported
        # lazily (model.save), and a hang-up that came while the main thread was importing it
        # found it half initialised ("partially initialized module 'tomlkit' has no attribute
        # 'dumps'"), and the edits were lost (one hang-up test in three).
        importlib.import_module("tomlkit")
        importlib.import_module("tomlkit.items")
        signal.signal(signal.SIGHUP, self.on_hangup)
        signal.signal(signal.SIGTERM, self.on_terminate)

    def save(self) -> None:
        try:
            write_recovery(self.session)
        except Exception:  # noqa: BLE001 - leaving matters more than a message nobody sees
            pass

    def on_hangup(self, signum, frame) -> None:
        self.save()
        os._exit(EXIT_HANGUP)

    def on_terminate(self, signum, frame) -> None:
        self.save()
        watchdog = threading.Timer(LEAVE_WITHIN_S, os._exit, args=(EXIT_TERMINATED,))
        watchdog.daemon = True
        watchdog.start()
        self.exit_app()
