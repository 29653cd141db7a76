"""Fixtures for the editor tests: a small real project on disk, with real pictures.

The project is written with the model's own save, so the editor loads it the
way it loads a user's file. Physics is never mocked: tests start the app with
autostart=False (physics paused) and run steps explicitly when they need motion.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from floatpage.model.document import (
    Background, BlockItem, CalendarItem, ItemAnchor, Page, PictureItem, PointAnchor, Project,
    TextItem,
)
from floatpage.model.save import save_project

from editor_helpers import BLUE, RED, paint_picture  # noqa: F401  (fixtures use them)


def build_project(folder: Path) -> Path:
    """Two A5 pages. Front: a title, a picture with a caption following it, a block, a calendar
    anchored to a point and a decorative band; back: one text."""
    paint_picture(folder / "pictures" / "photo.png")
    paint_picture(folder / "pictures" / "second.png", size=(20, 40))
    front = Page(id="front", size="A5", width_mm=148.0, height_mm=210.0, items=[
        TextItem(id="title", x=74.0, y=25.0, w=110.0, h=24.0, text="Happy Birthday Anna",
                 color="#aa2222", bold=True),
        PictureItem(id="photo", x=45.0, y=85.0, w=60.0, h=45.0, path="pictures/photo.png"),
        TextItem(id="caption", x=45.0, y=115.0, w=60.0, h=10.0, text="Summer",
                 anchor=ItemAnchor(to="photo", dx=0.0, dy=30.0)),
        BlockItem(id="block", x=115.0, y=85.0, w=30.0, h=30.0, color="#22aa44"),
        CalendarItem(id="month", x=74.0, y=170.0, w=100.0, h=50.0, year=2027, month=3,
                     anchor=PointAnchor(x=74.0, y=170.0, gamma=0.8)),
        BlockItem(id="band", x=74.0, y=170.0, w=148.0, h=60.0, color="#ffe08a", z=-1,
                  decorative=True),
    ])
    back = Page(id="back", size="A5", width_mm=148.0, height_mm=210.0,
                background=Background(color="#eef4ff"), items=[
                    TextItem(id="greeting", x=74.0, y=105.0, w=90.0, h=30.0,
                             text="With love from all of us"),
                ])
    project = Project(title="Test card", pages=[front, back])
    path = folder / "card.toml"
    save_project(project, path)
    return path


@pytest.fixture
def project_path(tmp_path: Path) -> Path:
    return build_project(tmp_path / "card")


@pytest.fixture
def held_until_let_go(monkeypatch):
    """A nudged item stays held until the test lets go of it (`release_held`) or a command
    does: the editor's own release, RELEASE_AFTER_S (0.6 s) after the last arrow, came
    between a test's keys on a loaded machine (a shuffled, slowed run beside a CPU burner),
    and the test read an item let go by the timer instead of the state it was about."""
    from floatpage.tui import editor_screen

    monkeypatch.setattr(editor_screen, "RELEASE_AFTER_S", 600.0)
