"""A merge template: a project whose texts and picture paths name columns of the data.

The template is checked against the data's columns before any record is laid out, so a
misspelt column fails in a second, not after a thousand records.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass
from pathlib import Path

from floatpage.model import Project, load_project
from floatpage.model.errors import FloatpageError
from floatpage.merge.placeholders import PlaceholderError, fields_in


@dataclass(frozen=True)
class FieldUse:
    """Where the template asks for columns: an item's text or path, or a page background."""

    page_id: str
    item_id: str | None  # None: the page's background picture
    attribute: str       # "text", "path" or "picture"
    names: tuple[str, ...]

    @property
    def where(self) -> str:
        if self.item_id is None:
            return f'the background of page "{self.page_id}"'
        return f'item "{self.item_id}" on page "{self.page_id}"'


class MergeTemplate:
    def __init__(self, path: Path, *, allow_outside_files: bool = False):
        self.path = Path(path)
        self.project = load_project(self.path, allow_outside_files=allow_outside_files,
                                    merge_template=True)
        if not self.project.pages:
            raise FloatpageError(f"{self.path}: the template has no pages; add a [[pages]] table")
        self.allow_outside = allow_outside_files or self.project.allow_outside_files
        self.project.source_document = None  # records are written afresh, not edited in place
        self.uses = self.find_uses()

    def find_uses(self) -> list[FieldUse]:
        uses, problems = [], []
        for page in self.project.pages:
            sources = [(item.id, "text" if item.kind == "text" else "path",
                        getattr(item, "text" if item.kind == "text" else "path", ""))
                       for item in page.items if item.kind in ("text", "picture")]
            if page.background is not None and page.background.picture:
                sources.append((None, "picture", page.background.picture))
            for item_id, attribute, value in sources:
                try:
                    names = fields_in(value)
                except PlaceholderError as error:
                    where = FieldUse(page.id, item_id, attribute, ()).where
                    problems.append(f"{self.path}: {where}, {attribute}: {error}")
                    continue
                if names:
                    uses.append(FieldUse(page.id, item_id, attribute, tuple(names)))
        if problems:
            raise FloatpageError("\n".join(problems))
        return uses

    @property
    def fields(self) -> list[str]:
        seen: dict[str, None] = {}
        for use in self.uses:
            seen.update(dict.fromkeys(use.names))
        return list(seen)

    def check_columns(self, columns: list[str], data: Path, extra_fields: list[str] = ()
                      ) -> list[str]:
        """Placeholders without a column are errors (raised); returns notes on unused columns."""
        missing = []
        for use in self.uses:
            for name in use.names:
                if name not in columns:
                    missing.append(f'{self.path}: {use.where} asks for "{{{name}}}", but '
                                   f"{data} has no column {name!r}")
        for name in extra_fields:
            if name not in columns:
                missing.append(f"--name asks for {{{name}}}, but {data} has no column {name!r}")
        if missing:
            known = ", ".join(repr(column) for column in columns) or "none"
            raise FloatpageError("\n".join(missing) + f"\n(the columns are: {known})")
        used = set(self.fields) | set(extra_fields)
        return [f"column {column!r} of {data} is used by no placeholder of {self.path}"
                for column in columns if column not in used]

    def copy_project(self) -> Project:
        return copy.deepcopy(self.project)
