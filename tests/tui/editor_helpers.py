"""Shared helpers for driving the editor with Pilot and reading its preview."""

from __future__ import annotations

from contextlib import asynccontextmanager
from pathlib import Path

from PIL import Image

from floatpage.tui.app import FloatpageApp, make_app
from floatpage.tui.editor_screen import EditorScreen

SIZE = (100, 40)
RED = (220, 30, 30)
BLUE = (30, 60, 220)


def paint_picture(path: Path, size=(40, 30)) -> Path:
    """A 4:3 picture, red on top and blue below, so a thumbnail is easy to recognise."""
    image = Image.new("RGB", size, BLUE)
    image.paste(RED, (0, 0, size[0], size[1] // 2))
    path.parent.mkdir(parents=True, exist_ok=True)
    image.save(path)
    return path


@asynccontextmanager
async def editor(path: Path, size: tuple[int, int] = SIZE, *, autostart: bool = False):
    """The real app on a project file, physics paused unless autostart; yields (app, pilot)."""
    app = make_app(path, autostart=autostart)
    async with app.run_test(size=size) as pilot:
        await pilot.pause()
        yield app, pilot


async def until(pilot, condition, seconds: float = 10.0) -> bool:
    """Wait, a tenth of a second at a time, until ``condition()`` holds, at most ``seconds``:
    a fixed pause that suits an idle machine is too short on a loaded CI runner."""
    for _ in range(int(seconds / 0.1)):
        if condition():
            return True
        await pilot.pause(0.1)
    return condition()


def screen_of(app: FloatpageApp) -> EditorScreen:
    return app.editor


def item(app: FloatpageApp, item_id: str):
    """The model's item, with the engine's live position written back."""
    session = app.session
    session.sync_positions()
    return session.page.item(item_id)


def position(app: FloatpageApp, item_id: str) -> tuple[float, float]:
    return app.session.engine.positions()[item_id]


async def type_text(pilot, text: str) -> None:
    await pilot.press(*[{" ": "space"}.get(char, char) for char in text])


def preview_text(app: FloatpageApp) -> str:
    return "\n".join(screen_of(app).preview.text_lines())


def pixel(app: FloatpageApp, col: int, pixel_row: int) -> tuple[int, int, int]:
    canvas = screen_of(app).preview.canvas
    return tuple(int(v) for v in canvas.pixels[pixel_row, col])


def item_pixel_box(app: FloatpageApp, item_id: str) -> tuple[int, int, int, int]:
    preview = screen_of(app).preview
    x, y = position(app, item_id)
    it = app.session.page.item(item_id)
    return preview.projection.rect(x, y, it.w, it.h)
