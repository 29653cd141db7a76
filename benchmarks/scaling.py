"""Scaling figures of issue 10: 10,000 items, 2,000 photos, a 2,000-anchor chain.

The 2,000 photos come twice: on one page (a scene, below) and as a 200-page album file of
ten photos a page, every third captioned (the command table), as a user would settle it.

Each scene settles (`Engine.settle()`, the no-overlap pass included) in its own process, which
reports its own peak memory (ru_maxrss), so each figure is that scene's alone.  Then the chain
as a user meets it: a project file of 2,000 items anchored one to the next, and the wall time
of each `floatpage` command on it, start to exit (loading the file, anchoring, the quality
measures, the save; render includes LuaLaTeX), with the CPU seconds the command and its
children used (user + system: on a shared machine the wall time grows with the load, the CPU
time much less).  For the floor under render, the same commands on a file of one block; and
`settle` of the 10,000-item scene as a file (benchmarks/fixed_point.scene_project).

    .venv/bin/python benchmarks/scaling.py            # every scene, each capped at 600 s
    .venv/bin/python benchmarks/scaling.py --commands [--small]   # the command table alone
    .venv/bin/python benchmarks/scaling.py --album     # the 200-page album rows alone
"""

from __future__ import annotations

import json
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

SCENES = ("10,000 items, 30 %", "2,000 photos, 50 %", "2,000-anchor chain")
GOALS = {"10,000 items, 30 %": "60 s, 1 GB", "2,000 photos, 50 %": "30 s",
         "2,000-anchor chain": "2 s"}


