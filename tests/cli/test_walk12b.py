"""A LaTeX publishing workflow's command lines (user-walk-12b): names a Makefile passes when a
variable is empty, or a Unix habit (`-o -`), are refused with what to type, and nothing is
written where the user did not ask."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from floatpage.model import Page, Project, TextItem, save_project

SAMPLE = Path(__file__).resolve().parents[2] / "sample_projects" / "merge-offers"


def card(folder: Path) -> Path:
    path = folder / "card.toml"
    save_project(Project(title="Card", pages=[Page(id="front", size="A6", items=[
        TextItem(id="title", x=52.0, y=70.0, w=60.0, h=20.0, text="Hello")])]), path)
    return path


def listing(folder: Path) -> dict[str, bytes | None]:
    return {str(path.relative_to(folder)): (path.read_bytes() if path.is_file() else None)
            for path in sorted(folder.rglob("*"))}


def run(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "floatpage.cli.main", *args], capture_output=True,
                          text=True, timeout=300, cwd=cwd, stdin=subprocess.DEVNULL)


@pytest.mark.parametrize("option", ["-o", "--tex", "--fragment"])
@pytest.mark.parametrize("name", ["-", "", " "])
def test_render_refuses_standard_output_and_an_empty_name(tmp_path, option, name):
    """`-o -` wrote a PDF called `-`; `-o ""` (`-o $(OUT)` with OUT unset) wrote card.pdf
    beside the project without a word, and `--tex ""` wrote no .tex without one."""
    card(tmp_path)
    before = listing(tmp_path)
    args = ["render", "card.toml", option, name, *(["-o", "card.pdf"] if option != "-o" else [])]
    result = run(*args, cwd=tmp_path)
    assert result.returncode == 1, result.stderr
    if name == "-":
        assert result.stderr.startswith(f"floatpage: {option} -: render writes files, not to "
                                        "standard output; name the file, e.g.")
    else:
        assert result.stderr.startswith(f"floatpage: {option} {name!r} names no file")
    assert listing(tmp_path) == before


@pytest.mark.parametrize("name", ["-", ""])
def test_merge_refuses_standard_output_and_an_empty_folder_name(tmp_path, name):
    """`merge -o ""` wrote 40 PDFs, report.csv and its keys into the current folder, among
    the template and the data; `-o -` made a folder called `-`."""
    shutil.copy(SAMPLE / "offer.toml", tmp_path / "offer.toml")
    shutil.copy(SAMPLE / "customers.csv", tmp_path / "customers.csv")
    shutil.copytree(SAMPLE / "pictures", tmp_path / "pictures")
    before = listing(tmp_path)
    result = run("merge", "offer.toml", "customers.csv", "-o", name, "-q", cwd=tmp_path)
    assert result.returncode == 1, result.stderr
    assert "name the folder" in result.stderr and "e.g. -o out" in result.stderr
    assert listing(tmp_path) == before


def test_check_quiet_prints_only_what_needs_attention(tmp_path):
    """`check --strict -q` in a Makefile was exit 2 ("unrecognized arguments: -q"), where
    render, settle and merge take -q: quiet, a sound project prints nothing, and a page
    with a problem prints its lines and the closing line, not the sound page's figures."""
    path = tmp_path / "card.toml"
    save_project(Project(title="Card", pages=[
        Page(id="front", size="A6", items=[
            TextItem(id="title", x=52.0, y=40.0, w=60.0, h=20.0, text="Hello")]),
        Page(id="back", size="A6", items=[
            TextItem(id="lost", x=300.0, y=40.0, w=60.0, h=20.0, text="Far away")])]), path)
    loud = run("check", "--strict", "card.toml", cwd=tmp_path)
    quiet = run("check", "--strict", "-q", "card.toml", cwd=tmp_path)
    assert loud.returncode == quiet.returncode == 1, quiet.stderr
    assert "valid project" in loud.stdout and "page front:" in loud.stdout
    assert "valid project" not in quiet.stdout and "page front:" not in quiet.stdout
    assert "page back:" in quiet.stdout and "1 off page" in quiet.stdout
    assert quiet.stdout.rstrip().splitlines()[-1].startswith("card.toml: 1 layout problem(s)")
    (tmp_path / "sound.toml").write_text(path.read_text().split("[[pages]]")[0] + "[[pages]]"
                                         + path.read_text().split("[[pages]]")[1])
    sound = run("check", "--strict", "-q", "sound.toml", cwd=tmp_path)
    assert (sound.returncode, sound.stdout, sound.stderr) == (0, "", "")
