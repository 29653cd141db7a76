"""Does font fallback cost a Latin-only document anything? Render it with two code trees, in turn.

    .venv/bin/python benchmarks/latin_speed.py --old /path/to/tree/of/an/older/commit
    .venv/bin/python benchmarks/latin_speed.py --old OLD --repeat 7 PROJECT.toml

OLD is a checkout of floatpage before the fallback fonts (e.g. `git worktree add /tmp/old
dd563be`). Each round renders the project once with this tree and once with OLD, each in a
fresh Python process (import, layout, fitting, templates, one LuaLaTeX run, the write), the
order alternating; it prints the medians and their ratio. A multilingual control (the same
project plus one box of CJK, Arabic and emoji) shows what the fallback costs where it is used.
The machine is shared: compare the ratio within one run.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_PROJECT = ROOT / "sample_projects" / "greeting-card" / "greeting-card.toml"
FOLDERS = ("physics", "model", "typeset", "tui", "cli", "starters", "latex_templates")
RENDER = """
import sys, time
from floatpage.model import load_project
from floatpage.model.document import TextItem
from floatpage.typeset import render_pdf
project = load_project(sys.argv[1])
if sys.argv[3] == "multilingual":
    page = project.pages[0]
    page.items.append(TextItem(id="ml", x=40, y=20, w=60, h=15,
                               text="生日快乐 عيد ميلاد سعيد 🎉", font="serif"))
started = time.perf_counter()
render_pdf(project, sys.argv[2])
print(time.perf_counter() - started)
"""


def package_path(tree: Path, scratch: Path) -> Path:
    """A folder holding `floatpage` as links to the tree's top-level folders."""
    package = scratch / "floatpage"
    package.mkdir(parents=True)
    for folder in FOLDERS:
        (package / folder).symlink_to(tree / folder)
    return scratch


def render_once(python_path: Path | None, project: Path, out: Path, variant: str) -> float:
    env = dict(os.environ)
    if python_path is not None:
        env["PYTHONPATH"] = str(python_path)
    started = time.perf_counter()
    subprocess.run([sys.executable, "-c", RENDER, str(project), str(out), variant], env=env,
                   check=True, capture_output=True)
    return time.perf_counter() - started


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("project", nargs="?", type=Path, default=DEFAULT_PROJECT)
    parser.add_argument("--old", type=Path, required=True, help="checkout of an older commit")
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="floatpage-bench-") as scratch:
        scratch = Path(scratch)
        old = package_path(args.old.resolve(), scratch / "old")
        out = scratch / "out.pdf"
        render_once(None, args.project, out, "latin")  # warm the caches
        render_once(old, args.project, out, "latin")
        render_once(None, args.project, out, "multilingual")
        times: dict[str, list[float]] = {"new": [], "old": [], "multilingual": []}
        for round_ in range(args.repeat):
            order = [("new", None), ("old", old)]
            for name, path in order if round_ % 2 == 0 else order[::-1]:
                times[name].append(render_once(path, args.project, out, "latin"))
            times["multilingual"].append(render_once(None, args.project, out, "multilingual"))
    median = {name: statistics.median(values) for name, values in times.items()}
    print(f"project: {args.project} ({args.repeat} rounds, a fresh process per render)")
    print(f"Latin-only, this tree:  median {median['new']:.3f} s")
    print(f"Latin-only, {args.old}: median {median['old']:.3f} s")
    print(f"ratio this / old: {median['new'] / median['old']:.3f} (target <= 1.10)")
    print(f"with one multilingual box, this tree: median {median['multilingual']:.3f} s "
          f"({median['multilingual'] / median['new']:.2f} x Latin-only)")


if __name__ == "__main__":
    main()
