"""How often, and how long, `floatpage check` fits its texts: on each sample, in-process.

    .venv/bin/python benchmarks/check_fits.py [--repeat 5] [PROJECT.toml ...]

For each project: `floatpage check` run through the CLI's own main() (stdout caught), once
to warm the font caches, then --repeat times; prints the fits made per run (calls of
typeset.text_layout.fit_in_box, counted by wrapping the name typeset.roles calls, and of
typeset.calendar_panel.layout_calendar), the texts and calendars the project has, the
median wall-clock seconds of a run, and a hash of check's output, so two versions can be
held against each other: the same hash means the same words.  Then check's two text passes
alone (its fit warnings and its contrast notes), median seconds of --repeat: "apart", each
fitting the project itself (as before the sixteenth session), and "shared", one
typeset.render.document_fits for both (as `check` does now), with their ratio; a different
set of words between the two is an error.  The machine is shared and noisy: compare within
one run, and note `uptime`.
"""

from __future__ import annotations

import argparse
import contextlib
import hashlib
import io
import statistics
import time
from pathlib import Path

import floatpage.typeset.placed as placed_module
import floatpage.typeset.roles as roles_module
from floatpage.cli.main import main
from floatpage.model import load_project
from floatpage.typeset.render import document_fits, faint_text_notes, text_fit_warnings

ROOT = Path(__file__).resolve().parents[1]


def counting(module, name: str, counts: dict) -> None:
    original = getattr(module, name)

    def counted(*args, **kwargs):
        counts[name] = counts.get(name, 0) + 1
        return original(*args, **kwargs)

    setattr(module, name, counted)


def run_check(path: Path) -> tuple[str, float]:
    out, err = io.StringIO(), io.StringIO()
    start = time.perf_counter()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        main(["check", str(path)])
    return out.getvalue() + err.getvalue(), time.perf_counter() - start


def text_passes(project, shared: bool) -> tuple[list[str], float]:
    start = time.perf_counter()
    fits = document_fits(project) if shared else None
    words = text_fit_warnings(project, fits) + faint_text_notes(project, fits)
    return words, time.perf_counter() - start


def main_benchmark() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("projects", nargs="*", type=Path)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    projects = args.projects or sorted(ROOT.glob("sample_projects/*/*.toml"))
    counts: dict[str, int] = {}
    counting(roles_module, "fit_in_box", counts)
    counting(placed_module, "layout_calendar", counts)
    print(f"{'project':<34} {'texts':>5} {'cals':>4} {'fits/run':>8} {'cal lays':>8} "
          f"{'median s':>9} {'apart s':>8} {'shared s':>8} {'ratio':>6}  output")
    for path in projects:
        project = load_project(path)
        texts = sum(item.kind == "text" for page in project.pages for item in page.items)
        calendars = sum(item.kind == "calendar" for page in project.pages for item in page.items)
        run_check(path)  # warm the caches
        counts.clear()
        times, outputs = [], set()
        for _ in range(args.repeat):
            output, seconds = run_check(path)
            times.append(seconds)
            outputs.add(hashlib.sha256(output.encode()).hexdigest()[:12])
        fits_per_run = counts.get("fit_in_box", 0) / args.repeat
        lays_per_run = counts.get("layout_calendar", 0) / args.repeat
        passes = {True: [], False: []}
        words = {}
        for _ in range(args.repeat):
            for shared in (False, True):
                words[shared], seconds = text_passes(project, shared)
                passes[shared].append(seconds)
        if words[True] != words[False]:
            raise SystemExit(f"{path}: the shared fits changed check's words")
        apart, shared = statistics.median(passes[False]), statistics.median(passes[True])
        print(f"{path.relative_to(ROOT) if path.is_relative_to(ROOT) else path!s:<34} "
              f"{texts:>5} {calendars:>4} {fits_per_run:>8.0f} {lays_per_run:>8.0f} "
              f"{statistics.median(times):>9.3f} {apart:>8.4f} {shared:>8.4f} "
              f"{shared / apart:>6.2f}  {','.join(sorted(outputs))}")


if __name__ == "__main__":
    main_benchmark()
