"""The document model: pages and the items that float on them.

Plain dataclasses, free of TOML, physics and UI, so every other stage (the
physics bridge, the typesetter, the editor) reads the same objects.

Units are millimetres. The page origin is its top-left corner, x grows to the
right and y grows down; an item's (x, y) is the centre of its rectangle, as in
section 4 of the paper.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal, Union

FORMAT_VERSION = 1

Orientation = Literal["portrait", "landscape"]
FontFamily = Literal["serif", "sans", "display"]
WEEKDAYS = ("monday", "tuesday", "wednesday", "thursday", "friday", "saturday", "sunday")
ITEM_KINDS = ("text", "picture", "block", "calendar")


@dataclass
class PointAnchor:
    """Glue an item to a page point (section 4.5): a spring of rigidity gamma, or hard."""

    x: float
    y: float
    gamma: float = 1.0
    hard: bool = False


@dataclass
class ItemAnchor:
    """Glue an item to another item: the follower keeps offset (dx, dy) from the target's centre."""

    to: str
    dx: float = 0.0
    dy: float = 0.0


Anchor = Union[PointAnchor, ItemAnchor]


@dataclass
class ItemBase:
    """What every item has: a stable id, a rectangle, a z-order and how the physics treats it."""

    id: str
    x: float
    y: float
    w: float
    h: float
    z: int = 0
    decorative: bool = False
    anchor: Anchor | None = None

    kind = "base"

    @property
    def left(self) -> float:
        return self.x - self.w / 2

    @property
    def top(self) -> float:
        return self.y - self.h / 2


@dataclass
class TextItem(ItemBase):
    """A text box whose font size the typesetter fits to the rectangle."""

    text: str = ""
    font: FontFamily = "serif"
    color: str = "#000000"
    bold: bool = False
    italic: bool = False

    kind = "text"


@dataclass
class PictureItem(ItemBase):
    """A picture scaled to its rectangle; `path` is relative to the project file."""

    path: str = ""
    lock_aspect: bool = True
    bleed: bool = False  # print: extend past the trim wherever the picture meets the page edge

    kind = "picture"


@dataclass
class BlockItem(ItemBase):
    """A rectangle of colour, for decoration or as a placeholder."""

    color: str = "#cccccc"
    opacity: float = 1.0
    bleed: bool = False  # print: extend past the trim wherever the block meets the page edge

    kind = "block"


@dataclass
class CalendarItem(ItemBase):
    """A month panel: a grid of the month's days with localised names."""

    year: int = 2027
    month: int = 1
    first_weekday: str = "monday"
    language: str = "en"
    font: FontFamily = "sans"
    color: str = "#000000"

    kind = "calendar"


Item = Union[TextItem, PictureItem, BlockItem, CalendarItem]
ITEM_CLASSES: dict[str, type] = {
    "text": TextItem,
    "picture": PictureItem,
    "block": BlockItem,
    "calendar": CalendarItem,
}


@dataclass
class Background:
    """A page background: a colour, or a picture covering the page (bleeding to its edge)."""

    color: str | None = None
    picture: str | None = None


@dataclass
class Page:
    """One independent page; items never flow between pages (paper, section 4)."""

    id: str
    size: str = "A4"
    orientation: Orientation = "portrait"
    width_mm: float = 210.0
    height_mm: float = 297.0
    background: Background | None = None
    items: list[Item] = field(default_factory=list)

    def item(self, item_id: str) -> Item:
        for item in self.items:
            if item.id == item_id:
                return item
        raise KeyError(item_id)

    def item_ids(self) -> list[str]:
        return [item.id for item in self.items]


@dataclass
class PhysicsSettings:
    """The paper's parameters (section 6.3 values as defaults) plus our own.

    `mode` picks the engine: "fast" (default, beyond the paper) or "paper"
    (equations 1-8 as published). `distance` is section 4.6's measure:
    "euclidean" (eq. 7) or "axis" (eq. 8). `heat_decay` is section 4.7's
    per-step decay of alpha and beta.
    """

    mode: str = "fast"
    alpha: float = 150.0
    beta: float = 1.0
    delta: float = 0.01
    dt: float = 0.005
    steps_per_frame: int = 500
    distance: str = "axis"
    heat_decay: float = 0.01
    gutter_mm: float = 3.0
    seed: int = 0


@dataclass
class Project:
    """A whole document, as read from (and written back to) one TOML file."""

    path: Path | None = None
    format: int = FORMAT_VERSION
    title: str = ""
    language: str = "en"
    physics: PhysicsSettings = field(default_factory=PhysicsSettings)
    pages: list[Page] = field(default_factory=list)
    # `[files] allow_outside` or --allow-outside-files: pictures may lie outside the folder.
    allow_outside_files: bool = False
    utf8_bom: bool = field(default=False, compare=False)  # kept on save, as the user wrote it
    # The parsed tomlkit document the project was read from; saving edits it in place so
    # the user's comments and key order survive.
    source_document: Any = field(default=None, repr=False, compare=False)

    @property
    def base_dir(self) -> Path:
        """Folder that relative picture paths are resolved against."""
        return self.path.parent if self.path is not None else Path.cwd()

    def page(self, page_id: str) -> Page:
        for page in self.pages:
            if page.id == page_id:
                return page
        raise KeyError(page_id)

    def all_item_ids(self) -> set[str]:
        return {item.id for page in self.pages for item in page.items}
