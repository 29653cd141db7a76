"""`floatpage merge`, from data file to folder: check, plan, dispatch, write, report.

The template is checked against the data's columns before anything runs. Records then
stream from the data file into chunks; a record whose inputs (its values, the template,
every picture it uses) hash to the digest kept from an earlier run is skipped. Results
come back in any order and are written as they come; report.csv lists records in order.
"""

from __future__ import annotations

import hashlib
import json
import os
import stat
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Iterator

from floatpage.merge.chunk_job import ChunkTask, RecordResult, TemplateSource, input_digest
from floatpage.merge.outputs import COMBINED, Names, OutputFolder, Report, name_fields
from floatpage.merge.placeholders import fill
from floatpage.merge.pools import cores, dask_results, local_results
from floatpage.merge.records import JSON_LINES, DataFile, Record
from floatpage.merge.template import MergeTemplate
from floatpage.model.errors import FloatpageError
from floatpage.model.picture_files import is_outside
from floatpage.typeset.compile import check_engine_settings
from floatpage.typeset.pdf_split import concatenate

FORMAT = b"floatpage-merge-1"  # part of every digest: bump when output bytes change


@dataclass
class MergeOptions:
    template: Path
    data: Path
    outdir: Path
    name: str | None = None
    combined: bool = False
    write_toml: bool = False
    chunk_size: int = 0        # records per engine run; 0: chosen from the data's size
    workers: int = 0           # 0: one per core
    dask: str | None = None    # None: local pool; "local": a LocalCluster; else an address
    ship_pictures: bool = False
    force: bool = False
    allow_outside_files: bool = False
    prune: bool = False        # remove the files of records this data no longer names


@dataclass
class MergeSummary:
    records: int = 0
    made: int = 0
    unchanged: int = 0
    failed: int = 0
    seconds: float = 0.0
    notes: tuple[str, ...] = ()
    # (record, line, what, words) of each text printed around an empty column in a record
    # made (`record_layout.empty_column_words`), or skipped as unchanged since it was made
    # so, in the order the records came back
    empty_columns: list[tuple[int, int, str, str]] = field(default_factory=list)
    combined: Path | None = None
    report: Path | None = None
    # PDFs an earlier run made for records this data no longer names (a surname corrected
    # with --name "{id}-{surname}", a record taken out), by name; removed with --prune
    others: list[str] = field(default_factory=list)
    # records whose --name was another's, renamed NAME-2 (merge.outputs.Names.clashes)
    renamed: list[tuple[int, int, str, str, tuple[int, int]]] = field(default_factory=list)
    # records that failed, whose PDF from an earlier run on other data was removed
    outdated: list[str] = field(default_factory=list)


# An engine run costs about 0.5 s to start and a record 40-60 ms more, and the records of
# one run share font subsets (typeset.batch.FontSlots) while a worker settles each page
# geometry once: the longer the run, the cheaper each record. So runs of up to 128 records,
# but at most a quarter of each worker's share of the records still to come, so that the
# last runs are short and no worker waits long for another to finish (guided scheduling).
# The PDFs do not depend on where a chunk starts or ends.
MAX_AUTO_CHUNK = 128
MIN_AUTO_CHUNK = 16


