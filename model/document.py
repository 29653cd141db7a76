"""The document model: pages and the items that float on them.

Plain dataclasses, free of TOML and UI, so every other stage (the physics bridge, the
typesetter, the editor) reads the same objects.  Each field also says what a project file may
write for it (`model.key_specs.spec`): this is the one description of the model, from which
`model.schema` takes the keys the loader checks.  The [physics] settings take their defaults
and ranges from the engine's own `physics.params`.

Units are millimetres. The page origin is its top-left corner, x grows to the
right and y grows down; an item's (x, y) is the centre of its rectangle, as in
section 4 of the paper.
"""

from __future__ import annotations

import calendar
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal, Union

from floatpage.model.key_specs import (
    CALENDAR_LANGUAGES, FONT_FAMILIES, MAX_SET_PT, MAX_TEXT_CHARS, MIN_SET_PT, TEXT_ALIGNMENTS,
    WEEKDAYS, at_most_chars, between, colour, finite, item_id, name_or_empty, one_of, positive,
    spec, zero_or_between,
)
from floatpage.physics.params import DISTANCES, MODES, Params, out_of_range

FORMAT_VERSION = 1

Orientation = Literal["portrait", "landscape"]
FontFamily = Literal["serif", "sans", "display"]
TextAlignment = Literal["start", "left", "centre", "right"]
ITEM_KINDS = ("text", "picture", "block", "calendar")
COLOUR_LABEL = "Colour (#rrggbb)"
MONTH_CHOICES = tuple((calendar.month_name[number], number) for number in range(1, 13))


def setting(name: str, kind: str = "number") -> Any:
    """A [physics] field: the engine's default, and the engine's own range (physics.params)."""
    return field(default=getattr(Params, name),
                 metadata=spec(kind, lambda value: out_of_range(name, value)))


@dataclass
class PointAnchor:
    """Glue an item to a page point (section 4.5): a spring of rigidity gamma, or hard."""

    x: float = field(metadata=spec("number", finite, required=True))
    y: float = field(metadata=spec("number", finite, required=True))
    gamma: float = field(default=1.0, metadata=spec("number", between(0.0, 1.0),
                                                    label="Anchor gamma: 0 loose … 1 rigid"))
    hard: bool = field(default=False, metadata=spec("bool"))


@dataclass
class ItemAnchor:
    """Glue an item to another item: the follower keeps offset (dx, dy) from the target's centre."""

    to: str = field(metadata=spec("str", required=True))
    dx: float = field(default=0.0, metadata=spec("number", finite))
    dy: float = field(default=0.0, metadata=spec("number", finite))


Anchor = Union[PointAnchor, ItemAnchor]


@dataclass
class ItemBase:
    """What every item has: a stable id, a rectangle, a z-order and how the physics treats it."""

    id: str = field(metadata=spec("str", item_id, required=True))
    x: float = field(metadata=spec("number", finite, required=True))
    y: float = field(metadata=spec("number", finite, required=True))
    w: float = field(metadata=spec("number", positive, required=True))
    h: float = field(metadata=spec("number", positive, required=True))
    z: int = field(default=0, metadata=spec("int"))
    decorative: bool = field(default=False, metadata=spec(
        "bool", label="Decorative (behind, never pushed)"))
    # `floatpage merge`: a record whose value for any of this item's placeholders is empty
    # leaves the item out, instead of printing an empty box
    drop_if_empty: bool = field(default=False, metadata=spec("bool"))
    anchor: Anchor | None = field(default=None, metadata=spec("table"))
    # the page region (Page.regions) the item is confined to; "" for the whole page
    region: str = field(default="", metadata=spec("str", name_or_empty,
                                                 label="Keep inside region"))
    # items that share a group name move as one rigid body (see Page.group_lead)
    group: str = field(default="", metadata=spec(
        "str", name_or_empty, label="Group (items of one group move as one; empty: none)"))

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

    text: str = field(default="", metadata=spec("str", at_most_chars(MAX_TEXT_CHARS),
                                                label="Text", form="text"))
    font: FontFamily = field(default="serif", metadata=spec("str", one_of(*FONT_FAMILIES),
                                                            label="Font"))
    color: str = field(default="#000000", metadata=spec("str", colour, label=COLOUR_LABEL))
    bold: bool = field(default=False, metadata=spec("bool", label="Bold"))
    italic: bool = field(default=False, metadata=spec("bool", label="Italic"))
    # Where each line sits across the box. A title centred on the page keeps its full box (its
    # edges on the page's lines) and still prints centred, where a box hugging its words
    # puts its edges wherever the words end, a few mm from other items' edges.
    align: TextAlignment = field(default="start", metadata=spec(
        "str", one_of(*TEXT_ALIGNMENTS), label="Alignment",
        choices=(("Start (right for right-to-left text)", "start"), ("Left", "left"),
                 ("Centred", "centre"), ("Right", "right"))))
    # What the text is ("price", "caption", "month-name"): every text of one role in the
    # document is set at one size, the largest at which each of their boxes still fits
    # (typeset.roles), as a designer gives each paragraph style one size; "" for none: the
    # text fills its own box.
    role: str = field(default="", metadata=spec(
        "str", name_or_empty, label="Role (texts of one role share one size; empty: none)"))
    # A size set by hand, in points, kept whatever its role; 0 fits the text to its box.
    size_pt: float = field(default=0.0, metadata=spec(
        "number", zero_or_between(MIN_SET_PT, MAX_SET_PT), label="Size in pt (0: fit the box)"))

    kind = "text"


