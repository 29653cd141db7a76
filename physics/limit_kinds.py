"""The reasons `physics.page_limits` gives, as records `check` spells out, and what the limit
searches share: the tolerance of a saved position, how many of a kind are listed, and the
clearance of every pair of two sets of rows.  Apart so that each family of limits
(page_limits, stack_limits, room_limits) builds them without importing the others."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Union

import numpy as np

TOLERANCE_MM = 0.01  # saved positions are rounded to 0.01 mm
CROSSING_BLOCK = 512  # rows compared with all others at once: memory O(512 n)
LISTED = 1_000  # reasons of one kind kept: enough to name, bounded on a hostile file
# A settle keeps the widest gap a page's limits leave to within two roundings of a saved
# position (Engine._relocate_to_cap aims 0.02 mm inside it): a pair this near it is explained.
WIDEST_GAP_SLACK_MM = 0.03


@dataclass(frozen=True)
class PinnedClash:
    rows: tuple[int, int]
    gap_mm: float  # edge to edge, negative when they overlap


@dataclass(frozen=True)
class PinnedOutside:
    row: int
    past_edge_mm: float  # how far it reaches past the page's edge (0 if inside the page)
    into_margin_mm: float  # how far it reaches into its margin
    decoration: bool = False  # a decoration: keeps no margin, but never moves either


@dataclass(frozen=True)
class TooLarge:
    rows: tuple[int, ...]  # the group's members, its root first
    axis: int  # 0 across (width), 1 down (height)
    extent_mm: float
    room_mm: float  # between its walls (the margins, or its region)
    page_mm: float


@dataclass(frozen=True)
class Crossing:
    rows: tuple[int, int]
    needs_mm: tuple[float, float]  # side by side (widths + gutter), one above the other
    room_mm: tuple[float, float]  # inside the margins
    widest_gap_mm: float  # the widest gap the two can keep inside the margins (< 0: overlap)
    fits_page: bool  # whether they can be parted at all if the margins give way


@dataclass(frozen=True)
class Stack:
    rows: tuple[int, ...]  # tallest first
    axis: int  # the axis they must be stacked along: 1 one above another, 0 side by side
    needs_mm: float  # their sizes along it, and a gutter between each two
    room_mm: float  # inside the margins
    widest_gap_mm: float  # at most this gap between them inside the margins (< 0: overlap)
    fits_page: bool  # whether they can be parted at all if the margins give way


@dataclass(frozen=True)
class NoRoom:
    rows: tuple[int, ...]  # the free item, then the items following it
    pinned: tuple[int, ...]  # the items that cannot move, that leave it no room
    widest_gap_mm: float  # the widest gap from them it can keep inside the margins (< 0: overlap)
    fits_page: bool  # whether it can stand clear of them at all if the margins give way


@dataclass(frozen=True)
class PinnedStack:
    rows: tuple[int, ...]  # free items of which no two stand beside each other (or above)
    pinned: tuple[int, ...]  # the items that cannot move that one of them cannot pass
    axis: int  # the axis they must stand along: 1 one above another, 0 side by side
    room_mm: float  # inside the margins, along it
    widest_gap_mm: float  # at most this gap between them and those items (< 0: overlap)
    fits_page: bool  # whether they can be parted at all if the margins give way


@dataclass(frozen=True)
class NoArrangement:
    rows: tuple[int, ...]  # every item that takes part on the page
    room_mm: tuple[float, float]  # inside the margins
    widest_gap_mm: float  # the widest gap they can all keep inside the margins (< 0: overlap)
    fits_page: bool  # whether they can be parted at all if the margins give way
    pinned: tuple[int, ...] = ()  # the items that cannot move they must stand around
    # found by physics.unit_arrangements (units, pinned items, regions): it explains a pair
    # down to its widest gap only, not at any depth, since a settle sets the units down there
    units: bool = False
    # False where the search for the widest gap ran out of its budget part way (physics.
    # unit_arrangements.widest_bracket): the gutter is ruled out, ``widest_gap_mm`` is the
    # widest gap a layout was found for, and none keeps ``at_most_mm``
    proved: bool = True
    at_most_mm: float = float("nan")


Limit = Union[PinnedClash, PinnedOutside, TooLarge, Crossing, Stack, NoRoom, PinnedStack,
              NoArrangement]
GAP_LIMITS = (Crossing, Stack, NoRoom, PinnedStack, NoArrangement)  # with a widest_gap_mm


def block_clearances(centres_a: np.ndarray, halves_a: np.ndarray, centres_b: np.ndarray,
                     halves_b: np.ndarray) -> np.ndarray:
    """finalize.pair_clearances for every a (k rows) against every b (m rows), (k, m), in the
    same arithmetic, so that a pair gets the same clearance either way."""
    return (np.abs(centres_a[:, None] - centres_b[None]) - halves_a[:, None]
            - halves_b[None]).max(axis=2)
