"""The two status lines under the preview: the physics, then the layout's quality."""

from __future__ import annotations

import re
import textwrap
from dataclasses import dataclass

from textual.widgets import Static


@dataclass(frozen=True)
class Status:
    """What the status line shows; the screen builds one per frame."""

    state: str  # "settling", "settled", "paused" or "exporting …"
    energy: float
    fps: float
    steps_per_s: float
    quality: str  # the measures, for the details view
    frame_ms: float = 0.0
    quality_words: str = ""  # the same, said in words
    details: bool = False  # `v` shows the numbers
    held: int = 0  # frames held back in the last second: the link could not take them
    alignment: str = ""  # near misses, edge lines, share aligned (physics.alignment.short)
    note: str = ""  # what the last release did ("photo anchored where you put it"), until a key
    reasons: tuple[str, ...] = ()  # `check`'s lines on why a guarantee gave way, for `v`


STATE_WORDS = {"settling": "settling…", "settled": "still", "paused": "paused · Space resumes"}


def status_text(status: Status) -> str:
    """Words by default ("settling…", "still", "2 overlaps"); the numbers in the details view
    (`v`): an energy of 1.45e-24 told a user nothing (issue 11)."""
    words = STATE_WORDS.get(status.state, status.state)
    # The note goes on the first line, not in a notice over the page (a notice there made a
    # key's answer come in two writes for seconds after); in the details view after the
    # figures the user asked for, which it pushed off an 80-column line.
    note = f" · {status.note}" if status.note else ""
    if not status.details:
        return f"{words}{note}\n{status.quality_words or status.quality}"
    alignment = f" · {status.alignment}" if status.alignment else ""
    if status.state in ("settled", "paused"):
        # At rest the first line has room: the alignment figures go there, first, where at
        # 80 columns they fell off the end of the quality line (user-walk-2).
        return f"{words}{alignment}{note} · idle\n{status.quality}"  # no energy: nothing moves
    rate = (f"{status.fps:4.1f} fps · {status.held} held · "
            f"{status.steps_per_s:,.0f} steps/s · frame {status.frame_ms:4.1f} ms")
    # Moving, the alignment figures go first on the first line too, and the frame figures
    # give way to them (`fitted`): at the end of the quality line, 80 columns cut them to
    # "misses 3.60…" while the page settled (user-walk-12a).
    return f"{words}{alignment}{note} · energy {status.energy:.2e} · {rate}\n{status.quality}"


REASON_ROWS = 8  # at most this many rows of `check`'s reasons in the details view


def reason_rows(reasons: tuple[str, ...], width: int) -> list[str]:
    """`check`'s reasons, wrapped to ``width``, at most REASON_ROWS rows (the last one says
    `floatpage check` has the rest): the status line had only the short one, and the full
    text was in `check` alone (user-walk-6)."""
    rows = [row for reason in reasons
            for row in textwrap.wrap(reason, max(width, 20), subsequent_indent="  ")]
    if len(rows) > REASON_ROWS:
        rows = rows[:REASON_ROWS - 1] + ["… the rest: floatpage check"]
    return rows


DROPPED_FIRST = ("v details", "no overlaps", "gaps kept")  # what a narrow line goes without
# then, in the details view while the page moves, the frame figures, the least telling first
DROPPED_RATES = (re.compile(r"frame .* ms"), re.compile(r".* steps/s"), re.compile(r"\d+ held"),
                 re.compile(r".* fps"))


def fitted(line: str, width: int) -> str:
    """``line`` without the parts a user can spare, in DROPPED_FIRST's order, then
    DROPPED_RATES', until it fits ``width``: at 60 columns "no overlaps · gutter 1.5 of 3 mm:
    page too full (96% of t…" lost the why, the one part that said something (user-walk-6)."""
    parts = line.split(" · ")
    spares = [part.__eq__ for part in DROPPED_FIRST] + [rate.fullmatch for rate in DROPPED_RATES]
    for spare in spares:
        if len(" · ".join(parts)) <= width:
            break
        found = [part for part in parts if spare(part.strip())]
        if found and len(parts) > 1:
            parts.remove(found[0])
    return " · ".join(parts)


class StatusLine(Static):
    """Shows a Status; the `-settled` / `-paused` classes colour it (see app.tcss).  Two
    lines, and in the details view (`v`) as many more as `check`'s reasons take."""

    def show(self, status: Status) -> None:
        text = status_text(status)
        if self.size.width:
            text = "\n".join(fitted(line, self.size.width - 2) for line in text.split("\n"))
        extra = reason_rows(status.reasons, self.size.width - 2) if status.details else []
        if extra:
            text += "\n" + "\n".join(extra)
        if text != getattr(self, "_shown", None):  # an unchanged line costs no bytes
            self._shown = text
            rows = 2 + len(extra)
            if rows != getattr(self, "_rows", 2):  # only the details view changes the height
                self._rows = rows
                self.styles.height = rows
            self.update(text, layout=False)  # two fixed lines: no layout pass, which cost ms
        if status.state != getattr(self, "_state", None):  # a class change restyles: ~1 ms,
            self._state = status.state                     # so one change, and only on a change
            self.set_classes({"settled": "-settled", "paused": "-paused"}.get(status.state, ""))
