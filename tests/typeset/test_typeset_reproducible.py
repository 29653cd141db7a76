"""The same project gives the same bytes, wherever it is built from."""

from __future__ import annotations

import hashlib
import os
import shutil
from pathlib import Path

from PIL import Image

from floatpage.model.document import Background, BlockItem, CalendarItem, Page, PictureItem, Project, TextItem
from floatpage.typeset import render_pdf


def project_in(folder: Path) -> Project:
    Image.new("RGB", (64, 48), (10, 120, 90)).save(folder / "leaf.gif")
    return Project(path=folder / "card.toml", title="Reproducible", pages=[
        Page(id="front", background=Background(color="#fdf6e3"), items=[
            TextItem(id="t", x=105, y=40, w=150, h=30, text="Same bytes, every time — déjà vu",
                     font="display", bold=True),
            PictureItem(id="p", x=105, y=120, w=80, h=60, path="leaf.gif"),
            BlockItem(id="b", x=105, y=200, w=190, h=10, color="#268bd2", opacity=0.4)]),
        Page(id="month", items=[CalendarItem(id="c", x=105, y=150, w=180, h=150, year=2027,
                                             month=2, language="de")])])


def sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def test_two_renders_from_different_directories_are_byte_identical(tmp_path):
    first, second = tmp_path / "a", tmp_path / "elsewhere" / "b"
    first.mkdir()
    second.mkdir(parents=True)
    render_pdf(project_in(first), first / "card.pdf")
    shutil.copy(first / "leaf.gif", second / "leaf.gif")
    cwd = os.getcwd()
    try:
        os.chdir(second)
        render_pdf(project_in(second), Path("card.pdf"))
    finally:
        os.chdir(cwd)
    assert sha256(first / "card.pdf") == sha256(second / "card.pdf")


def test_a_different_project_gives_a_different_pdf_id(tmp_path):
    project = project_in(tmp_path)
    render_pdf(project, tmp_path / "one.pdf")
    project.pages[0].items[0].text = "Other bytes"
    render_pdf(project, tmp_path / "two.pdf")
    assert sha256(tmp_path / "one.pdf") != sha256(tmp_path / "two.pdf")


def test_the_picture_cache_location_does_not_change_the_bytes(tmp_path, monkeypatch):
    project = project_in(tmp_path)
    monkeypatch.setenv("FLOATPAGE_CACHE_DIR", str(tmp_path / "cache-one"))
    render_pdf(project, tmp_path / "one.pdf")
    monkeypatch.setenv("FLOATPAGE_CACHE_DIR", str(tmp_path / "cache-two"))
    render_pdf(project, tmp_path / "two.pdf")
    assert (tmp_path / "cache-two").is_dir()
    assert sha256(tmp_path / "one.pdf") == sha256(tmp_path / "two.pdf")
