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


def test_a_second_byte_order_mark_is_not_part_of_the_first_column_either(tmp_path):
    """A tool that adds a BOM to a file that had one: merge said the file had no column 'id',
    only '\ufeffid'."""
    source = data(tmp_path, "\ufeff\ufeffid,x\n1,2\n")
    assert source.columns == ["id", "x"]
    assert [record.values for record in source.records()] == [{"id": "1", "x": "2"}]


def test_json_lines_joined_from_files_with_a_bom_each_read_every_record(tmp_path):
    """`cat a.jsonl b.jsonl`, each saved with a BOM: every record after the first file failed
    with "not valid JSON (Unexpected UTF-8 BOM)"."""
    source = data(tmp_path, '\ufeff{"id": 1}\n\ufeff{"id": 2}\n', name="data.jsonl")
    assert source.columns == ["id"]
    assert [(record.values, record.problem) for record in source.records()] == [
        ({"id": "1"}, ""), ({"id": "2"}, "")]


def test_a_row_with_too_many_fields_fails_alone(tmp_path):
    first, second = data(tmp_path, "a,b\n1,2,3\n4,5\n").records()
    assert "3 fields" in first.problem and not second.problem


@pytest.mark.parametrize("separator, word", [(";", "semicolon"), ("\t", "tab")])
def test_a_spreadsheets_semicolons_or_tabs_separate_columns(tmp_path, separator, word):
    """A spreadsheet set to German or French saves CSV with `;` (its decimal point is the
    comma): the file was one column named 'id;name;price', and the merge stopped, saying the
    data had none of the template's columns."""
    text = f'id{separator}name{separator}price\n1{separator}"Ann; Bo"{separator}2,40\n' \
           f"2{separator}Cy{separator}3,10{separator}extra\n"
    found = data(tmp_path, text)
    assert found.columns == ["id", "name", "price"]
    first, second = found.records()
    assert first.values == {"id": "1", "name": "Ann; Bo", "price": "2,40"} and not first.problem
    assert f"(a {word} in a value needs quotes)" in second.problem
    assert data(tmp_path, "id,name\n1,a;b\n").columns == ["id", "name"]  # commas still rule


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


def test_a_ten_megabyte_value_fails_its_record_alone_and_is_not_carried(tmp_path):
    big = "x" * (10 << 20)
    first, second, third = data(tmp_path, f"a,b\n1,ok\n2,{big}\n3,ok\n").records()
    assert not first.problem and not third.problem and third.values == {"a": "3", "b": "ok"}
    assert "column 'b' holds 10,485,760 characters" in second.problem
    assert second.values["b"] == ""  # not shipped to a worker


def test_a_row_the_reader_refuses_fails_alone_and_the_next_rows_stay_in_step(tmp_path):
    first, second, third = data(tmp_path, 'a,b\n1,"x"y\n2,"ok, quoted"\n3,z\n').records()
    assert (first.line, "not readable as CSV" in first.problem) == (2, True)
    assert (second.line, second.values, second.problem) == (3, {"a": "2", "b": "ok, quoted"}, "")
    assert (third.line, third.values) == (4, {"a": "3", "b": "z"})


def test_a_quote_left_open_stops_before_work_naming_its_line(tmp_path):
    """Without this, the open quote made the rest of the file one value: rows 3 and 4 were
    silently lost inside record 1."""
    source = data(tmp_path, 'a,b\n1,ok\n2,"open\n3,x\n4,y\n')
    with pytest.raises(FloatpageError, match=r"data.csv, line 3: .*never closes"):
        list(source.records())


def test_a_column_named_like_a_placeholder_is_only_a_name(tmp_path):
    source = data(tmp_path, "{id},{{x}}\n1,2\n")
    assert source.columns == ["{id}", "{{x}}"]
    (record,) = source.records()
    assert record.values == {"{id}": "1", "{{x}}": "2"}


def test_json_lines_with_a_non_object_line_fail_that_record_only(tmp_path):
    source = data(tmp_path, '{"a": "1"}\n"just a string"\n42\nnull\n{"a": "5"}\n',
                  name="data.jsonl")
    found = list(source.records())
    assert [bool(record.problem) for record in found] == [False, True, True, True, False]
    assert [record.line for record in found] == [1, 2, 3, 4, 5]


def test_a_folder_or_a_pipe_given_as_data_is_named_as_such(tmp_path):
    """Both were "no such data file", though the folder was there and the pipe (a shell's
    `<(grep … customers.csv)`) too."""
    import os

    folder = tmp_path / "records"
    folder.mkdir()
    with pytest.raises(FloatpageError, match="is a folder, not a data file"):
        DataFile(folder)
    pipe = tmp_path / "records.csv"
    os.mkfifo(pipe)
    with pytest.raises(FloatpageError, match="is a pipe or device, not a file; merge reads"):
        DataFile(pipe)
    with pytest.raises(FloatpageError, match="no such data file"):
        DataFile(tmp_path / "missing.csv")
