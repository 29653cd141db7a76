"""Is a settled file a fixed point?  Settle a project file, settle the result again, compare bytes.

Runs the `floatpage settle` code path (load, settle_project, save) on every benchmark scene, a
few scenes the engine was never tuned on, every sample and every starter, and prints per file:
whether the second settle changed any byte, what `check --strict` would say of the settled
file (overlaps, items off the page, the smallest gap against the gutter) and the time of both
settles.  Usage: .venv/bin/python benchmarks/fixed_point.py [--quick]
"""

from __future__ import annotations

import argparse
import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from floatpage import starters
from floatpage.model import load_project, save_project
from floatpage.model.document import BlockItem, Page, Project
from floatpage.model.layout import engine_for_page, settle_project
from seeded_scenes import Scene, big_item_scene, dropped_scene, mixed_scene

ROOT = Path(__file__).resolve().parents[1]
LETTER = (215.9, 279.4)


def extreme_aspects(count: int, coverage: float, seed: int) -> Scene:
    """Letter page, aspect ratios from 1:8 to 8:1 (log-uniform)."""
    rng = np.random.default_rng(seed)
    aspects = np.exp(rng.uniform(np.log(1 / 8), np.log(8), count))
    areas = rng.uniform(0.5, 2.0, count)
    areas *= coverage * LETTER[0] * LETTER[1] / areas.sum()
    widths = np.sqrt(areas * aspects)
    sizes = np.column_stack([widths, areas / widths])
    extent = np.array(LETTER)
    low, high = np.minimum(sizes / 2, extent / 2), np.maximum(extent - sizes / 2, extent / 2)
    centres = low + rng.random(sizes.shape) * (high - low)
    return Scene(f"Letter {count} items 1:8-8:1", *LETTER, centres, sizes)


def scenes(quick: bool) -> list[Scene]:
    chosen = [mixed_scene(n, 0.5, seed=1) for n in (5, 10, 20, 50, 200)]
    chosen += [mixed_scene(40, 0.9, seed=1), dropped_scene(12), big_item_scene(seed=1),
               mixed_scene(10, 0.45, seed=7), extreme_aspects(120, 0.45, seed=2)]
    if not quick:
        chosen += [mixed_scene(500, 0.5, seed=1), mixed_scene(200, 0.5, seed=5)]
    return chosen


def scene_project(scene: Scene, path: Path) -> Path:
    page = Page(id="page", size="custom", width_mm=scene.page_w_mm, height_mm=scene.page_h_mm,
                items=[BlockItem(id=item_id, x=float(x), y=float(y), w=float(w), h=float(h))
                       for item_id, (x, y), (w, h) in zip(scene.ids, scene.centres, scene.sizes)])
    save_project(Project(title=scene.name, pages=[page]), path)
    return path


def settle_file(path: Path) -> float:
    started = time.perf_counter()
    project = load_project(path)
    settle_project(project)
    save_project(project)
    return time.perf_counter() - started


def strict_check(path: Path) -> str:
    project = load_project(path)
    problems, gaps = 0, []
    for page in project.pages:
        quality = engine_for_page(page, project.physics).quality()
        problems += quality.overlap_count + len(quality.off_page)
        gaps.append(quality.min_gap_mm)
    return f"{problems} problems, min gap {min(gaps):.2f} mm"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="skip the 500-item scenes")
    args = parser.parse_args()
    work = Path(tempfile.mkdtemp(prefix="floatpage-fixed-point-"))
    files: list[tuple[str, Path]] = []
    for k, scene in enumerate(scenes(args.quick)):
        files.append((scene.name, scene_project(scene, work / f"scene{k}.toml")))
    for sample in sorted((ROOT / "sample_projects").glob("*/*.toml")):
        shutil.copytree(sample.parent, work / sample.parent.name)
        files.append((f"sample {sample.parent.name}", work / sample.parent.name / sample.name))
    for kind in ("blank", "card", "calendar", "album", "flyer"):
        target = work / f"starter-{kind}" / f"{kind}.toml"
        target.parent.mkdir()
        starters.create(kind, target)
        files.append((f"starter {kind}", target))
    print(f"{'file':34} {'1st settle':>10} {'2nd settle':>10}  2nd changed  check --strict")
    unchanged = 0
    for name, path in files:
        first = settle_file(path)
        before = path.read_bytes()
        second = settle_file(path)
        same = path.read_bytes() == before
        unchanged += same
        print(f"{name:34} {first:9.2f}s {second:9.2f}s  {'no' if same else 'YES':11}  "
              f"{strict_check(path)}")
    print(f"{unchanged} of {len(files)} files unchanged by a second settle")
    shutil.rmtree(work)
    return 0 if unchanged == len(files) else 1


if __name__ == "__main__":
    sys.exit(main())
