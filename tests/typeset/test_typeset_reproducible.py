"""The same project gives the same bytes, wherever it is built from."""

from __future__ import annotations

import hashlib
import os
import shutil
from pathlib import Path

import pytest
from PIL import Image

from floatpage.model.document import Background, BlockItem, CalendarItem, Page, PictureItem, Project, TextItem
from floatpage.typeset import render_pdf
from floatpage.typeset.errors import RenderError


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


def small_project(folder: Path) -> Project:
    return Project(path=folder / "note.toml", title="Anywhere", pages=[
        Page(id="front", size="custom", width_mm=90, height_mm=50, items=[
            TextItem(id="t", x=45, y=25, w=70, h=20, text="Same bytes in Paris and in CI")])])


def test_the_time_zone_the_locale_and_an_empty_source_date_epoch_leave_the_bytes(
        tmp_path, monkeypatch):
    """user-walk-12b: TZ=Pacific/Kiritimati wrote the PDF's dates as "+14'00'" (other bytes
    than UTC's); LC_ALL naming a locale the machine lacks (a Docker image's LANG) stopped
    LuaTeX before its log, told as "out of memory"; SOURCE_DATE_EPOCH set but empty dated the
    PDF now. Each must give the bytes of a plain render."""
    for name in ("TZ", "LC_ALL", "LANG", "SOURCE_DATE_EPOCH"):
        monkeypatch.delenv(name, raising=False)
    project = small_project(tmp_path)
    render_pdf(project, tmp_path / "plain.pdf")
    settings = {"zone": {"TZ": "Pacific/Kiritimati"},
                "locale": {"LC_ALL": "xx_XX.UTF-8", "LANG": "xx_XX.UTF-8"},
                "empty-date": {"SOURCE_DATE_EPOCH": ""}}
    for name, variables in settings.items():
        with monkeypatch.context() as patched:
            for variable, value in variables.items():
                patched.setenv(variable, value)
            render_pdf(project, tmp_path / f"{name}.pdf")
        assert sha256(tmp_path / f"{name}.pdf") == sha256(tmp_path / "plain.pdf"), name


def test_a_source_date_epoch_that_is_no_time_is_refused_before_any_work(tmp_path, monkeypatch):
    """LuaTeX read SOURCE_DATE_EPOCH=abc as 1970 without a word; reproducible-builds.org asks
    a build to stop on a malformed value."""
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "yesterday")
    with pytest.raises(RenderError, match="SOURCE_DATE_EPOCH='yesterday' is not a time"):
        render_pdf(small_project(tmp_path), tmp_path / "note.pdf")
    assert not (tmp_path / "note.pdf").exists()
