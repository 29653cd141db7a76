"""The space between two items that move as one (a caption and the photo it follows, a
group's member and its lead), when an edit scales it: a page made smaller (`S`, `o`), or the
room search shrinking the items after it.  The space scales, but a space that read as clear
space stays clear of the band the eye reads as a near miss (physics.alignment: more than
``ALIGNED_MM``, less than ``NEAR_MM``).

The alignment snap never changes the space within such a pair: they are one rigid body to it,
so a space scaled into the band stays a near miss for good.  The album's captions stand
4.51 mm below their photos on A4 (the starters keep a follower's space out of the band); `S`
to A5 on every page scaled that space by 210/297, and the room search by 0.81 more, to
2.58 mm: on the album's page 2 all five of its near misses, on page 1 nine of its thirteen
(user-walk-12a, real-pages in docs/benchmarks.md).
"""

from __future__ import annotations

from floatpage.model.document import PictureItem
from floatpage.physics.alignment import ALIGNED_MM, NEAR_MM

CLEAR_MM = NEAR_MM + 0.05  # a clear space scaled into the band stays this wide (the snap's
# ESCAPE_MM: rounded to the 0.01 mm a save writes, still beyond NEAR_MM)
SAVED_MM = 0.005  # half the step a save writes: a space of 4.00 in the file reads as
# 3.999999999999993 from the centres and sizes, clear all the same


def scaled_space(space: float, scale: float) -> float:
    """``space`` (mm between two facing edges) scaled by ``scale``, kept on its side of the
    near-miss band: a space of at least ``NEAR_MM`` (as saved) that shrinks stays at least
    ``CLEAR_MM``, however much it shrinks (in steps, as the room search tries, or at once, as
    its answer is applied, it ends the same; kept at exactly 4.00 mm, floats would put it back
    in the band); one of at most ``ALIGNED_MM`` (the edges on one line) stays at most what it
    was; a space inside the band scales as it is (it was a near miss already)."""
    scaled = space * scale
    if space >= NEAR_MM - SAVED_MM and scaled < min(space, CLEAR_MM):
        return CLEAR_MM
    if space <= ALIGNED_MM < scaled:
        return space
    return scaled


def scaled_offset(offset: float, half_before: float, half_after: float, scale: float) -> float:
    """The offset between the centres of two items moving as one, on one axis, once the space
    between them scales by ``scale`` and their half sizes' sum goes from ``half_before`` to
    ``half_after``: where they stand apart on the axis, the space between their facing edges
    scales (``scaled_space``); where they overlap on it (a caption centred under its photo, a
    label on a picture), the offset itself scales."""
    space = abs(offset) - half_before
    length = half_after + scaled_space(space, scale) if space >= 0 else abs(offset) * scale
    return length if offset >= 0 else -length


def scaled_size(item, w: float, h: float, scale: float) -> tuple[float, float]:
    """``item``'s size ``w`` x ``h`` scaled by ``scale``, each side kept on its side of the
    near-miss band (``scaled_space``; a picture whose shape is locked keeps it,
    by the larger of its sides' factors): a side is the space between the item's own edges,
    a near miss with any item whose edge lines up with one of them.  The album made A6 (its
    items scaled by 0.498) had 8 mm captions 3.99 mm high, side by side on one line: each
    one's top 3.99 mm from the other's bottom, four near misses on page 1."""
    new_w, new_h = scaled_space(w, scale), scaled_space(h, scale)
    if isinstance(item, PictureItem) and item.lock_aspect:
        factor = max(new_w / w, new_h / h) if w > 0 and h > 0 else scale
        return w * factor, h * factor
    return new_w, new_h
