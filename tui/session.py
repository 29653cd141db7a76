"""An editing session: the project, the page on screen, its physics engine and the undo history.

Every edit the editor offers is one method here, free of Textual, so the
screen stays a thin layer of key bindings and dialogs. Each edit records a
snapshot first (so undo restores positions too), changes the model, and tells
the engine; the engine owns the live positions while the physics runs, and
`sync_positions` copies them back into the model.
"""

from __future__ import annotations

import copy
import dataclasses
import hashlib
import itertools
import math
import os
from pathlib import Path

from floatpage.model.atomic_file import atomic_write
from floatpage.model.document import (
    Background, BlockItem, CalendarItem, ItemAnchor, Page, PictureItem, PointAnchor, Project,
    TextItem,
)
from floatpage.model.errors import FloatpageError
from floatpage.model.layout import copy_of, engine_for_page, settle_page, write_back
from floatpage.model.page_names import named_by_place, place_name, rename_by_place
from floatpage.model.page_sizes import page_dimensions
from floatpage.model.picture_files import is_merge_placeholder, read_header
from floatpage.model.save import save_project
from floatpage.physics import Engine
from floatpage.physics.params import page_margin
from floatpage.tui.clear_spaces import scaled_offset, scaled_size
from floatpage.tui.history import History, Snapshot
from floatpage.tui.insert_style import new_item_style
from floatpage.tui.page_resize import (
    kept_by, page_scale_of, resize_page, scale_follow_offsets, size_words,
)
from floatpage.tui.reading_order import reading_order, step_through
from floatpage.tui.region_edits import body_misfit

MIN_SIDE_MM = 3.0
# The item fields the physics reads (model.layout.engine_for_page): an edit of any other
# (words, colours, fonts, a calendar's month, another picture of the same shape) keeps the
# engine and its rest, as `floatpage settle` of the edited file moves nothing either
PHYSICAL_FIELDS = frozenset({"id", "x", "y", "w", "h", "decorative", "bleed", "anchor",
                             "group", "region"})
# How far an unmoved item's position as the engine has it may lie from the file's and still
# be the file's (one step of the saved 0.01 mm, and the float error of the sum)
ROUNDING_KEPT_MM = 0.0101


class EditError(FloatpageError):
    """An edit that cannot be done as asked; the message says why, for a notification."""


def file_digest(path: Path | None) -> str | None:
    """The file's content hash, or None when there is no such file to read."""
    try:
        return hashlib.sha256(path.read_bytes()).hexdigest() if path is not None else None
    except OSError:
        return None


def file_stamp(path: Path | None) -> tuple[int, int, int] | None:
    """What a cheap look at the file tells (size, modification time, inode), or None when
    there is no such file: a change to any of them is worth reading the file for."""
    try:
        found = path.stat() if path is not None else None
    except OSError:
        return None
    return (found.st_size, found.st_mtime_ns, found.st_ino) if found is not None else None


def picture_aspect(path: Path) -> float | None:
    """Height / width of a picture file as it prints, or None if Pillow cannot read it (the
    item keeps the default shape). A phone's portrait photo, stored sideways with an EXIF
    turn, got a landscape box: the PDF, which turns it upright, cut off its top and bottom."""
    header = read_header(path)
    width, height = header.size
    return height / width if not header.problem and width else None


def inside(centre: float, size: float, page: float) -> float:
    """A centre that keeps an item of ``size`` on a page of ``page`` (centred if it cannot)."""
    if size >= page:
        return page / 2
    return min(max(centre, size / 2), page - size / 2)


MAKE_ROOM_ATTEMPTS = 8
MAKE_ROOM_STEP = 0.9  # each attempt shrinks by this; 8 attempts reach 43 %


def needs_settling(page: Page, settings, engine: Engine) -> bool:
    """Whether a page has overlaps or items off it that `floatpage settle` would change.

    A settled file opens still (it is a fixed point of settle, issue 10); a page with 156
    overlaps used to open still too, and stayed so until an item was nudged.  A page too full
    for any layout without overlap, which settle keeps as it is, stays still as well."""
    quality = engine.quality()
    if not (quality.overlapping_pairs or quality.off_page):
        return False
    trial = copy_of(page)
    try:
        settle_page(trial, settings)
    except FloatpageError:  # items piled past what settle takes on: open it still, as it is
        return False
    return any((a.x, a.y) != (b.x, b.y) for a, b in zip(page.items, trial.items))


def finalize_as_shown(engine: Engine) -> None:
    """The no-overlap pass, lining the page up only if it had something to mend (see
    ``EditSession.finalize_for_export``)."""
    quality = engine.quality()
    engine.finalize(align=bool(quality.overlapping_pairs or quality.off_page))


def copy_into(picture: Path, folder: Path) -> Path:
    """Copy ``picture`` into ``folder`` under its own name (numbered if another file holds it);
    the same bytes already there are reused."""
    folder.mkdir(parents=True, exist_ok=True)
    data = picture.read_bytes()
    candidate, number = folder / picture.name, 1
    while candidate.exists():
        if candidate.is_file() and candidate.read_bytes() == data:
            return candidate
        number += 1
        candidate = folder / f"{picture.stem}-{number}{picture.suffix}"
    atomic_write(candidate, data, backup=False)
    return candidate


def layout_of(page: Page) -> dict[str, tuple[float, float]]:
    return {item.id: (item.x, item.y) for item in page.items}


def room_steps(page_scale: float = 1.0) -> list[float]:
    """The room search's shrinks, each applied after the one before fails: ``MAKE_ROOM_STEP``
    each time; after a new page size of the same shape, smaller, the page's own scale first
    (then steps on from it)."""
    steps = [MAKE_ROOM_STEP] * MAKE_ROOM_ATTEMPTS
    if page_scale < MAKE_ROOM_STEP:
        steps[0] = page_scale
    return steps


def refit(page: Page, request: "RoomRequest", scale: float) -> None:
    """The items a new page size made smaller to fit it, once the room search has shrunk the
    page's items by ``scale`` in all: at the page's own scale, their old size scaled as much
    (the new page is the old one scaled, every line kept); at any other, the size they were
    fitted to, scaled (past the page's own scale, cut to the page's width they stay one
    width, lined up, where their old widths scaled would be some 3 mm apart: the merge
    sample's texts, 120 and 110 mm wide, made A6).  Set whole, so that the room search's
    trials in steps and its answer at once agree."""
    if request.page_scale >= 1.0:
        return
    own = abs(scale - request.page_scale) < 1e-12
    for id_, w, h, fitted_w, fitted_h in request.fitted:
        item = page.item(id_)
        item.w, item.h = (scaled_size(item, min(fitted_w, w * scale) / scale,
                                      min(fitted_h, h * scale) / scale, scale) if own
                          else scaled_size(item, fitted_w, fitted_h, scale))


