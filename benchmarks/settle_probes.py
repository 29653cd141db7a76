"""How many probes a settle needs on realistic project files (issue 16: a settle with guides
at most 1.25x one without): fresh_projects.py's files (``random_project``), every page settled
once the `floatpage settle` way (model.layout.settle_page) with the file's physics and
``guides`` set to --guides; per page its items, its ``Engine.settle`` calls (the first probe,
the full run, the probes after it), its settle CPU seconds and its near misses per item; and
the totals.  A page at rest after its full run takes 2 or 3 calls; each call more is a probe
that found the page not at rest (model.layout.settle_page).

    .venv/bin/python benchmarks/settle_probes.py --seeds 1-60
    .venv/bin/python benchmarks/settle_probes.py --seeds 1-60 --guides 0
"""

from __future__ import annotations

import argparse
import tempfile
import time
from dataclasses import replace
from pathlib import Path

import floatpage.physics.engine as engine_module
from floatpage.model import load_project
from floatpage.model.layout import copy_of, engine_for_page, settle_page
from fresh_projects import random_project, seed_range


def counted_settles() -> list[int]:
    """Wrap Engine.settle to note each call's steps in the returned list."""
    calls: list[int] = []
    settle = engine_module.Engine.settle

    def counted(self, *args, **kwargs):
        report = settle(self, *args, **kwargs)
        calls.append(report.steps)
        return report
    engine_module.Engine.settle = counted
    return calls


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", default="1-60")
    parser.add_argument("--guides", type=float, default=1.0)
    args = parser.parse_args()
    calls = counted_settles()
    pages = settles = 0
    cpu = misses = 0.0
    print("| seed | page | items | settle calls | CPU s | near misses/item |")
    print("|---|---|---|---|---|---|")
    for seed in seed_range(args.seeds):
        with tempfile.TemporaryDirectory() as folder:
            project = load_project(random_project(seed, Path(folder)))
        physics = replace(project.physics, guides=args.guides)
        for page in project.pages:
            calls.clear()
            trial = copy_of(page)
            start = time.process_time()
            settle_page(trial, physics)
            seconds = time.process_time() - start
            miss = engine_for_page(trial, physics).alignment().near_misses_per_item
            print(f"| {seed} | {page.id} | {len(page.items)} | {len(calls)} | {seconds:.3f} "
                  f"| {miss:.2f} |", flush=True)
            pages, settles, cpu, misses = pages + 1, settles + len(calls), cpu + seconds, misses + miss
    print(f"\n{pages} pages: {settles} settle calls, {cpu:.2f} s CPU, near misses per item "
          f"summed {misses:.2f}")


if __name__ == "__main__":
    main()
