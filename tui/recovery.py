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


# Words typed into a form that was open when the terminal went, one per line at the top of the
# recovery file: they were lost (a text typed into the insert form over SSH, then the link
# dropped), and are shown again when the edits are restored. Comments: the file stays TOML.
TYPED_NOTE = "# typed when the terminal went, not applied: "


# The project file as the editor had read or saved it when the terminal went, as a digest on a
# comment line at the top: another program (vim, `git checkout`) may have changed the file while
# the editor had it open, before the hang-up, which the recovery question's dates cannot tell;
# restored and saved, the edits replaced that change without a word (user-walk-9).
BASE_NOTE = "# edited from the project file with sha256 "


def comment_safe(text: str) -> str:
    """``text`` on one line a TOML comment may hold: line breaks as " ⏎ ", other control
    characters (which no comment may hold) and lone surrogates as \\uXXXX."""
    text = text.replace("\r\n", "\n").replace("\n", " ⏎ ")
    return "".join(f"\\u{ord(char):04x}" if (ord(char) < 0x20 and char != "\t")
                   or ord(char) == 0x7F or 0xD800 <= ord(char) <= 0xDFFF else char
                   for char in text)


def write_recovery(session, typed: list[str] | tuple[str, ...] = ()) -> Path | None:
    """Write the session's unsaved project, and ``typed`` (words in a form not yet applied), to
    its recovery file; None when there is neither."""
    if not (session.unsaved or typed) or session.project.path is None:
        return None
    try:
        session.sync_positions()
    except Exception:  # noqa: BLE001 - mid-step numbers: the model's last positions will do
        pass
    path = recovery_path(session.project.path)
    base = getattr(session, "disk_digest", None)
    notes = f"{BASE_NOTE}{base}\n" if base else ""
    notes += "".join(f"{TYPED_NOTE}{comment_safe(words)}\n" for words in typed)
    atomic_write(path, (notes + dump_project(session.project)).encode("utf-8"), backup=False)
    return path


def split_typed(text: str) -> tuple[list[str], str | None, str]:
    """The typed notes at the top of a recovery file's text, the digest of the project file
    the edits were made to (BASE_NOTE; None in a file written before it was kept), and the
    rest of the text."""
    lines = text.splitlines(keepends=True)
    notes, base = [], None
    while lines and lines[0].startswith((TYPED_NOTE, BASE_NOTE)):
        line = lines.pop(0).rstrip("\r\n")
        if line.startswith(BASE_NOTE):
            base = line[len(BASE_NOTE):].strip()
        else:
            notes.append(line[len(TYPED_NOTE):])
    return notes, base, "".join(lines)


def recovery_base(project_path: str | Path) -> str | None:
    """The digest of the project file the kept edits were made to, or None if not known."""
    try:
        with recovery_path(project_path).open(encoding="utf-8", errors="replace") as file:
            first = file.readline()  # write_recovery puts it first
    except OSError:
        return None
    return split_typed(first)[1]


def pending_recovery(project_path: str | Path) -> Path | None:
    path = recovery_path(project_path)
    return path if path.is_file() else None


def load_recovered(project_path: str | Path, *, allow_outside_files: bool = False):
    """The project as the recovery file holds it, to be saved under the project's own name,
    the words that were in open forms when the terminal went (see TYPED_NOTE) and the digest
    of the project file the edits were made to (BASE_NOTE), or None."""
    project = load_project(recovery_path(project_path), allow_outside_files=allow_outside_files,
                           missing_pictures_ok=True)
    project.path = Path(project_path)
    typed: list[str] = []
    base = None
    if project.source_text is not None:  # the notes are no part of the project, nor saved
        typed, base, project.source_text = split_typed(project.source_text)
    return project, typed, base


def discard_recovery(project_path: str | Path) -> None:
    recovery_path(project_path).unlink(missing_ok=True)


class HangupGuard:
    """Signal handlers that save unsaved edits to the recovery file and leave promptly.

    SIGHUP (and end of input, which the driver turns into SIGHUP) means the terminal is gone:
    write the recovery file and exit with no attempt to restore a screen nobody sees. SIGTERM
    asks the app to exit normally, with a watchdog that ends the process after LEAVE_WITHIN_S
    should a terminal that stopped reading hold the exit up.
    """

    def __init__(self, session, exit_app: Callable[[], None],
                 typed: Callable[[], list[str]] = list):
        self.session = session
        self.exit_app = exit_app
        self.typed = typed  # the words in open forms (`FloatpageApp.typed_in_forms`)

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
            typed = self.typed()
        except Exception:  # noqa: BLE001 - the edits matter more than the words in a form
            typed = []
        try:
            write_recovery(self.session, typed)
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