def shrink_items(page: Page, ids: frozenset[str] | None, scale: float) -> None:
    """Shrink the page's items of ``ids`` (all that take part, if None) by ``scale`` to make
    room; a follower shrunk with its target, or a member with its group's lead, comes closer
    by as much (but a space clear of the near-miss band stays clear: tui.clear_spaces), so
    that they shrink as one (sizes alone shrunk left a caption and its photo as far apart as
    ever, and after a smaller page size such a pair still reached past the page however small
    they got)."""
    shrunk = {item.id for item in page.items
              if not item.decorative and (ids is None or item.id in ids)}
    leads = {item.group: page.group_lead(item.group) for item in page.items if item.group}
    halves = {item.id: (item.w / 2, item.h / 2) for item in page.items}  # before the shrink
    for item in page.items:
        if item.id in shrunk:
            item.w, item.h = scaled_size(item, item.w, item.h, scale)

    def offset(value: float, axis: int, item, other) -> float:
        before = halves[item.id][axis] + halves[other.id][axis]
        after = ((item.w, item.h)[axis] + (other.w, other.h)[axis]) / 2
        return scaled_offset(value, before, after, scale)

    for item in page.items:
        if item.id in shrunk:
            anchor = item.anchor
            lead = leads.get(item.group)
            if isinstance(anchor, ItemAnchor) and anchor.to in shrunk:
                target = page.item(anchor.to)
                anchor.dx = offset(anchor.dx, 0, item, target)
                anchor.dy = offset(anchor.dy, 1, item, target)
            elif lead is not None and lead is not item and lead.id in shrunk:
                # a group shrinks as one, too (its lead stays where it is)
                item.x = lead.x + offset(item.x - lead.x, 0, item, lead)
                item.y = lead.y + offset(item.y - lead.y, 1, item, lead)


@dataclasses.dataclass(frozen=True)
class RoomRequest:
    """Room wanted for ``ids`` (None: every item) on a page, as the document stood."""

    version: int
    page_index: int
    ids: frozenset[str] | None
    # the items that kept the print-safe margin before the change, which the room found must
    # let them keep (issue 16): a turned greeting card left its picture 1.4 mm from the edge
    margin_kept: frozenset[str] = frozenset()
    # whether the page kept the gutter before a new page size: the room found keeps it too
    # where it fits (user-walk-11: the calendar made A6 kept 1.6-2.2 mm of its 3 mm gutter on
    # five pages, the room search having looked for zero overlap only)
    gutter_kept: bool = False
    # a new page size of the same shape, smaller: the scale of the page itself (A4 to A5:
    # 0.707); the room search tries it first (tui.page_resize.page_scale_of)
    page_scale: float = 1.0
    # the items the new size made smaller than they were, to fit it: (id, w, h as they were,
    # w, h as made); at the page's own scale they take their old size scaled, no larger
    fitted: tuple[tuple[str, float, float, float, float], ...] = ()


