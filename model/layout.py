"""The bridge from the document model to the physics: one Engine per page, and back.

Kept apart from the model's dataclasses so that the model stays physics-free and the physics
stays model-free; this module is the only place that knows both.
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass, fields, replace

import numpy as np

from floatpage.physics import Engine, Params, Quality, SettleReport
from floatpage.physics.finalize import ROUNDING_MM
from floatpage.physics.geometry import GUTTER_FITS_COVER
from floatpage.physics.page_limits import binding, page_limits
from floatpage.physics.snapping import ESCAPE_REACH
from floatpage.physics.stillness import PROBE_HEAT
from floatpage.model.errors import FloatpageError
from floatpage.model.document import (
    Item, ItemAnchor, Page, PhysicsSettings, PointAnchor, Project,
)

POSITION_DECIMALS = 2  # positions are written back to 0.01 mm
FIXED_POINT_ROUNDS = 20  # probes before giving up on a fixed point (most pages need 1-3)
AT_REST_MM = 0.25  # a layout that settling moves no further than this is at rest (below what print shows)
PROBE_ALIGNS_WITHIN = 4  # a probe whose run moves an item further than 4 snap ranges (16 mm on
# A4) found the page far from rest: it skips the alignment snap (Engine.settle); a later probe,
# nearer rest, snaps
STUCK_ROUNDS = 3  # probes without gain that prove a too-full page stuck


def params_from_settings(settings: PhysicsSettings) -> Params:
    """The engine's Params from a project's [physics] table: the same names, field for field
    (PhysicsSettings takes its fields' defaults and ranges from Params itself)."""
    return Params(**{f.name: getattr(settings, f.name) for f in fields(PhysicsSettings)})


def engine_for_page(page: Page, settings: PhysicsSettings) -> Engine:
    """An Engine holding the page's items at their saved positions, anchors applied.

    The engine starts at rest (``settled``): a page opened from a file keeps the layout it was
    saved with until the first edit or ``reheat``.  A hard anchor or an item anchor does
    position its item, since the anchor is what the user asked for.
    """
    engine = Engine(page.width_mm, page.height_mm, params_from_settings(settings))
    engine.insert_all([item.id for item in page.items],
                      [(item.x, item.y, item.w, item.h) for item in page.items],
                      [item.decorative for item in page.items],
                      [bool(getattr(item, "bleed", False)) for item in page.items])
    following: list[tuple[str, str, float, float]] = []  # anchor_to's, applied in order
    for item in page.items:
        anchor = item.anchor
        if isinstance(anchor, PointAnchor):
            if anchor.hard:  # it moves its item: the followers before it go first
                engine.anchor_all_to(following)
                following = []
            engine.anchor_point(item.id, anchor.x, anchor.y, gamma=anchor.gamma,
                                hard=anchor.hard)
        elif isinstance(anchor, ItemAnchor):
            following.append((item.id, anchor.to, anchor.dx, anchor.dy))
    following += [(item.id, lead.id, item.x - lead.x, item.y - lead.y)
                  for item, lead in group_followers(page)]
    engine.anchor_all_to(following)
    regions = {region.id: region.box for region in page.regions}
    for item in page.items:
        if item.region in regions:
            engine.confine(item.id, *regions[item.region])
    engine.mark_settled()
    return engine


def group_followers(page: Page) -> list[tuple[Item, Item]]:
    """(member, lead) for every member of a group that the engine makes follow its group's
    lead (Page.group_lead) where it now stands: a group is one rigid body.  Members with an
    anchor of their own keep it (the loader allows only item anchors within the group)."""
    pairs = []
    for group in dict.fromkeys(item.group for item in page.items if item.group):
        lead = page.group_lead(group)
        pairs += [(member, lead) for member in page.group_members(group)
                  if member is not lead and member.anchor is None]
    return pairs


def safe_round(centre_mm: float, half_mm: float, page_mm: float) -> float:
    """A centre rounded to 0.01 mm, towards safety: an item that lies inside the page stays
    inside once rounded (rounding to the nearest would push an item flush with an edge 0.005 mm
    past it).  Gaps between items survive rounding because the no-overlap pass keeps
    ``physics.finalize.ROUNDING_MM`` beyond the gutter."""
    step = 10.0 ** -POSITION_DECIMALS
    nearest = round(centre_mm, POSITION_DECIMALS)
    inside = centre_mm - half_mm >= -1e-9 and centre_mm + half_mm <= page_mm + 1e-9
    if inside and half_mm * 2 <= page_mm:
        if nearest - half_mm < 0:
            nearest = round(math.ceil(round(half_mm / step, 6)) * step, POSITION_DECIMALS)
        if nearest + half_mm > page_mm:
            nearest = round(math.floor(round((page_mm - half_mm) / step, 6)) * step,
                            POSITION_DECIMALS)
    return nearest + 0.0  # + 0.0 turns -0.0 into 0.0


def write_back(page: Page, engine: Engine) -> float:
    """Copy the engine's positions into the page's items, rounded to 0.01 mm towards safety.

    Items the engine does not know (added to the page since) are left as they are.  Returns how
    far the farthest item moved, in mm (0.0 when the page is unchanged).
    """
    positions, sizes = engine.positions(), engine.sizes()
    moved = 0.0
    for item in page.items:
        if item.id in positions:
            (x, y), (w, h) = positions[item.id], sizes[item.id]
            if not (math.isfinite(x) and math.isfinite(y)):
                raise FloatpageError(
                    f'page "{page.id}", item "{item.id}": the physics diverged (its position '
                    "became inf or NaN); nothing was saved. Lower [physics] alpha or dt, or "
                    "report this as a bug with the project file")
            new_x = safe_round(x, w / 2, page.width_mm)
            new_y = safe_round(y, h / 2, page.height_mm)
            moved = max(moved, abs(new_x - item.x), abs(new_y - item.y))
            item.x, item.y = new_x, new_y
            if isinstance(item.anchor, PointAnchor) and item.anchor.hard:
                # A hard anchor *is* the position: round it the same safe way, or the saved
                # anchor, rounded to the nearest, would put the item 0.005 mm past an edge.
                item.anchor.x, item.anchor.y = new_x, new_y
    return moved


# The physics holds every pair of touching items at once, and the no-overlap pass works
# through them: 10,000 items on one spot (50 million pairs) failed past 4 GB, 2,000 (2 million
# pairs) took 270 s and 530 MB, 630 (198,000 pairs) take 13 s.
MAX_PILED_PAIRS = 200_000


PAIRS_PER_SWEEP = 4_000_000  # candidate pairs tested at once: about 100 MB


def piled_pairs(page: Page) -> int:
    """How many pairs of items (decorations and pairs in one follow chain aside) overlap, by a
    sweep along x: items sorted by their left edge, each tested only against those starting
    before it ends, a few million candidates at a time.  A spread-out page of 10,000 items has under a million
    candidates (well under a second); 10,000 on one spot have 50 million (a few seconds)."""
    kept = [k for k, item in enumerate(page.items) if not getattr(item, "decorative", False)]
    boxes = np.array([(item.x, item.y, item.w, item.h) for item in page.items],
                     float).reshape(-1, 4)[kept]
    order = np.argsort(boxes[:, 0] - boxes[:, 2] / 2, kind="stable")
    groups = follow_roots(page)[kept][order]
    left = (boxes[:, 0] - boxes[:, 2] / 2)[order]
    right = (boxes[:, 0] + boxes[:, 2] / 2)[order]
    top = (boxes[:, 1] - boxes[:, 3] / 2)[order]
    bottom = (boxes[:, 1] + boxes[:, 3] / 2)[order]
    rows = np.arange(len(boxes))
    # item k is tested against k+1 .. reach[k]-1: those starting before it ends
    candidates = np.clip(np.searchsorted(left, right, "left") - rows - 1, 0, None)
    total, start = 0, 0
    ends = np.cumsum(candidates)
    while start < len(boxes):
        stop = max(start + 1, int(np.searchsorted(ends, ends[start] - candidates[start]
                                                  + PAIRS_PER_SWEEP, "right")))
        counts = candidates[start:stop]
        firsts = np.repeat(rows[start:stop], counts)
        offsets = np.arange(int(counts.sum())) - np.repeat(np.cumsum(counts) - counts, counts)
        seconds = firsts + 1 + offsets
        total += int(np.count_nonzero((top[seconds] < bottom[firsts])
                                      & (top[firsts] < bottom[seconds])
                                      & (groups[firsts] != groups[seconds])))
        start = stop
    return total


def follow_roots(page: Page) -> np.ndarray:
    """(n,) index of the item each item follows in the end (itself if none).  A follower sits
    where its user put it beside its target, so pairs within one follow chain are never
    pulled apart (a 2,000-item chain on one spot settles in a blink)."""
    index = {item.id: k for k, item in enumerate(page.items)}
    roots = np.array([index.get(item.anchor.to, k) if isinstance(item.anchor, ItemAnchor) else k
                      for k, item in enumerate(page.items)], dtype=np.int64)
    for member, lead in group_followers(page):
        roots[index[member.id]] = index[lead.id]
    while True:  # pointer jumping: log2(chain length) rounds (the loader refuses cycles)
        jumped = roots[roots]
        if np.array_equal(jumped, roots):
            return roots
        roots = jumped


def refuse_piled_up(page: Page) -> None:
    pairs = piled_pairs(page)
    if pairs > MAX_PILED_PAIRS:
        raise FloatpageError(
            f'page "{page.id}": its {len(page.items):,} items are piled on each other '
            f"({pairs:,} overlapping pairs, more than the {MAX_PILED_PAIRS:,} settle can pull "
            "apart at once); spread them over the page, make them smaller, or move some to "
            "another page")


def settle_page(page: Page, settings: PhysicsSettings, *, max_steps: int = 200_000,
                max_rounds: int = FIXED_POINT_ROUNDS) -> SettleReport:
    """Settle one page to a fixed point: settling the result again changes nothing, so a settled
    file *is* the layout that the editor shows and render prints.

    One run of the physics and the no-overlap pass does not end at a fixed point: the pass
    nudges items off the physics' equilibrium, and the next full run from the nudged, rounded
    layout moves them again (up to 30 mm on a crowded page).  So a settle first *probes* the
    layout: a gentle run (heat ``PROBE_HEAT``) from the page as it is, the same numbers and seed
    every time (a plainly scattered page, whose probe's answer is known, goes straight to the
    full run: see ``plainly_scattered``).  The layout is kept exactly as it is when it is

    - *at rest*: the probe moves no item more than ``AT_REST_MM`` and the layout already keeps
      every guarantee the probe reaches (``keeps_guarantees``: it is at least as sound, in
      ``soundness_key``'s order, as the probe's result); or
    - *stuck*: a page whose probes only shuffle its items (too full, or torn between the
      physics and the no-overlap pass): the next ``STUCK_ROUNDS`` probes, each from the last
      one's result, never improve on it (``layout_score``: a sounder layout in
      ``soundness_key``'s order, or one as sound whose probe moves items less).  A probe that finds a less sound layout at rest is no gain.

    Otherwise a layout *near rest* (it keeps every guarantee, and so does its probe, which
    moves no item further than the alignment snap's longest move, ``ESCAPE_REACH`` snap
    ranges, on a page roomy enough to be lined up) keeps its probe's result: a settled file
    whose lines the snap can improve, or a file moved a little by hand, stays the layout it
    was instead of being laid out anew.  Any other layout gets one full run.  Then probes,
    each adopting its own result, until one finds the layout at rest (and at least as sound
    as every layout probed before it), or the best layout of the sequence proves stuck.  Both
    tests are repeated by a later settle on the same numbers and find the same, so it changes
    no byte.  The sequence starts from the soundest of the full run's layout, those the
    probes before it left and the page as it was (``soundest_start``), so no layout a settle
    saw is sounder than what it saves, but for the last probe's result.
    """
    refuse_piled_up(page)
    first = None if plainly_scattered(page, settings) else probe_rest(page, settings, max_steps)
    if first is not None and first.at_rest:
        return replace(first.report, fixed_point=True)
    seen: list[Probe] = []  # the probes that proves_stuck ran
    if first is not None and proves_stuck(first, settings, max_steps, seen):
        return replace(first.report, fixed_point=True)
    if first is not None and first.near_rest:
        page.items, report = first.trial.items, first.report
    else:
        start = copy_of(page) if first is not None else None
        engine = engine_for_page(page, settings)
        engine.reheat()
        report = engine.settle(max_steps)
        write_back(page, engine)
        if first is not None:
            page.items, report = soundest_start(page, report, [first, *seen], start,
                                                settings)
    best: tuple[list, tuple, SettleReport] | None = None  # items, score, report
    rounds_without_gain = 0
    for _ in range(max_rounds):
        probe = probe_rest(page, settings, max_steps)
        if probe.at_rest and (best is None or probe.sound_as(best[1])):
            return replace(report, fixed_point=True)
        if best is None or probe.score < best[1]:
            best = (page.items, probe.score, probe.report)
            rounds_without_gain = 0
        else:
            rounds_without_gain += 1
            if rounds_without_gain >= STUCK_ROUNDS:
                page.items = best[0]
                return replace(best[2], fixed_point=True)
        page.items, report = probe.trial.items, probe.report
    if best is not None:
        # Out of rounds, not at rest: the soundest, stillest layout of the sequence, as a stuck
        # page keeps, rather than the last probe's, which can be a jump away (a photo and its
        # soft-anchored caption crept 4.2 mm down to 0.36 mm a probe over 19 probes, then one
        # probe moved them 26 mm and that was saved; a second settle moved it again: fresh
        # project seed 7038).  A later settle probes it and finds the same sequence.
        page.items = best[0]
        return replace(best[2], fixed_point=False)
    return replace(report, fixed_point=False)


def soundest_start(settled: Page, report: SettleReport, probes: list["Probe"], start: Page,
                   settings: PhysicsSettings) -> tuple[list, SettleReport]:
    """The items (and report) the probe sequence starts from after a full run: the full run's
    layout (``settled``), unless a layout the probes before it left (``probes``: the first
    probe's, then those of ``proves_stuck``) or the page as it was (``start``) is sounder
    (``soundness``, in ``soundness_key``'s order).

    The sequence keeps the soundest, stillest layout it probes, but a layout it never probes
    it cannot keep.  On fresh project seed 227, p1 (a hard-anchored group, a soft-anchored
    text and block, two regions), the first probe's gentle run parted the page (13 overlaps
    to none, a 0.3 mm gap); the full run from the same page, at full heat, left 6 overlaps
    (9.7 mm), and every probe from there kept them, so that was saved.  Ties go to the full
    run, as before, then to the earliest."""
    candidates = [(settled, report), *((probe.trial, probe.report) for probe in probes),
                  (start, probes[0].report)]
    scores = [soundness(page, settings) for page, _ in candidates]
    page, report = candidates[min(range(len(candidates)), key=scores.__getitem__)]
    return page.items, report


def plainly_scattered(page: Page, settings: PhysicsSettings) -> bool:
    """Whether the page's first probe is skipped for a full run at once: free items (no point
    anchor, group or region; followers allowed) that overlap, on a page where the no-overlap
    pass parts them: they cover at most the GUTTER_FITS_COVER of the room that rectangles pack
    to (geometry.grown_cover without a gutter), nothing rules zero overlap out (no binding
    physics.page_limits: 3 items on A5, one 196 mm tall beside one 99 mm wide, must cross
    whatever their area), and with followers ``parts_some``.  There the probe's no-overlap
    pass leaves fewer overlaps than the page has (10,000 scattered items: 6,290 -> 127), and
    then its answer is known: not at rest (at rest keeps every overlap), not near rest (that
    needs none) and not stuck (its result is sounder than the page), so the full run follows,
    from the page as it was:
    skipping the probe changes no result.  On those 10,000 items the probe was an eighth of
    the settle; on an album page of photos with captions that follow them it was as long as
    the full run (a 200-page album: 46 s of CPU, half of it these probes).  Only a probe whose
    pass jams, leaving as many overlaps, would have answered otherwise and kept the page as it
    was; such a free page gets the full run (with its second start) instead.  A page whose
    overlaps may stay (held by point anchors, groups or regions, or too full by area) is
    probed first, as before.  Where the test was only whether the items fit by area
    (finalize.cannot_fit), the over-full page (40 items on 90 % of A4) was laid out anew from
    its own settled file, whose overlaps no pass removes, and moved again every time."""
    if any(isinstance(item.anchor, PointAnchor) or item.group or item.region
           for item in page.items):
        return False
    engine = engine_for_page(page, settings)
    if engine.quality().overlap_count == 0:
        return False
    if engine.grown_cover(0.0) > GUTTER_FITS_COVER:
        return False
    bodies = engine.bodies
    if binding(page_limits(bodies, engine.page_w_mm, engine.page_h_mm, engine.margin_mm, 0.0)):
        return False  # the items themselves rule zero overlap out
    return not bodies.followers.any() or parts_some(engine)


def parts_some(engine: Engine) -> bool:
    """Whether the no-overlap pass, run on the page as it lies, leaves it with fewer overlaps:
    for free items their fitting by area says so (the packing of the second start parts
    them), but a page with followers has no second start, and a file settle wrote may keep
    overlaps the pass cannot remove (random pages 25029 and 25045 of `anchored_pages.py
    --kind follow`: settled again, they were laid out anew every time).  Those, like any page
    whose pass leaves every overlap, are probed first.  It moves the engine's items."""
    before = engine.quality().overlap_count
    engine.finalize(fall_back=False, align=False)
    return engine.quality().overlap_count < before


def proves_stuck(first: "Probe", settings: PhysicsSettings, max_steps: int,
                 seen: list["Probe"] | None = None) -> bool:
    """Whether the page that ``first`` probed is *stuck* (see ``settle_page``): the
    ``STUCK_ROUNDS`` probes that follow never improve on it.  The probes it runs are added to
    ``seen``.

    A probe's score leads with how sound the layout it starts from is, so a probe from a layout
    already sounder than ``first``'s (fewer overlaps, say: a scattered page that ``first``
    spread out) improves on it whatever it then moves: that page is not stuck, and the probe,
    a gentle run with the alignment snap, need not run to say so (on a scattered page of 50
    items it was a third of the settle)."""
    trial = first.trial
    for _ in range(STUCK_ROUNDS):
        if soundness(trial, settings) < first.score[:SOUNDNESS_TERMS]:
            return False
        probe = probe_rest(trial, settings, max_steps)
        if seen is not None:
            seen.append(probe)
        if probe.score < first.score:  # at rest or not: a less sound rest is no gain
            return False
        trial = probe.trial
    return True


@dataclass(frozen=True)
class Probe:
    """What a gentle run from a page as it is tells (see ``settle_page``)."""

    report: SettleReport
    trial: Page  # the page the probe leaves, positions rounded as a save would write them
    at_rest: bool
    near_rest: bool
    score: tuple[int, int, float, int, int, float, float]  # lower is better (layout_score)

    def sound_as(self, score: tuple) -> bool:
        """Whether the layout this probe started from is at least as sound as the one
        ``score`` scores (their leading, ``SOUNDNESS_TERMS`` terms)."""
        return self.score[:SOUNDNESS_TERMS] <= score[:SOUNDNESS_TERMS]


def probe_rest(page: Page, settings: PhysicsSettings, max_steps: int) -> Probe:
    """A gentle run from the page as it is, then the no-overlap pass, the alignment snap and
    the rounding of a save: what settling would make of the page if it were nearly at rest.
    The snap is left out if the run found the page far from rest."""
    engine = engine_for_page(page, settings)
    before = engine.quality()
    engine.reheat(PROBE_HEAT)
    report = engine.settle(max_steps,
                           align_within_mm=PROBE_ALIGNS_WITHIN * engine.snap_range_mm)
    trial = copy_of(page)
    moved = write_back(trial, engine)
    sound = keeps_guarantees(before, engine.quality())
    at_rest = moved <= AT_REST_MM and sound
    near_rest = (engine.lines_up and sound and report.fits and before.overlap_count == 0
                 and not before.off_page and moved <= ESCAPE_REACH * engine.snap_range_mm)
    return Probe(report, trial, at_rest, near_rest, layout_score(before, moved))


def layout_score(quality: Quality,
                 probe_moved_mm: float) -> tuple[int, int, float, int, int, float, float]:
    """How sound and how still a layout is, lower is better: its ``soundness_key``, then how
    far its probe moved an item (to 0.01 mm, so that noise is no gain)."""
    return (*soundness_key(quality), round(probe_moved_mm, POSITION_DECIMALS))


SOUNDNESS_TERMS = 6  # layout_score's terms that depend on the layout alone, not on its probe
DEPTH_TERM, COUNT_TERM, GAP_TERM = 2, 3, 5  # soundness_key's summed depth, pair count, gap


def soundness_key(quality: Quality) -> tuple[int, int, float, int, int, float]:
    """The one order in which settle_page compares layouts, lower is sounder: whether any items
    overlap, then items off the page, then how deep the overlaps go (every overlapping pair's
    depth summed, ``Quality.overlap_depth_mm``), then how many pairs overlap, then items in the
    print-safe margin, then the smallest gap (up to the gutter; negative: the deepest
    overlap; lengths to 0.01 mm).  The at-rest test (``keeps_guarantees``), the stuck test
    (``proves_stuck``), the sequence's best layout and ``soundest_start`` all use it: where
    they ordered layouts differently, a layout one of them kept the next settle's probe left,
    and the settled file was not a fixed point.

    Zero overlap comes first: a layout without any is what issue 10 promises where one
    exists.  Among layouts that overlap, the summed depth comes before the count, as a user
    sees it: six overlaps, one of them 48.5 mm deep (186.6 mm summed), hide far more than
    seven hairline ones of at most 0.77 mm (5.4 mm summed), which print as touching edges;
    with the count first the six were saved (fresh project seed 7062, p3).  Summed, not the
    deepest alone: on seed 149 the deepest alone preferred eight overlaps of up to 8.8 mm
    (59.0 mm summed, 3,290 mm2 hidden) to two of 17.7 mm (35.4 mm, 1,827 mm2).  The depth
    comes before the margin, as issue 16's order gives up the margin before it lets items
    overlap: of two layouts with two overlaps each, the deepest 15.8 mm with two items in the
    margin or 7.1 mm with four (fresh project seed 15, p1), the second is the sounder."""
    gap = min(quality.min_gap_mm, quality.gutter_mm)
    depth = round(quality.overlap_depth_mm, POSITION_DECIMALS) + 0.0
    return (int(quality.overlap_count > 0), len(quality.off_page), depth,
            quality.overlap_count, len(quality.in_margin),
            0.0 if math.isinf(gap) else -round(gap, POSITION_DECIMALS) + 0.0)


def sound_as(key: tuple, other: tuple, slack_mm: float = 0.0) -> bool:
    """Whether the layout of soundness ``key`` is at least as sound as that of ``other`` in
    soundness_key's order, its lengths equal within ``slack_mm`` (the summed depth within
    that much for each overlapping pair)."""
    pairs = max(key[COUNT_TERM], other[COUNT_TERM])
    for term, (mine, theirs) in enumerate(zip(key[:SOUNDNESS_TERMS], other[:SOUNDNESS_TERMS])):
        slack = {DEPTH_TERM: slack_mm * pairs, GAP_TERM: slack_mm}.get(term, 0.0)
        if mine < theirs - slack:
            return True
        if mine > theirs + slack:
            return False
    return True


def soundness(page: Page, settings: PhysicsSettings) -> tuple:
    """The leading terms of the score a probe from ``page`` would give it (layout_score),
    without the probe."""
    return soundness_key(engine_for_page(page, settings).quality())


def copy_of(page: Page) -> Page:
    """A page whose items can be moved without touching ``page``'s: a copy of each item and of
    its anchor (a settle writes a hard anchor back with its item's rounded position, so a
    shared one was moved in the page being probed, or edited), sharing what no settle changes
    (a deep copy of 2,000 items took half a second a probe)."""
    return Page(id=page.id, width_mm=page.width_mm, height_mm=page.height_mm,
                items=[_copy_item(item) for item in page.items], regions=page.regions)


def _copy_item(item):
    copied = copy.copy(item)
    copied.anchor = copy.copy(item.anchor)
    return copied


def keeps_guarantees(layout: Quality, settled: Quality) -> bool:
    """Whether ``layout`` is as sound as what settling reaches, in the one order of
    ``soundness_key`` (the stuck test's and the saved layout's), its lengths within the
    rounding slack: a probe that leaves a less sound layout does not unsettle a sounder one,
    and one that leaves a sounder layout is taken."""
    return sound_as(soundness_key(layout), soundness_key(settled), ROUNDING_MM)


def settle_project(project: Project, *, max_steps: int = 200_000,
                   jobs: int = 1) -> list[SettleReport]:
    """Headless: settle every page to its fixed point (see ``settle_page``), positions written
    back.  Returns one report per page, in page order.  With ``jobs`` above 1 a project large
    enough settles its pages in that many processes (model.page_pool), to the same bytes."""
    from floatpage.model.page_pool import settle_here, settle_in_pool, worth_a_pool

    if worth_a_pool(project.pages, jobs):
        return settle_in_pool(project.pages, project.physics, max_steps, jobs)
    return settle_here(project.pages, project.physics, max_steps)