@dataclass
class PictureItem(ItemBase):
    """A picture scaled to its rectangle; `path` is relative to the project file."""

    path: str = field(default="", metadata=spec(
        "str", required=True, label="Picture file (from the project's folder, or a full path)"))
    lock_aspect: bool = field(default=True, metadata=spec(
        "bool", label="Keep the picture's aspect ratio"))
    # may reach the page's edge: no print-safe margin (`render --print` carries every picture
    # and block that meets the edge past the trim, marked or not)
    bleed: bool = field(default=False, metadata=spec("bool"))

    kind = "picture"


@dataclass
class BlockItem(ItemBase):
    """A rectangle of colour, for decoration or as a placeholder."""

    color: str = field(default="#cccccc", metadata=spec("str", colour, label=COLOUR_LABEL))
    opacity: float = field(default=1.0, metadata=spec("number", between(0.0, 1.0),
                                                      label="Opacity (0-1)"))
    # may reach the page's edge: no print-safe margin (`render --print` carries every picture
    # and block that meets the edge past the trim, marked or not)
    bleed: bool = field(default=False, metadata=spec("bool"))

    kind = "block"


@dataclass
class CalendarItem(ItemBase):
    """A month panel: a grid of the month's days with localised names."""

    year: int = field(default=2027, metadata=spec("int", between(1, 9999), label="Year"))
    month: int = field(default=1, metadata=spec("int", between(1, 12), label="Month",
                                                choices=MONTH_CHOICES))
    first_weekday: str = field(default="monday", metadata=spec(
        "str", one_of(*WEEKDAYS), label="Weeks start on",
        choices=tuple((day.capitalize(), day) for day in WEEKDAYS)))
    language: str = field(default="en", metadata=spec("str", one_of(*CALENDAR_LANGUAGES),
                                                      label="Language of the names"))
    font: FontFamily = field(default="sans", metadata=spec("str", one_of(*FONT_FAMILIES),
                                                           label="Font"))
    color: str = field(default="#000000", metadata=spec("str", colour, label=COLOUR_LABEL))

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

    color: str | None = field(default=None, metadata=spec(
        "str", colour, label="Background colour (#rrggbb)"))
    picture: str | None = field(default=None, metadata=spec("str"))


@dataclass
class Region:
    """A named rectangle of a page (the paper's section 7 asks for regions), e.g. "photos in
    the top two-thirds".  Items confined to it (``region = "photos"``) keep inside it: its
    edges are walls for them, as the page's edges are, and guide lines for every item.
    (left, top) is its top-left corner, as a reader measures a frame on a page."""

    id: str = field(metadata=spec("str", item_id, required=True))
    left: float = field(metadata=spec("number", finite, required=True))
    top: float = field(metadata=spec("number", finite, required=True))
    w: float = field(metadata=spec("number", positive, required=True))
    h: float = field(metadata=spec("number", positive, required=True))

    @property
    def box(self) -> tuple[float, float, float, float]:
        """(left, top, right, bottom), mm."""
        return (self.left, self.top, self.left + self.w, self.top + self.h)


