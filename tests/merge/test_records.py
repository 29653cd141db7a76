from pathlib import Path

import pytest

from floatpage.merge.records import DataFile
from floatpage.model.errors import FloatpageError


def data(tmp_path: Path, text: str, name: str = "data.csv", encoding: str = "utf-8") -> DataFile:
    path = tmp_path / name
    path.write_bytes(text.encode(encoding))
    return DataFile(path)


def test_csv_records_keep_their_line_across_quoted_newlines_and_blank_lines(tmp_path):
    found = list(data(tmp_path, 'a,b\n1,"two\nlines"\n\n3,4\n').records())
    assert [(r.number, r.line, r.values) for r in found] == [
        (1, 2, {"a": "1", "b": "two\nlines"}), (2, 5, {"a": "3", "b": "4"})]


def test_a_byte_order_mark_is_not_part_of_the_first_column(tmp_path):
    assert data(tmp_path, "\ufeffid,x\n1,2\n").columns == ["id", "x"]


def test_a_row_with_too_many_fields_fails_alone(tmp_path):
    first, second = data(tmp_path, "a,b\n1,2,3\n4,5\n").records()
    assert "3 fields" in first.problem and not second.problem


def test_short_rows_are_padded_with_empty_values(tmp_path):
    (record,) = data(tmp_path, "a,b\n1\n").records()
    assert record.values == {"a": "1", "b": ""} and not record.problem


@pytest.mark.parametrize("text, message", [("a,a\n1,2\n", "named twice"),
                                           ("a,,b\n1,2,3\n", "no name"), ("", "empty")])
def test_bad_headers_are_refused_with_the_file_named(tmp_path, text, message):
    with pytest.raises(FloatpageError, match=message) as error:
        data(tmp_path, text)
    assert "data.csv" in str(error.value)


def test_text_that_is_not_utf8_is_refused_with_advice(tmp_path):
    with pytest.raises(FloatpageError, match="UTF-8"):
        list(data(tmp_path, "a\nZoë\n", encoding="latin-1").records())
    with pytest.raises(FloatpageError, match="UTF-8"):
        data(tmp_path, "Zoë,b\n1,2\n", encoding="latin-1")


def test_json_lines_take_their_columns_from_the_first_object(tmp_path):
    source = data(tmp_path, '{"id": 1, "name": "Ana", "vip": true, "gone": null}\n\n'
                            '[1, 2]\n{"id": 2, "name": {"nested": 1}}\nnot json\n',
                  name="data.jsonl")
    assert source.columns == ["id", "name", "vip", "gone"]
    first, second, third, fourth = source.records()
    assert first.values == {"id": "1", "name": "Ana", "vip": "true", "gone": ""}
    assert (second.line, "not a JSON object" in second.problem) == (3, True)
    assert "dict" in third.problem
    assert "not valid JSON" in fourth.problem
