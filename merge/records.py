"""Records read one at a time from CSV or JSON Lines, so 100,000 rows never sit in memory.

Every record keeps the line it starts on, which is what report.csv and error messages name.
A malformed record (a CSV row with too many fields, a JSON line that is not an object) is
yielded with its problem, so that record fails alone and the others go on.
"""

from __future__ import annotations

import contextlib
import csv
import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterator

from floatpage.model.errors import FloatpageError

# A value longer than MAX_VALUE_CHARS fails its record alone (no text may hold it). Python's
# csv reader cannot step past a field over its own limit without losing its place in quoted
# lines, so that limit is far higher, and a field beyond it stops the run, naming the line.
MAX_VALUE_CHARS = 1 << 20
READ_LIMIT_CHARS = 64 << 20
csv.field_size_limit(READ_LIMIT_CHARS)


JSON_LINES = (".jsonl", ".ndjson")
# Files read as CSV would turn into nonsense columns (a JSON array's first line, a project's
# first comment): refused before any work, saying what to give instead.
NOT_RECORDS = {".json": "a .json file is one JSON document, not records",
               ".toml": "a .toml file is a project, not records"}


@dataclass
class Record:
    number: int  # 1-based record number, in file order
    line: int    # the line of the data file it starts on
    values: dict[str, str] = field(default_factory=dict)
    problem: str = ""


class DataFile:
    """A data file's columns (read at once) and its records (read as they are asked for)."""

    def __init__(self, path: Path):
        self.path = Path(path)
        if not self.path.exists():
            raise FloatpageError(f"{self.path}: no such data file (give a .csv or .jsonl file)")
        if self.path.is_dir():  # it was "no such data file", of a folder that is there
            raise FloatpageError(f"{self.path}: is a folder, not a data file (name the .csv or "
                                 ".jsonl file inside it)")
        if not self.path.is_file():  # e.g. `<(grep … customers.csv)`: read more than once
            raise FloatpageError(f"{self.path}: is a pipe or device, not a file; merge reads "
                                 "its data file more than once, so save the records to a .csv "
                                 "or .jsonl file first")
        suffix = self.path.suffix.lower()
        if suffix in NOT_RECORDS:
            raise FloatpageError(f"{self.path}: {NOT_RECORDS[suffix]}; give the records as a .csv "
                                 "file with a header line, or a .jsonl file (one JSON object "
                                 "per line)")
        self.kind = "jsonl" if suffix in JSON_LINES else "csv"
        self.delimiter = ","
        self.columns = self.read_columns()

    def read_columns(self) -> list[str]:
        if self.kind == "csv":
            with self.open() as handle, self.readable():
                first = handle.readline()
            self.delimiter = separator_of(first)
            with self.open() as handle, self.readable():
                header = next(csv.reader(handle, delimiter=self.delimiter), None)
            if not header:
                raise FloatpageError(f"{self.path}: the file is empty; its first line must name "
                                     "the columns")
            columns = header_names(header)
        else:
            first = next(self.records(), None)
            if first is None or first.problem:
                raise FloatpageError(f"{self.path}, line {first.line if first else 1}: the first "
                                     "line must be a JSON object whose keys name the columns"
                                     + (f" ({first.problem})" if first else ""))
            columns = list(first.values)
        blank = [index + 1 for index, name in enumerate(columns) if not name]
        if blank:
            raise FloatpageError(f"{self.path}, line 1: column {blank[0]} has no name; name "
                                 "every column in the first line")
        repeated = sorted({name for name in columns if columns.count(name) > 1})
        if repeated:
            raise FloatpageError(f"{self.path}, line 1: column {repeated[0]!r} is named twice")
        return columns

    def open(self):
        try:
            return self.path.open(encoding="utf-8-sig", newline="")
        except OSError as error:
            raise FloatpageError(f"{self.path}: cannot be read ({error.strerror})") from None

    def records(self) -> Iterator[Record]:
        with self.readable():
            yield from (self.csv_records() if self.kind == "csv" else self.json_records())

    @contextlib.contextmanager
    def readable(self) -> Iterator[None]:
        """Turn a file that is not UTF-8, or not CSV, into a message naming the file."""
        try:
            yield
        except UnicodeDecodeError as error:
            raise FloatpageError(f"{self.path}: not UTF-8 text ({error.reason} near byte "
                                 f"{error.start}); save it as UTF-8") from None
        except csv.Error as error:
            raise FloatpageError(f"{self.path}: not a readable CSV file ({error})") from None

    def csv_records(self) -> Iterator[Record]:
        with self.open() as handle:
            reader = csv.reader(handle, delimiter=self.delimiter, strict=True)
            header = header_names(next(reader, []))
            number = 0
            for row, line, problem in self.rows(reader):
                if not problem and not any(cell.strip() for cell in row):
                    continue  # blank lines separate nothing
                number += 1
                record = Record(number, line, problem=problem)
                if len(row) > len(header):
                    record.problem = (f"the row has {len(row)} fields but the header names "
                                      f"{len(header)} columns (a {SEPARATOR_WORDS[self.delimiter]} "
                                      "in a value needs quotes)")
                record.values = {name: (row[index] if index < len(row) else "")
                                 for index, name in enumerate(header)}
                yield too_long_values_dropped(record)

    def rows(self, reader) -> Iterator[tuple[list[str], int, str]]:
        """(row, the line it starts on, "" or why it cannot be read). A row the reader
        refuses (`"a"b`) fails alone: the reader goes on from the next line, in step. A quote
        left open swallows the rest of the file, and a field beyond READ_LIMIT_CHARS leaves the
        reader out of step: both end the run, naming the line where that row starts."""
        while True:
            line = reader.line_num + 1
            try:
                row = next(reader)
            except StopIteration:
                return
            except csv.Error as error:
                if "unexpected end of data" in str(error) or "field limit" in str(error):
                    raise FloatpageError(
                        f"{self.path}, line {line}: not readable as CSV ({error}): a quote "
                        "that opens there never closes, so the rest of the file would be one "
                        "value; close the quote, or quote the whole value") from None
                yield [], line, (f"not readable as CSV ({error}); a value with a quote in "
                                 'it must be quoted whole, its quotes doubled: "say ""hi"""')
                continue
            yield row, line, ""

    def json_records(self) -> Iterator[Record]:
        with self.open() as handle:
            number = 0
            for line_number, line in enumerate(handle, start=1):
                if not line.strip():
                    continue
                number += 1
                record = Record(number, line_number)
                try:
                    # a BOM at a line's start: files joined with `cat`, each saved with
                    # one, failed every record after the first file ("Unexpected UTF-8 BOM")
                    data = json.loads(line.lstrip(BOM))
                except (json.JSONDecodeError, RecursionError) as error:
                    record.problem = f"not valid JSON ({getattr(error, 'msg', 'too deep')})"
                    yield self.padded(record)
                    continue
                except ValueError:  # Python reads no integer of more than 4,300 digits
                    record.problem = ("a number in it is too long to read (more than 4,300 "
                                      'digits); quote it as a string: "123…"')
                    yield self.padded(record)
                    continue
                if not isinstance(data, dict):
                    record.problem = "the line is not a JSON object ({...})"
                    yield self.padded(record)
                    continue
                for key, value in data.items():
                    if isinstance(value, (dict, list)):
                        record.problem = f"the value of {key!r} is a JSON {type(value).__name__}; " \
                                         "give a string or a number"
                    record.values[str(key)] = "" if value is None else (
                        ("true" if value else "false") if isinstance(value, bool) else str(value))
                    if not is_text(str(key)) or not is_text(record.values[str(key)]):
                        record.problem = (  # "\ud800" alone: an internal error at the digest
                            f"{'the key' if not is_text(str(key)) else 'the value of'} "
                            f"{ascii(str(key))} holds half of a UTF-16 surrogate pair (\\ud800-"
                            "\\udfff written alone), which is no character; export the data "
                            "again as UTF-8")
                yield too_long_values_dropped(self.padded(record))

    def padded(self, record: Record) -> Record:
        """A key left out is an empty value, as null is and as a CSV row's missing fields
        are: it ended the whole run with an internal error (KeyError), as did `--name {id}`
        on a line that is no JSON object."""
        for name in getattr(self, "columns", ()):
            record.values.setdefault(name, "")
        return record


