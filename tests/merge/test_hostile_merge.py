"""Hostile and careless merge input found by a fresh attacker's eye (fifteenth session): each
one ended in "internal error" (exit 70) and now gets a message naming what to change."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from merge_helpers import rows, write_csv

FLOATPAGE = str(Path(sys.executable).with_name("floatpage"))


def merge(*args: str, cwd: Path, timeout: int = 300) -> subprocess.CompletedProcess:
    return subprocess.run([FLOATPAGE, "merge", *args], capture_output=True, text=True,
                          cwd=cwd, timeout=timeout)


@pytest.mark.parametrize("address", ["ftp://scheduler:8786", "scheduler", "tcp://host:port"])
def test_a_dask_address_that_is_no_address_is_a_clear_error(merge_folder, address):
    data = write_csv(merge_folder / "customers.csv", rows(1))
    result = merge("offer.toml", str(data), "-o", "out", "--dask", address, "-q",
                   cwd=merge_folder, timeout=120)
    assert result.returncode == 1, result.stderr
    assert "internal error" not in result.stderr
    assert f"floatpage: --dask {address}: not a scheduler's address" in result.stderr
    assert "tcp://HOST:PORT" in result.stderr


def test_a_json_integer_too_long_for_python_fails_its_record_alone(tmp_path):
    """`{"id": 999…9}` with 5,000 digits: json.loads raises a plain ValueError (Python's
    4,300-digit limit), which escaped as an internal error; as the first line, it said so."""
    from floatpage.merge.records import DataFile
    from floatpage.model.errors import FloatpageError

    huge = "9" * 5000
    data = tmp_path / "people.jsonl"
    data.write_text('{"id": "1", "name": "Ann"}\n{"id": ' + huge + ', "name": "Bo"}\n'
                    '{"id": "3", "name": "Cy"}\n')
    records = list(DataFile(data).records())
    assert [record.problem for record in records] == [
        "", 'a number in it is too long to read (more than 4,300 digits); quote it as a string: '
            '"123…"', ""]
    assert records[2].values == {"id": "3", "name": "Cy"}
    first = tmp_path / "first.jsonl"
    first.write_text('{"id": ' + huge + "}\n")
    with pytest.raises(FloatpageError, match=r"first\.jsonl, line 1: the first line must be a "
                                             r"JSON object .* too long to read"):
        DataFile(first)


def test_json_lines_with_a_key_left_out_a_lone_surrogate_or_no_object_fail_alone(merge_folder):
    """A record that leaves out a key ended the whole run with KeyError; a "\\ud800" escape
    with UnicodeEncodeError; a line that is no object, with `--name {id}`, with KeyError."""
    import csv
    import json

    first = dict(zip(next(csv.reader([",".join(["id", "first_name", "surname", "product",
                                                 "price", "photo", "note", "valid_until"])])),
                     rows(1)[0]))
    left_out = {key: value for key, value in first.items() if key != "first_name"}
    lines = [json.dumps(first), json.dumps(left_out),
             json.dumps(first).replace(first["first_name"], "\\ud800"), "[1, 2]",
             json.dumps(first).replace('"surname"', '"\\udc00"')]
    data = merge_folder / "people.jsonl"
    data.write_text("\n".join(lines) + "\n", encoding="utf-8")
    result = merge("offer.toml", str(data), "-o", "out", "--name", "{id}-{surname}", "-q",
                   cwd=merge_folder, timeout=600)
    assert result.returncode == 3, result.stderr
    assert "internal error" not in result.stderr
    report = list(csv.DictReader((merge_folder / "out" / "report.csv").open(encoding="utf-8")))
    assert [row["status"] for row in report] == ["made", "made", "failed", "failed", "failed"]
    assert report[2]["reason"] == (
        "the value of 'first_name' holds half of a UTF-16 surrogate pair (\\ud800-\\udfff "
        "written alone), which is no character; export the data again as UTF-8")
    assert report[3]["reason"] == "the line is not a JSON object ({...})"
    assert report[4]["reason"].startswith("the key '\\udc00' holds half of a UTF-16 surrogate")
    assert sorted(path.name for path in (merge_folder / "out").glob("*.pdf")) == [
        f"{first['id']}-{first['surname']}-2.pdf", f"{first['id']}-{first['surname']}.pdf"]


@pytest.mark.parametrize("value,name", [('=HYPERLINK("http://evil.example","click")',
                                         "HYPERLINK(-http-evil.example-,-click-)"),
                                        ("+1+1", "1+1"), ("@SUM(A1)", "SUM(A1)"),
                                        ("-2+3", "2+3"), ("=cmd|' /C calc'!A0", "cmd- -C calc-A0"),
                                        ("= @ =", "record-00004"), ("a=b", "a=b")])
def test_a_record_name_never_starts_as_a_spreadsheet_formula(value, name):
    """`--name {id}` with an id of `=HYPERLINK(…)` wrote that name first in its report.csv
    cell (and its file name), where the print shop's spreadsheet ran it as a formula."""
    from floatpage.merge.outputs import Names

    assert Names("{id}").name_for(4, {"id": value}) == name


def test_a_state_folder_that_is_a_link_is_refused_and_nothing_is_written_through_it(merge_folder):
    """A `.floatpage-merge` link in the output folder took every record's key and the
    partial report to wherever it pointed."""
    data = write_csv(merge_folder / "customers.csv", rows(1))
    elsewhere = merge_folder / "elsewhere"
    elsewhere.mkdir()
    (merge_folder / "out").mkdir()
    (merge_folder / "out" / ".floatpage-merge").symlink_to(elsewhere)
    result = merge("offer.toml", str(data), "-o", "out", "-q", cwd=merge_folder)
    assert result.returncode == 1, result.stderr
    assert result.stderr.startswith("floatpage: out/.floatpage-merge: is a symbolic link; ")
    assert not list(elsewhere.iterdir())
    assert not list((merge_folder / "out").glob("*.pdf"))
