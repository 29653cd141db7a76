"""Where a merge writes: one folder, names made safe and unique, nothing half-written.

Every file is written whole to a temporary name and renamed (write_whole), so Ctrl+C or a
kill never leaves a partial PDF at an output path. A record's input digest is kept in
`.floatpage-merge/NAME.key`, written after its PDF: a second run skips a record whose
digest and outputs are unchanged.

Not model.save.atomic_write, which suits one project file: it flushes every file and its
folder to disk (16 ms a record here) and lists the folder for a killed save's leftovers on
every write, which grows with the folder (34 ms a file at 20,000 PDFs). A merge lists its
folders for leftovers once, when it starts, and flushes the disk once, when it ends; a
resumed run keeps a PDF only if it ends whole, so a power cut in between costs a redo.
"""

from __future__ import annotations

import csv
import json
import os
import re
import secrets
import time
import unicodedata
from pathlib import Path

from floatpage.merge.folder_lock import lock_output_folder, unlock
from floatpage.merge.placeholders import PlaceholderError, fields_in, fill
from floatpage.model.errors import FloatpageError
from floatpage.model.atomic_file import STALE_AFTER_S, TEMPORARY_SUFFIX

STATE_DIR = ".floatpage-merge"
REPORT = "report.csv"
COMBINED = "combined.pdf"
UNSAFE = re.compile(r"[^\w.\-+=@,()\[\] ]+", re.UNICODE)
# File systems limit a name to 255 bytes; the temporary a file is written under adds ~40.
MAX_NAME_BYTES = 120
# Windows refuses these as a name's first part, whatever follows ("con.pdf", "lpt1.tar.pdf").
WINDOWS_RESERVED = {"con", "prn", "aux", "nul", *(f"com{n}" for n in range(10)),
                    *(f"lpt{n}" for n in range(10))}
REPORT_COLUMNS = ("record", "line", "name", "status", "reason")
# A name, the only report.csv cell a record's data begins, never starts as a spreadsheet
# formula: `--name {id}` with an id of `=HYPERLINK(…)` ran in the print shop's Excel.
FORMULA_START = "=+@-. "


def name_fields(pattern: str | None) -> list[str]:
    if pattern is None:
        return []
    try:
        return fields_in(pattern)
    except PlaceholderError as error:
        raise FloatpageError(f"--name {pattern!r}: {error}") from None


def safe_name(text: str, number: int) -> str:
    """A file name any file system takes: no separators, controls or leading dots, at most
    MAX_NAME_BYTES in UTF-8, and no name Windows reserves for a device."""
    text = unicodedata.normalize("NFC", text)
    text = UNSAFE.sub("-", text).strip(" .-").lstrip(FORMULA_START)
    text = re.sub(r"\s+", " ", text)
    text = text.encode("utf-8")[:MAX_NAME_BYTES].decode("utf-8", "ignore").strip(" .-")
    first, dot, rest = text.partition(".")
    if first.rstrip().casefold() in WINDOWS_RESERVED:
        text = f"{first.rstrip()}_{dot}{rest}"
    return text or f"record-{number:05d}"


class Names:
    """Record names in record order: from --name's pattern, made safe, then unique (a later
    record that would clash gets -2, -3…; case is ignored, for case-blind file systems)."""

    RESERVED = {"report", "combined"}

    def __init__(self, pattern: str | None):
        self.pattern = pattern
        self.taken: dict[str, str] = {}  # each name given, case-folded: the name as given
        self.owners: dict[str, tuple[int, int]] = {}  # a name given: (record, line) it is
        # (record, line, name, base, (record, line) that had the base): a key column that
        # repeats in the data is mostly one customer twice, and was renamed without a word
        self.clashes: list[tuple[int, int, str, str, tuple[int, int]]] = []

    def name_for(self, number: int, values: dict[str, str], line: int = 0) -> str:
        if self.pattern is None:
            base = f"record-{number:05d}"
        else:
            base = safe_name(fill(self.pattern, values), number)
        name, count = base, 1
        while name.casefold() in self.taken or name.casefold() in self.RESERVED:
            count += 1
            name = f"{base}-{count}"
        self.taken[name.casefold()] = name
        self.owners[name.casefold()] = (number, line)
        if base.casefold() in self.owners and name != base:  # not "report", "combined"
            self.clashes.append((number, line, name, base, self.owners[base.casefold()]))
        return name


def write_whole(path: Path, data: bytes) -> None:
    """`data` at `path`, whole or not at all: written to a hidden temporary beside it, then
    renamed over it (a link at `path` is replaced, never written through)."""
    temporary: Path | None = path.with_name(
        f".{path.name}.{os.getpid()}.{secrets.token_hex(4)}{TEMPORARY_SUFFIX}")
    try:
        with open(temporary, "xb") as handle:
            handle.write(data)
        os.replace(temporary, path)
        temporary = None
    except OSError as error:
        raise FloatpageError(f"{path}: could not write it ({error.strerror or error}); check "
                             "that the output folder is writable and the disk not full") from None
    finally:  # also on Ctrl+C: no temporary stays behind
        if temporary is not None:
            temporary.unlink(missing_ok=True)