@dataclass
class Page:
    """One independent page; items never flow between pages (paper, section 4)."""

    id: str = field(metadata=spec("str", item_id, required=True))
    size: str = field(default="A4", metadata=spec("str"))
    orientation: Orientation = field(default="portrait",
                                     metadata=spec("str", one_of("portrait", "landscape")))
    width_mm: float = field(default=210.0, metadata=spec("number", between(10.0, 5000.0),
                                                         label="Width (mm)"))
    height_mm: float = field(default=297.0, metadata=spec("number", between(10.0, 5000.0),
                                                          label="Height (mm)"))
    background: Background | None = field(default=None, metadata=spec("table"))
    items: list[Item] = field(default_factory=list, metadata=spec("array"))
    regions: list[Region] = field(default_factory=list, metadata=spec("array"))

    def region(self, region_id: str) -> Region:
        for region in self.regions:
            if region.id == region_id:
                return region
        raise KeyError(region_id)

    def region_misfit(self, item: Item, region_id: str) -> str | None:
        """Why ``item`` cannot be confined to ``region_id`` on this page (the page lacks it, or
        the item is larger than it), in words after the item's name; None if it can.  The
        loader and the editor both ask this."""
        try:
            region = self.region(region_id)
        except KeyError:
            return f'is confined to region "{region_id}", which page "{self.id}" does not have'
        if item.w > region.w + 1e-9 or item.h > region.h + 1e-9:
            return (f'is {item.w:g} x {item.h:g} mm, larger than its region "{region.id}" '
                    f"({region.w:g} x {region.h:g} mm)")
        return None

    def group_members(self, group: str) -> list[Item]:
        """The items of a group, in file order."""
        return [item for item in self.items if group and item.group == group]

    def group_lead(self, group: str) -> Item | None:
        """The member a group moves by: the one with a point anchor (an anchor on the group),
        else the first member that follows no other item.  The others follow it rigidly, so
        the group moves as one body wherever the physics or the user moves its lead."""
        members = self.group_members(group)
        for member in members:
            if isinstance(member.anchor, PointAnchor):
                return member
        for member in members:
            if not isinstance(member.anchor, ItemAnchor):
                return member
        return members[0] if members else None

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

    mode: str = field(default=Params.mode, metadata=spec("str", one_of(*MODES)))
    alpha: float = setting("alpha")
    beta: float = setting("beta")
    delta: float = setting("delta")
    dt: float = setting("dt")
    steps_per_frame: int = setting("steps_per_frame", "int")
    distance: str = field(default=Params.distance, metadata=spec("str", one_of(*DISTANCES)))
    heat_decay: float = setting("heat_decay")
    gutter_mm: float = setting("gutter_mm")
    margin_mm: float = setting("margin_mm")
    guides: float = setting("guides")
    seed: int = setting("seed", "int")


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
    crlf: bool = field(default=False, compare=False)  # Windows line ends: kept on every line saved
    # The text the project was read from.  Saving edits its tomlkit document in place, so the
    # user's comments and key order survive; the document is parsed when first asked for
    # (``source_document``): tomlkit took 10 s over a 2,000-item file, and check and render
    # never save.
    source_text: str | None = field(default=None, repr=False, compare=False)
    parsed_source: Any = field(default=None, repr=False, compare=False)
    # Pictures whose files were gone when the editor loaded it ("item "x": picture file
    # "p.jpg""), said when it opens; any other loader refuses such a file.
    missing_pictures: list[str] = field(default_factory=list, repr=False, compare=False)

    @property
    def source_document(self) -> Any:
        """The tomlkit document of the file read (None for a new project); may raise
        RecursionError on nesting too deep for tomlkit."""
        if self.parsed_source is None and self.source_text is not None:
            import tomlkit  # only a save that edits the document needs it

            self.parsed_source = tomlkit.parse(self.source_text)
        return self.parsed_source

    @source_document.setter
    def source_document(self, document: Any) -> None:
        """A document to save into; None to write the file afresh, as a new project."""
        self.parsed_source = document
        if document is None:
            self.source_text = None

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
