"""From the document model to everything the templates print, every number computed.

`place_document(project)` is the only place that turns mm rectangles into text
runs, picture placements and rules: a PlacedDocument of PlacedPages holding
PlacedText, PlacedPicture, PlacedBlock and PlacedCalendar, each an item as it
will be printed. The templates only lay them out. It reads picture files (to
hash them) but writes nothing.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import ClassVar

from floatpage.model.document import (
    BlockItem, CalendarItem, Page, PictureItem, Project, TextItem,
)
from floatpage.model.schema import complaints
from floatpage.typeset.calendar_panel import Rect, layout_calendar
from floatpage.model.picture_files import is_merge_placeholder
from floatpage.typeset.errors import RenderError
from floatpage.typeset.pictures import PicturePlan, materialize, plan_picture
from floatpage.typeset.templates import SAFE_PATH
from floatpage.typeset.fonts import FaceKey, font_path, metrics_for
from floatpage.typeset.text_layout import (
    RunGroup, face_for, fit_in_box, fit_warnings, missing_glyph_warning,
    place_lines,
)
from floatpage.typeset.roles import RoleFits, fit_item


@dataclass(frozen=True)
class PlacedItem:
    """What every placed item has: its id, a label that names it in messages, and its marker
    (its number in the .tex, which maps a TeX error back to the item). `kind` names the
    template that prints it, latex_templates/items/KIND.tex.j2."""

    item_id: str
    label: str
    marker: int = field(default=0, kw_only=True)
    kind: ClassVar[str]


@dataclass(frozen=True)
class PlacedText(PlacedItem):
    kind: ClassVar[str] = "text"
    groups: tuple[RunGroup, ...]


@dataclass(frozen=True)
class PlacedPicture(PlacedItem):
    kind: ClassVar[str] = "picture"
    left_mm: float
    top_mm: float
    w_mm: float
    h_mm: float
    plan: PicturePlan
    clip: Rect | None = None  # its frame, where the picture covers (and overflows) it


@dataclass(frozen=True)
class PlacedBlock(PlacedItem):
    kind: ClassVar[str] = "block"
    rect: Rect
    color: str
    opacity: float


@dataclass(frozen=True)
class PlacedCalendar(PlacedItem):
    kind: ClassVar[str] = "calendar"
    rect: Rect
    color: str
    groups: tuple[RunGroup, ...]
    rules: tuple[tuple[float, float, float, float], ...]
    weekend: tuple[Rect, ...]


@dataclass
class PlacedPage:
    page_id: str
    w_mm: float
    h_mm: float
    background: list[PlacedItem] = field(default_factory=list)  # a block or a picture
    items: list[PlacedItem] = field(default_factory=list)
    print_setup: object = None  # print_marks.PrintSetup for `render --print`


@dataclass
class PlacedDocument:
    title: str
    pages: list[PlacedPage]
    faces: list[tuple[FaceKey, Path]]
    colors: list[str]
    pictures: list[PicturePlan]
    warnings: list[str]
    labels: list[str] = field(default_factory=list)  # marker number -> "item ... on page ..."
    picture_dir: Path | None = None  # for \graphicspath, when TeX can take the path


def item_label(item, page: Page) -> str:
    return f'item "{item.id}" on page "{page.id}"'


def check_item(item, label: str) -> None:
    """Refuse what the loader would have refused, for projects built in code (the editor, merge),
    with the model's own checks and words."""
    problems = complaints(item)
    if problems:
        name, complaint = problems[0]
        raise RenderError(f'{label}: "{name}" {complaint} (change it in the editor or the project '
                          "file, or undo the edit that made it)")


def rect_of(item) -> Rect:
    return Rect(item.x - item.w / 2, item.y - item.h / 2, item.x + item.w / 2, item.y + item.h / 2)


def place_text(item: TextItem, label: str, warnings: list[str],
               roles: RoleFits | None = None) -> PlacedText | None:
    """The text's lines, at its own size (`size_pt`), its role's (``roles``, from
    typeset.roles) or the largest its box holds."""
    fit, missing, face = roles.fit_of(item) if roles else fit_item(item, {})
    warnings += fit_warnings(label, face, fit, missing)
    if item.size_pt and fit.lines and fit.font_pt < item.size_pt * (1 - 1e-3):
        warnings.append(f"{label}: the text does not fit its box at its own size of "
                        f"{item.size_pt:g} pt, so it is set at {fit.font_pt:.1f} pt (enlarge "
                        "the box, shorten the text or lower its size)")
    if not fit.lines:
        return None
    runs = place_lines(fit, None, item.x - item.w / 2, item.y - item.h / 2, item.h,
                       widths_mm=item.w, align=item.align,
                       block_em=roles.block_of(item, fit) if roles else None)
    return PlacedText(item.id, label, (RunGroup(face, fit.font_pt, item.color, runs),))


