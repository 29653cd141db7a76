"""The editor: the page preview with live physics, the status lines, keys and dialogs.

Edits go through the EditSession; this screen only turns keys, clicks and
dialog answers into session calls, then redraws and wakes the physics loop.
The loop is a 30 Hz interval: each tick runs one frame of physics steps (the
engine's frame_steps, cut short by a time budget so a big page cannot stall
the keys), redraws once, and pauses itself once the page settles, so an idle
editor sends nothing over the wire.
"""

from __future__ import annotations

import copy
import datetime
import math
import time
from functools import partial
from pathlib import Path
from typing import Callable, TypeVar

import numpy as np
from rich.text import Text
from textual import work
from textual.app import ComposeResult
from textual.reactive import reactive
from textual.screen import ModalScreen, Screen
from textual.timer import Timer
from rich.cells import cell_len

from floatpage.model.atomic_file import read_only
from floatpage.model.document import Background, ItemAnchor, PointAnchor
from floatpage.model.errors import FloatpageError, printable
from floatpage.model.layout import copy_of, engine_for_page
from floatpage.model.page_report import page_reasons
from floatpage.tui import item_forms, region_edits
from floatpage.tui.dialogs import ChoiceDialog, FormDialog, HelpScreen, PictureDialog
from floatpage.tui.direct_paint import draws_none_of, stale_lines_hidden
from floatpage.tui.frame_meter import FrameMeter
from floatpage.tui.frame_pacer import FramePacer
from floatpage.tui.key_bar import KeyBar
from floatpage.tui.keymap import ITEM_ACTIONS, ITEM_KEYS, bindings, footer_rank, in_footer
from floatpage.tui.page_bar import PageBar
from floatpage.tui.page_painter import PageView, shown_guides
from floatpage.tui.page_preview import PagePreview
from floatpage.tui.session import EditError, EditSession
from floatpage.tui.status_line import Status, StatusLine

FRAME_S = 1 / 30
PHYSICS_BUDGET_S = 0.008  # leaves most of a 33 ms frame for drawing and for keys
RELEASE_AFTER_S = 0.6  # a nudged item is let go this long after the last arrow key
# How often the editor looks at the project file's size and time for changes another program
# made (`look_at_file`): a stat a second costs nothing, and a change is told within two (it
# is read once its size and time have held still for one look)
LOOK_AT_FILE_S = 1.0
STILL_FRAMES = 15  # half a second of frames that change nothing on screen: at rest
ANSWER_FIRST_S = 0.02  # longer than Textual's screen update period (1/60 s)
QUALITY_EVERY_S = 0.25  # the quality measure is O(n^2): while settling, refresh it 4 times a second


def describe_item(item, page=None) -> str:
    """Kind, size and how the item is held in place, for the page bar; a member of a group
    whose anchor another member holds says so (`u` on it takes the group's anchor off)."""
    words = [item.kind, f"{item.w:.0f}×{item.h:.0f} mm"]
    if item.decorative:
        words.append("decorative")
    holder = item
    if item.anchor is None and item.group and page is not None:
        holder = page.group_lead(item.group) or item
    anchor = holder.anchor
    if isinstance(anchor, PointAnchor):
        words.append("hard anchor" if anchor.hard else f"anchored γ {anchor.gamma:g}")
        if holder is not item:
            words[-1] += f" by {holder.id}"
    elif isinstance(anchor, ItemAnchor) and holder is item:
        words.append(f"follows {anchor.to}")
    return ", ".join(words)


EXPORT_WARNINGS_SHOWN = 5
ALWAYS_IN_FOOTER = frozenset({"help", "save", "export_pdf", "quit"})
PALETTE_CELLS = 13  # the footer's "^p palette" at its right end


def quality_in_words(quality, reason: str = "") -> str:
    """"2 overlaps · 1 off the page", or "no overlaps · gaps kept" when all is well.  Where a
    guarantee gave way, ``reason`` says which and why, as `check` does (model.page_reasons:
    "gutter 1.5 of 3 mm: page too full (96% of the room)"); "some gaps narrow" said neither
    (user-walk-6).  Until the reason is known (it is found in a thread), the gap in mm."""
    words = []
    overlaps, off = quality.overlap_count, len(quality.off_page)
    if reason and not overlaps:
        words.append("no overlaps")
    elif not reason:
        words.append(f"{overlaps} overlap{'s' if overlaps != 1 else ''}" if overlaps
                     else "no overlaps")
    if reason:
        words.append(reason)
    if off:
        words.append(f"{off} off the page")
    if not reason and quality.in_margin:
        words.append(f"{len(quality.in_margin)} in the margin")
    if not reason and not overlaps and not math.isinf(quality.min_gap_mm):
        words.append("gaps kept" if quality.gutter_kept else
                     f"gap {max(quality.min_gap_mm, 0.0):.1f} of {quality.gutter_mm:g} mm")
    return " · ".join(words) + " · v details"


def next_month(project) -> tuple[int, int]:
    """(year, month) a new calendar panel starts at: the month after the project's latest
    panel, or else next month, as a printed calendar is made ahead of time (it was always
    January 2027)."""
    panels = [(item.year, item.month) for page in project.pages for item in page.items
              if item.kind == "calendar"]
    year, month = max(panels) if panels else (datetime.date.today().year,
                                              datetime.date.today().month)
    return (year + 1, 1) if month == 12 else (year, month + 1)


Answer = TypeVar("Answer")


# An empty page (an `N` too many) said "no overlaps" and printed as a blank sheet: as
# `check`'s note (model.page_report.empty_page_notes) says, with what to do
EMPTY_PAGE_WORDS = "no items: prints as a blank page · i inserts · D removes the page"
SNAP_SAID_MM = 0.5  # a save's settle that moves the selected item this far says so


