"""The command line's contract for Makefiles: help everywhere, 0 / 1 / 2 exit codes, quiet pipes."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from floatpage.cli.main import main

ROOT = Path(__file__).resolve().parents[2]
COMMANDS = ["new", "edit", "settle", "render", "check"]


def run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "floatpage.cli.main", *args], capture_output=True, text=True,
                          timeout=120, cwd=ROOT, stdin=subprocess.DEVNULL)


def test_top_level_help_lists_every_command():
    result = run("--help")
    assert result.returncode == 0
    for command in COMMANDS:
        assert command in result.stdout


@pytest.mark.parametrize("command", COMMANDS)
def test_every_command_has_help(command, capsys):
    with pytest.raises(SystemExit) as exited:
        main([command, "--help"])
    assert exited.value.code == 0
    assert f"usage: floatpage {command}" in capsys.readouterr().out


def test_every_argument_of_every_command_says_what_it_is():
    """`floatpage edit --help` listed `path` with no word, and `new --help` listed
    `--orientation {portrait,landscape}` with none."""
    import argparse

    from floatpage.cli.main import build_parser

    parser = build_parser()
    commands = next(action for action in parser._actions
                    if isinstance(action, argparse._SubParsersAction))
    silent = [f"{name} {action.dest}" for name, command in commands.choices.items()
              for action in command._actions if not action.help]
    assert silent == []


@pytest.mark.parametrize("argv", [[], ["frobnicate"], ["render"], ["new", "poster", "x.toml"],
                                  ["settle", "a.toml", "--bogus"]])
def test_misuse_exits_2(argv, capsys):
    with pytest.raises(SystemExit) as exited:
        main(argv)
    assert exited.value.code == 2
    assert "usage:" in capsys.readouterr().err


def test_edit_on_a_broken_file_fails_before_taking_the_screen(tmp_path):
    broken = tmp_path / "broken.toml"
    broken.write_text("format = 1\npages = 3\n")
    result = run("edit", str(broken))
    assert result.returncode == 1
    assert '"pages" must be an array of tables' in result.stderr
    assert "Traceback" not in result.stderr


def test_edit_without_a_terminal_says_so_and_writes_no_screen_codes(tmp_path):
    """Run from a script (input and output not a terminal), the editor wrote screen codes into
    the output and ended "floatpage: interrupted" with exit 130, as if Ctrl+C had been pressed."""
    path = tmp_path / "card.toml"
    assert run("new", "blank", str(path)).returncode == 0
    result = run("edit", str(path))
    assert result.returncode == 1
    assert result.stdout == ""
    assert result.stderr.startswith(f"floatpage: {path}: floatpage edit needs a terminal, and "
                                    "its input and output are not one"), result.stderr
    assert "`floatpage settle`, `check` or `render`" in result.stderr


@pytest.mark.parametrize("kind, options, named", [
    ("card", ["--year", "2030"], "--year"),
    ("flyer", ["--first-weekday", "sunday"], "--first-weekday"),
    ("album", ["--year", "2030", "--first-weekday", "sunday"], "--year and --first-weekday"),
])
def test_new_says_when_a_calendar_option_shapes_nothing(tmp_path, kind, options, named):
    """`floatpage new card x.toml --year 2030` made a card and said nothing of the year: a
    Makefile that meant `calendar` never learnt. The project is still made (exit 0)."""
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "new", kind,
                             str(tmp_path / "x.toml"), *options, "-j", "1"],
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "x.toml").is_file()
    verb = "shape" if " and " in named else "shapes"
    assert f"note: {named} only {verb} a calendar; ignored for `new {kind}`" in result.stderr


def test_new_calendar_takes_its_options_without_a_note(tmp_path):
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "new", "calendar",
                             str(tmp_path / "x.toml"), "--year", "2030", "--first-weekday",
                             "sunday", "-j", "1"], capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    assert "note:" not in result.stderr
    assert 'first_weekday = "sunday"' in (tmp_path / "x.toml").read_text()


def test_render_bleed_without_print_is_a_mistyped_command_line(tmp_path):
    """`floatpage render x.toml --bleed 5` wrote a plain PDF with no bleed at all (--bleed
    only shapes --print's sheet), so a file meant for the print shop went out without it."""
    from floatpage.model import Page, Project, save_project

    path = tmp_path / "x.toml"
    save_project(Project(pages=[Page(id="p")]), path)
    result = run("render", str(path), "--bleed", "5", "-o", str(tmp_path / "x.pdf"))
    assert result.returncode == 2
    assert "--bleed" in result.stderr and "--print" in result.stderr
    assert not (tmp_path / "x.pdf").exists()


def test_version_names_the_installed_floatpage():
    """`floatpage --version` said 'the following arguments are required: COMMAND' (exit 2),
    though a bug report (the crash message asks for one) wants the version."""
    from importlib.metadata import version

    result = run("--version")
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == f"floatpage {version('floatpage')}"


@pytest.mark.parametrize("name", ["card.png", "card.JPG", "card.svg", "card.tex"])
def test_render_refuses_an_output_named_as_another_format(tmp_path, name):
    """`render -o card.png` wrote a PDF named card.png (a Makefile's %.png rule then shipped a
    file no image viewer opens). Such a name is refused, with how to get that format."""
    from floatpage.model import Page, Project, save_project

    path = tmp_path / "card.toml"
    save_project(Project(pages=[Page(id="p")]), path)
    result = run("render", str(path), "-o", str(tmp_path / name))
    assert result.returncode == 1
    assert name in result.stderr and ".pdf" in result.stderr
    assert not (tmp_path / name).exists()


@pytest.mark.parametrize("option,name", [("--tex", "card.pdf"), ("--fragment", "part.PNG"),
                                         ("--tex", "other.toml")])
def test_render_refuses_latex_source_named_as_another_format(tmp_path, option, name):
    """`--tex card.pdf -o card.tex` (the options swapped) wrote LaTeX source into card.pdf."""
    from floatpage.model import Page, Project, save_project

    path = tmp_path / "card.toml"
    save_project(Project(pages=[Page(id="p")]), path)
    result = run("render", str(path), option, str(tmp_path / name), "-o",
                 str(tmp_path / "out.pdf"))
    assert result.returncode == 1, result.stderr
    assert f"{option} writes LaTeX source; name it .tex" in result.stderr, result.stderr
    assert not (tmp_path / name).exists() and not (tmp_path / "out.pdf").exists()


@pytest.mark.parametrize("seed,said", [("-1", "the seed must be at least 0 (it is -1)"),
                                       ("1" + "0" * 22, "the seed must be at most"),
                                       ("1.5", "'1.5' is not a whole number")])
def test_edit_seed_out_of_range_is_a_mistyped_command_line(tmp_path, seed, said, capsys):
    """`edit --seed -1` (or 10**22) reached the editor and ended in "internal error", exit 70,
    with a crash log."""
    from floatpage.model import Page, Project, save_project

    path = tmp_path / "card.toml"
    save_project(Project(pages=[Page(id="p")]), path)
    with pytest.raises(SystemExit) as exited:
        main(["edit", str(path), "--seed", seed])
    assert exited.value.code == 2
    assert said in capsys.readouterr().err
