"""What `floatpage check` costs now that it asks, of a page whose lines would send the user to
`settle`, whether a settle mends it (a settle of a copy of that page, model.page_report.
settle_mends).  A settled, sound page asks nothing; a stuck or unsettled one pays a settle.

CPU seconds of the command and its children (user + system), start to exit, each file
checked ``--repeat`` times; the files are made once in a temporary folder:

- every sample project, as shipped (settled: no page asks);
- a greeting card from `floatpage new card`, its size typed down to A6 and settled (stuck:
  both pages ask, and the answer is "no");
- the same card, unsettled: its inside page's items piled on one spot (the answer is "yes").

    .venv/bin/python benchmarks/check_cost.py [--python OTHER/.venv/bin/python] [--repeat 3]

``--python`` runs `check` with another checkout's interpreter (main's, for the figure
before), on the same files.
"""

from __future__ import annotations

import argparse
import resource
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def cpu_of(python: str, args: list[str], cwd: Path) -> float:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([python, "-m", "floatpage.cli.main", *args], cwd=cwd, check=False,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   stdin=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def make_files(folder: Path) -> dict[str, Path]:
    from floatpage.model import load_project, save_project

    files = {}
    for sample in sorted((ROOT / "sample_projects").iterdir()):
        for toml in sorted(sample.glob("*.toml")):
            target = folder / sample.name
            shutil.copytree(sample, target, dirs_exist_ok=True)
            files[f"sample {toml.name}"] = target / toml.name
    stuck = folder / "stuck"
    stuck.mkdir()
    here = [sys.executable, "-m", "floatpage.cli.main"]
    subprocess.run([*here, "new", "card", "card.toml"], cwd=stuck, check=True,
                   capture_output=True)
    card = stuck / "card.toml"
    card.write_text(card.read_text().replace('size = "5x8in"', 'size = "A6"'))
    subprocess.run([*here, "settle", "-q", "card.toml"], cwd=stuck, check=True,
                   capture_output=True)
    files["card typed down to A6, settled (stuck)"] = card
    piled = folder / "piled"
    piled.mkdir()
    subprocess.run([*here, "new", "card", "card.toml"], cwd=piled, check=True,
                   capture_output=True)
    project = load_project(piled / "card.toml")
    free = [item for item in project.pages[1].items
            if not item.decorative and item.anchor is None]
    for item in free:
        item.x, item.y = free[0].x, free[0].y
    save_project(project, piled / "card.toml")
    files["card, inside piled up (unsettled)"] = piled / "card.toml"
    return files


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--python", default=sys.executable)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        files = make_files(Path(tmp))
        print(f"check CPU seconds ({args.python}), best and median of {args.repeat}")
        for name, path in files.items():
            times = sorted(cpu_of(args.python, ["check", path.name], path.parent)
                           for _ in range(args.repeat))
            print(f"  {name:45s} {times[0]:6.2f} {times[len(times) // 2]:6.2f}")


if __name__ == "__main__":
    main()