class EditorScreen(Screen):
    """The main screen: a thin layer that turns keys, clicks and dialog answers into session
    calls, then shows the session's state (`after_edit`).

    The session holds the document, the selection included (undo brings a selection back with
    its page); the screen holds only how it is shown: `running`, `labels`, `details` and the
    export state. `item_selected` follows the session's selection so that the footer greys
    out the item commands when nothing is selected."""

    BINDINGS = bindings()

    running: reactive[bool] = reactive(True, init=False)
    item_selected: reactive[bool] = reactive(False, bindings=True, init=False)

    def __init__(self, session: EditSession, *, autostart: bool = True):
        super().__init__(id="editor")
        self.session = session
        self.meter = FrameMeter()
        self.set_reactive(EditorScreen.running, autostart)
        self.export_state: str | None = None
        self.export_path: Path | None = None  # where Ctrl+E writes, once the usual PDF was refused
        self.release_timer: Timer | None = None  # lets go of a nudged item after the last key
        self.frames_ticked = 0  # frames the physics loop has drawn, for tests and benchmarks
        self._steps_undrawn = 0  # physics steps since the last drawn frame
        self._wake_timer = None
        self.pacer = FramePacer(None)  # on_mount gives it the terminal's link, if there is one
        self._quality = ("", "", "")
        self.details = False  # `v`: the status line shows its numbers
        self.note = ""  # what the last release did, on the status line until the next key
        self.labels = False  # `n`: every item's id on the preview, not only the selected one's
        self.reasons: list[str] = []  # `check`'s lines on why a guarantee gave way (`v` shows them)
        self._quality_at = float("-inf")
        self._quality_key: bytes | None = None  # what the figures were measured on, at rest
        self.passes_running = 0  # no-overlap passes running in threads (`finish_settling`)
        self.room_searches = 0  # searches for room running in threads (`room_worker`)
        self.after_room: dict[str, Callable[[], object]] = {}  # see `once_room_is_found`
        self._held_notices: list[tuple[str, dict, float | None]] = []  # while a dialog is open
        self._shown_notice: tuple[str, dict, float] | None = None  # the toast last shown

    def compose(self) -> ComposeResult:
        yield PageBar(id="page-bar")
        yield PagePreview(id="preview")
        yield StatusLine("", id="status")
        yield KeyBar(id="footer")

    def on_mount(self) -> None:
        self.frame_timer = self.set_interval(FRAME_S, self.tick, pause=True)
        self.file_timer = self.set_interval(LOOK_AT_FILE_S, self.look_at_file)
        self.pacer = FramePacer(getattr(self.app._driver, "link", None))
        self.query_one(PagePreview).focus()
        self.redraw()
        self.wake()
        missing = self.session.project.missing_pictures
        if missing:  # opened all the same, so that the user can mend it here
            gone = all(entry.endswith(" is missing") for entry in missing)
            self.notify("\n".join(f"• {printable(entry)}" for entry in missing[:4])
                        + (f"\n• and {len(missing) - 4} more" if len(missing) > 4 else "")
                        + "\nCopy the files back (or good ones over them), give each its new path (Tab to it, Enter: "
                        "Picture file), or delete these items (Del); until then the PDF "
                        "cannot be made",
                        title="Pictures not found" if gone else "Pictures that cannot be used",
                        severity="warning", timeout=20)
        typed = self.session.typed_when_lost
        if typed:  # restored edits: the words in a form the lost terminal left unapplied
            self.notify("\n".join(f"• {printable(words)}" for words in typed[:4])
                        + "\nThey are not in the page: type them again (Enter on the item, or "
                        "i to insert)", title="Typed when the terminal went, not applied",
                        severity="warning", timeout=30)
        path = self.session.project.path
        if path is not None and read_only(path):  # said at once, not after an hour's edits
            self.notify(f"{printable(path.name)} is read-only: edits can be made and exported, "
                        "but Ctrl+S is refused until it is writable (chmod u+w)",
                        title="Read-only", severity="warning", timeout=10)

    @property
    def preview(self) -> PagePreview:
        return self.query_one(PagePreview)

    # -- the physics loop ----------------------------------------------------------------

    def tick(self) -> None:
        """One frame: physics for a time budget, then one redraw, if the link has taken the
        frames before (`frame_pacer`); else the physics goes on and the drawing waits. Pauses
        itself once settled and its last frame is drawn."""
        engine = self.session.engine
        if not self.running or engine.settled:  # at rest: draw the last frame, then stop
            if self.pacer.may_draw():
                self.frame_timer.pause()
                self.redraw()
            else:
                self.meter.record_held(time.perf_counter())
            return
        start = time.perf_counter()
        self._steps_undrawn += engine.advance(budget_s=PHYSICS_BUDGET_S, clock=time.perf_counter)
        if engine.settled:
            self.finish_settling()
        if not self.pacer.may_draw():
            self.meter.record_held(time.perf_counter())
            return
        if engine.settled:
            self.frame_timer.pause()
        self.redraw()
        if self.preview.unchanged_frames >= STILL_FRAMES and self.session.held_id is None:
            self.come_to_rest()
        now = time.perf_counter()
        self.meter.record(now, self._steps_undrawn, now - start)
        self._steps_undrawn = 0
        self.frames_ticked += 1

    def come_to_rest(self) -> None:
        """The page has looked the same for STILL_FRAMES frames: what moves still moves by
        less than a cell, so stop there, as `finish_settling` would at the physics' own rest.
        The calendar went on creeping unseen for 5 s after a held arrow, and a key meanwhile
        waited for the frame in progress (issue 11: visibly still within 2 s)."""
        self.session.engine.mark_settled()
        self.finish_settling()
        self.frame_timer.pause()
        self.redraw()

    def finish_settling(self) -> None:
        """What `floatpage settle` does at the end, the editor does too: the no-overlap pass,
        when the physics came to rest with items overlapping or off the page (an inserted
        picture stayed on top, "settled · 2 overlaps", defect 7; so did a turned page, 9).
        The rest of the settle (its probes and the alignment snap) waits for a save
        (`action_save`): run at every rest, it cost the flyer's keys 6 ms each (a settle in
        a thread beside them) and held the calendar's stillness back to 2.2 s.

        The pass runs on a copy, in a thread: on a page too full for its gutter it took
        0.5-0.9 s (the calendar after a held arrow), and run here it held back every key
        pressed meanwhile; the calendar's keys answered in 42 or 131 ms, by whether they
        came during it (issue 11)."""
        engine = self.session.engine
        if self.session.held_id is not None:
            return
        quality = engine.quality()
        if quality.overlapping_pairs or quality.off_page:
            self.passes_running += 1
            self.finalize_worker(engine, copy.deepcopy(engine), engine.bodies.centres.copy())

    @work(thread=True, group="finalize")
    def finalize_worker(self, engine, trial, centres: np.ndarray) -> None:
        try:
            trial.finalize()
        finally:
            self.app.call_from_thread(self.adopt_finalized, engine, trial, centres)

    def adopt_finalized(self, engine, trial, centres: np.ndarray) -> None:
        """Take the pass's result, if the page is still as it was when the pass began; else
        an edit came first, and its own rest runs the pass again."""
        self.passes_running -= 1
        session = self.session
        if session.engine is engine and session.held_id is None and engine.settled \
                and np.array_equal(engine.bodies.centres, centres):
            session.engine = trial
        self.redraw()

    def _on_timer_update(self) -> None:
        """Textual's screen update; when it draws none of the preview's cells (a key's top
        bar, a frame's status line), without rendering again the preview rows painted past it
        (`direct_paint`): 3-5 ms of a key's answer, for lines it never shows."""
        preview = self.preview
        if not draws_none_of(self, preview):
            super()._on_timer_update()
            return
        with stale_lines_hidden(preview):
            super()._on_timer_update()

    def wake(self) -> None:
        """Start the frame timer if the physics has something to do, a screen update later:
        a key's answer is written before the physics frame it set off, which used to come
        first and hold the answer back by a frame (issue 11)."""
        if self._wake_timer is None:
            self._wake_timer = self.set_timer(ANSWER_FIRST_S, self._resume_frames)

    def _resume_frames(self) -> None:
        self._wake_timer = None
        if self.running and not self.session.engine.settled:
            self.frame_timer.resume()

    def step_physics(self, steps: int) -> int:
        """Run a fixed number of steps and redraw (frozen-physics tests and the benchmark)."""
        done = self.session.engine.advance(steps=steps)
        self.redraw()
        return done

    def watch_running(self, running: bool) -> None:
        if running:
            self.wake()
        self.redraw()

    @property
    def selected_id(self) -> str | None:
        """The selected item's id: the session's, the one selection there is."""
        return self.session.selected_id

    @selected_id.setter
    def selected_id(self, item_id: str | None) -> None:
        self.session.select(item_id)
        self.after_edit()

    # -- drawing ------------------------------------------------------------------------------

    def page_view(self) -> PageView:
        session = self.session
        moving = session.held_id is not None or self.running and not session.engine.settled
        return PageView(page=session.page, positions=session.engine.positions(),
                     selected_id=session.selected_id, base_dir=session.project.base_dir,
                     labels=self.labels,
                     guides=shown_guides(session.engine, session.selected_id, moving),
                     greys=self.app.no_color)

    def state_word(self) -> str:
        if self.export_state:
            return self.export_state
        if self.after_room and self.room_searches:
            return f"{' and '.join(self.after_room)} once room is found ({self.room_searches} " \
                "page(s) left)"
        if not self.running:
            return "paused"
        return "settled" if self.at_rest else "settling"

    @property
    def at_rest(self) -> bool:
        """Settled, and the no-overlap pass (if it was needed) done."""
        return self.session.engine.settled and not self.passes_running \
            and not self.room_searches

    def redraw(self, measure: bool = True) -> None:
        """Paint the preview, the status lines and the top bar.  ``measure=False`` (a key's
        own answer, while the physics it woke runs) leaves the status lines to the physics
        frame right after: measuring the page cost 2 ms of the answer, and the lines' change
        from "still" to "settling…" (a restyle and two rows to compose) 1-2 ms more.

        The preview's changed cells and the top bar go to the terminal together, in one
        write (`DirectPainter.answer`): a key's answer came in two, the top bar 3-4 ms after
        the moved item, through Textual's next screen update (issue 11: key to screen)."""
        preview = self.preview
        with preview.direct.answer(self.app):
            preview.show(self.page_view())
            engine = self.session.engine
            moving = self.running and not engine.settled
            if measure or not moving or not self._quality[0]:
                summary, words, alignment = self.quality_summary()
                self.query_one(StatusLine).show(Status(
                    state=self.state_word(), energy=engine.kinetic_energy, fps=self.meter.fps,
                    held=self.meter.held, steps_per_s=self.meter.steps_per_s, quality=summary,
                    frame_ms=1000 * self.meter.last_frame_s, quality_words=words,
                    details=self.details, alignment=alignment, note=self.note,
                    reasons=tuple(self.reasons)))
            bar = self.query_one(PageBar)
            if bar.show(self.page_bar_runs(), refresh=False) \
                    and not preview.direct.paint_lines(bar):  # an unchanged bar costs no bytes
                bar.refresh()

    def quality_summary(self) -> tuple[str, str, str]:
        """The layout's quality, as numbers and in words, and its alignment figures; exact
        when idle, refreshed a few times a second while moving."""
        now = time.perf_counter()
        engine = self.session.engine
        moving = self.running and not engine.settled
        if moving and now - self._quality_at < QUALITY_EVERY_S:
            return self._quality
        key = None if moving else engine.quality_key()
        if key is None or key != self._quality_key:  # at rest, measured once per layout:
            quality = engine.quality()  # a decoration nudged on a still page changes nothing
            words = quality_in_words(quality) if self.session.page.items else EMPTY_PAGE_WORDS
            self._quality = (quality.summary(), words, engine.alignment().short())
            self._quality_key = key
            self.reasons = []
            if key is not None and not quality.ok:  # why, as `check` says it: off this thread
                self.session.sync_positions()       # (its search for room can take seconds)
                self.reasons_worker(key, copy_of(self.session.page), quality)
        self._quality_at = now
        return self._quality

    @work(thread=True, group="reasons", exclusive=True)
    def reasons_worker(self, key: bytes, page, quality) -> None:
        """`check`'s reasons (model.page_reasons) for a still page, on a copy of it."""
        physics = self.session.project.physics
        lines, _, short = page_reasons(page, engine_for_page(page, physics), physics.gutter_mm)
        self.app.call_from_thread(self.adopt_reasons, key, quality, lines[2:], short)

    def adopt_reasons(self, key: bytes, quality, lines: list[str], short: str) -> None:
        """Show the reasons found, if the page is still the one they were found for: the
        short one on the status line, all of `check`'s lines in the details view (`v`)."""
        if key != self._quality_key:
            return
        summary, _, alignment = self._quality
        self._quality = (summary, quality_in_words(quality, short), alignment)
        self.reasons = [line.strip() for line in lines]
        self.redraw()

    def action_toggle_labels(self) -> None:
        self.labels = not self.labels
        self.redraw()

    def action_toggle_details(self) -> None:
        self.details = not self.details
        self.redraw()

    def page_bar_runs(self) -> tuple[tuple[str, bool], ...]:
        """The top bar, as runs of (text, bold), built to fit its width by priority: the unsaved
        mark first and always, then the selected item and its anchor, the page, the title,
        then size and count (at 80 columns the unsaved mark and the anchor state used to be
        cut off, defect 5)."""
        session = self.session
        page = session.page
        selected = session.selected_item
        parts = []  # (priority: lower is kept longer, position, runs)
        if session.unsaved:
            parts.append((0, 0, (("● unsaved", True),)))
        title = session.project.title or (session.project.path.stem if session.project.path else "")
        if title:
            parts.append((3, 1, ((title, True),)))
        parts.append((2, 2, ((f"page {session.page_index + 1}/{len(session.project.pages)} ",
                              False), (page.id, True))))
        parts.append((5, 3, ((f"{page.size} {page.orientation}", False),)))
        count = len(page.items)  # "1 items" on a new blank page
        parts.append((4, 4, ((f"{count} item{'' if count == 1 else 's'}", False),)))
        if selected:
            parts.append((1, 5, ((selected.id, True),
                                 (f" ({describe_item(selected, page)})", False))))
            # where it is: an arrow moves it 2 mm, often less than a cell of the preview, and
            # the key would have shown nothing at all (issue 11: key to screen)
            x_mm, y_mm = session.engine.positions().get(selected.id, (selected.x, selected.y))
            parts.append((2, 6, ((f"at {x_mm:.0f}, {y_mm:.0f} mm", False),)))
        width = max(self.size.width - 2, 20) if self.is_mounted else 200
        kept = sorted(parts)

        def shown(kept_parts) -> tuple[tuple[str, bool], ...]:
            runs: list[tuple[str, bool]] = []
            for _, _, part in sorted(kept_parts, key=lambda p: p[1]):
                if runs:
                    runs.append((" · ", False))
                runs.extend(part)
            return tuple(runs)

        while len(kept) > 1 and cell_len("".join(text for text, _ in shown(kept))) > width:
            kept.pop()
        return shown(kept)

    def notify(self, message: str, *, markup: bool = False, **kwargs) -> None:
        """Notifications quote file names, ids and errors: plain text, never Rich markup.

        Each replaces the one before: they used to pile up over the preview and the status
        line for seconds (defect 3), and the newest is the one that answers the last key.
        While a dialog is open, one is held until it closes: Textual draws toasts on the top
        screen, where they covered the dialog's fields (a finished export over the form being
        typed in; on a short terminal the dialog is the whole screen; user-walk-6)."""
        kwargs["markup"] = markup
        if self.is_mounted and self.app.screen_stack[-1] is not self:
            self._held_notices.append((message, kwargs, None))
            return
        self.app.clear_notifications()
        self._shown_notice = (message, kwargs, time.monotonic())
        super().notify(message, **kwargs)

    def on_screen_suspend(self) -> None:
        """A dialog opens over the editor: the toast showing goes with the editor, to come
        back for the rest of its time when the dialog closes (`on_screen_resume`)."""
        shown, self._shown_notice = self._shown_notice, None
        if shown is None:
            return
        message, kwargs, at = shown
        left = kwargs.get("timeout", self.app.NOTIFICATION_TIMEOUT) - (time.monotonic() - at)
        if left > 0.5:
            self._held_notices.insert(0, (message, kwargs, left))
        self.app.clear_notifications()

    def on_screen_resume(self) -> None:
        """The dialog closed: the held notices show now, in the order they came."""
        held, self._held_notices = self._held_notices, []
        for number, (message, kwargs, left) in enumerate(held):
            if number == 0:
                self.app.clear_notifications()
            if left is not None:
                kwargs = {**kwargs, "timeout": left}
            self._shown_notice = (message, kwargs, time.monotonic())
            super().notify(message, **kwargs)

    def after_edit(self, *, keep_note: bool = False) -> None:
        """Show what an edit, a selection or a release did: the footer's item commands follow
        the selection, the page is redrawn and the physics woken (or, when a held key outruns
        the link or the byte budget, only woken: the next frame shows it).  The status line's
        note (`session.status_note`) stays until the next edit, or as long as ``keep_note``
        (the room found for the page size that set it)."""
        self.item_selected = self.session.selected_id is not None
        note, self.session.status_note = self.session.status_note, None
        if note is not None or not keep_note:
            self.note = note or ""
        requests, self.session.room_wanted = self.session.room_wanted, []
        if requests:  # an insert or a page change: room is found off this thread
            self.room_searches += len(requests)
            pages = self.session.project.pages
            self.room_worker([(request, copy_of(pages[request.page_index]))
                              for request in requests])
        if self.running and not self.session.engine.settled and not self.pacer.may_draw():
            self.wake()
            return
        self.redraw(measure=False)
        self.wake()

    def ask(self, dialog: ModalScreen[Answer | None], then: Callable[[Answer], object]) -> None:
        """Show a dialog; its answer goes to `then`, unless it was cancelled (None)."""
        def answered(answer: Answer | None) -> None:
            if answer is not None:
                then(answer)
        self.app.push_screen(dialog, callback=answered)

    def attempt(self, edit, *args) -> bool:
        """Run a session edit; a refusal (EditError, or the engine's ValueError) is a notice."""
        try:
            edit(*args)
        except (FloatpageError, ValueError) as error:
            self.notify(str(error), severity="warning")
            return False
        self.after_edit()
        return True

    @work(thread=True, group="room")
    def room_worker(self, requests) -> None:
        """`EditSession.room_scale` on a copy of each page, in a thread (see `want_room`):
        one page after another (`S` on every page of a calendar asks for 12), the page on
        screen first."""
        current = self.session.page_index
        for request, page in sorted(requests, key=lambda pair: pair[0].page_index != current):
            scale = 1.0
            try:
                scale = self.session.room_scale(page, request)
            finally:
                self.app.call_from_thread(self.adopt_room, request, scale)

    def adopt_room(self, request, scale: float) -> None:
        self.room_searches -= 1
        on_screen = request.page_index == self.session.page_index
        if self.session.make_room(request, scale):
            page = self.session.project.pages[request.page_index]
            where = "the page" if on_screen else f"page {page.id}"
            self.notify(f"made {1 - scale:.0%} smaller so that everything fits {where} "
                        "without overlap (Ctrl+Z undoes it)", timeout=4)
            if on_screen:
                self.after_edit(keep_note=True)
            else:
                self.redraw()
        else:
            self.redraw()
        if not self.room_searches and self.after_room:
            waiting, self.after_room = self.after_room, {}
            for then in waiting.values():
                then()

    def once_room_is_found(self, what: str, then: Callable[[], object]) -> bool:
        """Run ``then`` once the room searches still running are done, saying so (``what``:
        "export", "save and quit"); False, and nothing kept, when none is running.  Ctrl+E
        pressed right after `S` on every page of a calendar printed the pages with their
        items piled up, the searches not done, and the export's own pass then left the
        searches' answers unused: five overlaps stayed on the page on screen."""
        if not self.room_searches:
            return False
        self.after_room[what] = then
        self.notify(f"{what} once room is found on {self.room_searches} page(s); "
                    "the editor answers meanwhile", timeout=4)
        self.redraw()
        return True

    @property
    def active_bindings(self):
        """The footer's bindings, fitted to the width by priority (display only; every key still
        works): Help, Save, Export and Quit always, then what makes sense now (item commands
        when one is selected, page commands when not), then the rest, while they fit. The
        footer used to cut off at 80 and 100 columns, Save, Export and Quit first (defect 4)."""
        selected = self.selected_id is not None
        shown = sorted(super().active_bindings.items(), key=lambda entry: (
            entry[1].binding.action not in ALWAYS_IN_FOOTER,
            not in_footer(entry[1].binding.action, selected),
            footer_rank(entry[1].binding.action)))
        budget = (self.size.width if self.is_mounted else 200) - PALETTE_CELLS
        # The footer shows an action once, by its first key, and a group as one unit, all of
        # it or none.
        units: dict[object, list] = {}
        for key, entry in shown:
            group = entry.binding.group
            units.setdefault(group.description if group else entry.binding.action,
                             []).append((key, entry))
        kept, used = [], 0
        for name, members in units.items():
            first_keys = {}
            for _, entry in members:
                first_keys.setdefault(entry.binding.action, self.app.get_key_display(entry.binding))
            keys = sum(len(display) for display in first_keys.values())
            group = members[0][1].binding.group
            # as tui.key_bar draws it: "keys description "
            cost = keys + len(group.description if group else
                              members[0][1].binding.description) + 2
            essential = any(entry.binding.action in ALWAYS_IN_FOOTER for _, entry in members)
            if not essential and used + cost > budget:
                break  # in order of priority: nothing after the first that does not fit
            kept += members
            used += cost
        return dict(kept)

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        if action in ITEM_ACTIONS and self.selected_id is None:
            return None  # shown greyed out in the footer
        return True

    def on_resize(self, event) -> None:
        self.redraw()  # the top bar and the footer fit themselves to the width
        self.refresh_bindings()  # the footer reads them again only when told

    def on_key(self, event) -> None:
        """A key whose command needs a selected item, pressed with none, says what to do
        (its binding is disabled then, and used to do nothing at all)."""
        command = ITEM_KEYS.get(event.key)
        if command is not None and self.selected_id is None:
            self.notify(f"{command.label}: select an item first (Tab, or click it)", timeout=2)
            event.stop()

    # -- selecting ---------------------------------------------------------------------------

    def action_select_next(self) -> None:
        self.session.select_step(1)
        self.after_edit()

    def action_select_previous(self) -> None:
        self.session.select_step(-1)
        self.after_edit()

    def action_select_none(self) -> None:
        self.selected_id = None

    def on_page_preview_item_pressed(self, message: PagePreview.ItemPressed) -> None:
        self.selected_id = message.item_id

    # -- moving and resizing ------------------------------------------------------------------

    def action_nudge(self, dx_mm: float, dy_mm: float) -> None:
        """Move the selected item, held until RELEASE_AFTER_S after the last arrow key."""
        if self.attempt(self.session.nudge, dx_mm, dy_mm):
            self.stop_release_timer()
            self.release_timer = self.set_timer(RELEASE_AFTER_S, self.release_held)

    def on_page_preview_item_dragged(self, message: PagePreview.ItemDragged) -> None:
        self.stop_release_timer()  # a drag holds the item until the button goes up
        self.attempt(self.session.move_to, message.item_id, message.x_mm, message.y_mm)

    def on_page_preview_drag_ended(self, message: PagePreview.DragEnded) -> None:
        self.release_held()

    def release_held(self) -> None:
        """Let go of the nudged or dragged item. Any other edit or a new selection lets go of
        it too, in the session, before it changes anything."""
        self.stop_release_timer()
        self.session.end_move()
        self.after_edit()

    def stop_release_timer(self) -> None:
        if self.release_timer is not None:
            self.release_timer.stop()
            self.release_timer = None

    def action_resize(self, fx: float, fy: float) -> None:
        self.attempt(self.session.resize_selected, fx, fy)

    # -- inserting -----------------------------------------------------------------------------

    def action_insert(self) -> None:
        self.ask(ChoiceDialog("Insert", item_forms.INSERT_CHOICES, dialog_id="insert-dialog"),
                 self.action_insert_kind)

    def action_insert_kind(self, kind: str) -> None:
        project = self.session.project
        if kind == "picture":
            self.ask(PictureDialog(project.base_dir, outputs=self.own_pdfs()),
                     self.insert_picture)
        elif kind == "background":
            self.ask(ChoiceDialog("Page background", item_forms.BACKGROUND_CHOICES,
                                  dialog_id="background-dialog"), self.choose_background)
        elif kind == "text":
            self.ask(FormDialog("Insert a text box", item_forms.new_text_fields(),
                                item_forms.parse_new_text, dialog_id="text-dialog"),
                     partial(self.insert, "text"))
        elif kind == "block":
            self.ask(FormDialog("Insert a colour block",
                                item_forms.new_block_fields(self.session.new_item_look("block")),
                                item_forms.parse_new_block, dialog_id="block-dialog"),
                     partial(self.insert, "block"))
        elif kind == "calendar":
            fields = item_forms.new_calendar_fields(*next_month(project), project.language,
                                                    self.session.new_item_look("calendar"))
            self.ask(FormDialog("Insert a calendar month", fields, item_forms.parse_calendar,
                                dialog_id="calendar-dialog"), partial(self.insert, "calendar"))

    def insert(self, kind: str, values: dict) -> None:
        self.attempt(lambda: self.session.insert_item(self.session.make_item(kind, **values)))

    def insert_picture(self, path: Path) -> None:
        session = self.session
        self.attempt(lambda: session.insert_item(session.make_item(
            "picture", path=session.relative_picture_path(path))))

    def choose_background(self, choice: str) -> None:
        session = self.session
        if choice == "none":
            self.attempt(session.set_background, None)
        elif choice == "color":
            current = session.page.background.color if session.page.background else None
            self.ask(FormDialog("Background colour", item_forms.background_colour_fields(current),
                                item_forms.parse_background_colour,
                                dialog_id="background-colour"),
                     partial(self.attempt, session.set_background))
        else:
            self.ask(PictureDialog(session.project.base_dir, "Background picture",
                                   outputs=self.own_pdfs()), self.set_background_picture)

    def set_background_picture(self, path: Path) -> None:
        session = self.session
        self.attempt(lambda: session.set_background(
            Background(picture=session.relative_picture_path(path))))

    # -- editing -------------------------------------------------------------------------------

    def action_edit(self) -> None:
        item = self.session.selected_item
        if item is not None:
            regions = tuple(region.id for region in self.session.page.regions)
            parse = item_forms.parse_edit if item.kind != "picture" else \
                item_forms.picture_edit_parser(item.path, self.session.typed_picture_path)
            self.ask(FormDialog(f"Edit {item.id} ({item.kind})",
                                item_forms.edit_fields(item, regions), parse,
                                dialog_id="edit-dialog"),
                     partial(self.attempt, self.session.update_item, item.id))

    def action_toggle_decorative(self) -> None:
        item = self.session.selected_item
        if item is not None:
            self.attempt(self.session.update_item, item.id, {"decorative": not item.decorative})

    def action_delete(self) -> None:
        self.attempt(self.say_deleted)

    def say_deleted(self) -> None:
        self.notify(self.session.delete_selected(), timeout=4)

    # -- anchoring ------------------------------------------------------------------------------

    def action_anchor_here(self) -> None:
        self.attempt(self.session.anchor_here)

    def action_anchor_to_item(self) -> None:
        item = self.session.selected_item
        if item is None:
            return
        accepted, left_out = self.session.anchor_targets()
        if not accepted:  # say why, rather than offer items that `anchor_to` refuses
            self.notify(f"{item.id} can follow no item on this page: {left_out}" if left_out
                        else "there is no other item on this page to anchor to",
                        severity="warning")
            return
        self.ask(ChoiceDialog(f"Anchor {item.id} to…", [(other, other) for other in accepted],
                              message=left_out, dialog_id="anchor-dialog"),
                 partial(self.attempt, self.session.anchor_to))

    def action_unanchor(self) -> None:
        self.attempt(self.session.unanchor)

    def action_group(self) -> None:
        item = self.session.selected_item
        if item is None:
            return
        groups = tuple(dict.fromkeys(other.group for other in self.session.page.items
                                     if other.group))
        self.ask(FormDialog(f"Group {item.id} with…", item_forms.group_fields(item, groups),
                            item_forms.parse_group, dialog_id="group-dialog"),
                 partial(self.attempt, self.say_group))

    def say_group(self, group: str) -> None:
        self.notify(self.session.set_group(group))

    def action_region(self) -> None:
        """Make a region, or change or remove the selected item's (`tui.region_edits`).  With
        nothing selected on a page that has regions, ask which: a new one, or one of them to
        change or remove; a region holding no item could be neither once made (a stray `R`
        left one the editor could not take away, user-walk-12a)."""
        session = self.session
        if session.selected_item is None and session.page.regions:
            self.ask(ChoiceDialog("Region", region_edits.region_choices(session.page),
                                  dialog_id="which-region-dialog"), self.edit_region)
            return
        self.edit_region(None)

    def edit_region(self, region_id: str | None) -> None:
        """The form for the region ``region_id`` of the page, or for the selected item's
        region, or for a new one around the selected item (or the page's top two-thirds)."""
        session = self.session
        item = session.selected_item
        if item is not None:
            session.sync_positions()  # the region offered is around where the item is now
        old_id = region_id or (item.region if item is not None and item.region else None)
        region = session.page.region(old_id) if old_id else \
            region_edits.proposed_region(session.page, item)
        title = f"Region {old_id}" if old_id else "New region"
        self.ask(FormDialog(title, region_edits.region_fields(region, item, new=old_id is None),
                            region_edits.region_parser(session.page, old_id, item,
                                                       session.engine.margin_mm),
                            dialog_id="region-dialog"),
                 partial(self.attempt, self.say_region, old_id,
                         item.id if item is not None else None))

    def say_region(self, old_id: str | None, item_id: str | None, answer: dict) -> None:
        self.notify(region_edits.put_region(self.session, old_id, answer, item_id))

    # -- physics ------------------------------------------------------------------------------

    def action_toggle_pause(self) -> None:
        self.running = not self.running

    def action_reheat(self) -> None:
        """Heat the page up again; a paused page stays paused until resumed."""
        if not self.session.engine.settled:
            self.notify("the page is already settling", timeout=2)
            return
        self.session.engine.reheat()
        self.wake()
        self.redraw()

    # -- history ------------------------------------------------------------------------------

    def action_undo(self) -> None:
        self.step_history(self.session.undo, "undid")

    def action_redo(self) -> None:
        self.step_history(self.session.redo, "redid")

    def step_history(self, step, verb: str) -> None:
        """Undo or redo, and say which edit it was."""
        try:
            label = step()
        except EditError as error:
            self.notify(str(error), severity="warning")
            return
        self.notify(f"{verb} {label}", timeout=2)
        self.after_edit()

    # -- pages ---------------------------------------------------------------------------------

    def action_switch_page(self, step: int) -> None:
        self.attempt(self.session.switch_page, step)

    def action_add_page(self) -> None:
        self.attempt(self.session.add_page)

    def action_remove_page(self) -> None:
        page = self.session.page
        if len(self.session.project.pages) == 1:
            self.notify("a project keeps at least one page", severity="warning")
            return
        self.ask(ChoiceDialog(f"Remove page {page.id}?", [("Remove it", page.id),
                                                          ("Keep it", None)],
                              message=f"It holds {len(page.items)} item(s). Undo brings it back.",
                              highlighted=None, dialog_id="remove-page-dialog"),
                 self.remove_page)

    def remove_page(self, page_id: str) -> None:
        if page_id == self.session.page.id:  # still the page the dialog asked about
            self.attempt(self.session.remove_page)

    def action_page_size(self) -> None:
        self.ask(ChoiceDialog("Page size", item_forms.PAGE_SIZE_CHOICES,
                              highlighted=self.session.page.size, dialog_id="page-size-dialog"),
                 self.choose_page_size)

    def choose_page_size(self, size: str) -> None:
        page = self.session.page
        if size != "custom":
            self.ask_which_pages(size, page.orientation)
            return
        self.ask(FormDialog("Custom page size", item_forms.custom_size_fields(page.width_mm,
                                                                             page.height_mm),
                            item_forms.parse_custom_size, dialog_id="custom-size-dialog"),
                 self.set_custom_size)

    def set_custom_size(self, size: dict) -> None:
        self.ask_which_pages("custom", self.session.page.orientation, size["width_mm"],
                             size["height_mm"])

    def ask_which_pages(self, size: str, orientation: str, width_mm: float | None = None,
                        height_mm: float | None = None) -> None:
        """In a project of several pages, ask whether the size is for every page or this one:
        `S` resized only the page on screen, and a calendar or an album made A5 kept eleven
        A4 pages (user-walk-9).  A card's inside may differ from its front, so both are
        offered; "Every page" is highlighted where every page now has this one's size."""
        session = self.session
        pages, page = session.project.pages, session.page
        others = {index for index, *_ in session.size_changes(
            size, orientation, width_mm, height_mm, every_page=True)} - {session.page_index}
        if not others:  # one page, or the others have the size already: nothing to ask
            self.attempt(session.set_page_size, size, orientation, width_mm, height_mm)
            return
        alike = all((other.width_mm, other.height_mm) == (page.width_mm, page.height_mm)
                    for other in pages)
        named = f"{width_mm:g} × {height_mm:g} mm" if size == "custom" else size
        self.ask(ChoiceDialog(
            f"Page size {named}", [(f"Every page ({len(pages)})", True),
                                   (f"This page only ({page.id})", False)],
            message="Each page keeps its own orientation." if size != "custom" else "",
            highlighted=alike, dialog_id="which-pages-dialog"),
            lambda every: self.attempt(self.resize_pages, size, orientation, width_mm,
                                       height_mm, every))

    def resize_pages(self, size: str, orientation: str, width_mm: float | None,
                     height_mm: float | None, every_page: bool) -> None:
        self.session.set_page_size(size, orientation, width_mm, height_mm,
                                   every_page=every_page)

    def action_toggle_orientation(self) -> None:
        """`o` turns the page on screen; in a project of several pages it asks, as `S` does,
        whether every page turns or this one (a calendar turned landscape kept eleven pages
        portrait, user-walk-10).  "Every page" is highlighted where every page has this one's
        orientation; nothing is asked where no other page would turn."""
        session = self.session
        turned = session.turned_orientation()
        others = {index for index, *_ in session.orientation_changes(
            turned, every_page=True)} - {session.page_index}
        if not others:
            self.attempt(session.set_orientation, turned)
            return
        pages, page = session.project.pages, session.page
        alike = all(other.orientation == page.orientation for other in pages)
        self.ask(ChoiceDialog(
            f"Turn to {turned}", [(f"Every page ({len(pages)})", True),
                                  (f"This page only ({page.id})", False)],
            message="Each page keeps its own size.", highlighted=alike,
            dialog_id="which-pages-dialog"),
            lambda every: self.attempt(self.turn_pages, turned, every))

    def turn_pages(self, orientation: str, every_page: bool) -> None:
        self.session.set_orientation(orientation, every_page=every_page)

    # -- files -------------------------------------------------------------------------------

    def action_save(self, then: Callable[[], object] | None = None) -> None:
        """Save, after asking first when another program changed the file since the editor
        read or saved it (an edit in a text editor, a `git checkout`): Ctrl+S replaced such
        changes without a word. `then` runs once the project is saved.  While room is
        searched for after an insert or a new page size, the save waits for it, as Ctrl+E
        does: saved at once, the file held the items piled up, the answers then came and
        marked the project unsaved again, and a user who saved and hung up had a file no
        settle leaves (user-walk-12a); a hang-up meanwhile still keeps the edits (recovery)."""
        if self.once_room_is_found("save", lambda: self.action_save(then)):
            return
        if not self.session.changed_on_disk():
            self.save_now(then)
            return
        self.ask_about_changed_file(
            "Since the editor opened or last saved {name}, another program changed it. Saving "
            "replaces those changes; the file as it is now stays as {name}.bak. Opened as it "
            "is now, the editor's unsaved edits and undo history go.",
            then=then, highlighted=None)

    def ask_about_changed_file(self, message: str, *, then=None, highlighted=None) -> None:
        """The question for a project file another program changed (Ctrl+S's, and the one
        `look_at_file` asks as soon as it sees the change): replace it, open it as it is
        now, or keep editing."""
        self.session.told_of_the_file()  # answered here: the timer does not ask it again
        name = printable(self.session.project.path.name)
        self.ask(ChoiceDialog(f"{name} was changed by another program",
                              [("Replace it with the editor's version", "replace"),
                               ("Open the file as it is now", "reload"),
                               ("Keep editing (save nothing)", None)],
                              message=message.format(name=name), highlighted=highlighted,
                              dialog_id="changed-on-disk-dialog"),
                 lambda choice: self.save_now(then) if choice == "replace"
                 else self.reload_from_disk())

    def look_at_file(self) -> None:
        """Every LOOK_AT_FILE_S: tell at once when another program (vim, `git checkout`, a
        script) changed or removed the project file, instead of at
        the next Ctrl+S, maybe an hour of edits later. Never in the middle of an edit: while a
        dialog or form is open, or an item is held (nudged, dragged), the look waits, and the
        change is told when the edit is done. Told once for each new state of the file."""
        session = self.session
        if session.project.path is None or not self.is_mounted \
                or self.app.screen_stack[-1] is not self or session.held_id is not None \
                or self.preview.dragging:
            return
        found = session.look_at_file()
        name = printable(session.project.path.name)
        if found == "gone":
            self.notify(f"{name} was removed or renamed by another program; Ctrl+S writes the "
                        "editor's version there again", title="Project file gone",
                        severity="warning", timeout=10)
        elif found == "changed":
            unsaved = session.unsaved
            self.ask_about_changed_file(
                "Another program changed {name} just now. " + (
                    "The editor has unsaved edits: replacing the file keeps it as it is now as "
                    "{name}.bak; opened as it is now, the editor's edits and undo history go."
                    if unsaved else "Nothing in the editor is unsaved: open it as it is now to "
                    "go on from their version (the undo history goes)."),
                highlighted=None if unsaved else "reload")

    def reload_from_disk(self) -> None:
        """The project as another program left it, in place of the editor's version."""
        try:
            self.session.reload()
        except FloatpageError as error:  # their version does not load: say why, keep ours
            self.notify(f"{error}\nThe editor's version is kept; mend the file, or replace "
                        "it with Ctrl+S", title="Not opened", severity="error", timeout=15)
            return
        self.notify(f"opened {self.session.project.path.name} as it is now", timeout=4)
        self.after_edit()

    def save_now(self, then: Callable[[], object] | None = None) -> None:
        """Save the pages edited since the last save as `floatpage settle` would leave them,
        so a saved file is a fixed point of it: saved after a nudge, the greeting card's
        picture was snapped back onto the page's centre line by the next settle, 1.8 mm from
        where the editor had it. The page on screen takes the same answer, and a nudge it
        takes back says so. Paused, the page is saved as it stands."""
        if self.running:
            selected = self.session.selected_id
            before = self.session.engine.positions().get(selected)
            self.session.settle_edited_pages()
            after = self.session.engine.positions().get(selected)
            if before is not None and after is not None \
                    and math.dist(before, after) >= SNAP_SAID_MM:
                self.notify(f"{selected} lined up {math.dist(before, after):.1f} mm, as "
                            "`floatpage settle` does: onto a line it nearly met, or clear of "
                            "the others; Shift+arrows move it 10 mm", timeout=5)
        try:
            path = self.session.save()
        except Exception as error:  # the work stays in the editor; say why and let them retry
            message = str(error) if isinstance(error, FloatpageError) else \
                f"{type(error).__name__}: {error}"
            self.notify(message, title="Not saved", severity="error", timeout=10)
            return
        self.notify(f"saved {path}", timeout=3)
        self.redraw()
        if then is not None:
            then()

    def action_export_pdf(self) -> None:
        if self.export_state:
            self.notify("an export is already running", severity="warning")
            return
        session = self.session
        if session.project.path is None:
            self.notify("save the project first; the PDF goes beside it", severity="warning")
            return
        if self.once_room_is_found("export", self.action_export_pdf):
            return
        from floatpage.typeset.render import check_pdf_output

        out = self.export_path or session.project.path.with_suffix(".pdf")
        try:
            check_pdf_output(session.project, out)
        except FloatpageError as error:
            # "name a new file" could not be followed in the editor, which had no name to ask
            # for: it asks for one now, and keeps it for the session's later exports
            folder = session.project.path.parent
            self.ask(FormDialog("Export the PDF to another file",
                                item_forms.export_fields(str(error),
                                                         item_forms.free_pdf_name(
                                                             session.project.path)),
                                item_forms.export_parser(folder, self.refuse_output),
                                dialog_id="export-dialog"),
                     self.export_to)
            return
        self.export_to(out)

    def own_pdfs(self) -> list[Path]:
        """The PDFs this project is exported to (NAME.pdf, and the file chosen for the
        session's exports): no pictures to insert into it."""
        path = self.session.project.path
        return [] if path is None else [path.with_suffix(".pdf")] + (
            [self.export_path] if self.export_path else [])

    def refuse_output(self, path: Path) -> None:
        """The export dialog's check: what render would refuse, as the dialog's error line."""
        from floatpage.typeset.render import check_pdf_output

        try:
            check_pdf_output(self.session.project, path)
        except FloatpageError as error:
            raise ValueError(str(error)) from None

    def export_to(self, out: Path) -> None:
        session = self.session
        try:
            project = session.finalize_for_export()
        except FloatpageError as error:
            self.notify(str(error), title="Export failed", severity="error", timeout=10)
            return
        self.after_edit()
        if out != session.project.path.with_suffix(".pdf"):
            self.export_path = out
        self.export_state = "exporting…"
        self.redraw()
        self.export_worker(project, out)

    @work(thread=True, exclusive=True, group="export")
    def export_worker(self, project, out: Path) -> None:
        """Typeset in a thread; only call_from_thread touches the UI from here."""
        def progress(*args, **kwargs) -> None:
            words = " ".join(str(arg) for arg in args) or ""
            self.app.call_from_thread(self.export_progress, words)

        try:
            from floatpage.typeset import render_pdf

            report = render_pdf(project, out, progress=progress)
        except FloatpageError as error:
            self.app.call_from_thread(self.export_done, None, str(error))
        except Exception as error:  # never a crash: the user keeps the editor and their work
            self.app.call_from_thread(self.export_done, None,
                                      f"{type(error).__name__}: {error}")
        else:
            self.app.call_from_thread(self.export_done, report, None)

    def export_progress(self, words: str) -> None:
        self.export_state = f"exporting: {words}" if words else "exporting…"
        self.redraw()

    def export_done(self, report, error: str | None) -> None:
        self.export_state = None
        if error is not None:
            self.notify(error, title="Export failed", severity="error", timeout=15)
        else:
            wrote = f"wrote {report.pdf} ({report.pages} page(s), {report.seconds:.1f} s)"
            if not report.warnings:
                self.notify(wrote, title="PDF exported", timeout=8)
            else:  # counted and never shown used to hide a missing 日本 (defect 11)
                shown = report.warnings[:EXPORT_WARNINGS_SHOWN]
                more = len(report.warnings) - len(shown)
                self.notify(wrote + "\n" + "\n".join(f"• {printable(warning)}" for warning in shown)
                            + (f"\n… and {more} more (`floatpage check` lists them all)"
                               if more > 0 else ""),
                            title="PDF exported, with warnings", severity="warning", timeout=20)
        self.redraw()

    # -- help and quitting ---------------------------------------------------------------------

    def action_help(self) -> None:
        self.app.push_screen(HelpScreen(id="help"))

    def action_quit(self) -> None:
        if not self.session.unsaved:
            self.app.exit()
            return
        self.ask(ChoiceDialog("Quit floatpage?", [("Save and quit", "save"),
                                                  ("Quit without saving", "discard"),
                                                  ("Keep editing", None)],
                              message="There are unsaved changes.", highlighted="save",
                              dialog_id="quit-dialog"),
                 self.finish_quit)

    def finish_quit(self, choice: str) -> None:
        if choice == "discard":
            self.app.exit()
        elif choice == "save" and not self.once_room_is_found(
                "save and quit", lambda: self.finish_quit("save")):
            self.action_save(then=lambda: None if self.session.unsaved else self.app.exit())
