"""Every malformed project file gets one clear message and exit code 1, never a traceback.

Each file in malformed/ starts with `# expect: <text the message must contain>`.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from floatpage.cli.main import main
from floatpage.model import ProjectFileError, load_project

MALFORMED = sorted((Path(__file__).parent / "malformed").glob("*.toml"))

# Where the problem is, for the cases whose line a reader would look for.
EXPECTED_LINES = {
    "syntax_unclosed_string": 3,
    "unknown_top_key": 3,
    "unknown_item_key": 16,
    "x_is_string": 12,
    "negative_width": 14,
    "unknown_page_size": 7,
    "missing_picture_file": 16,
    "anchor_to_unknown_item": 16,
    "colour_by_name": 16,
    "negative_time_step": 6,
}


def expectation(path: Path) -> str:
    first = path.read_bytes().split(b"\n", 1)[0].decode("ascii")
    assert first.startswith("# expect: "), path
    return first.removeprefix("# expect: ")


def test_there_are_at_least_25_malformed_files():
    assert len(MALFORMED) >= 25


@pytest.mark.parametrize("path", MALFORMED, ids=lambda p: p.stem)
def test_check_answers_with_a_clear_message_and_exit_1(path, capsys):
    code = main(["check", str(path)])
    captured = capsys.readouterr()
    assert code == 1
    assert expectation(path) in captured.err
    assert captured.err.startswith(f"floatpage: {path}"), "the message must name the file first"
    assert "Traceback" not in captured.err + captured.out
    assert "internal error" not in captured.err


@pytest.mark.parametrize("stem,line", sorted(EXPECTED_LINES.items()))
def test_the_message_names_the_line(stem, line):
    path = Path(__file__).parent / "malformed" / f"{stem}.toml"
    with pytest.raises(ProjectFileError) as caught:
        load_project(path)
    assert [problem.line for problem in caught.value.problems] == [line]


def test_several_problems_are_reported_together(tmp_path):
    path = tmp_path / "two.toml"
    path.write_text('format = 1\n\n[[pages]]\nid = "p"\n\n[[pages.items]]\nid = "a"\nkind = "block"\n'
                    'x = 1.0\ny = "two"\nw = -1.0\nh = 3.0\n')
    with pytest.raises(ProjectFileError) as caught:
        load_project(path)
    messages = [problem.message for problem in caught.value.problems]
    assert messages == ['"y" must be a number, not the string "two"', '"w" must be greater than 0']


@pytest.mark.parametrize("stem", ["syntax_unclosed_string", "anchor_cycle", "not_utf8"])
def test_the_installed_command_exits_1_without_traceback(stem):
    path = Path(__file__).parent / "malformed" / f"{stem}.toml"
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "check", str(path)],
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 1
    assert expectation(path) in result.stderr
    assert "Traceback" not in result.stderr


def test_a_missing_file_is_a_user_error(tmp_path, capsys):
    assert main(["check", str(tmp_path / "nope.toml")]) == 1
    assert "no such file" in capsys.readouterr().err


def test_a_custom_width_out_of_range_is_one_message_not_also_a_missing_key(tmp_path):
    """`width_mm = 1e9` on a custom page said both that width_mm must be between 10 and 5000
    and that the page needs width_mm (add both): the second sent the user looking for a key
    that is there."""
    path = tmp_path / "big.toml"
    path.write_text('format = 1\n[[pages]]\nid = "p"\nsize = "custom"\nwidth_mm = 1e9\n'
                    'height_mm = 100\n')
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "check", str(path)],
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 1
    assert '"width_mm" must be between' in result.stderr
    assert "needs width_mm and height_mm" not in result.stderr


def test_a_missing_picture_names_the_projects_folder_in_words(tmp_path):
    """Run beside the project, the hint read "paths are relative to .; fix the path ..."
    (user-walk-2): it names the project's folder, and the folder's path when there is one."""
    path = tmp_path / "p.toml"
    path.write_text('format = 1\n[[pages]]\nid = "p"\n[[pages.items]]\nid = "a"\n'
                    'kind = "picture"\nx = 50\ny = 50\nw = 20\nh = 20\npath = "nope.jpg"\n')
    for cwd, named, folder in ((tmp_path, "p.toml", "the project's folder;"),
                               (tmp_path.parent, f"{tmp_path.name}/p.toml",
                                f"the project's folder, {tmp_path.name};")):
        result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "check", named],
                                capture_output=True, text=True, timeout=120, cwd=cwd)
        assert result.returncode == 1
        assert f"paths are relative to {folder}" in result.stderr, result.stderr
