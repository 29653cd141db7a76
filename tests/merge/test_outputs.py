"""Names from --name patterns: safe on every file system, and unique."""

import unicodedata

import pytest

from floatpage.merge.outputs import MAX_NAME_BYTES, Names, safe_name


def test_a_long_name_in_any_script_fits_a_file_system(tmp_path):
    """120 CJK characters are 360 bytes: the old limit counted characters, and writing the
    PDF failed with 'File name too long', a crash of the whole run."""
    name = safe_name("李" * 200, 1)
    assert len(name.encode("utf-8")) <= MAX_NAME_BYTES and name == "李" * 40
    (tmp_path / f".{name}.pdf.4194304.0badcafe.floatpage-tmp").write_bytes(b"fits")


@pytest.mark.parametrize("text, expected", [("CON", "CON_"), ("con.txt", "con_.txt"),
                                            ("Lpt9 .tar", "Lpt9_.tar"), ("aux", "aux_"),
                                            ("nul-1", "nul-1"), ("COM10", "COM10")])
def test_names_windows_keeps_for_devices_are_never_a_name(text, expected):
    assert safe_name(text, 1) == expected


@pytest.mark.parametrize("text", ["..", "", "   ", "/", "../..", ". . .", "\x00\x01"])
def test_a_pattern_that_leaves_nothing_gives_the_record_number(text):
    assert safe_name(text, 7) == "record-00007"


def test_separators_and_dots_never_leave_the_folder():
    assert safe_name("../../etc/passwd", 1) == "etc-passwd"
    assert safe_name(".hidden", 1) == "hidden"


def test_names_are_unique_ignoring_case_and_unicode_form():
    names = Names("{n}")
    composed, decomposed = "Zoë", unicodedata.normalize("NFD", "Zoë")
    given = [names.name_for(number, {"n": value}) for number, value in
             enumerate([composed, decomposed, "ZOË", "Zoë-2", "report", "x"], start=1)]
    assert given == ["Zoë", "Zoë-2", "ZOË-3", "Zoë-2-2", "report-2", "x"]
