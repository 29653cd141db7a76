"""The work a worker process does for one chunk of records, and what it sends back.

A chunk travels as plain data (ChunkTask), so the same function runs in a local process
pool and on a Dask worker on another machine. Pictures come from a shared path, or travel
inside the task (`shipped`) and are unpacked into a private folder on the worker.
"""

from __future__ import annotations

import functools
import hashlib
import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from floatpage.merge.record_layout import RecordFailure, lay_out_record
from floatpage.merge.records import Record
from floatpage.merge.template import MergeTemplate
from floatpage.model.errors import FloatpageError
from floatpage.model.save import dump_project
from floatpage.typeset.batch import typeset_batch
from floatpage.typeset.errors import EngineDidNotStart
from floatpage.typeset.placed import place_document
from floatpage.typeset.text_layout import DOES_NOT_FIT_HINT


@dataclass(frozen=True)
class TemplateSource:
    """The template as text plus where its pictures are; hashable, so workers cache it."""

    path: str        # where it was read (names in messages; its folder, for shared pictures)
    text: str
    allow_outside: bool = False
    shipped: tuple[tuple[str, bytes], ...] = ()  # (relative path, bytes): the template's pictures


@dataclass
class ChunkTask:
    template: TemplateSource
    records: list[Record]
    names: list[str]
    toml_picture_prefix: str | None = None  # write each record's .toml; paths get this prefix
    shipped: dict[str, bytes] = field(default_factory=dict)  # the records' pictures, if sent


@dataclass
class RecordResult:
    number: int
    line: int
    name: str
    reason: str = ""
    warnings: list[str] = field(default_factory=list)
    # (what, words) of each text printed around an empty column (record_layout)
    empty_columns: list[tuple[str, str]] = field(default_factory=list)
    pdf: bytes | None = None
    toml: str | None = None
    pages: int = 0

    @property
    def ok(self) -> bool:
        return not self.reason


@functools.lru_cache(maxsize=4)
def template_on_worker(source: TemplateSource) -> tuple[MergeTemplate, Path]:
    """Load (once per process) the template; with shipped pictures, in a private folder."""
    if not source.shipped and Path(source.path).is_file():
        template = MergeTemplate(Path(source.path), allow_outside_files=source.allow_outside)
        return template, template.project.base_dir
    folder = Path(tempfile.mkdtemp(prefix="floatpage-merge-"))
    unpack(folder, dict(source.shipped))
    copy = folder / Path(source.path).name
    copy.write_text(source.text, encoding="utf-8")
    return MergeTemplate(copy, allow_outside_files=source.allow_outside), folder


def unpack(folder: Path, files: dict[str, bytes]) -> None:
    for relative, data in files.items():
        target = (folder / relative).resolve()
        if not str(target).startswith(str(folder.resolve()) + os.sep):
            continue  # only paths inside the folder were shipped; never write outside it
        target.parent.mkdir(parents=True, exist_ok=True)
        if not target.exists():
            target.write_bytes(data)


def run_chunk(task: ChunkTask) -> list[RecordResult]:
    """Lay out every record of the chunk, typeset the good ones in one engine run."""
    template, root = template_on_worker(task.template)
    if task.shipped:
        unpack(root, task.shipped)
    results, documents, made = [], [], []
    for record, name in zip(task.records, task.names):
        result = RecordResult(record.number, record.line, name)
        results.append(result)
        if record.problem:
            result.reason = record.problem
            continue
        try:
            project = lay_out_record(template, record.values, root, result.empty_columns)
            document = place_document(project)
        except RecordFailure as failure:
            result.reason = naming_columns(str(failure), template.uses)
            continue
        except FloatpageError as error:
            result.reason = str(error)
            continue
        too_long = [w for w in document.warnings if w.endswith(DOES_NOT_FIT_HINT)]
        if too_long:
            result.reason = naming_columns(too_long[0], template.uses)
            continue
        result.warnings = list(document.warnings)
        result.pages = len(document.pages)
        if task.toml_picture_prefix is not None:
            result.toml = record_toml(project, task.toml_picture_prefix)
        documents.append(document)
        made.append(result)
    typeset_chunk(documents, made)
    return results


def naming_columns(reason: str, uses) -> str:
    """A record's failure with the data columns that fed its item: the report names the
    record's line, and the user fixes a value in the data, not the template's item id (a
    subtitle too long for its box is column first_name's doing, not item "greeting"'s)."""
    for use in uses:
        if reason.startswith(use.where + ":"):
            names = ", ".join(f'"{name}"' for name in use.names)
            plural = "s" if len(use.names) > 1 else ""
            return f"{reason} [data column{plural} {names}]"
    return reason


def typeset_chunk(documents: list, results: list[RecordResult]) -> None:
    """One engine run for all; if it fails, each half is run again, and so on down to the
    records that fail alone: a bad record in a chunk of 128 costs 15 runs, not 128."""
    if not documents:
        return
    try:
        pdfs = typeset_batch(documents)
    except EngineDidNotStart:
        raise  # no record is at fault: the merge stops, saying so once
    except FloatpageError as error:
        if len(documents) == 1:
            results[0].reason = engine_failure(error, documents[0])
        else:
            half = len(documents) // 2
            typeset_chunk(documents[:half], results[:half])
            typeset_chunk(documents[half:], results[half:])
        return
    for result, pdf in zip(results, pdfs):
        result.pdf = pdf


def engine_failure(error: FloatpageError, document) -> str:
    """A record's failed engine run, for report.csv: the log's errors with their items (the
    log itself went with the build folder, so its path is left out). An error LuaTeX reports
    at shipout (a damaged picture) lies in no item: then the record's pictures are named."""
    errors = getattr(error, "errors", None)
    if not errors:
        return f"LuaLaTeX could not typeset it: {error}"
    reason = "LuaLaTeX could not typeset it: " + "; ".join(str(found) for found in errors)
    if not any(found.item for found in errors) and document.pictures:
        reason += " (its pictures: " + ", ".join(str(plan.source) for plan in document.pictures) + ")"
    return reason


def record_toml(project, prefix: str) -> str:
    """The settled record as a project file that opens from the output folder."""
    for page in project.pages:
        for item in page.items:
            if item.kind == "picture":
                item.path = os.path.normpath(os.path.join(prefix, item.path))
        if page.background is not None and page.background.picture:
            page.background.picture = os.path.normpath(os.path.join(prefix,
                                                                    page.background.picture))
    text = dump_project(project)
    return text + "\n[files]\nallow_outside = true  # the pictures stay beside the template\n"


def input_digest(*parts: bytes) -> str:
    digest = hashlib.sha256()
    for part in parts:
        digest.update(len(part).to_bytes(8, "big"))
        digest.update(part)
    return digest.hexdigest()
