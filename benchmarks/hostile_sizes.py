"""Time and peak memory of `check` and `settle` on hostile sizes (issue 12's cost section).

Each file is written to a scratch folder and each command runs in its own process; the
peak resident memory is the kernel's (wait4's ru_maxrss), so it counts everything the command
touched.  Prints one line per run:

    .venv/bin/python benchmarks/hostile_sizes.py
"""

from __future__ import annotations

import os
import random
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HEAD = 'format = 1\n\n[[pages]]\nid = "p"\nsize = "A4"\n'


def blocks(places) -> str:
    return HEAD + "".join(f'\n[[pages.items]]\nid = "b{k}"\nkind = "block"\nx = {x:.2f}\n'
                          f"y = {y:.2f}\nw = {w:.2f}\nh = {h:.2f}\n"
                          for k, (x, y, w, h) in enumerate(places))


def piled(count: int) -> str:
    return blocks([(74.0, 105.0, 1.0, 1.0)] * count)


def spread(count: int) -> str:
    rng = random.Random(1)
    return blocks([(rng.uniform(5, 205), rng.uniform(5, 292), rng.uniform(1, 4), rng.uniform(1, 4))
                   for _ in range(count)])


CASES = [
    ("100,000 blocks on one page", lambda: piled(100_000), ("check",)),
    ("10,000 blocks spread over A4", lambda: spread(10_000), ("check",)),
    ("10,000 blocks on one spot", lambda: piled(10_000), ("check", "settle")),
    ("2,000 blocks on one spot", lambda: piled(2_000), ("settle",)),
    ("630 blocks on one spot", lambda: piled(630), ("settle",)),
]


def measure(command: str, path: Path) -> tuple[int, float, float]:
    """(exit code, seconds, peak MB) of one floatpage command in its own process."""
    started = time.perf_counter()
    process = subprocess.Popen([sys.executable, "-m", "floatpage.cli.main", command, str(path)],
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(process.pid, 0)
    return os.waitstatus_to_exitcode(status), time.perf_counter() - started, usage.ru_maxrss / 1024


def main() -> None:
    with tempfile.TemporaryDirectory() as folder:
        for name, make, commands in CASES:
            path = Path(folder) / "case.toml"
            for command in commands:
                path.write_text(make())
                code, seconds, peak = measure(command, path)
                print(f"{name:30s} {command:6s} exit {code}  {seconds:6.1f} s  {peak:6.0f} MB",
                      flush=True)


if __name__ == "__main__":
    main()