BOM = "\ufeff"


def header_names(header: list[str]) -> list[str]:
    """The column names of a CSV header row, spaces trimmed; a second byte-order mark before
    the first (a tool that adds one to a file that had one) is no part of its name: merge
    said the file had no column 'id' but '\ufeffid'."""
    names = [name.strip() for name in header]
    if names:
        names[0] = names[0].lstrip(BOM).strip()
    return names


def is_text(value: str) -> bool:
    """Whether ``value`` can be written as UTF-8 (no lone surrogate from a JSON escape)."""
    try:
        value.encode("utf-8")
    except UnicodeEncodeError:
        return False
    return True


SEPARATORS = (",", ";", "\t")
SEPARATOR_WORDS = {",": "comma", ";": "semicolon", "\t": "tab"}


def separator_of(header_line: str) -> str:
    """The field separator a CSV header line uses: the one of SEPARATORS that splits it into
    the most columns, a comma on a tie.  Spreadsheets set to German, French or Dutch write
    `;` (a comma is their decimal point), and such a file's one column
    'id;first_name;surname;…' matched none of the template's placeholders."""
    def columns(separator: str) -> int:
        return len(next(csv.reader([header_line], delimiter=separator), []))
    return max(SEPARATORS, key=lambda separator: (columns(separator), separator == ","))


def too_long_values_dropped(record: Record) -> Record:
    """A value no text could hold fails its record, and is dropped rather than carried along
    to a worker."""
    for name, value in record.values.items():
        if len(value) > MAX_VALUE_CHARS:
            record.problem = record.problem or (
                f"column {name!r} holds {len(value):,} characters, more than a value may hold "
                f"({MAX_VALUE_CHARS:,}); is a quote in that row left open?")
            record.values[name] = ""
    return record
