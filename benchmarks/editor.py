"""Editor benchmark: frame time (physics + drawing) at N items, and keypress-to-redraw latency.

Runs the real app headless (Textual's run_test, 100 x 40 cells) on a generated A4 page of N
items, so the figures include the real engine, the real painter and the real Strip building.

    .venv/bin/python benchmarks/editor.py            # N = 50 and N = 200
    .venv/bin/python benchmarks/editor.py --n 50 --frames 120

Frame time: each frame is what `EditorScreen.tick` does, timed in two parts: the physics
(`engine.advance` under the editor's time budget, and separately one default frame of steps)
and the drawing (paint the grid, build the Strips, status lines). The page is reheated before
every frame so the physics never idles. Keypress to redraw: from sending an arrow key until the
app is idle again with the moved item drawn, with the physics running in the background.
"""

from __future__ import annotations

import argparse
import asyncio
import random
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from model.document import BlockItem, Page, Project, TextItem  # noqa: E402
from model.save import save_project  # noqa: E402
from tui.app import make_app  # noqa: E402
from tui.editor_screen import PHYSICS_BUDGET_S  # noqa: E402


def build_page(folder: Path, count: int, seed: int = 1) -> Path:
    """An A4 page with `count` text and block items scattered at random (overlapping at first)."""
    rng = random.Random(seed)
    items = []
    for index in range(count):
        w, h = rng.uniform(10, 40), rng.uniform(8, 30)
        x, y = rng.uniform(w / 2, 210 - w / 2), rng.uniform(h / 2, 297 - h / 2)
        if index % 2:
            items.append(TextItem(id=f"t{index}", x=x, y=y, w=w, h=h, text=f"text {index}"))
        else:
            items.append(BlockItem(id=f"b{index}", x=x, y=y, w=w, h=h, color="#4c8ed9"))
    project = Project(title=f"bench {count}", pages=[Page(id="p", items=items)])
    path = folder / f"bench-{count}.toml"
    save_project(project, path)
    return path


def summary(samples_s: list[float]) -> str:
    ms = sorted(1000 * s for s in samples_s)
    p95 = ms[min(len(ms) - 1, int(0.95 * len(ms)))]
    return f"median {statistics.median(ms):6.2f} ms · p95 {p95:6.2f} ms · max {ms[-1]:6.2f} ms"


async def measure_frames(path: Path, frames: int) -> dict:
    app = make_app(path, autostart=False)
    async with app.run_test(size=(100, 40)) as pilot:
        await pilot.pause()
        screen, engine = app.editor, app.session.engine
        budget_physics, fixed_physics, drawing, steps = [], [], [], []
        for _ in range(frames):
            engine.reheat()
            start = time.perf_counter()
            steps.append(engine.advance(budget_s=PHYSICS_BUDGET_S, clock=time.perf_counter))
            budget_physics.append(time.perf_counter() - start)
            engine.reheat()
            start = time.perf_counter()
            engine.advance()  # one default frame of steps (the mode's frame_steps)
            fixed_physics.append(time.perf_counter() - start)
            start = time.perf_counter()
            screen.redraw()
            for y in range(screen.preview.size.height):
                screen.preview.render_line(y)
            drawing.append(time.perf_counter() - start)
        frame_steps = engine.params.frame_steps
    return {"budget_physics": budget_physics, "fixed_physics": fixed_physics,
            "drawing": drawing, "steps": steps, "frame_steps": frame_steps}


async def measure_keypresses(path: Path, presses: int) -> list[float]:
    app = make_app(path, autostart=True)
    latencies = []
    async with app.run_test(size=(100, 40)) as pilot:
        await pilot.pause()
        await pilot.press("tab")
        preview = app.editor.preview
        for index in range(presses):
            app.session.engine.reheat()  # keep the physics loop busy underneath the keys
            app.editor.wake()
            drawn = preview.frames_drawn
            start = time.perf_counter()
            await pilot.press("l" if index % 2 else "h")
            await pilot.pause()
            latencies.append(time.perf_counter() - start)
            assert preview.frames_drawn > drawn, "the key did not redraw the preview"
    return latencies


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--n", type=int, nargs="*", default=[50, 200])
    parser.add_argument("--frames", type=int, default=90)
    parser.add_argument("--presses", type=int, default=40)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        for count in args.n:
            path = build_page(Path(folder), count)
            result = asyncio.run(measure_frames(path, args.frames))
            totals = [p + d for p, d in zip(result["budget_physics"], result["drawing"])]
            fixed = [p + d for p, d in zip(result["fixed_physics"], result["drawing"])]
            print(f"N = {count}")
            print(f"  physics, {1000 * PHYSICS_BUDGET_S:.0f} ms budget: "
                  f"{summary(result['budget_physics'])} · "
                  f"{statistics.median(result['steps']):.0f} steps/frame")
            print(f"  physics, {result['frame_steps']} steps:      {summary(result['fixed_physics'])}")
            print(f"  drawing:                 {summary(result['drawing'])}")
            print(f"  frame (budget + drawing): {summary(totals)}")
            print(f"  frame ({result['frame_steps']} steps + drawing): {summary(fixed)}")
            latencies = asyncio.run(measure_keypresses(path, args.presses))
            print(f"  keypress to redraw, physics running: {summary(latencies)}")


if __name__ == "__main__":
    main()
