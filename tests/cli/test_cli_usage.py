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