def remove_leftovers(folder: Path, *, now: float | None = None) -> None:
    """Temporaries of a merge that was killed (SIGKILL, a power cut): older than a write."""
    now = time.time() if now is None else now
    for entry in os.scandir(folder):
        if entry.name.startswith(".") and entry.name.endswith(TEMPORARY_SUFFIX):
            try:
                if entry.is_file(follow_symlinks=False) and \
                        now - entry.stat(follow_symlinks=False).st_mtime > STALE_AFTER_S:
                    os.unlink(entry.path)
            except OSError:
                pass


def ends_whole(pdf: Path) -> bool:
    """Whether a PDF ends as a written one does (its last bytes hold %%EOF)."""
    try:
        with pdf.open("rb") as handle:
            handle.seek(max(0, pdf.stat().st_size - 32))
            return b"%%EOF" in handle.read()
    except OSError:
        return False


class OutputFolder:
    def __init__(self, folder: Path, inputs: list[Path]):
        self.folder = Path(folder)
        if self.folder.is_symlink() or (self.folder.exists() and not self.folder.is_dir()):
            raise FloatpageError(f"{self.folder}: the output folder must be a folder (not a file "
                                 "or a link); name a new or existing folder with -o")
        try:
            (self.folder / STATE_DIR).mkdir(parents=True, exist_ok=True)
        except OSError as error:
            raise FloatpageError(f"{self.folder}: cannot create the output folder "
                                 f"({error.strerror})") from None
        state = self.folder / STATE_DIR
        if state.is_symlink():  # mkdir took the link's folder, and the keys went there
            raise FloatpageError(f"{state}: is a symbolic link; floatpage keeps its merge state "
                                 "in a folder of its own there (remove the link, or name "
                                 "another output folder with -o)")
        self.lock = lock_output_folder(self.folder, state)  # before another run's files go
        try:
            remove_leftovers(self.folder)
            remove_leftovers(self.folder / STATE_DIR)
            self.inputs = {self.key(path) for path in inputs}
            for fixed in (self.folder / REPORT, self.folder / COMBINED):
                problem = self.refuse(fixed)
                if problem:
                    raise FloatpageError(f"{problem} (floatpage merge writes {fixed.name} "
                                         "there)")
        except BaseException:
            self.release()
            raise

    def release(self) -> None:
        """Let another merge write here (the run's end; a process's exit does it anyway)."""
        unlock(self.lock)
        self.lock = None

    @staticmethod
    def key(path: Path) -> str:
        return os.path.realpath(path)

    def pdf(self, name: str) -> Path:
        return self.folder / f"{name}.pdf"

    def toml(self, name: str) -> Path:
        return self.folder / f"{name}.toml"

    def digest_file(self, name: str) -> Path:
        return self.folder / STATE_DIR / f"{name}.key"

    def note_file(self, name: str) -> Path:
        return self.folder / STATE_DIR / f"{name}.note"

    def note(self, name: str) -> tuple[str, list[tuple[str, str]]]:
        """What report.csv said beside "made" when the record was made (a column printed
        empty, a text set small), and the empty columns it was made with, each (what,
        words) as `record_layout.empty_column_words` gave them: a run that skips the record
        as unchanged says both again, where the report said nothing and then the terminal
        said nothing (user-walk-12a: a re-run showed no "Dear ," warning).  A note kept as
        plain text by an older floatpage is the report's words alone."""
        try:
            text = self.note_file(name).read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError):
            return "", []
        try:
            kept = json.loads(text)
            return str(kept["note"]), [(str(what), str(words))
                                       for what, words in kept["empty_columns"]]
        except (ValueError, KeyError, TypeError):
            return text, []

    def unchanged(self, name: str, digest: str, with_toml: bool) -> bool:
        try:
            if self.digest_file(name).read_text(encoding="ascii") != digest:
                return False
        except (OSError, UnicodeDecodeError):
            return False
        return ends_whole(self.pdf(name)) and (not with_toml or self.toml(name).is_file())

    def refuse(self, path: Path) -> str:
        """Why `path` may not be written ("" if it may): never an input, link or device."""
        if self.key(path) in self.inputs:
            return f"{path} is one of the merge's inputs; choose another --name or -o"
        if path.is_symlink():
            return f"{path} is a symbolic link; floatpage writes only regular files"
        if path.exists() and not path.is_file():
            return f"{path} is not a regular file; floatpage writes only regular files"
        return ""

    def write_record(self, name: str, pdf: bytes, toml: str | None, digest: str,
                     note: str = "", empty_columns: list[tuple[str, str]] = ()) -> str:
        """Write the record's files ("" if written, else the reason they were not), and
        keep its report note for a later run that finds it unchanged."""
        targets = [(self.pdf(name), pdf)]
        if toml is not None:
            targets.append((self.toml(name), toml.encode("utf-8")))
        for path, _ in targets:
            problem = self.refuse(path)
            if problem:
                return problem
        self.digest_file(name).unlink(missing_ok=True)  # stale until all its files are new
        for path, data in targets:
            write_whole(path, data)
        if note:
            kept = {"note": note, "empty_columns": [list(pair) for pair in empty_columns]}
            write_whole(self.note_file(name), json.dumps(kept, ensure_ascii=False).encode("utf-8"))
        else:
            self.note_file(name).unlink(missing_ok=True)
        write_whole(self.digest_file(name), digest.encode("ascii"))
        return ""

    def names_not_in(self, taken: dict[str, str]) -> list[str]:
        """The records an earlier run made here (their .key) that are none of this run's
        (``taken``: each name given, case-folded, to the name as given): `1001-Doe.pdf` stayed
        beside `1001-Doe-Smith.pdf` once the surname was corrected, and `lpr out/*.pdf` printed
        both.  A name that differs only in case is another record's where the disk tells the
        two files apart: `1002-müller.pdf` stayed beside `1002-Müller.pdf` on Linux, where on
        a case-blind disk they are one file."""
        state = self.folder / STATE_DIR
        return sorted(name for name in (entry.name[:-len(".key")] for entry in os.scandir(state)
                                        if entry.name.endswith(".key")
                                        and entry.is_file(follow_symlinks=False))
                      if not self.same_record(name, taken.get(name.casefold())))

    def same_record(self, kept: str, given: str | None) -> bool:
        """Whether the key an earlier run kept as ``kept`` is the one this run's name
        ``given`` writes: the same name, or one the disk does not tell apart from it."""
        if given is None:
            return False
        if given == kept:
            return True
        try:
            return self.digest_file(kept).samefile(self.digest_file(given))
        except OSError:  # no key under the name given: a case-sensitive disk (or it failed)
            return False

    def remove_record(self, name: str) -> None:
        """A record's files, as this merge wrote them: its key first, so a run stopped half
        way leaves nothing that counts as made."""
        for path in (self.digest_file(name), self.pdf(name), self.toml(name),
                     self.note_file(name)):
            if path.is_file() and not path.is_symlink():
                path.unlink(missing_ok=True)

    def drop_outdated(self, name: str, digest: str | None) -> bool:
        """For a record that failed: remove the files an earlier run made for it from other
        data (or another project), and say whether a PDF went. The folder kept the old PDF
        beside a report that said "failed", and `lpr out/*.pdf` printed a letter with the
        old address. Files made from this very data stay (a `--force` run that failed)."""
        try:
            made_from = self.digest_file(name).read_text(encoding="ascii")
        except (OSError, UnicodeDecodeError):
            return False  # not made by a merge here: never touched
        if made_from == digest:
            return False
        had_pdf = self.pdf(name).is_file() and not self.pdf(name).is_symlink()
        self.remove_record(name)
        return had_pdf

    @staticmethod
    def flush() -> None:
        """Everything written so far to the disk, once per run rather than once per file."""
        os.sync()


