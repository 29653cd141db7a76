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