def auto_chunk_size(remaining: int, total: int, workers: int) -> int:
    share = -(-remaining // (2 * workers))
    floor = min(MIN_AUTO_CHUNK, -(-total // (2 * workers)))
    return max(1, min(MAX_AUTO_CHUNK, max(floor, share)))


def open_regular(path: Path):
    """`path` open for reading if it is a regular file, else None: a picture path from the
    data may name a pipe (opening it would wait forever) or /dev/zero (it never ends)."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    except OSError:
        return None
    if not stat.S_ISREG(os.fstat(fd).st_mode):
        os.close(fd)
        return None
    return os.fdopen(fd, "rb")


def file_digest(path: Path) -> bytes:
    handle = open_regular(path)
    if handle is None:
        return b"missing"  # the worker reports why, with the record
    with handle:
        return hashlib.file_digest(handle, "sha256").digest()


def file_bytes(path: Path) -> bytes | None:
    handle = open_regular(path)
    if handle is None:
        return None
    with handle:
        return handle.read()


def refuse_swapped_arguments(template: Path, data: Path) -> None:
    """A data file where the template goes: say so, rather than report its first line as a
    TOML syntax error (a user who wrote `merge customers.csv offer.toml` saw exactly that)."""
    if template.suffix.lower() not in (".csv", ".tsv", ".txt") + JSON_LINES:
        return
    usage = "floatpage merge TEMPLATE.toml DATA.csv -o OUTDIR"
    if data.suffix.lower() == ".toml":
        raise FloatpageError(f"{template} and {data} are the wrong way round: the template "
                             f"project (.toml) comes first, then the records ({usage})")
    raise FloatpageError(f"{template}: the first file is the template, a project (.toml) with "
                         f"{{column}} placeholders; the records come second ({usage})")


class Merge:
    def __init__(self, options: MergeOptions):
        self.options = options
        refuse_swapped_arguments(options.template, options.data)
        check_engine_settings()  # no TeX, a bad setting: say so once, not once per record
        self.template = MergeTemplate(options.template,
                                      allow_outside_files=options.allow_outside_files)
        self.data = DataFile(options.data)
        self.notes = self.template.check_columns(self.data.columns, self.data.path,
                                                 name_fields(options.name))
        self.root = self.template.project.base_dir
        self.picture_uses = [use for use in self.template.uses if use.attribute != "text"]
        self.fixed_pictures = self.template_pictures()
        text = options.template.read_text(encoding="utf-8-sig")
        self.source = TemplateSource(str(options.template.resolve()), text,
                                     self.template.allow_outside,
                                     tuple(self.fixed_pictures.items()) if options.ship_pictures
                                     else ())
        self.template_digest = input_digest(
            FORMAT, text.encode("utf-8"), b"toml" if options.write_toml else b"",
            *(name.encode() + file_digest(self.root / name) for name in sorted(self.fixed_pictures)))
        inputs = [options.template, options.data] + [self.root / p for p in self.fixed_pictures]
        self.out = OutputFolder(options.outdir, inputs)
        self.toml_prefix = (os.path.relpath(self.root.resolve(), options.outdir.resolve())
                            if options.write_toml else None)

    def template_pictures(self) -> dict[str, bytes | None]:
        """The template's own pictures (no placeholder in their paths), by relative path."""
        found: dict[str, bytes | None] = {}
        for page in self.template.project.pages:
            paths = [item.path for item in page.items if item.kind == "picture"]
            if page.background is not None and page.background.picture:
                paths.append(page.background.picture)
            for path in paths:
                if "{" not in path:
                    found[path] = (file_bytes(self.root / path) if self.options.ship_pictures
                                   else None)
        return found

    def readable(self, path: str) -> bool:
        """Whether a picture path from the data may be read here: inside the template's
        folder, or anywhere with --allow-outside-files (the worker says why not)."""
        return self.template.allow_outside or not is_outside(self.root / path, self.root)

    def record_pictures(self, record: Record) -> list[str]:
        paths = []
        for use in self.picture_uses:
            page = self.template.project.page(use.page_id)
            raw = page.background.picture if use.item_id is None else page.item(use.item_id).path
            try:
                paths.append(fill(raw, record.values))
            except KeyError:
                pass
        return [path for path in paths if path.strip()]

    def digest(self, record: Record, name: str) -> str:
        values = json.dumps(record.values, sort_keys=True, ensure_ascii=False).encode("utf-8")
        pictures = [path.encode() + (file_digest(self.root / path) if self.readable(path)
                                     else b"outside") for path in self.record_pictures(record)]
        return input_digest(self.template_digest.encode(), values, name.encode(), *pictures)

    def run(self, progress: Callable[[int, int, int], None] | None = None) -> MergeSummary:
        try:
            return self.run_held(progress)
        finally:
            self.out.release()

    def run_held(self, progress: Callable[[int, int, int], None] | None) -> MergeSummary:
        """The run, with the output folder's lock held (merge.folder_lock)."""
        started = time.perf_counter()
        options = self.options
        total = sum(1 for _ in self.data.records())
        report = Report(self.out.folder)
        summary = MergeSummary(records=total, notes=tuple(self.notes), report=report.path)
        ordered = InOrder(report)
        done_names: list[str] = []
        show = progress or (lambda done, total, failed: None)
        workers = options.workers or cores()

        def chunk_size(records_read: int) -> int:
            return options.chunk_size or auto_chunk_size(total - records_read, total, workers)

        names = Names(options.name)

        def tasks() -> Iterator[ChunkTask]:
            chunk: list[tuple[Record, str, str]] = []
            size = chunk_size(0)
            for record in self.data.records():
                name = names.name_for(record.number, record.values, record.line)
                if record.problem:
                    reason = record.problem + self.failed_loses_outdated(name, None, summary)
                    ordered.add(record.number, (record.line, name, "failed", reason))
                    continue
                digest = self.digest(record, name)
                if not options.force and self.out.unchanged(name, digest, options.write_toml):
                    note, empty_columns = self.out.note(name)
                    ordered.add(record.number, (record.line, name, "unchanged", note))
                    summary.unchanged += 1
                    summary.empty_columns += [(record.number, record.line, what, words)
                                              for what, words in empty_columns]
                    continue
                chunk.append((record, name, digest))
                if len(chunk) >= size:
                    yield self.task(chunk)
                    chunk = []
                    size = chunk_size(record.number)
            if chunk:
                yield self.task(chunk)

        self.digests: dict[int, str] = {}
        results = (dask_results(tasks(), options.dask, workers) if options.dask
                   else local_results(tasks(), workers))
        failure: BaseException | None = None
        try:
            for chunk_results in results:
                for result in chunk_results:
                    self.write(result, ordered, summary)
                show(ordered.count, total, report.failed)
        except BaseException as error:
            failure = error
            raise
        finally:
            results.close()  # now, not when the traceback lets go: stops the pool's workers
            try:
                ordered.flush_all()
                report.save()
            except FloatpageError:
                if failure is None:  # else the first error (a PDF the full disk refused) says
                    raise            # what went wrong first
            self.out.flush()
            summary.failed = report.failed
            summary.seconds = time.perf_counter() - started
        show(total, total, report.failed)
        others = self.out.names_not_in(names.taken)  # only once every record is read
        summary.others = [name for name in others if self.out.pdf(name).is_file()]
        summary.renamed = names.clashes
        if options.prune:
            for name in others:  # a key whose PDF you removed goes too
                self.out.remove_record(name)
        if options.combined:
            combined = self.out.folder / COMBINED
            if concatenate((self.out.pdf(name) for name in report.made_names()), combined):
                summary.combined = combined
        return summary

    def task(self, chunk: list[tuple[Record, str, str]]) -> ChunkTask:
        shipped: dict[str, bytes] = {}
        for record, _, digest in chunk:
            self.digests[record.number] = digest
            if self.options.ship_pictures:
                for path in self.record_pictures(record):
                    data = file_bytes(self.root / path) if self.readable(path) else None
                    if data is not None:  # else the worker reports why, with the record
                        shipped[path] = data
        return ChunkTask(self.source, [record for record, _, _ in chunk],
                         [name for _, name, _ in chunk], self.toml_prefix, shipped)

    def write(self, result: RecordResult, ordered: "InOrder", summary: MergeSummary) -> None:
        digest = self.digests.pop(result.number)
        note = "; ".join([words for _, words in result.empty_columns] + result.warnings)
        if result.ok and result.pdf is not None:
            problem = self.out.write_record(result.name, result.pdf, result.toml, digest,
                                            note, result.empty_columns)
            if problem:
                result.reason = problem
        if result.ok:
            summary.made += 1
            summary.empty_columns += [(result.number, result.line, what, words)
                                      for what, words in result.empty_columns]
            ordered.add(result.number, (result.line, result.name, "made", note))
        else:
            reason = result.reason + self.failed_loses_outdated(result.name, digest, summary)
            ordered.add(result.number, (result.line, result.name, "failed", reason))

    def failed_loses_outdated(self, name: str, digest: str | None, summary: MergeSummary) -> str:
        """A failed record's PDF from an earlier run on other data goes (OutputFolder.
        drop_outdated); the words its report row adds, and the name for the terminal."""
        if not self.out.drop_outdated(name, digest):
            return ""
        summary.outdated.append(name)
        return (f"; {name}.pdf, made by an earlier run from other data (or another template "
                "or --toml), was removed")


class InOrder:
    """Report rows in record order, whatever order chunks finish in."""

    def __init__(self, report: Report):
        self.report = report
        self.waiting: dict[int, tuple] = {}
        self.next = 1
        self.count = 0

    def add(self, number: int, row: tuple) -> None:
        self.waiting[number] = row
        self.count += 1
        while self.next in self.waiting:
            self.emit(self.next, self.waiting.pop(self.next))
            self.next += 1

    def emit(self, number: int, row: tuple) -> None:
        line, name, status, reason = row
        self.report.row(number, line, name, status, reason)

    def flush_all(self) -> None:
        for number in sorted(self.waiting):
            self.emit(number, self.waiting.pop(number))