def run_scene(name: str) -> dict:
    from floatpage.physics import Engine, Params
    from seeded_scenes import load, mixed_scene

    if name.startswith("10,000"):
        scene = mixed_scene(10_000, 0.3, seed=1)
    elif name.startswith("2,000 photos"):
        scene = mixed_scene(2_000, 0.5, seed=1)
    else:
        scene = None
    if scene is not None:
        engine = Engine(scene.page_w_mm, scene.page_h_mm, Params())
        load(engine, scene)
    else:  # a chain: each small item follows the one before it
        engine = Engine(210.0, 297.0, Params())
        rng = np.random.default_rng(1)
        for k in range(2_000):
            engine.insert(f"n{k}", float(rng.uniform(10, 200)), float(rng.uniform(10, 287)),
                          2.0, 2.0)
        for k in range(1, 2_000):
            engine.anchor_to(f"n{k}", f"n{k - 1}", 0.05, 0.05)
        engine.reheat()
    start = time.perf_counter()
    report = engine.settle()
    seconds = time.perf_counter() - start
    quality = engine.quality()
    return {"seconds": seconds, "steps": report.steps, "settled": report.settled,
            "overlaps": quality.overlap_count, "off_page": len(quality.off_page),
            "peak_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}


def chain_project(folder: Path, count: int = 2_000) -> Path:
    """A project file: ``count`` small items on an A4 page, each anchored to the one before."""
    from floatpage.model import save_project
    from floatpage.model.document import BlockItem, ItemAnchor, Page, Project

    rng = np.random.default_rng(1)
    items = [BlockItem(id=f"n{k}", x=float(rng.uniform(10, 200)), y=float(rng.uniform(10, 287)),
                       w=2.0, h=2.0, anchor=ItemAnchor(to=f"n{k - 1}", dx=0.05, dy=0.05)
                       if k else None) for k in range(count)]
    path = folder / "chain.toml"
    save_project(Project(title="chain", pages=[Page(id="p", size="A4", items=items)]), path)
    return path


def album_project(folder: Path, pages: int = 200, photos: int = 10) -> Path:
    """seeded_scenes.album_pages as a file of pictures (small JPEGs of six shapes, written into
    the folder); not settled yet."""
    from PIL import Image

    from floatpage.model import save_project
    from floatpage.model.document import PictureItem, Project
    from seeded_scenes import album_pages

    rng = np.random.default_rng(11)
    (folder / "photos").mkdir()

    def picture(number: int, k: int, x: float, y: float) -> PictureItem:
        name = f"photos/p{number:03d}-{k}.jpg"
        aspect = float(rng.choice([1.5, 2 / 3, 1.0, 16 / 9, 9 / 16, 1.75]))
        Image.new("RGB", (int(40 * aspect), 40), tuple(int(v) for v in rng.integers(0, 256, 3))
                  ).save(folder / name, quality=60)
        area = float(rng.uniform(1800, 3200))
        w = round((area * aspect) ** 0.5, 2)
        return PictureItem(id=f"p{number}-{k}", x=x, y=y, w=w, h=round(area / w, 2), path=name)

    path = folder / "album.toml"
    save_project(Project(title="album", pages=album_pages(pages, photos, picture, rng)), path)
    return path


def album_rows(folder: Path) -> None:
    """`floatpage settle` of the unsettled album in one process and over every core
    (-j default), from the same file: the wall time, and whether both wrote the same bytes.
    The CPU column counts the command's own process and children it waited for: a worker of
    the page pool is the child of a server process, so with more than one job it is left
    out."""
    import shutil

    floatpage = Path(sys.executable).with_name("floatpage")
    unsettled = album_project(folder)
    written = []
    for label, options in (("-j 1", ["-j", "1"]), ("default jobs", [])):
        path = folder / f"album{len(written)}.toml"
        shutil.copy(unsettled, path)
        seconds, cpu, code = timed([str(floatpage), "settle", *options, str(path)])
        written.append(path.read_bytes())
        print(f"| 200-page album, 2,000 photos (file) | floatpage settle {label} | 30 s "
              f"| {seconds:.1f} | {cpu:.1f} | exit {code} |", flush=True)
    print(f"\nthe two settles wrote the same bytes: {'yes' if written[0] == written[1] else 'NO'}")


def one_block_project(folder: Path) -> Path:
    """The floor: a project of one block on A4."""
    from floatpage.model import save_project
    from floatpage.model.document import BlockItem, Page, Project

    path = folder / "one.toml"
    save_project(Project(title="one", pages=[Page(id="p", size="A4", items=[
        BlockItem(id="b", x=105.0, y=148.5, w=20.0, h=20.0)])]), path)
    return path


def timed(command: list[str]) -> tuple[float, float, int]:
    """(wall seconds, CPU seconds of the command and its children, exit code)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    started = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True, timeout=900)
    seconds = time.perf_counter() - started
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return seconds, cpu, done.returncode


def command_rows(big: bool = True) -> None:
    """The wall and CPU time of each command on the chain file (settle twice: the second
    finds it settled), on a one-block file, and (``big``) settle of 10,000 items."""
    sys.path.insert(0, str(Path(__file__).parent))
    from fixed_point import scene_project
    from seeded_scenes import mixed_scene

    floatpage = Path(sys.executable).with_name("floatpage")
    with tempfile.TemporaryDirectory() as folder:
        files = [("2,000-anchor chain file", "2 s", chain_project(Path(folder))),
                 ("one block (the floor)", "", one_block_project(Path(folder)))]
        for label, goal, path in files:
            for command in (["check"], ["settle"], ["settle"],
                            ["render", "-o", f"{folder}/c.pdf"]):
                seconds, cpu, code = timed([str(floatpage), *command, str(path)])
                print(f"| {label} | floatpage {command[0]} | {goal} | {seconds:.2f} "
                      f"| {cpu:.2f} | exit {code} |", flush=True)
        if big:
            album_rows(Path(folder))
            path = scene_project(mixed_scene(10_000, 0.3, seed=1), Path(folder) / "ten.toml")
            seconds, cpu, code = timed([str(floatpage), "settle", str(path)])
            print(f"| 10,000 items, 30 % (file) | floatpage settle | 60 s | {seconds:.1f} "
                  f"| {cpu:.1f} | exit {code} |", flush=True)


def main() -> None:
    if len(sys.argv) > 2 and sys.argv[1] == "--one":
        print(json.dumps(run_scene(sys.argv[2])))
        return
    if len(sys.argv) > 1 and sys.argv[1] == "--album":
        print("| file | command | goal | s | CPU s | |\n|---|---|---|---|---|---|")
        with tempfile.TemporaryDirectory() as folder:
            album_rows(Path(folder))
        return
    if len(sys.argv) > 1 and sys.argv[1] == "--commands":  # the command table alone
        print("| file | command | goal | s | CPU s | |\n|---|---|---|---|---|---|")
        command_rows(big="--small" not in sys.argv)
        return
    print("| scene | goal | s | steps | settled | overlapping pairs | off page | peak memory |")
    print("|---|---|---|---|---|---|---|---|")
    for name in SCENES:
        started = time.perf_counter()
        try:
            done = subprocess.run([sys.executable, __file__, "--one", name], capture_output=True,
                                  text=True, timeout=600)
            figures = json.loads(done.stdout) if done.returncode == 0 else None
        except subprocess.TimeoutExpired:
            figures = None
        if figures is None:
            print(f"| {name} | {GOALS[name]} | > {time.perf_counter() - started:.0f} (stopped) "
                  f"| | | | | |", flush=True)
            continue
        print(f"| {name} | {GOALS[name]} | {figures['seconds']:.1f} | {figures['steps']} "
              f"| {'yes' if figures['settled'] else 'no'} | {figures['overlaps']} "
              f"| {figures['off_page']} | {figures['peak_mb']:.0f} MB |", flush=True)
    print("\n| file | command | goal | s | CPU s | |\n|---|---|---|---|---|---|")
    command_rows()


if __name__ == "__main__":
    main()