# A frame whose shape is within this of the picture's is filled as it is (a rounding of the
# size to 0.01 mm is no reason to crop a picture by a pixel).
SAME_SHAPE = 0.002


def framed_picture(item_id: str, label: str, frame: Rect, plan: PicturePlan) -> PlacedPicture:
    """The picture filling its frame, never distorted: in a frame of another shape (a box the
    user drew, or one the editor let change shape) it is scaled, proportions kept, to cover
    the frame, centred, and clipped to it, as a layout program's "fill frame
    proportionally".  Stretched to the frame, photos printed up to 65 % squashed.  A PDF's
    own shape is not read here: it fills its frame as it is drawn."""
    w, h = frame.right_mm - frame.left_mm, frame.bottom_mm - frame.top_mm
    if plan.pixel_size == (0, 0) or abs(plan.aspect / (w / h) - 1) <= SAME_SHAPE:
        return PlacedPicture(item_id, label, frame.left_mm, frame.top_mm, w, h, plan)
    scale = max(w / plan.aspect, h)  # the height of the picture drawn
    drawn_w, drawn_h = scale * plan.aspect, scale
    return PlacedPicture(item_id, label, frame.left_mm + (w - drawn_w) / 2,
                         frame.top_mm + (h - drawn_h) / 2, drawn_w, drawn_h, plan, clip=frame)


@dataclass
class DocumentFits:
    """Every text of a document fitted (``roles``) and every calendar laid out, once, for
    the passes that read one unchanged project: `floatpage check` fitted each text and laid
    out each calendar twice, for its fit warnings (text_warnings) and again for its contrast
    notes (place_document).  Keyed by id() of the item, as RoleFits: the project must not
    change while they are used."""

    roles: RoleFits
    calendars: dict[int, object] = field(default_factory=dict)

    @classmethod
    def of(cls, project: Project) -> "DocumentFits":
        return cls(RoleFits.of(project))

    def calendar(self, item: CalendarItem):
        found = self.calendars.get(id(item))
        if found is None:
            found = self.calendars[id(item)] = layout_calendar(item)
        return found


def place_calendar(item: CalendarItem, label: str, warnings: list[str],
                   fits: DocumentFits) -> PlacedCalendar:
    layout = fits.calendar(item)
    if layout.missing:
        warnings.append(missing_glyph_warning(label, layout.groups[0].face, list(layout.missing)))
    return PlacedCalendar(item.id, label, rect_of(item), item.color, layout.groups, layout.rules,
                          layout.weekend)


def merge_template_error(label: str, path: str) -> RenderError:
    return RenderError(f'{label}: picture "{path}" is filled from a data column; this is a '
                       "merge template: make its documents with `floatpage merge TEMPLATE DATA "
                       "-o OUTDIR`")


def place_background(project: Project, page: Page) -> list:
    background = page.background
    if background is None:
        return []
    label = f'the background of page "{page.id}"' + (
        f' (picture file "{background.picture}")' if background.picture else '')
    whole = Rect(0.0, 0.0, page.width_mm, page.height_mm)
    if background.picture:
        # as for a picture item (it said "cannot be read", of the name with its braces)
        if is_merge_placeholder(background.picture, project.base_dir):
            raise merge_template_error(f'the background of page "{page.id}"', background.picture)
        plan = plan_picture(project.base_dir / background.picture, page.width_mm, page.height_mm,
                            label, cover=True)
        # Cover the page, keeping the picture's proportions; the clip trims the overflow.
        scale = max(page.width_mm / plan.aspect, page.height_mm)
        w, h = scale * plan.aspect, scale
        if plan.pixel_size == (0, 0):
            w, h = page.width_mm, page.height_mm
        return [PlacedPicture("background", label, (page.width_mm - w) / 2,
                              (page.height_mm - h) / 2, w, h, plan, clip=whole)]
    if background.color:
        check_item(background, label)
        return [PlacedBlock("background", label, whole, background.color, 1.0)]
    return []


