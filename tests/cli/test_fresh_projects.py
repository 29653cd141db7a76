"""Project files drawn by benchmarks/fresh_projects.py that once broke a promise, cut down to
what still broke it: through the real `floatpage` command, a settle then a second settle
changes no byte, and `check --strict` passes on the settled file, or (files named limit-*)
fails with a reason no settle can fix and never sends the user back to `settle`."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

FILES = Path(__file__).parent / "fresh_projects"


def floatpage(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "floatpage.cli.main", *args], cwd=cwd,
                          capture_output=True, text=True, timeout=600, stdin=subprocess.DEVNULL)


def settle(name: str, folder: Path) -> None:
    done = floatpage("settle", "-q", "-j", "1", name, cwd=folder)
    assert done.returncode == 0, done.stdout + done.stderr


@pytest.mark.parametrize("name", sorted(path.name for path in FILES.glob("*.toml")))
def test_a_settled_fresh_project_keeps_its_promises(tmp_path, name):
    path = tmp_path / name
    shutil.copy(FILES / name, path)
    settle(name, tmp_path)
    first = path.read_bytes()
    settle(name, tmp_path)
    assert path.read_bytes() == first, "the second settle moved items"
    check = floatpage("check", "--strict", name, cwd=tmp_path)
    assert "internal error" not in check.stderr
    if name.startswith("limit-"):
        assert check.returncode == 1
        assert "run `floatpage settle`" not in check.stdout.split("layout problem(s)")[0], \
            check.stdout
    else:
        assert check.returncode == 0, check.stdout
