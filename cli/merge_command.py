"""`floatpage merge TEMPLATE DATA -o OUTDIR`: the command line of merge (the work: merge/)."""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import Callable

from floatpage.model.errors import FloatpageError, printable

EXIT_SOME_RECORDS_FAILED = 3


def positive(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if value < 1:
        raise argparse.ArgumentTypeError("must be 1 or more")
    return value


def add_merge_parser(commands, allow_outside_option) -> None:
    merge = commands.add_parser(
        "merge", help="one personalised PDF per record of a CSV or JSON Lines file",
        description="Fill the template's {column} placeholders from each record of DATA, lay "
                    "the page out again for that record, and typeset one PDF per record. "
                    f"Exit status: 0 all made, {EXIT_SOME_RECORDS_FAILED} when some records "
                    "failed (see OUTDIR/report.csv), 1 when nothing could start.")
    merge.add_argument("template", help="the template project (.toml) with {column} placeholders")
    merge.add_argument("data", help="the records: .csv with a header line, or .jsonl")
    merge.add_argument("-o", "--output", required=True, metavar="OUTDIR",
                       help="folder for the PDFs and report.csv (created if missing)")
    merge.add_argument("--name", metavar="PATTERN",
                       help='file names from columns, e.g. "{id}-{surname}" (default: record-00001)')
    merge.add_argument("--combined", action="store_true",
                       help="also write OUTDIR/combined.pdf, every record in order, for printing")
    merge.add_argument("--toml", action="store_true",
                       help="also write each record's settled project, to open in the editor")
    merge.add_argument("--prune", action="store_true",
                       help="remove the PDFs an earlier run made here for records the data "
                            "no longer names (a record taken out, a name changed)")
    merge.add_argument("--force", action="store_true",
                       help="redo every record, even those whose inputs have not changed")
    merge.add_argument("--chunk-size", type=positive, default=None, metavar="N",
                       help="records per LuaLaTeX run (default: up to 128, fewer towards the "
                            "end so every worker has work); the PDFs do not depend on it")
    merge.add_argument("--workers", type=positive, default=None, metavar="N",
                       help="worker processes (default: one per core)")
    merge.add_argument("--dask", metavar="ADDRESS",
                       help='run on a Dask scheduler (tcp://host:8786), or "local" for a '
                            "LocalCluster on this machine")
    merge.add_argument("--pictures", choices=("shared", "ship"), default="shared",
                       help="workers read pictures from the same path (shared) or receive them "
                            "with each task (ship); default shared")
    merge.add_argument("-q", "--quiet", action="store_true", help="no progress output")
    allow_outside_option(merge)
    merge.set_defaults(run=cmd_merge)


def cmd_merge(args: argparse.Namespace) -> int:
    from floatpage.merge.run import Merge, MergeOptions

    refuse_no_folder_name(args.output)
    merge = Merge(MergeOptions(
        template=Path(args.template), data=Path(args.data), outdir=Path(args.output),
        name=args.name, combined=args.combined, write_toml=args.toml, force=args.force,
        prune=args.prune,
        chunk_size=args.chunk_size or 0, workers=args.workers or 0, dask=args.dask,
        ship_pictures=args.pictures == "ship", allow_outside_files=args.allow_outside_files))
    for note in merge.notes:
        print(f"note: {printable(note)}", file=sys.stderr)
    with merge_progress(args.quiet) as show:
        summary = merge.run(show)
    tell_empty_columns(summary.empty_columns, Path(args.data), summary.report)
    print(f"{summary.made} made, {summary.unchanged} unchanged, {summary.failed} failed of "
          f"{summary.records} record(s) in {summary.seconds:.1f} s; report: {printable(str(summary.report))}")
    if summary.combined:
        print(f"combined PDF: {printable(str(summary.combined))}")
    tell_other_records(summary.others, Path(args.output), args.prune)
    tell_renamed(summary.renamed, Path(args.data), args.name)
    if summary.failed:
        print(f"floatpage: {summary.failed} record(s) failed; their reasons are in "
              f"{printable(str(summary.report))}", file=sys.stderr)
    if summary.outdated:  # only failed records lose a PDF
        shown = first_few([f"{name}.pdf" for name in summary.outdated])
        print(f"floatpage: {len(summary.outdated)} of them had a PDF an earlier run made from "
              f"other data or another template ({printable(shown)}); it was removed, so that the folder holds no "
              f"copy out of date: mend the data and run merge again", file=sys.stderr)
    return EXIT_SOME_RECORDS_FAILED if summary.failed else 0


def refuse_no_folder_name(name: str) -> None:
    """`-o ""` (a Makefile's variable left empty) wrote every record's PDF, report.csv and
    the run's keys into the current folder, among the template and the data; `-o -` made a
    folder called `-`.  `-o .` still writes here, as asked."""
    if name == "-":
        raise FloatpageError("-o -: merge writes a folder of PDFs, not to standard output; "
                             "name the folder, e.g. -o out")
    if not name.strip():
        raise FloatpageError(f"-o {name!r} names no folder (an empty variable in a "
                             "Makefile?); name the folder for the PDFs, e.g. -o out (or -o . "
                             "for this one)")


def tell_renamed(clashes: list, data: Path, pattern: str | None) -> None:
    """Records whose --name another record had already: the first few in full, then a count
    (a key column that repeats is mostly one customer twice, and each got a card)."""
    for number, line, name, base, (first, first_line) in clashes[:EMPTY_COLUMNS_SHOWN]:
        print(f"warning: record {number} (line {line} of {printable(str(data))}) is named "
              f"{printable(name)}: --name {printable(repr(pattern))} gave it {printable(base)}, "
              f"the name of record {first} (line {first_line}); if they are one record twice, "
              f"take one out of the data", file=sys.stderr)
    if len(clashes) > EMPTY_COLUMNS_SHOWN:
        print(f"warning: {len(clashes) - EMPTY_COLUMNS_SHOWN} more record(s) renamed so; "
              "their names are in report.csv", file=sys.stderr)


def tell_other_records(names: list[str], outdir: Path, pruned: bool) -> None:
    """The PDFs an earlier run left for records this data no longer names: removed (--prune)
    on stdout, else a note on stderr, as a folder printed whole would print them too."""
    if not names:
        return
    shown = first_few([f"{name}.pdf" for name in names])
    if pruned:
        print(f"removed {len(names)} record(s) this data no longer names: {printable(shown)}")
        return
    print(f"note: {printable(str(outdir))} holds {len(names)} PDF(s) an earlier run made for "
          f"records this data no longer names ({printable(shown)}); they are not in "
          f"report.csv or combined.pdf: remove them before printing the folder, or run again "
          f"with --prune", file=sys.stderr)


EMPTY_COLUMNS_SHOWN = 10  # kinds of empty column told in full; record numbers per kind


def first_few(names: list[str]) -> str:
    """The first EMPTY_COLUMNS_SHOWN names, then how many more: a terminal line, not a list."""
    more = len(names) - EMPTY_COLUMNS_SHOWN
    return ", ".join(names[:EMPTY_COLUMNS_SHOWN]) + (f" and {more} more" if more > 0 else "")


def tell_empty_columns(empty: list[tuple[int, int, str, str]], data: Path, report) -> None:
    """Warn of the records made with words around an empty column ("Dear ,"), in record
    order: for each column and item, the first record in full (its number, its line in the
    data, the column, the item, what it prints), then the other records it happened to; a
    file of 10,000 rows with an empty column is 10,000 rows of report.csv, not of screen."""
    kinds: dict[str, list[tuple[int, int, str]]] = {}
    for number, line, what, words in sorted(empty):
        kinds.setdefault(what, []).append((number, line, words))
    for what, records in list(kinds.items())[:EMPTY_COLUMNS_SHOWN]:
        number, line, words = records[0]
        print(f"warning: record {number} (line {line} of {printable(str(data))}): "
              f"{printable(words)}", file=sys.stderr)
        if len(records) > 1:
            others = [str(other) for other, _, _ in records[1:]]
            listed = first_few(others)
            print(f"warning: the same in {len(others)} more record(s): {listed}; their lines "
                  f"are in {printable(str(report))}", file=sys.stderr)
    if len(kinds) > EMPTY_COLUMNS_SHOWN:
        print(f"warning: {len(kinds) - EMPTY_COLUMNS_SHOWN} more empty column(s) in other "
              f"texts; each record's is in {printable(str(report))}", file=sys.stderr)


class merge_progress:
    """A bar with records per second and ETA on a terminal; a plain line every few seconds
    (and at the end) in a pipe or a CI log; nothing with --quiet."""

    PLAIN_EVERY_S = 5.0

    def __init__(self, quiet: bool):
        self.quiet = quiet
        self.bar = None
        self.started = time.monotonic()
        self.last_line = 0.0
        self.last_done = -1

    def __enter__(self) -> Callable[[int, int, int], None]:
        if not self.quiet and sys.stderr.isatty():
            from rich.console import Console
            from rich.progress import (BarColumn, MofNCompleteColumn, Progress, TextColumn,
                                       TimeRemainingColumn)

            self.bar = Progress(TextColumn("merging"), BarColumn(), MofNCompleteColumn(),
                                TextColumn("{task.fields[rate]} records/s"),
                                TextColumn("{task.fields[failed]} failed"),
                                TextColumn("ETA"), TimeRemainingColumn(),
                                console=Console(stderr=True), transient=True)
            self.bar.start()
            self.task = self.bar.add_task("", total=None, rate="–", failed=0)
        return self.show

    def show(self, done: int, total: int, failed: int) -> None:
        if self.quiet:
            return
        elapsed = max(time.monotonic() - self.started, 1e-6)
        rate = done / elapsed
        if self.bar is not None:
            self.bar.update(self.task, completed=done, total=total, rate=f"{rate:.1f}",
                            failed=failed)
            return
        now = time.monotonic()
        if done == self.last_done:
            return  # the end is reported once, though the run reports it again when done
        if now - self.last_line >= self.PLAIN_EVERY_S or done == total:
            self.last_line, self.last_done = now, done
            left = (total - done) / rate if rate > 0 else 0
            print(f"merge: {done}/{total} records, {failed} failed, {rate:.1f} records/s, "
                  f"ETA {left:.0f} s", file=sys.stderr, flush=True)

    def __exit__(self, *exc) -> None:
        if self.bar is not None:
            self.bar.stop()