class EditSession:
    """The project being edited and everything needed to change it and undo the change."""

    def __init__(self, project: Project, *, seed: int = 0):
        self.seed = seed
        self.selected_id: str | None = None
        self.typed_when_lost: list[str] = []  # words in forms a lost terminal left unapplied
        self.open(project)

    def open(self, project: Project, page_id: str | None = None, page_index: int = 0) -> None:
        """Edit ``project`` as read from its file: nothing unsaved, no undo history, on the
        page ``page_id`` if it has one, else at ``page_index`` (or its last page)."""
        if not project.pages:
            width, height = page_dimensions("A4", "portrait")
            project.pages.append(Page(id="page-1", width_mm=width, height_mm=height))
        self.project = project
        ids = [page.id for page in project.pages]
        self.page_index = ids.index(page_id) if page_id in ids else min(page_index, len(ids) - 1)
        if self.selected_id not in {item.id for item in self.page.items}:
            self.selected_id = None
        self.pages_edited: set[str] = set()  # page ids a save settles (settle_edited_pages)
        self.history = History()
        self.version = 0  # the document state: every edit makes a new one, undo returns to one
        self.saved_version = 0
        # The file as the editor last read or wrote it: a save checks that no other program
        # (a text editor, `git checkout`) changed it meanwhile; the lock keeps out only
        # floatpage's own writers, and Ctrl+S replaced such changes without a word.
        self.disk_digest = file_digest(project.path)
        self.disk_stamp = self.stamp_seen = file_stamp(project.path)  # see `look_at_file`
        self.disk_told: str | None = None  # the digest (or "gone") `look_at_file` last told of
        self.read_text = project.source_text  # see `save`
        self._versions = itertools.count(1)
        self.held_id: str | None = None
        self.status_note: str | None = None  # what a release or a page size did, in words
        self.room_wanted: list[RoomRequest] = []  # see want_room
        self.engine: Engine = self._build_engine()

    # -- what is on screen ---------------------------------------------------------------

    @property
    def page(self) -> Page:
        return self.project.pages[self.page_index]

    @property
    def unsaved(self) -> bool:
        return self.version != self.saved_version

    def mark_unsaved(self) -> None:
        """The project differs from its file although no edit was made here (a recovery)."""
        self.saved_version = -1

    @property
    def selected_item(self):
        if self.selected_id is None:
            return None
        try:
            return self.page.item(self.selected_id)
        except KeyError:
            return None

    def _build_engine(self, check: bool = True) -> Engine:
        """The page's engine, at rest as saved; a page that is not sound as saved starts
        settling at once rather than waiting for a nudge (see ``needs_settling``).  Without
        ``check``, for a caller that reheats it anyway: the check settles a copy of the page,
        0.2-1.6 s of an insert or a turned page spent on an answer never used."""
        settings = dataclasses.replace(self.project.physics, seed=self.seed)
        engine = engine_for_page(self.page, settings)
        self.mark_rest(engine)
        if check and needs_settling(self.page, settings, engine):
            engine.reheat()
        return engine

    def mark_rest(self, engine: Engine) -> None:
        """Note where the new engine has the page's items (rounded as a save writes them)
        beside where the model has them, for `sync_positions`."""
        page = self.page
        resting = self.resting_copy(engine)
        self.rest_marks = (page.id, {
            item.id: ((done.x, done.y), (item.x, item.y))
            for item, done in zip(page.items, resting.items)})

    def resting_copy(self, engine: Engine | None = None) -> Page:
        """A copy of the page with the engine's positions (the session's, or ``engine``'s),
        rounded as a save writes them."""
        page = copy_of(self.page)
        write_back(page, self.engine if engine is None else engine)
        return page

    def settle_copy(self, page: Page) -> None:
        """Settle a page (a copy: it is changed) as `floatpage settle` does, with the
        project's own settings, so its answer is the file's fixed point."""
        settle_page(page, self.project.physics)

    def adopt_layout(self, page: Page) -> bool:
        """Take the positions of a settled copy of the page, if they differ from the page's
        own (rounded as a save writes them); the engine starts from them, at rest. Returns
        whether they differed."""
        settled = {item.id: item for item in page.items}
        if all(settled[id_].x == x and settled[id_].y == y
               for id_, (x, y) in layout_of(self.resting_copy()).items() if id_ in settled):
            return False
        for item in self.page.items:  # a hard anchor as write_back left it, with its item
            if item.id in settled:
                done = settled[item.id]
                item.x, item.y, item.anchor = done.x, done.y, done.anchor
        self.engine = self._build_engine(check=False)
        return True

    def settle_edited_pages(self) -> None:
        """Settle every page edited since the last save as `floatpage settle` would, the
        current one through its engine (it takes the answer, at rest)."""
        self.end_move()
        current = self.page.id
        for page in self.project.pages:
            if page.id not in self.pages_edited:
                continue
            if page.id == current:
                settled = self.resting_copy()
                self.settle_copy(settled)
                self.adopt_layout(settled)
            else:
                self.settle_copy(page)
        self.pages_edited.clear()

    def sync_positions(self) -> None:
        """Copy the engine's live positions into the model's items.

        An item the engine has not moved since it was built keeps the model's own position:
        a follower stands at its target plus its offset, which can round 0.01 mm away from
        the position the file says (the album's captions: 76.44 + 36.36 against 112.81), and
        Ctrl+S on a project nobody had changed rewrote it, as did undoing every edit."""
        page = self.page
        write_back(page, self.engine)
        page_id, marks = self.rest_marks
        if page_id != page.id:
            return
        for item in page.items:
            mark = marks.get(item.id)
            if mark is None or mark[0] != (item.x, item.y) or mark[1] == mark[0] \
                    or max(abs(a - b) for a, b in zip(*mark)) > ROUNDING_KEPT_MM \
                    or isinstance(item.anchor, PointAnchor) and item.anchor.hard:
                continue
            item.x, item.y = mark[1]

    def reading_order(self) -> list[str]:
        self.sync_positions()
        return reading_order(self.page.items)

    def select_step(self, step: int) -> str | None:
        self.select(step_through(self.reading_order(), self.selected_id, step))
        return self.selected_id

    def select(self, item_id: str | None) -> None:
        """Select an item (None: nothing), letting go of the held one first."""
        self.end_move()
        self.selected_id = item_id

    # -- history ---------------------------------------------------------------------------

    def _snapshot(self, label: str) -> Snapshot:
        """The document at rest. A held item is let go first: every edit, undo and redo takes
        a snapshot, so a move ends here before anything else changes the page, and the
        editor's commands need not each remember to end it."""
        self.end_move()
        self.sync_positions()
        return Snapshot.take(label, self.project.pages, self.page_index, self.selected_id,
                             self.version)

    def checkpoint(self, label: str) -> None:
        """Record the state before an edit; the edit makes a new (unsaved) document state."""
        self.history.record(self._snapshot(label))
        self.version = next(self._versions)
        self.pages_edited.add(self.page.id)

    def _restore(self, snapshot: Snapshot) -> None:
        self.held_id = None
        self.project.pages[:] = snapshot.pages  # a fresh copy
        self.page_index = min(snapshot.page_index, len(self.project.pages) - 1)
        self.selected_id = snapshot.selected_id
        self.version = snapshot.version
        self.engine = self._build_engine()
        self.pages_edited.add(self.page.id)

    def undo(self) -> str:
        """Return to the state before the last edit; the name of the edit undone."""
        if not self.history.undo_stack:
            history = self.history
            if history.dropped:  # "nothing to undo" read as "back where I began", unsaved
                raise EditError(f"nothing more to undo: the editor keeps the last "
                                f"{history.limit} edits, and {history.dropped} came before them")
            raise EditError("nothing to undo")
        label = self.history.undo_stack[-1].label  # the edit that left this state
        self._restore(self.history.undo(self._snapshot(label)))
        return label

    def redo(self) -> str:
        """Do the last undone edit again; its name (each snapshot keeps the edit's name, so
        undo and redo of one edit both speak of it)."""
        if not self.history.redo_stack:
            raise EditError("nothing to redo")
        label = self.history.redo_stack[-1].label
        self._restore(self.history.redo(self._snapshot(label)))
        return label

    # -- ids and placement -------------------------------------------------------------------

    def new_id(self, stem: str) -> str:
        """``stem-N`` with the least N that no item or page has."""
        taken = self.project.all_item_ids() | {page.id for page in self.project.pages}
        for number in itertools.count(1):
            candidate = f"{stem}-{number}"
            if candidate not in taken:
                return candidate
        raise AssertionError("unreachable")

    def default_size(self, kind: str) -> tuple[float, float]:
        """A size that reads well on this page: a fraction of its shorter side."""
        short = min(self.page.width_mm, self.page.height_mm)
        return {"text": (0.45 * short, 0.15 * short), "picture": (0.4 * short, 0.3 * short),
                "block": (0.2 * short, 0.2 * short),
                "calendar": (0.5 * short, 0.38 * short)}[kind]

    # -- item edits --------------------------------------------------------------------------

    def insert_item(self, item) -> str:
        """Insert an item near the page centre (its own x, y if given); the others make way."""
        if item.id in self.project.all_item_ids():
            raise EditError(f'the id "{item.id}" is already used')
        self.checkpoint(f"insert {item.id}")
        margin_kept, gutter_kept = kept_by(self.engine)
        self.page.items.append(item)
        if not item.decorative:
            self.want_room(frozenset({item.id}), margin_kept | {item.id}, gutter_kept=gutter_kept)
        self.engine = self._build_engine(check=False)
        self.engine.reheat()
        self.selected_id = item.id
        return item.id

    def want_room(self, ids: frozenset[str] | None = None,
                  margin_kept: frozenset[str] = frozenset(),
                  page_index: int | None = None, gutter_kept: bool = False,
                  page_scale: float = 1.0,
                  fitted: tuple[tuple[str, float, float, float, float], ...] = ()) -> None:
        """Ask for room for the items ``ids`` (all that take part, if None) after an insert or
        a page change (of the page on screen, or of ``page_index``): the caller runs
        ``room_scale`` on a copy of the page, off the UI thread, and hands the answer to
        ``make_room`` (issue 11: a fair start).  Run in the key's answer, it froze the editor
        for 0.8-2.3 s on an insert and 2.6-5.6 s on `o` (the calendar, load 7)."""
        index = self.page_index if page_index is None else page_index
        self.room_wanted.append(RoomRequest(self.version, index, ids, margin_kept,
                                            gutter_kept, page_scale, fitted))

    def room_scale(self, page: Page, request: "RoomRequest") -> float:
        """How much the items of ``request`` must shrink for ``page`` (a copy: it is changed)
        to have a layout without overlap, with the gutter where the page kept it before
        (``request.gutter_kept``; where no attempt keeps it, the least shrink without
        overlap), tried headless with `floatpage settle`'s own code; 1.0: not at all.  Reads
        nothing else of the session's, so it may run in a thread."""
        settings = dataclasses.replace(self.project.physics, seed=self.seed)
        scale, sound = 1.0, None
        for step in room_steps(request.page_scale):
            trial = copy_of(page)
            settle_page(trial, settings, max_rounds=3)
            engine = engine_for_page(trial, settings)
            quality = engine.quality()
            in_margin = {engine.ids[k] for k in quality.in_margin} & request.margin_kept
            if not (quality.overlapping_pairs or quality.off_page or in_margin):
                if not request.gutter_kept or quality.gutter_kept:
                    return scale
                sound = scale if sound is None else sound
            shrink_items(page, request.ids, step)
            scale *= step
            refit(page, request, scale)
        # no gutter within reach: the least shrink without overlap, not the most tried
        return scale if sound is None else sound

    def make_room(self, request: "RoomRequest", scale: float) -> bool:
        """Shrink the items of ``request`` by ``scale`` and start the physics again, if the
        document is still the one it was asked for (an edit since leaves the page as it is:
        its own rest mends what it can).  Returns whether it did."""
        if scale >= 1.0 or request.version != self.version or self.held_id is not None:
            return False
        if request.page_index != self.page_index:  # another page resized with this one
            page = self.project.pages[request.page_index]
            shrink_items(page, request.ids, scale)
            refit(page, request, scale)
            self.pages_edited.add(page.id)
            if self.saved_version == self.version:
                self.mark_unsaved()
            return True
        self.sync_positions()
        shrink_items(self.page, request.ids, scale)
        refit(self.page, request, scale)
        if self.saved_version == self.version:  # saved meanwhile: this is a change to save
            self.mark_unsaved()
        self.engine = self._build_engine(check=False)
        self.engine.reheat()
        self.pages_edited.add(self.page.id)
        return True

    def make_item(self, kind: str, **fields):
        """A new item of `kind` with a fresh id, at the page centre, in the style of the
        selected item of its kind or of the page's items of its kind (`insert_style`), else
        at the default size; ``fields`` (what the insert form asked) override the style."""
        w, h = self.default_size(kind)
        aspect = None
        if kind == "picture" and fields.get("path"):
            aspect = picture_aspect(self.project.base_dir / fields["path"])
            if aspect:
                h = w * aspect
        style = {"w": w, "h": h,
                 **new_item_style(kind, self.page, self.selected_item, aspect), **fields}
        fit = min(1.0, self.page.width_mm / style["w"], self.page.height_mm / style["h"])
        style["w"], style["h"] = style["w"] * fit, style["h"] * fit
        cls = {"text": TextItem, "picture": PictureItem, "block": BlockItem,
               "calendar": CalendarItem}[kind]
        return cls(id=self.new_id(kind), x=self.page.width_mm / 2, y=self.page.height_mm / 2,
                   z=max((i.z for i in self.page.items), default=0), **style)

    def new_item_look(self, kind: str) -> dict:
        """The look a new item of ``kind`` would take (`insert_style`), for the insert form
        to show: a form showing the defaults would give them back and undo the style."""
        return new_item_style(kind, self.page, self.selected_item)

    def relative_picture_path(self, path: str | Path) -> str:
        """The path to write for a picture the user picked: relative when it is inside the
        project's folder; otherwise a copy in the folder's `pictures/` (a project reads only
        its own folder, issue 12), unless the project allows outside files.  A file the
        loader would refuse (a text named .jpg, a folder, a 200-megapixel PNG) is refused
        here, with the loader's words: saved, it made a project no command would open."""
        path = Path(path).expanduser().resolve()
        header = read_header(path)
        if header.problem:
            raise EditError(f'"{path.name}" {header.problem}' +
                            (f" ({header.hint})" if header.hint else ""))
        base = self.project.base_dir.resolve()
        try:
            return str(path.relative_to(base))
        except ValueError:
            pass
        if self.project.allow_outside_files:
            return os.fspath(path)
        return str(copy_into(path, base / "pictures").relative_to(base))

    def typed_picture_path(self, typed: str) -> str:
        """The path to write for a picture path typed in the edit form (relative to the
        project's folder, or a full path; `relative_picture_path` then keeps it inside the
        folder); ValueError names the file it looked at and what to do, when it is missing,
        unreadable or not a picture (the form shows it and stays open)."""
        if not typed:
            raise ValueError("type the picture's file path, e.g. pictures/photo.jpg")
        if is_merge_placeholder(typed):  # a merge template's, filled per record (as loaded)
            return typed
        full = (self.project.base_dir / Path(typed).expanduser()).absolute()
        header = read_header(full)
        if header.problem:
            raise ValueError(f"{full} {header.problem}" + (f": {header.hint}" if header.hint
                                                            else ""))
        try:
            return self.relative_picture_path(full)
        except (EditError, OSError) as error:  # e.g. a copy into pictures/ that failed
            raise ValueError(f"{full}: {error}") from None

    def delete_selected(self) -> str:
        """Delete the selected item; its followers stay where they are, free.  Returns what
        the editor says of it (a caption freed from its deleted photo used to go unsaid)."""
        item = self._require_selected()
        self.checkpoint(f"delete {item.id}")
        before = reading_order(self.page.items)
        followers = [i for i in self.page.items
                     if isinstance(i.anchor, ItemAnchor) and i.anchor.to == item.id]
        for follower in followers:
            follower.anchor = None
        self.page.items.remove(item)
        if item.group:  # the group may lose its lead: the rest follow a new one
            self.rebuild_engine()
        else:
            self.engine.delete(item.id)  # the engine's edits reheat it themselves
        # the item after it in reading order (or before it, if it was the last): the selection
        # stays where the user was working; it jumped to the page's first item
        place = before.index(item.id)
        rest = before[:place] + before[place + 1:]
        self.selected_id = rest[min(place, len(rest) - 1)] if rest else None
        freed = ", ".join(f'"{follower.id}"' for follower in followers)
        # the group's anchor went with its lead, as unsaid as a freed caption was: a moved
        # group is anchored by its lead, so deleting that member let the rest float away
        unanchored = (f'; group "{item.group}" is no longer anchored'
                      if item.group and isinstance(item.anchor, PointAnchor)
                      and self.page.group_members(item.group) else "")
        return (f'deleted "{item.id}"'
                + (f"; {freed} no longer follow{'s' if len(followers) == 1 else ''} it"
                   if followers else "") + unanchored + " (Ctrl+Z brings it back)")

    def begin_move(self, item_id: str) -> None:
        """Hold an item (it pushes the others and is not pushed) for a move or a drag."""
        if self.held_id == item_id:
            return
        group = self.page.item(item_id).group  # the user moved a member, maybe not the lead
        self.checkpoint(f'move group "{group}"' if group else f"move {item_id}")  # lets go of
        # any other held item first
        self.held_id = item_id
        self.engine.hold(item_id)

    def mover_of(self, item_id: str) -> str:
        """The item a move of ``item_id`` moves: its group's lead for a member of a group (the
        group is one body, so moving any member moves all of it), else the item itself."""
        item = self.page.item(item_id)
        lead = self.page.group_lead(item.group) if item.group else None
        return lead.id if lead is not None else item_id

    def move_to(self, item_id: str, x_mm: float, y_mm: float) -> None:
        """Hold the item at (x, y), kept inside the page: a held key (or a drag) past the edge
        used to carry the item, and then its anchor, off the page (defect 10).  A member of a
        group moves its whole group (by its lead) so that it lands at (x, y)."""
        item_id, x_mm, y_mm = self._move_target(item_id, x_mm, y_mm)
        self.begin_move(item_id)
        self.engine.move(item_id, x_mm, y_mm)

    def _move_target(self, item_id: str, x_mm: float, y_mm: float) -> tuple[str, float, float]:
        """The item a move of ``item_id`` to (x, y) moves, and where, kept inside the page and
        the regions of the items it moves."""
        lead_id = self.mover_of(item_id)
        if lead_id != item_id:
            positions = self.engine.positions()
            (x, y), (lead_x, lead_y) = positions[item_id], positions[lead_id]
            item_id, x_mm, y_mm = lead_id, x_mm - x + lead_x, y_mm - y + lead_y
        item = self.page.item(item_id)
        x_mm, y_mm = (inside(x_mm, item.w, self.page.width_mm),
                      inside(y_mm, item.h, self.page.height_mm))
        # A region's edges are walls for its items, as the page's are: a held item (or a
        # group, by any member confined to a region) stays inside, where the engine used to
        # carry it out, push the others aside, and float it back when let go.
        members = self.page.group_members(item.group) if item.group else [item]
        confined = [member for member in members if member.region]
        if confined:
            positions = self.engine.positions()
            lead_x, lead_y = positions[item_id]
            for member in confined:
                region = self.page.region(member.region)
                mx, my = positions[member.id]
                to_x, to_y = x_mm + mx - lead_x, y_mm + my - lead_y
                x_mm += region.left + inside(to_x - region.left, member.w, region.w) - to_x
                y_mm += region.top + inside(to_y - region.top, member.h, region.h) - to_y
        return item_id, x_mm, y_mm

    def nudge(self, dx_mm: float, dy_mm: float) -> None:
        """Move the selected item a step; refused, with no edit made, when the page's edge
        leaves it no room that way (a full-width band nudged sideways used to be marked
        unsaved although nothing moved)."""
        item = self._require_selected()
        x, y = self.engine.positions()[item.id]
        mover, to_x, to_y = self._move_target(item.id, x + dx_mm, y + dy_mm)
        if self.held_id != mover and (to_x, to_y) == self.engine.positions()[mover]:
            edge = f'its region "{item.region}"' if item.region else "the page"
            raise EditError(f"{item.id} is at the edge of {edge}: no room to move that way")
        self.move_to(item.id, x + dx_mm, y + dy_mm)

    def end_move(self) -> None:
        """Let go of the held item; an anchored item is re-anchored where it was put, and a
        free one is anchored there, as `a` would (a spring, γ 1): let go, the others pushed it
        back, often farther than it was moved (20 mm of a 20 mm move among twelve blocks), and
        a user could not make an item stay without knowing `a`.  `u` lets it float again;
        Ctrl+Z undoes the move and its anchor as one edit (both follow the move's checkpoint).
        A decorative item is not pushed, so it needs no anchor."""
        item_id, self.held_id = self.held_id, None
        if item_id is None or item_id not in self.engine.ids:
            return
        self.engine.release(item_id)
        self.sync_positions()
        item = self.page.item(item_id)
        if item.anchor is None and not item.decorative:
            item.anchor = PointAnchor(x=item.x, y=item.y, gamma=1.0)
            self.engine.anchor_point(item.id, item.x, item.y, gamma=1.0)
            moved = f'group "{item.group}"' if item.group else item.id
            self.status_note = f"{moved} anchored where you put it (+) · u lets it float again"
        elif isinstance(item.anchor, PointAnchor):
            item.anchor.x, item.anchor.y = item.x, item.y
            self.engine.anchor_point(item.id, item.x, item.y, gamma=item.anchor.gamma,
                                     hard=item.anchor.hard)
        elif isinstance(item.anchor, ItemAnchor):
            target = self.page.item(item.anchor.to)
            item.anchor.dx, item.anchor.dy = item.x - target.x, item.y - target.y
            self.engine.anchor_to(item.id, target.id, item.anchor.dx, item.anchor.dy)

    def resize_selected(self, fx: float, fy: float) -> tuple[float, float]:
        """Scale the selected item's width by fx and height by fy; a locked picture scales both."""
        item = self._require_selected()
        if isinstance(item, PictureItem) and item.lock_aspect and fx != fy:
            fx = fy = fx if fx != 1 else fy
        w = min(max(item.w * fx, MIN_SIDE_MM), self.page.width_mm)
        h = min(max(item.h * fy, MIN_SIDE_MM), self.page.height_mm)
        if isinstance(item, PictureItem) and item.lock_aspect:
            scale = min(w / item.w, h / item.h) if fx >= 1 else max(w / item.w, h / item.h)
            w, h = item.w * scale, item.h * scale
        self.checkpoint(f"resize {item.id}")
        page = self.page
        followed = item.group or isinstance(item.anchor, ItemAnchor) or any(
            isinstance(other.anchor, ItemAnchor) and other.anchor.to == item.id
            for other in page.items)
        if not followed:
            item.w, item.h = w, h
            self.engine.resize(item.id, w, h)
            return w, h
        # A caption keeps its distance from the photo it follows, as on a new page size: its
        # offset between centres kept, a photo grown with `+` came down over its caption, and
        # neither the physics nor `check` saw it (one body: they never part)
        self.sync_positions()
        old_sizes = {other.id: (other.w, other.h) for other in page.items}
        item.w, item.h = w, h
        scale_follow_offsets(page, old_sizes, 1.0, 1.0)
        self.rebuild_engine(sync=False)
        return w, h

    def update_item(self, item_id: str, changes: dict, *, label: str | None = None) -> None:
        """Set fields of an item (text, font, colour, decorative, anchor gamma...) in one edit,
        undone as ``label`` ("edit ITEM" unless given)."""
        item = self.page.item(item_id)
        gamma = changes.pop("gamma", None)
        changes = {key: value for key, value in changes.items() if getattr(item, key) != value}
        gamma_changes = (gamma is not None and isinstance(item.anchor, PointAnchor)
                         and item.anchor.gamma != gamma)
        if not changes and not gamma_changes:
            return
        self.refuse_bad_group_or_region(item, changes)
        self.checkpoint(label or f"edit {item_id}")
        if "path" in changes and isinstance(item, PictureItem) \
                and changes.get("lock_aspect", item.lock_aspect):
            aspect = picture_aspect(self.project.base_dir / changes["path"])
            if aspect:  # another photo's shape, on the same area of paper
                w = math.sqrt(item.w * item.h / aspect)
                scale = min(1.0, 0.9 * self.page.width_mm / w,
                            0.9 * self.page.height_mm / (w * aspect))
                changes["w"], changes["h"] = w * scale, w * aspect * scale
        resized = "w" in changes or "h" in changes
        if resized:  # followers keep their distance, as `resize_selected` keeps it
            self.sync_positions()
            old_sizes = {other.id: (other.w, other.h) for other in self.page.items}
        for key, value in changes.items():
            setattr(item, key, value)
        if gamma_changes:
            item.anchor.gamma = gamma
        if resized:
            scale_follow_offsets(self.page, old_sizes, 1.0, 1.0)
        if gamma_changes or not changes.keys().isdisjoint(PHYSICAL_FIELDS):
            self.rebuild_engine(sync=not resized)
        # else: words, colours, fonts, another picture of the same shape change no body the
        # physics moves, so nothing is reheated: a price changed on the flyer reheated the
        # page, and the save's settle moved every item up to 9 mm (user-walk-9)

    def refuse_bad_group_or_region(self, item, changes: dict) -> None:
        """Raise EditError for a group or region the project file could not hold (the loader's
        rules, model.project_file): a region the page lacks or the item does not fit, a group
        with two anchors, or a member that follows an item outside its group."""
        region_id = changes.get("region", item.region)
        misfit = self.page.region_misfit(item, region_id) if region_id else None
        if misfit:
            raise EditError(f'"{item.id}" {misfit}')
        if region_id and ("region" in changes or "group" in changes):
            # the item's body (its group, its followers) needs a place inside its walls
            # (region_edits.shift_room): measured as the edit would leave it, then the item
            # put back as it was
            before = {key: getattr(item, key) for key in ("region", "group")}
            for key in before:
                setattr(item, key, changes.get(key, before[key]))
            try:
                misfit = body_misfit(self.page, item, self.engine.margin_mm)
            finally:
                for key, value in before.items():
                    setattr(item, key, value)
            if misfit:
                raise EditError(misfit)
        group = changes.get("group", item.group)
        if not group or group == item.group:
            return
        members = self.page.group_members(group)
        if isinstance(item.anchor, ItemAnchor) and item.anchor.to not in {m.id for m in members}:
            raise EditError(f'"{item.id}" follows "{item.anchor.to}"; remove that anchor (u) '
                            f'before it joins group "{group}"')
        pinned = [m for m in members if isinstance(m.anchor, PointAnchor)]
        if isinstance(item.anchor, PointAnchor) and pinned:
            raise EditError(f'group "{group}" is anchored already (by "{pinned[0].id}"); remove '
                            f'"{item.id}"\'s anchor (u) before it joins')

    def set_group(self, group: str) -> str:
        """Put the selected item in ``group`` ("" takes it out); returns what happened, in
        words."""
        item = self._require_selected()
        group = group.strip()
        if group == item.group:
            return f'"{item.id}" is already ' + (f'in group "{group}"' if group else "in no group")
        # undone as "group ITEM": "undid edit picture-1" did not say which edit (user-walk-10)
        self.update_item(item.id, {"group": group}, label=f"group {item.id}")
        return (f'"{item.id}" joined group "{group}": its members move as one' if group
                else f'"{item.id}" left its group')

    def rebuild_engine(self, *, sync: bool = True) -> None:
        """Rebuild the engine from the model after an edit the engine has no call for;
        ``sync=False`` keeps positions the edit itself wrote into the model."""
        if sync:
            self.sync_positions()
        self.held_id = None
        self.engine = self._build_engine()
        self.engine.reheat()

    def anchor_here(self) -> None:
        """Anchor the selected item where it is; for a member of a group, the group's anchor,
        which its lead holds (Page.group_lead)."""
        item = self._require_selected()
        if item.group:
            item = self.page.item(self.mover_of(item.id))
        self.checkpoint(f"anchor {item.id}")
        self.sync_positions()
        gamma = item.anchor.gamma if isinstance(item.anchor, PointAnchor) else 1.0
        item.anchor = PointAnchor(x=item.x, y=item.y, gamma=gamma)
        self.engine.unanchor(item.id)
        self.engine.anchor_point(item.id, item.x, item.y, gamma=gamma)

    def anchor_refusal(self, item, target) -> str | None:
        """Why ``item`` cannot follow ``target``, in words, or None when it can: the anchor
        dialog offers only the items this accepts (it offered the item's own followers, and
        choosing one was refused only afterwards)."""
        if target.id == item.id:
            return "an item cannot be anchored to itself"
        if item.group and target.group != item.group:
            return (f'"{item.id}" is in group "{item.group}", which moves as one: '
                    f'anchor the group with a, or take "{item.id}" out of it (G)')
        chain, current = {item.id}, target
        while isinstance(current.anchor, ItemAnchor):
            if current.anchor.to in chain or current.id in chain:
                return f'"{target.id}" already follows "{item.id}"; that would be a cycle'
            chain.add(current.id)
            current = self.page.item(current.anchor.to)
        if current.id == item.id:
            return f'"{target.id}" already follows "{item.id}"; that would be a cycle'
        return None

    def anchor_targets(self) -> tuple[list[str], str]:
        """The items on this page the selected item may follow, and a note in words on those
        left out (its followers, which would make a cycle; items outside its group)."""
        item = self._require_selected()
        accepted, followers, outside = [], [], []
        for other in self.page.items:
            if other.id == item.id:
                continue
            reason = self.anchor_refusal(item, other)
            if reason is None:
                accepted.append(other.id)
            else:
                (outside if item.group and other.group != item.group else followers).append(
                    other.id)
        notes = []
        if followers:
            notes.append(f"not offered: {', '.join(followers)}, which already follow"
                         f"{'s' if len(followers) == 1 else ''} {item.id} (a cycle)")
        if outside:
            notes.append(f'only group "{item.group}" is offered: the group moves as one '
                         "(a anchors it, G takes an item out)")
        return accepted, "; ".join(notes)

    def anchor_to(self, target_id: str) -> None:
        item = self._require_selected()
        target = self.page.item(target_id)
        reason = self.anchor_refusal(item, target)
        if reason:
            raise EditError(reason)
        self.checkpoint(f"anchor {item.id} to {target_id}")
        self.sync_positions()
        item.anchor = ItemAnchor(to=target_id, dx=item.x - target.x, dy=item.y - target.y)
        self.engine.unanchor(item.id)
        self.engine.anchor_to(item.id, target_id, item.anchor.dx, item.anchor.dy)

    def unanchor(self) -> None:
        """Take the selected item's anchor off; for a member of a group whose anchor another
        member holds, the group's (as `a` on any member anchors the group).  An item still held
        from arrow keys is let go first, as every edit lets go of it: its release anchors it
        where it was put, and `u` typed right after the arrows (within RELEASE_AFTER_S, as keys
        come over SSH) said "not anchored" while the status line said it was."""
        self.end_move()
        item = self._require_selected()
        if item.anchor is None and item.group:
            item = self.page.item(self.mover_of(item.id))
        if item.anchor is None:
            raise EditError(f'"{item.id}" is not anchored')
        self.checkpoint(f"unanchor {item.id}")
        item.anchor = None
        self.engine.unanchor(item.id)

    def set_background(self, background: Background | None) -> None:
        self.checkpoint("background")
        self.page.background = background

    def _require_selected(self):
        item = self.selected_item
        if item is None:
            raise EditError("select an item first (Tab)")
        return item

    # -- pages -------------------------------------------------------------------------------

    def switch_page(self, step: int) -> None:
        self.end_move()
        self.sync_positions()
        self.page_index = (self.page_index + step) % len(self.project.pages)
        self.selected_id = None
        self.engine = self._build_engine()

    def add_page(self) -> str:
        """A page after the current one, named by its place (`model.page_names`): the pages
        the editor named after it move up a number, the ones the user named keep theirs."""
        self.checkpoint("add page")
        current = self.page
        followers = named_by_place(self.project.pages)
        # named by its place; rename_by_place below settles the name (and renumbers the rest)
        page = Page(id=place_name(self.page_index + 2), size=current.size,
                    orientation=current.orientation,
                    width_mm=current.width_mm, height_mm=current.height_mm)
        self.project.pages.insert(self.page_index + 1, page)
        followers.add(id(page))
        self._renamed(rename_by_place(self.project.pages, followers,
                                      self.project.all_item_ids()))
        self.page_index += 1
        self.selected_id = None
        self.engine = self._build_engine()
        return page.id

    def remove_page(self) -> str:
        if len(self.project.pages) == 1:
            raise EditError("a project keeps at least one page")
        self.checkpoint(f"remove page {self.page.id}")
        followers = named_by_place(self.project.pages)
        removed = self.project.pages.pop(self.page_index)
        self.pages_edited.discard(removed.id)
        self._renamed(rename_by_place(self.project.pages, followers,
                                      self.project.all_item_ids()))
        self.page_index = min(self.page_index, len(self.project.pages) - 1)
        self.selected_id = None
        self.engine = self._build_engine()
        return removed.id

    def _renamed(self, renamed: dict[str, str]) -> None:
        """The pages a save settles keep that mark under their new names."""
        self.pages_edited = {renamed.get(page_id, page_id) for page_id in self.pages_edited}

    def set_page_size(self, size: str, orientation: str, width_mm: float | None = None,
                      height_mm: float | None = None, *, label: str = "page size",
                      every_page: bool = False) -> None:
        """Change size and orientation; items keep their relative place on the page.

        A named size takes the orientation; a custom one takes width and height (default: the
        page's own), and its orientation follows from them.  ``every_page``: every page of
        the project takes the size (a calendar's or an album's pages are one size; `S` on a
        12-page calendar resized January only, user-walk-9), each in its own orientation for
        a named size; one undo step, and room is searched for on each page changed.
        """
        changes = [(index, size, own, width, height) for index, own, width, height
                   in self.size_changes(size, orientation, width_mm, height_mm,
                                        every_page=every_page)]
        self._resize_pages(changes, label, lambda width, height:
                           f"made {size_words(size, width, height)}")

    def _resize_pages(self, changes: list[tuple[int, str, str, float, float]], label: str,
                      done_words) -> None:
        """Give each page its (index, size, orientation, width, height): one undo step, its
        items moved in proportion, room searched for on each page changed, each marked for
        the save's settle.  ``done_words(width, height)`` says what became of several pages
        ("made A6", "turned landscape")."""
        pages = self.project.pages
        if not changes:
            return
        self.checkpoint(label)
        too_large: list[str] = []
        for index, size, own, width, height in changes:
            page = pages[index]
            margin_kept, gutter_kept = kept_by(self.engine if index == self.page_index else
                                               engine_for_page(page, self.project.physics))
            own_scale = page_scale_of(page, width, height)
            sizes = {item.id: (item.w, item.h) for item in page.items if not item.decorative}
            too_large += resize_page(page, size, own, width, height,
                                     page_margin(self.project.physics.margin_mm, width, height))
            fitted = tuple((item.id, *sizes[item.id], item.w, item.h) for item in page.items
                           if item.id in sizes and (item.w, item.h) != sizes[item.id]) \
                if own_scale < 1.0 else ()
            self.pages_edited.add(page.id)
            self.want_room(margin_kept=margin_kept, page_index=index, gutter_kept=gutter_kept,
                           page_scale=own_scale, fitted=fitted)
        self.held_id = None
        if too_large:  # said, as the room search's smaller shrink is: "10 % smaller" was all
            # a user read when a 150 mm title became 9 mm wide on a 10 mm page
            self.status_note = (f"{too_large[0]} was larger than the new page: made smaller"
                                if len(too_large) == 1 else f"{len(too_large)} items larger "
                                "than the new page were made smaller")
        if len(changes) > 1:
            *_, width, height = changes[-1]
            self.status_note = "; ".join(filter(None, (
                f"{len(changes)} pages {done_words(width, height)}", self.status_note)))
        self.engine = self._build_engine(check=False)
        self.engine.reheat()

    def size_changes(self, size: str, orientation: str, width_mm: float | None = None,
                     height_mm: float | None = None, *, every_page: bool = False
                     ) -> list[tuple[int, str, float, float]]:
        """(index, orientation, width, height) of each page the size would change: the page on
        screen, or every page (each in its own orientation, for a named size)."""
        pages, changes = self.project.pages, []
        for index in (range(len(pages)) if every_page else [self.page_index]):
            page = pages[index]
            own = orientation if index == self.page_index or size == "custom" \
                else page.orientation
            width, height = page_dimensions(size, own, width_mm or page.width_mm,
                                            height_mm or page.height_mm)
            if size == "custom":
                own = "landscape" if width > height else "portrait"
            if (size, own, width, height) != (page.size, page.orientation, page.width_mm,
                                              page.height_mm):
                changes.append((index, own, width, height))
        return changes

    def turned_orientation(self) -> str:
        """The orientation `o` turns the page on screen to."""
        return "landscape" if self.page.orientation == "portrait" else "portrait"

    def orientation_changes(self, orientation: str, *, every_page: bool = False
                            ) -> list[tuple[int, str, str, float, float]]:
        """(index, size, orientation, width, height) of each page that turning to
        ``orientation`` would change: the page on screen, or every page, each keeping its own
        size (a custom page's sides swap)."""
        pages, changes = self.project.pages, []
        for index in (range(len(pages)) if every_page else [self.page_index]):
            page = pages[index]
            if page.orientation == orientation:
                continue
            if page.size == "custom":  # its orientation follows from its sides
                width, height = page.height_mm, page.width_mm
                if (width > height) != (orientation == "landscape"):
                    continue  # a square page: nothing to turn
            else:
                width, height = page_dimensions(page.size, orientation)
            changes.append((index, page.size, orientation, width, height))
        return changes

    def set_orientation(self, orientation: str, *, every_page: bool = False) -> str:
        """Turn the page on screen, or every page (`o` turned only the page on screen in a
        12-page calendar, while `S` asks; user-walk-10): one undo step, as `S`'s."""
        self._resize_pages(self.orientation_changes(orientation, every_page=every_page),
                           "orientation", lambda width, height: f"turned {orientation}")
        return self.page.orientation

    def toggle_orientation(self) -> str:
        return self.set_orientation(self.turned_orientation())

    # -- files -------------------------------------------------------------------------------

    def save(self) -> Path:
        self.end_move()
        self.sync_positions()
        if self.version == 0 and self.read_text is not None:
            # every edit undone: saved into the text as it was read, not into the one the last
            # save left (an anchor taken off and put back came at its table's end, pages
            # removed and brought back left blank lines), so the file is as it was read
            self.project.source_text, self.project.parsed_source = self.read_text, None
        path = save_project(self.project)
        self.saved_version = self.version
        self.disk_digest = file_digest(path)
        self.disk_stamp = self.stamp_seen = file_stamp(path)
        self.disk_told = None
        return path

    def reload(self) -> None:
        """Read the project file again as it now is (another program changed it): the edits
        not saved and the undo history go; the page on screen stays if it is still there.
        Raises the loader's error, leaving the session as it was, for a file that no longer
        loads."""
        from floatpage.model.project_file import load_project

        project = load_project(self.project.path,
                               allow_outside_files=self.project.allow_outside_files,
                               missing_pictures_ok=True)
        self.open(project, self.page.id, self.page_index)

    def look_at_file(self) -> str | None:
        """A cheap look, for the editor's timer, at whether another program (a text editor,
        `git checkout`, a script; floatpage's own writers wait for the editor's lock) changed
        or removed the project file since the editor read or saved it: such changes were
        found only at Ctrl+S.

        The file is read (and hashed) only when its size, time or inode changed, and only
        once they have stayed the same for one look (a `git checkout` or a slow write is
        over, not read half done). Returns "changed" or "gone" once for each new state of the
        file that differs from the editor's (a file changed back, or touched only, is no
        change), and None otherwise."""
        path = self.project.path
        stamp = file_stamp(path)
        if stamp == self.disk_stamp:
            self.stamp_seen = stamp
            return None
        if stamp != self.stamp_seen:  # changed since the last look: still being written?
            self.stamp_seen = stamp
            return None
        self.disk_stamp = stamp
        now = file_digest(path) if stamp is not None else "gone"
        if now is None:  # unreadable just now (a rename under way): look again next time
            self.disk_stamp = self.stamp_seen = None
            return None
        if now == self.disk_digest:
            self.disk_told = None
            return None
        if now == self.disk_told:
            return None
        self.disk_told = now
        return "gone" if now == "gone" else "changed"

    def changed_on_disk(self) -> bool:
        """Whether another program changed the project file since the editor read or saved it
        (a file since removed is not: a save only writes it again, and loses nothing)."""
        now = file_digest(self.project.path)
        return now is not None and now != self.disk_digest

    def told_of_the_file(self) -> None:
        """The user is being asked about the file as it now is (Ctrl+S's question): the timer's
        `look_at_file` stays quiet about that state, as about one it told of itself. Else,
        a second after "Keep editing", the same question came again (and under load it came
        up between a test's keys). The stamp is taken before the content is read, so a change
        made after that read still differs at the next look and is told."""
        stamp = file_stamp(self.project.path)
        now = file_digest(self.project.path) if stamp is not None else "gone"
        if now is not None:
            self.disk_stamp = self.stamp_seen = stamp
            self.disk_told = now

    def finalize_for_export(self) -> Project:
        """Run the no-overlap pass on every page, write positions back; return a copy to render.

        The finalised positions become part of the document (undoable), so the
        page on screen is the page in the PDF.

        A page with nothing overlapping and nothing off it is not lined up by the alignment
        snap here: it is the page as shown, as saved. The snap pulled a picture nudged one step
        back onto the page's centre, so Ctrl+S then Ctrl+E left the project unsaved again and
        the PDF undid the nudge (defect 1). A page the pass has to mend is lined up, as the
        editor's own pass at rest lines it up (`EditorScreen.finish_settling`).
        """
        self.end_move()
        self.sync_positions()
        before = [(item.x, item.y) for page in self.project.pages for item in page.items]
        version, undo_depth = self.version, len(self.history.undo_stack)
        self.checkpoint("finalise for export")
        finalize_as_shown(self.engine)
        self.sync_positions()
        settings = dataclasses.replace(self.project.physics, seed=self.seed)
        for index, page in enumerate(self.project.pages):
            if index != self.page_index:
                engine = engine_for_page(page, settings)
                finalize_as_shown(engine)
                write_back(page, engine)
        after = [(item.x, item.y) for page in self.project.pages for item in page.items]
        if after == before:  # nothing moved: no edit, and a saved project stays saved
            del self.history.undo_stack[undo_depth:]
            self.version = version
        return copy.deepcopy(self.project)