class Report:
    """report.csv, one row per record in record order. Rows stream to a file in the state
    folder, which replaces report.csv when the run ends (also when it is interrupted)."""

    def __init__(self, folder: Path):
        self.path = folder / REPORT
        self.partial = folder / STATE_DIR / "report.partial"
        self.handle = self.partial.open("w", encoding="utf-8", newline="")
        self.writer = csv.writer(self.handle, lineterminator="\n")
        self.writer.writerow(REPORT_COLUMNS)
        self.failed = 0

    def row(self, number: int, line: int, name: str, status: str, reason: str = "") -> None:
        if status == "failed":
            self.failed += 1
        try:
            self.writer.writerow((number, line, name, status, " ".join(reason.split())))
        except OSError as error:
            raise self.unwritten(error) from None

    def save(self) -> None:
        """report.partial becomes report.csv; on a full disk (whose error surfaces only at
        the close) a message, as for a record's PDF, not an internal error."""
        try:
            self.handle.close()
            os.replace(self.partial, self.path)
        except OSError as error:
            raise self.unwritten(error) from None

    def unwritten(self, error: OSError) -> FloatpageError:
        return FloatpageError(f"{self.path}: could not write it ({error.strerror or error}); "
                              "check that the output folder is writable and the disk not "
                              "full, then run merge again (it skips the records already made)")

    def made_names(self):
        """The names of the records that have a PDF, in record order, read back from the
        saved report (a list of them all would grow with the data file)."""
        with self.path.open(encoding="utf-8", newline="") as handle:
            for row in csv.DictReader(handle):
                if row["status"] in ("made", "unchanged"):
                    yield row["name"]
