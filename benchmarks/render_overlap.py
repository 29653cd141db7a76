"""`floatpage render` of a settled file, typeset while it settles (typeset.while_settling)
against settling first, then typesetting (the render before it), in one run.

    .venv/bin/python benchmarks/render_overlap.py              # 5 rounds each
    .venv/bin/python benchmarks/render_overlap.py --rounds 9

The files: the 2,000-anchor chain of issue 10 (benchmarks/scaling.chain_project, settled
first) and the shipped samples.  Each round renders each file both ways, alternating, with the
real command in a fresh process; the one-after-the-other way is the same command with
``worth_overlapping`` answering no.  Wall seconds (start to exit) and the CPU seconds of the
command and its children (LuaLaTeX), medians over the rounds, and whether both ways wrote the
same bytes.  The machine is shared: the load is printed, compare within one run.
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SERIAL = ("import sys\n"
          "import floatpage.typeset.while_settling as overlap\n"
          "overlap.worth_overlapping = lambda project, jobs: False\n"
          "from floatpage.cli.entry import main\n"
          "sys.argv = ['floatpage', *sys.argv[1:]]\n"
          "sys.exit(main())\n")


def timed(command: list[str]) -> tuple[float, float]:
    """Wall and CPU seconds (the command and its children) of one run."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(command, check=True, capture_output=True, cwd=ROOT)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def files(folder: Path) -> list[tuple[str, Path]]:
    sys.path.insert(0, str(Path(__file__).parent))
    from scaling import chain_project

    floatpage = Path(sys.executable).with_name("floatpage")
    chain = chain_project(folder)
    subprocess.run([str(floatpage), "settle", "-q", str(chain)], check=True, cwd=ROOT)
    found = [("2,000-anchor chain", chain)]
    for sample in sorted((ROOT / "sample_projects").iterdir()):
        if sample.is_dir() and sample.name != "merge-offers":
            copy = folder / sample.name
            shutil.copytree(sample, copy)
            found.extend((sample.name, path) for path in sorted(copy.glob("*.toml")))
    return found


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    floatpage = str(Path(sys.executable).with_name("floatpage"))
    print(f"load {os.getloadavg()[0]:.1f}, cores {len(os.sched_getaffinity(0))}")
    print("| file | settle, then typeset: wall s | CPU s | typeset while settling: wall s "
          "| CPU s | wall ratio | same bytes |")
    print("|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as folder:
        for label, path in files(Path(folder)):
            serial_out, overlap_out = Path(folder) / "serial.pdf", Path(folder) / "overlap.pdf"
            serial, overlapped = [], []
            for _ in range(args.rounds):
                serial.append(timed([sys.executable, "-c", SERIAL, "render", "-q", str(path),
                                     "-o", str(serial_out)]))
                overlapped.append(timed([floatpage, "render", "-q", str(path), "-o",
                                         str(overlap_out)]))
            wall_s = statistics.median(w for w, _ in serial)
            wall_o = statistics.median(w for w, _ in overlapped)
            same = serial_out.read_bytes() == overlap_out.read_bytes()
            print(f"| {label} | {wall_s:.2f} | {statistics.median(c for _, c in serial):.2f} "
                  f"| {wall_o:.2f} | {statistics.median(c for _, c in overlapped):.2f} "
                  f"| {wall_o / wall_s:.2f} | {'yes' if same else 'NO'} |", flush=True)
    print(f"load {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
