"""One record's document: placeholders filled, pictures at their own proportions, the page
settled again from the template's positions, then the quality gate.

Anything wrong with one record raises RecordFailure with a reason a person can act on;
the caller writes it to report.csv and goes on with the other records.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Mapping

from floatpage.merge.placeholders import fill
from floatpage.merge.settled_layouts import SettledLayouts
from floatpage.merge.template import FieldUse, MergeTemplate
from floatpage.model import Project
from floatpage.model.document import ItemAnchor, MAX_TEXT_CHARS
from floatpage.model.errors import FloatpageError
from floatpage.model.picture_files import is_outside, read_header
from floatpage.typeset.errors import RenderError
from floatpage.typeset.pictures import plan_picture


class RecordFailure(Exception):
    """This record cannot be made; the message says why and what to change."""


def fill_record(template: MergeTemplate, values: Mapping[str, str],
                picture_root: Path | None = None, empty: list[tuple[str, str]] | None = None
                ) -> Project:
    """The template with this record's values in place; items with empty fields dropped.
    A text not marked `drop_if_empty` that prints words around an empty column gets a line
    in ``empty`` (see `empty_column_words`)."""
    project = template.copy_project()
    root = picture_root or template.project.base_dir
    by_place = {(use.page_id, use.item_id): use for use in template.uses}
    for page in project.pages:
        kept, dropped = [], set()
        for item in page.items:
            use = by_place.get((page.id, item.id))
            if use is None:
                kept.append(item)
                continue
            if item.drop_if_empty and any(not values[name].strip() for name in use.names):
                dropped.add(item.id)
                continue
            if item.kind == "text":
                item.text = fill(item.text, values)
                if empty is not None:
                    empty += empty_column_words(use, item.text, values)
                if len(item.text) > MAX_TEXT_CHARS:
                    raise RecordFailure(f"{use.where}: the text is {len(item.text):,} characters "
                                        f"long, more than the {MAX_TEXT_CHARS:,} a text may hold")
            else:
                item.path = fill(item.path, values)
                check_picture(root, item.path, template.allow_outside, use, values)
                reshape_to_picture(item, root / item.path, page, use)
            kept.append(item)
        for item in kept:  # a follower of a dropped item stays where the template put it
            if isinstance(item.anchor, ItemAnchor) and item.anchor.target in dropped:
                item.anchor = None
        page.items = kept
        use = by_place.get((page.id, None))
        if use is not None:
            page.background.picture = fill(page.background.picture, values)
            if not page.background.picture.strip() or any(not values[name].strip()
                                                            for name in use.names):
                page.background.picture = None  # an empty column: no background picture
            else:
                check_picture(root, page.background.picture, template.allow_outside, use,
                              values)
    return project


def empty_column_words(use: FieldUse, text: str, values: Mapping[str, str]
                       ) -> list[tuple[str, str]]:
    """What a user of mail merge is told of a text whose column is empty but whose other words
    print: "Dear {first_name}," came out "Dear ," without a word (user-walk-10).  Word and
    LibreOffice print the blank too; here the record is still made, but the run names the
    column, the item and what it prints, and the way to leave the item out.  A text that is
    the column alone prints nothing, as the template asks, and is not named.  Each is
    (what: the columns and the item, the same in every record it happens to; the words)."""
    blank = [name for name in use.names if not values[name].strip()]
    if not blank or not text.strip():
        return []
    columns = ", ".join(f'"{name}"' for name in blank)
    shown = " ".join(text.split())
    shown = shown if len(shown) <= 60 else shown[:59] + "…"
    plural = "s" if len(blank) > 1 else ""
    what = f"data column{plural} {columns} {'are' if plural else 'is'} empty: {use.where}"
    return [(what, f'{what} prints "{shown}" (fill the value, or mark the item '
                   "`drop_if_empty = true` to leave it out of such records)")]


def check_picture(root: Path, relative: str, allow_outside: bool, use: FieldUse,
                  values: Mapping[str, str]) -> None:
    # "pictures/{photo}" with an empty photo is "pictures/", which read as "is a folder"
    if not relative.strip() or any(not values[name].strip() for name in use.names):
        raise RecordFailure(f"{use.where}: the picture's column is empty (mark the item "
                            "`drop_if_empty = true` to leave it out instead)")
    path = root / relative
    if not allow_outside and is_outside(path, root):  # refused before a byte of it is read
        raise RecordFailure(f'{use.where}: picture "{relative}" is outside {root}; copy it '
                            "there, or allow it with --allow-outside-files")
    header = read_header(path)
    if header.problem:
        raise RecordFailure(f'{use.where}: picture "{relative}" {header.problem} '
                            f"(paths are relative to {root})")


def reshape_to_picture(item, path: Path, page, use: FieldUse) -> None:
    """Give the box the picture's proportions: the same area as the template's box, the longer
    side no longer than the template box's longer side, and never larger than the page."""
    try:
        aspect = plan_picture(path, item.w, item.h, use.where).aspect
    except RenderError as error:
        raise RecordFailure(str(error)) from None
    if not aspect or not math.isfinite(aspect) or aspect <= 0:
        return  # a PDF picture: its box stays as the template drew it
    area, longest = item.w * item.h, max(item.w, item.h)
    w, h = math.sqrt(area * aspect), math.sqrt(area / aspect)
    shrink = min(1.0, longest / max(w, h), page.width_mm / w, page.height_mm / h)
    item.w, item.h = w * shrink, h * shrink


# One per process: pages of the same geometry settle once (see settled_layouts.py).
SETTLED = SettledLayouts()


def settle_and_gate(project: Project, layouts: SettledLayouts = SETTLED) -> None:
    """Settle every page from the template's positions (anchors kept), then demand no
    overlap and nothing off the page."""
    for page in project.pages:
        problem = layouts.settle(page, project.physics)
        if problem:
            raise RecordFailure(problem)


def lay_out_record(template: MergeTemplate, values: Mapping[str, str],
                   picture_root: Path | None = None,
                   empty: list[tuple[str, str]] | None = None) -> Project:
    try:
        project = fill_record(template, values, picture_root, empty)
        settle_and_gate(project)
    except FloatpageError as error:
        raise RecordFailure(str(error)) from None
    return project
