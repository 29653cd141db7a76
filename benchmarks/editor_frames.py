"""The editor's own time, headless: frame time (physics + drawing) at N items, and
keypress-to-redraw latency inside the app. Part of benchmarks/editor.py (`frames`).

Runs the real app headless (Textual's run_test, 100 x 40 cells) on a generated A4 page of N
items, so the figures include the real engine, the real painter and the real Strip building.

    .venv/bin/python benchmarks/editor.py frames            # N = 50 and N = 200
    .venv/bin/python benchmarks/editor.py frames --n 50 --frames 120

Frame time: `EditorScreen.tick` as a whole (physics under the editor's time budget, then
the drawing: paint the grid, build the Strips, status lines), and the drawing alone. The page
starts scattered and is scattered again whenever it settles, so the physics never idles.
Then the real 30 Hz loop runs on its own for two seconds and its frame rate is counted. Keypress to redraw: from sending an arrow key until the
screen with the moved item has been written out, with the physics running in the background.
"""

from __future__ import annotations

import argparse
import asyncio
import copy
import random
import statistics
import sys
import tempfile
import time
from pathlib import Path


from textual import events

from floatpage.model.document import BlockItem, Page, Project, TextItem
from floatpage.model.save import save_project
from floatpage.tui.app import make_app
from floatpage.tui.editor_screen import PHYSICS_BUDGET_S


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
    """Time `EditorScreen.tick` (physics under its budget, then the redraw) frame by frame.

    The frame timer is paused and ticks are driven here, one after another; whenever the page
    settles it is put back to its scattered start and reheated, so every frame has work to do.
    """
    app = make_app(path, autostart=True)
    async with app.run_test(size=(100, 40)) as pilot:
        await pilot.pause()
        screen, session = app.editor, app.session
        start_items = copy.deepcopy(session.page.items)

        def restart() -> None:
            session.page.items[:] = copy.deepcopy(start_items)
            session.engine = session._build_engine()  # from the scattered start, not write-back
            session.engine.reheat()
            screen.frame_timer.pause()

        restart()
        frame, drawing, steps = [], [], []
        original_redraw = screen.redraw

        def timed_redraw() -> None:  # the drawing inside the tick, timed where it happens
            start = time.perf_counter()
            original_redraw()
            drawing.append(time.perf_counter() - start)

        screen.redraw = timed_redraw
        for _ in range(frames):
            if session.engine.settled:
                restart()
            start = time.perf_counter()
            screen.tick()
            frame.append(time.perf_counter() - start)
            steps.append(screen.meter.frames[-1][1])
        screen.redraw = original_redraw
        restart()
        screen.wake()  # now let the real 30 Hz loop run on its own for two seconds
        ticked, began = screen.frames_ticked, time.perf_counter()
        while time.perf_counter() - began < 2.0:
            await asyncio.sleep(0.02)
            if session.engine.settled:  # scatter it again so the loop never idles
                restart()
                screen.wake()
        live_fps = (screen.frames_ticked - ticked) / (time.perf_counter() - began)
    return {"frame": frame, "drawing": drawing, "steps": steps, "live_fps": live_fps}


async def measure_keypresses(path: Path, presses: int) -> list[float]:
    """Key event posted -> action done and preview repainted -> the screen written to the driver.

    The physics loop runs throughout (the page is reheated before each key), so a key may have
    to wait for the frame in progress; that wait is part of the figure.
    """
    app = make_app(path, autostart=True)
    displays: list[float] = []
    original_display = app._display

    def timed_display(screen, renderable) -> None:
        original_display(screen, renderable)
        displays.append(time.perf_counter())

    app._display = timed_display
    latencies = []
    async with app.run_test(size=(100, 40)) as pilot:
        await pilot.press("tab")
        await pilot.pause()
        screen = app.editor
        handled: list[float] = []
        original_nudge = screen.action_nudge

        def timed_nudge(dx_mm: float, dy_mm: float) -> None:
            original_nudge(dx_mm, dy_mm)
            handled.append(time.perf_counter())

        screen.action_nudge = timed_nudge
        for index in range(presses):
            app.session.engine.reheat()
            screen.wake()
            await asyncio.sleep(0.05 + 0.011 * (index % 3))  # land keys at varied frame phases
            handled.clear()
            key = "l" if index % 2 else "h"
            start = time.perf_counter()
            app.post_message(events.Key(key, key))
            while not (handled and displays and displays[-1] > handled[0]):
                await asyncio.sleep(0.0005)
            latencies.append(displays[-1] - start)
    return latencies


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--n", type=int, nargs="*", default=[50, 200])
    parser.add_argument("--frames", type=int, default=90)
    parser.add_argument("--presses", type=int, default=40)


def run(args: argparse.Namespace) -> None:
    with tempfile.TemporaryDirectory() as folder:
        for count in args.n:
            path = build_page(Path(folder), count)
            result = asyncio.run(measure_frames(path, args.frames))
            print(f"N = {count}")
            print(f"  frame, physics ({1000 * PHYSICS_BUDGET_S:.0f} ms budget) + drawing: "
                  f"{summary(result['frame'])} · {statistics.median(result['steps']):.0f} "
                  "steps/frame")
            print(f"  of which drawing:                         {summary(result['drawing'])}")
            print(f"  live loop: {result['live_fps']:.1f} frames/s; steps per frame: mean "
                  f"{statistics.mean(result['steps']):.0f}, max {max(result['steps'])}")
            latencies = asyncio.run(measure_keypresses(path, args.presses))
            print(f"  keypress to redraw, physics running: {summary(latencies)}")
