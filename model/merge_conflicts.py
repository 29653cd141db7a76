"""A version-control merge conflict left in a project file, and the one kind a settle mends.

Two people who each change a project and settle it change the positions of the items their
change pushed: merged, git leaves a conflict at each item both settles moved, in `x = ...`
and `y = ...` lines only, while the changes that matter (a size, a text) merged cleanly
(user-walk-13: one picture made wider on one branch, another taller on the other, gave 8
such conflicts on the shop flyer). Whichever side of such a conflict is kept, a settle lays
the page out again from both people's changes, so `floatpage settle` does that itself.
"""

from __future__ import annotations

import re
import tomllib
from dataclasses import dataclass
from pathlib import Path

from floatpage.model.atomic_file import atomic_write

OPENING, BASE, MIDDLE, CLOSING = "<<<<<<<", "|||||||", "=======", ">>>>>>>"
MARKER = re.compile(r"(<{7}|\|{7}|>{7})( .*)?|={7}")
POSITION_LINE = re.compile(r"\s*[xy]\s*=\s*[^\s#]+\s*(#.*)?")


def marker_lines(text: str) -> list[int]:
    """Numbers of the lines of ``text`` that are a conflict's markers (git, Mercurial:
    `<<<<<<< HEAD`, `=======`, `>>>>>>> branch`, diff3's `|||||||`). Lines inside a
    multi-line string could look the same, so ask this only of a file TOML refused."""
    return [number for number, line in enumerate(text.splitlines(), start=1)
            if MARKER.fullmatch(line.rstrip("\r"))]


@dataclass(frozen=True)
class Conflict:
    """One conflict: the lines of the side above `=======` (HEAD's, in a merge), the base's
    (diff3 only) and the side below, without their line ends."""

    first: tuple[str, ...]
    base: tuple[str, ...]
    second: tuple[str, ...]


def conflicts(text: str) -> list[Conflict] | None:
    """Every conflict in ``text`` in order, or None where its markers do not pair up."""
    found: list[Conflict] = []
    part: list[list[str]] | None = None
    for line in text.splitlines():
        mark = line.rstrip("\r")
        if mark.startswith(OPENING) and MARKER.fullmatch(mark):
            if part is not None:
                return None
            part = [[]]
        elif part is not None and mark.startswith(BASE) and MARKER.fullmatch(mark):
            part.append([])
        elif part is not None and mark == MIDDLE:
            if len(part) == 1:
                part.append([])
            part.append([])
        elif part is not None and mark.startswith(CLOSING) and MARKER.fullmatch(mark):
            if len(part) != 3:
                return None
            found.append(Conflict(*(tuple(lines) for lines in part)))
            part = None
        elif part is not None:
            part[-1].append(mark)
        elif MARKER.fullmatch(mark):
            return None
    return found if part is None else None


def positions_only(text: str) -> int:
    """How many conflicts ``text`` holds if each is in item positions only (`x = ...`,
    `y = ...` lines on every side), else 0."""
    found = conflicts(text)
    if not found:
        return 0
    for conflict in found:
        for side in (conflict.first, conflict.base, conflict.second):
            if not all(POSITION_LINE.fullmatch(line) for line in side):
                return 0
        if not conflict.first:
            return 0
    return len(found)


def keep_first_sides(text: str) -> str:
    """``text`` with each conflict replaced by its first side (HEAD's, in a merge), line
    ends kept as written."""
    kept: list[str] = []
    skipping = inside = False
    for line in text.splitlines(keepends=True):
        mark = line.rstrip("\r\n")
        if mark.startswith(OPENING) and MARKER.fullmatch(mark):
            inside, skipping = True, False
            continue
        if inside and (mark == MIDDLE or mark.startswith(BASE) and MARKER.fullmatch(mark)):
            skipping = True
            continue
        if inside and mark.startswith(CLOSING) and MARKER.fullmatch(mark):
            inside = skipping = False
            continue
        if not skipping:
            kept.append(line)
    return "".join(kept)


def mend_positions(path: Path) -> tuple[bytes, int] | None:
    """Keep the first side of each conflict in the file at ``path`` where every conflict is
    in positions only and the rest then reads as TOML; return the file as it was (with its
    conflicts) and how many there were, or None, with nothing written, for any other file."""
    try:
        raw = path.read_bytes() if path.is_file() else b""
    except OSError:
        return None
    if b"\n=======" not in raw:
        return None
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:
        return None
    count = positions_only(text)
    if not count:
        return None
    kept = keep_first_sides(text)
    try:
        tomllib.loads(kept.removeprefix("\ufeff"))
    except tomllib.TOMLDecodeError:
        return None  # more is wrong than the conflicts: the loader says what
    # the file with its conflicts first: a load that then fails (a picture not found) leaves
    # the mended file, and the user's own is not lost
    atomic_write(path.with_name(path.name + ".bak"), raw, backup=False)
    atomic_write(path, kept.encode("utf-8"), backup=False)
    return raw, count