def paint_order(index: int, item) -> tuple[int, bool, int]:
    """Items print by z; at one z, words (texts, calendars) over pictures and blocks, then in
    file order.  In file order alone, a text listed before a picture it met (a page too
    full to part them, or a title put on a photo) printed hidden under it."""
    return (item.z, isinstance(item, (TextItem, CalendarItem)), index)


def place_document(project: Project, fits: DocumentFits | None = None) -> PlacedDocument:
    """The document as it will print; ``fits``, if given, are this project's own (DocumentFits)."""
    warnings: list[str] = []
    pages = []
    fits = fits if fits is not None else DocumentFits.of(project)
    roles = fits.roles
    for page in project.pages:
        placed_page = PlacedPage(page.id, page.width_mm, page.height_mm,
                                 background=place_background(project, page))
        ordered = sorted(enumerate(page.items), key=lambda pair: paint_order(*pair))
        for _, item in ordered:
            label = item_label(item, page)
            check_item(item, label)
            if isinstance(item, TextItem):
                made = place_text(item, label, warnings, roles)
            elif isinstance(item, PictureItem):
                if is_merge_placeholder(item.path, project.base_dir):
                    raise merge_template_error(label, item.path)
                plan = plan_picture(project.base_dir / item.path, item.w, item.h, label,
                                    cover=True)
                made = framed_picture(item.id, f'{label} (picture file "{item.path}")',
                                      rect_of(item), plan)
            elif isinstance(item, BlockItem):
                made = PlacedBlock(item.id, label, rect_of(item), item.color,
                                   min(1.0, max(0.0, float(item.opacity))))
            elif isinstance(item, CalendarItem):
                made = place_calendar(item, label, warnings, fits)
            else:
                raise TypeError(f"unknown item kind {type(item).__name__}")
            if made is not None:
                placed_page.items.append(made)
        pages.append(placed_page)
    labels: list[str] = []
    for page in pages:
        for group in (page.background, page.items):
            for index, placed in enumerate(group):
                group[index] = replace(placed, marker=len(labels))
                labels.append(placed.label)
    faces: dict[FaceKey, None] = {}
    colors: dict[str, None] = {}
    pictures: dict[Path, PicturePlan] = {}
    for page in pages:
        for placed in page.background + page.items:
            for group in getattr(placed, "groups", ()):
                faces[group.face] = None
                colors[group.color.lower()] = None
            if hasattr(placed, "color"):
                colors[placed.color.lower()] = None
            if isinstance(placed, PlacedPicture):
                pictures[placed.plan.cache_path] = placed.plan
    folders = {plan.cache_path.parent for plan in pictures.values()}
    picture_dir = folders.pop() if len(folders) == 1 else None
    if picture_dir is not None and not SAFE_PATH.match(str(picture_dir)):
        picture_dir = None
    return PlacedDocument(project.title, pages, [(face, font_path(face.plain)) for face in faces],
                         list(colors), list(pictures.values()), warnings, labels, picture_dir)


def text_warnings(project: Project, fits: DocumentFits | None = None) -> list[str]:
    """Fit warnings for texts and calendars only (no picture files are read)."""
    warnings: list[str] = []
    fits = fits if fits is not None else DocumentFits.of(project)
    roles = fits.roles
    for page in project.pages:
        for item in page.items:
            if isinstance(item, TextItem):
                place_text(item, item_label(item, page), warnings, roles)
            elif isinstance(item, CalendarItem):
                place_calendar(item, item_label(item, page), warnings, fits)
    return warnings


def materialize_pictures(document: PlacedDocument) -> None:
    """Write every picture's cached file; one that cannot be converted (a PNG whose pixels
    stop short, which its header check cannot see) is named by its item and file: the message
    was 'picture "/abs/path" could not be converted: image file is truncated', no item, no fix."""
    labels = {placed.plan.cache_path: placed.label for page in document.pages
              for placed in page.background + page.items if isinstance(placed, PlacedPicture)}
    for plan in document.pictures:
        try:
            materialize(plan)
        except (OSError, ValueError) as error:
            label = labels.get(plan.cache_path, f'picture "{plan.source}"')
            raise RenderError(f"{label}: the picture could not be converted ({error}); it may "
                              "be cut short or damaged: export it again, or use another "
                              "picture") from None
