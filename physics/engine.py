"""One page's physics behind the API the editor and the CLI share.

Every user operation (insert, delete, move, hold, release, resize, anchor, page resize) reheats
the page, as section 4.7 asks: alpha and beta go back to full strength; but moving, holding,
releasing or resizing a decoration nothing follows does not, since it takes no part in the
forces.  ``advance`` runs a
number of steps (one drawn frame by default), cut short by an optional time budget measured
by a clock the caller passes in; the engine itself never reads a clock.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from floatpage.physics.bodies import NO_TARGET, Bodies
from floatpage.physics.euler import kinetic_energy
from floatpage.physics.fast_mode import run_fast
from floatpage.physics.finalize import remove_overlaps
from floatpage.physics.geometry import grown_cover, lines_up
from floatpage.physics.guides import snap_range
from floatpage.physics.local_room import clear_locally
from floatpage.physics.paper_mode import run_paper
from floatpage.physics.params import Params, page_margin
from floatpage.physics.quality import Alignment, Quality, measure_alignment, measure_quality
from floatpage.physics.room_relocation import RoomRelocation
from floatpage.physics.second_start import SecondStart
from floatpage.physics.snapping import snap_page

BUDGET_CHUNK_STEPS = {"fast": 5, "paper": 50}  # steps between two looks at the clock


@dataclass(frozen=True)
class SettleReport:
    steps: int
    energy: float  # kinetic energy (1) at the end
    settled: bool
    fits: bool = True  # the final pass reached zero overlap and the gutter (True if not run)
    fixed_point: bool = True  # settling the result again changes nothing (see model.layout)


def _finite(name: str, *values: float) -> None:
    for value in values:
        if not math.isfinite(value):
            raise ValueError(f"{name} must be finite, not {value!r}")


def _positive(name: str, *values: float) -> None:
    _finite(name, *values)
    for value in values:
        if value <= 0:
            raise ValueError(f"{name} must be > 0, not {value!r}")


class Engine(SecondStart, RoomRelocation):
    """The items of one page and their motion.  Not thread-safe: one caller drives it."""

    def __init__(self, page_w_mm: float, page_h_mm: float, params: Params = Params()):
        _positive("page size", page_w_mm, page_h_mm)
        self.page_w_mm = float(page_w_mm)
        self.page_h_mm = float(page_h_mm)
        self.params = params
        self._bodies = Bodies()
        self._ids: list[str] = []
        self._rows: dict[str, int] = {}
        self._heat = 1.0
        self._settled = True
        self._spread_out = False  # the fast mode's page has spread and cools onto its guides
        self._rng = np.random.default_rng(params.seed)

    # ----- reading -------------------------------------------------------------------------
    @property
    def ids(self) -> tuple[str, ...]:
        return tuple(self._ids)

    @property
    def settled(self) -> bool:
        return self._settled

    @property
    def heat(self) -> float:
        """Section 4.7's factor on alpha and beta: 1 after an edit, shrinking while it settles."""
        return self._heat

    @property
    def kinetic_energy(self) -> float:
        """Equation (1) over the items that move."""
        return kinetic_energy(self._bodies.sizes, self._bodies.velocities, self._bodies.active)

    @property
    def bodies(self) -> Bodies:
        """The state arrays (read them, do not write them)."""
        return self._bodies

    def positions(self) -> dict[str, tuple[float, float]]:
        return {item_id: (float(x), float(y))
                for item_id, (x, y) in zip(self._ids, self._bodies.centres)}

    def sizes(self) -> dict[str, tuple[float, float]]:
        return {item_id: (float(w), float(h))
                for item_id, (w, h) in zip(self._ids, self._bodies.sizes)}

    @property
    def snap_range_mm(self) -> float:
        """How near a feature must come to a guide line to be pulled onto it (4 mm on A4)."""
        return snap_range(self.page_w_mm, self.page_h_mm)

    def quality(self) -> Quality:
        return measure_quality(self.page_w_mm, self.page_h_mm, self._bodies.centres,
                               self._bodies.sizes, self.params.gutter_mm,
                               decorative=self._bodies.decorative,
                               groups=self._bodies.group_roots()[0],
                               margins=self._kept_margins(),
                               regions=self._bodies.regions)

    def _kept_margins(self) -> np.ndarray:
        """Each row's print-safe margin as its walls keep it: none for bleed items, and less
        where a region flush with the page's edge has the margin give way (Bodies.insets)."""
        near, far = self._bodies.insets(self.margin_mm, self.page_w_mm, self.page_h_mm)
        return np.minimum(self._bodies.margins(self.margin_mm),
                          np.minimum(near.min(axis=1, initial=np.inf),
                                     far.min(axis=1, initial=np.inf)))

    def quality_key(self) -> bytes:
        """Everything ``quality`` and ``alignment`` read, as bytes, decorations' positions
        left out (neither counts them): a caller showing the figures need not measure again
        while this is unchanged (the editor measured on every arrow that moved a decoration
        on a still page, 4 ms of the key's answer on the flyer, issue 11)."""
        bodies = self._bodies
        centres = np.where(bodies.decorative[:, None], 0.0, bodies.centres)
        arrays = (centres, bodies.sizes, bodies.decorative, bodies.targets, bodies.offsets,
                  bodies.bleed, bodies.regions)
        return b"".join(array.tobytes() for array in arrays) + repr(
            (self.page_w_mm, self.page_h_mm, self.params)).encode()

    def alignment(self) -> Alignment:
        """How well the page lines up (physics.alignment), decorations left out."""
        return measure_alignment(self._bodies.centres, self._bodies.sizes,
                                 self._bodies.decorative)

    @property
    def margin_mm(self) -> float:
        """The print-safe margin on this page (params.page_margin)."""
        return page_margin(self.params.margin_mm, self.page_w_mm, self.page_h_mm)

    # ----- editing -------------------------------------------------------------------------
    def _row(self, item_id: str) -> int:
        try:
            return self._rows[item_id]
        except KeyError:
            raise KeyError(f"no item {item_id!r} on this page") from None

    def reheat(self, heat: float = 1.0) -> None:
        """Section 4.7's restart: alpha and beta back to ``heat`` (full strength by default; a
        lower heat gives a gentle run that only tells whether a layout is at rest)."""
        _positive("heat", heat)
        self._heat = min(float(heat), 1.0)
        self._settled = False
        self._spread_out = False

    def mark_settled(self) -> None:
        """Declare the current layout at rest: velocities zero, nothing runs until an edit or
        ``reheat``.  For a page loaded from a file, whose saved layout should stay as it is."""
        self._bodies.velocities[:] = 0.0
        self._settled = True

    def insert(self, item_id: str, x_mm: float, y_mm: float, w_mm: float, h_mm: float, *,
               decorative: bool = False, bleed: bool = False) -> None:
        self.insert_all([item_id], [(x_mm, y_mm, w_mm, h_mm)], [decorative], [bleed])

    def insert_all(self, item_ids: list[str], boxes: list[tuple[float, float, float, float]],
                   decorative: list[bool], bleed: list[bool]) -> None:
        """Insert several items at once, each (x, y, w, h) in mm: a page read from a file (one
        by one, every array was copied once an item)."""
        seen: set[str] = set()
        for item_id, (x_mm, y_mm, w_mm, h_mm) in zip(item_ids, boxes):
            if item_id in self._rows or item_id in seen:
                raise ValueError(f"item {item_id!r} is already on this page")
            seen.add(item_id)
            _finite("position", x_mm, y_mm)
            _positive("size", w_mm, h_mm)
        if not item_ids:
            return
        for item_id in item_ids:  # every item checked first: a refusal leaves the page as it was
            self._rows[item_id] = len(self._ids)
            self._ids.append(item_id)
        values = np.array(boxes, dtype=float).reshape(-1, 4)
        self._bodies.extend(values[:, :2], values[:, 2:], np.array(decorative),
                            np.array(bleed))
        self.reheat()

    def delete(self, item_id: str) -> None:
        row = self._row(item_id)
        self._bodies.remove(row)
        del self._ids[row]
        self._rows = {name: k for k, name in enumerate(self._ids)}
        self.reheat()

    def move(self, item_id: str, x_mm: float, y_mm: float) -> None:
        """A user move: the item jumps there at rest.  A hard anchor moves along with it, and an
        item that follows another keeps its new place beside it (its offset becomes the new
        one), as the editor does at the end of a drag; otherwise the next step would snap it
        back."""
        _finite("position", x_mm, y_mm)
        row = self._row(item_id)
        self._bodies.centres[row] = (x_mm, y_mm)
        self._bodies.velocities[row] = 0.0
        if self._bodies.hard[row]:
            self._bodies.anchors[row] = (x_mm, y_mm)
        target = int(self._bodies.targets[row])
        if target != NO_TARGET:
            self._bodies.offsets[row] = self._bodies.centres[row] - self._bodies.centres[target]
        self._carry_followers(row)
        self._reheat_for(row)

    def _reheat_for(self, row: int) -> None:
        """Reheat after an edit of ``row``, unless it is a decoration nothing follows: it
        takes no part in the forces, so the layout has nothing to answer.  Nudging the flyer's
        header band re-spread the whole page at full heat, its products 10 mm (issue 11: one
        arrow sent 20 KB)."""
        bodies = self._bodies
        if bodies.decorative[row] and not (bodies.targets == row).any():
            return
        self.reheat()

    def _carry_followers(self, row: int) -> None:
        """Set the items that follow ``row`` (directly or down a chain) beside it at once, so a
        moved group is drawn whole even while the physics is paused."""
        bodies = self._bodies
        if not bodies.followers.any():
            return
        roots, offsets = bodies.group_roots()
        carried = (roots == roots[row]) & bodies.followers
        carried[row] = False
        bodies.centres[carried] = bodies.centres[roots[carried]] + offsets[carried]

    def hold(self, item_id: str) -> None:
        row = self._row(item_id)
        self._bodies.held[row] = True
        self._bodies.velocities[row] = 0.0
        self._reheat_for(row)

    def release(self, item_id: str) -> None:
        row = self._row(item_id)
        self._bodies.held[row] = False
        self._reheat_for(row)

    def resize(self, item_id: str, w_mm: float, h_mm: float) -> None:
        _positive("size", w_mm, h_mm)
        row = self._row(item_id)
        self._bodies.sizes[row] = (w_mm, h_mm)
        self._reheat_for(row)

    def anchor_point(self, item_id: str, ax_mm: float, ay_mm: float, gamma: float = 1.0,
                     hard: bool = False) -> None:
        """Anchor to a page point: a spring (6) of rigidity gamma in [0, 1], or, if ``hard``,
        the position itself.  Replaces any earlier anchor of the item."""
        _finite("anchor", ax_mm, ay_mm, gamma)
        if not 0.0 <= gamma <= 1.0:
            raise ValueError(f"gamma must lie in [0, 1], not {gamma!r}")
        row = self._row(item_id)
        self.unanchor(item_id)
        self._bodies.anchors[row] = (ax_mm, ay_mm)
        self._bodies.gammas[row] = gamma
        self._bodies.hard[row] = hard
        if hard:
            self._bodies.centres[row] = (ax_mm, ay_mm)
            self._bodies.velocities[row] = 0.0
        self.reheat()

    def anchor_to(self, item_id: str, target_id: str, dx_mm: float, dy_mm: float) -> None:
        """The item follows ``target_id`` at offset (dx, dy) from the target's centre, rigidly.

        Refuses a chain that would lead back to the item itself.
        """
        _finite("offset", dx_mm, dy_mm)
        row, target = self._row(item_id), self._row(target_id)
        if self._leads_back(target, row):
            raise ValueError(f"anchoring {item_id!r} to {target_id!r} makes a cycle")
        self.unanchor(item_id)
        self._bodies.targets[row] = target
        self._bodies.offsets[row] = (dx_mm, dy_mm)
        self._bodies.centres[row] = self._bodies.centres[target] + (dx_mm, dy_mm)
        self.reheat()

    def anchor_all_to(self, anchors: list[tuple[str, str, float, float]]) -> None:
        """``anchor_to(item_id, target_id, dx, dy)`` for each entry, in order, with the same
        result, checked in one pass: a page read from a file anchors all its followers at
        once (on a 2,000-item chain, one by one, each call's cycle test and reheat took a
        tenth of a settle's engines).  An unknown id or an offset that is not finite refuses
        them all, leaving the page as it was; if they would make a cycle, they are applied
        one by one, so the refusal and what it leaves are ``anchor_to``'s."""
        if not anchors:
            return
        rows, targets, offsets = [], [], []
        for item_id, target_id, dx_mm, dy_mm in anchors:
            _finite("offset", dx_mm, dy_mm)
            rows.append(self._row(item_id))
            targets.append(self._row(target_id))
            offsets.append((dx_mm, dy_mm))
        bodies = self._bodies
        following = bodies.targets.copy()
        following[rows] = targets  # a later entry for the same item replaces an earlier one
        if self._has_cycle(following):
            for entry in anchors:
                self.anchor_to(*entry)
            return
        for row, target, offset in zip(rows, targets, offsets):
            bodies.anchors[row] = np.nan
            bodies.gammas[row] = 0.0
            bodies.hard[row] = False
            bodies.targets[row] = target
            bodies.offsets[row] = offset
            bodies.centres[row] = bodies.centres[target] + offset
        self.reheat()

    @staticmethod
    def _has_cycle(targets: np.ndarray) -> bool:
        """Whether following ``targets`` (NO_TARGET: none) from some row comes back to it, by
        pointer jumping: without a cycle every row reaches the end of its chain, a row that
        follows nothing, within log2(n) + 1 doublings.  A row in (or leading into) a cycle
        reaches only rows that follow something: on a cycle of 2, 4, 8... rows the doublings
        bring each row back to itself, which looks like an end unless that is asked."""
        count = len(targets)
        rows = np.arange(count)
        ahead = np.where(targets == NO_TARGET, rows, targets)
        for _ in range(max(count, 1).bit_length() + 1):
            ahead = ahead[ahead]
        return bool((targets[ahead] != NO_TARGET).any())

    def _leads_back(self, target: int, row: int) -> bool:
        """Whether the chain of anchors from ``target`` reaches ``row``.  Only an item that
        others follow can be reached (through one of them), so the walk is skipped for the
        rest: a file anchoring 2,000 items one to the next walked 2 million links as it
        loaded."""
        targets = self._bodies.targets
        if target != row and not (targets == row).any():
            return False
        current = target
        for _ in range(len(self._ids) + 1):
            if current == row:
                return True
            current = int(targets[current])
            if current == NO_TARGET:
                return False
        return False

    def unanchor(self, item_id: str) -> None:
        row = self._row(item_id)
        self._bodies.anchors[row] = np.nan
        self._bodies.gammas[row] = 0.0
        self._bodies.hard[row] = False
        self._bodies.targets[row] = NO_TARGET
        self._bodies.offsets[row] = 0.0
        self.reheat()

    def confine(self, item_id: str, left_mm: float, top_mm: float, right_mm: float,
                bottom_mm: float) -> None:
        """Keep the item inside the rectangle (left, top)-(right, bottom): a region of the page,
        whose edges are walls for it (and guides for every item).  Replaces an earlier region."""
        _finite("region", left_mm, top_mm, right_mm, bottom_mm)
        if right_mm <= left_mm or bottom_mm <= top_mm:
            raise ValueError("a region needs right > left and bottom > top")
        self._bodies.regions[self._row(item_id)] = (left_mm, top_mm, right_mm, bottom_mm)
        self.reheat()

    def resize_page(self, page_w_mm: float, page_h_mm: float) -> None:
        _positive("page size", page_w_mm, page_h_mm)
        self.page_w_mm, self.page_h_mm = float(page_w_mm), float(page_h_mm)
        self.reheat()

    # ----- running -------------------------------------------------------------------------
    def _run(self, steps: int, cool_onto_guides: bool = True) -> int:
        """``cool_onto_guides``: the editor's frames let the guides pull a still page onto its
        lines; a headless settle leaves that to the snap (fast_mode.run_fast)."""
        if self.params.mode == "paper":
            done, self._heat, self._settled = run_paper(
                self._bodies, self.page_w_mm, self.page_h_mm, self.params, self._heat, steps,
                self._rng)
        else:
            done, self._heat, self._settled, self._spread_out = run_fast(
                self._bodies, self.page_w_mm, self.page_h_mm, self.params, self._heat, steps,
                self._rng, self._spread_out, cool_onto_guides)
        return done

    def advance(self, steps: int | None = None, *, budget_s: float | None = None,
                clock: Callable[[], float] | None = None) -> int:
        """Run up to ``steps`` steps (default: one drawn frame of the mode, ``frame_steps``).

        With ``budget_s`` and a ``clock`` (e.g. time.perf_counter) it also stops once the budget
        is spent, looking at the clock every few steps: the budget is a ceiling that keeps a
        frame short on a big page, while the frame's step count keeps the motion smooth (a
        budget alone would run a small page's whole settle in a few jumpy frames).  Stops early
        once settled.  Returns the number of steps run.
        """
        if self._settled:
            return 0
        limit = self.params.frame_steps if steps is None else max(int(steps), 0)
        if budget_s is None:
            return self._run(limit)
        if clock is None:
            raise ValueError("a time budget needs a clock callable, e.g. time.perf_counter")
        chunk = BUDGET_CHUNK_STEPS[self.params.mode]
        start, total = clock(), 0
        while not self._settled and total < limit and clock() - start < budget_s:
            total += self._run(min(chunk, limit - total))
        return total

    def finalize(self, *, fall_back: bool = True, align: bool = True,
                 margin_mm: float | None = None, gutter_mm: float | None = None) -> bool:
        """The no-overlap pass, then the alignment snap unless not ``align``; returns whether
        every pair now keeps the gutter.  Without ``fall_back`` a page that misses the gutter
        is left as the first attempt leaves it, for a second start to try, instead of
        searching for the widest gap it can keep.  ``margin_mm`` and ``gutter_mm`` replace
        the page's in the pass (where they have given way: _pack_past_the_margin)."""
        fits = remove_overlaps(self._bodies, self.page_w_mm, self.page_h_mm,
                               self.params.gutter_mm if gutter_mm is None else gutter_mm,
                               margin_mm=self.margin_mm if margin_mm is None else margin_mm,
                               fall_back=fall_back)
        if not fits and fall_back and self._may_relocate():
            fits = self._relocate_rooms()
        elif not fits and fall_back and self.params.mode == "fast":
            # too many items to relocate: what the pass left overlapping, or in the margin it
            # gave up, is set down in room nearby (physics.local_room)
            clear_locally(self._bodies, self.page_w_mm, self.page_h_mm, self.margin_mm)
        if fits and align and self.lines_up:  # on a page too full for the gutter, or nearly,
            snap_page(self._bodies, self.page_w_mm, self.page_h_mm, self.params)  # it gives way
        self._bodies.velocities[:] = 0.0
        return fits

    @property
    def lines_up(self) -> bool:
        """Whether the page has room to line items up (geometry.lines_up): on a fuller one
        the snap found little (200 items covering half of A4 with the gutter kept: 18.5 near
        misses an item before it, 17.3 after) at the cost of two thirds of the settle."""
        return lines_up(self.grown_cover(), int(self._bodies.active.sum()))

    def grown_cover(self, gutter_mm: float | None = None) -> float:
        """How tight the page is (geometry.grown_cover): the share of the room inside its
        walls the items need, each grown by the gutter (or by ``gutter_mm``: 0 asks whether
        they fit at all).  Up to GUTTER_FITS_COVER the settle keeps the gutter, and `check`
        says so; the same number decides both."""
        near, far = self._bodies.insets(self.margin_mm, self.page_w_mm, self.page_h_mm)
        return grown_cover(self._bodies, near, far, self.page_w_mm, self.page_h_mm,
                           self.params.gutter_mm if gutter_mm is None else gutter_mm)

    def settle(self, max_steps: int = 200_000, *, finalize: bool = True,
               align_within_mm: float = math.inf) -> SettleReport:
        """Headless: run until settled (or ``max_steps``), then the no-overlap pass; if that
        misses the gutter on a page where it fits, once more from a second start.

        The alignment snap runs only if the run moved no item further than
        ``align_within_mm``.  A settle that asks whether a page is at rest (model.layout's
        probes) need not line up a page it finds far from rest: it does not keep that layout
        as it is, and a later probe lines it up.  On a scattered page those snaps were half
        the settle's time."""
        start = self._bodies.centres.copy()
        second_start = finalize and self._second_start_applies()
        steps = self._run_until_settled(max_steps)
        energy = self.kinetic_energy
        fits = True
        if finalize:
            align = self._moved_at_most(start, align_within_mm)
            fits = self.finalize(fall_back=not second_start, align=align)
            if not fits and second_start:
                fits = self._settle_from_packing(max_steps, align)
        return SettleReport(steps=steps, energy=energy, settled=self._settled, fits=fits)

    def _moved_at_most(self, start: np.ndarray, limit_mm: float) -> bool:
        if limit_mm == math.inf:
            return True
        active = self._bodies.active
        return bool(np.abs(self._bodies.centres[active] - start[active]).max(initial=0.0)
                    <= limit_mm)

    def _run_until_settled(self, max_steps: int) -> int:
        steps = 0
        while not self._settled and steps < max_steps:
            steps += self._run(min(10_000, max_steps - steps), cool_onto_guides=False)
        return steps
