"""Run `check`, `settle` and `render` on each project file named on the command line, in this
one process, and print one JSON line per file: exit codes, stderr, whether the saved file
still loads with finite numbers, and this process's peak memory with its children's.

The fuzz test runs a few of these side by side; one process per file would spend most of the
run starting Python.  A command that runs longer than TIMEOUT_S is stopped and reported.
"""

from __future__ import annotations

import contextlib
import io
import json
import math
import resource
import signal
import sys
import tomllib
from pathlib import Path

from floatpage.cli.main import main

TIMEOUT_S = 120


class Hang(Exception):
    pass


def on_alarm(signum, frame):
    raise Hang


def run(argv: list[str]) -> dict:
    out, err = io.StringIO(), io.StringIO()
    signal.signal(signal.SIGALRM, on_alarm)
    signal.alarm(TIMEOUT_S)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = main(argv)
    except Hang:
        code = "hang"
    except SystemExit as exit_:  # argparse
        code = exit_.code
    except BaseException as error:  # noqa: BLE001 - anything escaping main is the finding
        code = f"escaped: {type(error).__name__}: {error}"
    finally:
        signal.alarm(0)
    return {"code": code, "stdout": out.getvalue()[-2000:], "stderr": err.getvalue()[:2000]}


def finite_file(path: Path) -> str:
    """'' when the file parses and holds only finite numbers, else what is wrong."""
    try:
        data = tomllib.loads(path.read_bytes().decode("utf-8-sig"))
    except Exception as error:  # noqa: BLE001 - the original file may never have parsed
        return f"unparsable: {type(error).__name__}"
    bad = []
    stack = [(data, "")]  # a loop, not recursion: the corpus nests 3,000 levels deep
    while stack:
        value, where = stack.pop()
        if isinstance(value, float) and not math.isfinite(value):
            bad.append(where)
        elif isinstance(value, dict):
            stack += [(inner, f"{where}.{key}") for key, inner in value.items()]
        elif isinstance(value, list):
            stack += [(inner, f"{where}[{index}]") for index, inner in enumerate(value)]
    return ", ".join(bad[:5])


def peaks_mb() -> tuple[float, float]:
    """This process's peak and its largest finished child's (LuaLaTeX, mostly), in MB."""
    own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    children = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    return own / 1024, children / 1024


def peak_mb() -> float:
    return max(peaks_mb())


def measured(argv: list[str]) -> dict:
    """`run`, plus the peaks after it: a peak over the limit then names the file and the
    command that raised it, and whether this process or a child (LuaLaTeX) reached it."""
    before = peak_mb()
    outcome = run(argv)
    outcome["peak_before_mb"] = before
    outcome["peak_own_mb"], outcome["peak_children_mb"] = peaks_mb()
    return outcome


def drive(path: Path) -> dict:
    before_finite = finite_file(path)
    before = path.read_bytes()
    result = {"file": path.name, "check": measured(["check", str(path)])}
    result["settle"] = measured(["settle", "-q", str(path)])
    result["non_finite_after_settle"] = finite_file(path) if path.read_bytes() != before else ""
    result["non_finite_before"] = before_finite
    result["render"] = measured(["render", "-q", str(path), "-o", str(path.with_suffix(".pdf"))])
    result["peak_mb"] = peak_mb()
    return result


if __name__ == "__main__":
    for name in sys.argv[1:]:
        print(json.dumps(drive(Path(name))), flush=True)
