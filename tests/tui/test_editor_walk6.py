"""Defects a demanding user met over SSH (user-walk-6), each driven through the real app with
Pilot: labels that hid a text's row or a region's name, toasts over dialogs, and a status line
that said the gaps were narrow without saying why."""

from __future__ import annotations

from pathlib import Path

import re
import shutil
import subprocess
import sys

from floatpage.model import save_project
from floatpage.model.document import BlockItem, Page, PointAnchor, Project, Region, TextItem
from floatpage.tui.app import make_app

from editor_helpers import back_on_editor, editor, preview_text, screen_of, until

ROOT = Path(__file__).resolve().parents[2]
WORDS = ["alpha", "bravo", "charlie", "delta", "echo", "foxtrot", "golf", "hotel", "india",
         "juliet", "kilo", "lima", "mike", "november", "oscar", "papa"]


def words_shown(app) -> list[str]:
    text = preview_text(app)
    return [word for word in WORDS if re.search(rf"\b{word}\b", text)]


async def test_the_selected_items_id_hides_no_row_of_its_text(tmp_path):
    """The id went on the box's first row and pushed the text a row down, so a text that filled
    its box lost its last shown line the moment it was selected."""
    path = tmp_path / "t.toml"
    save_project(Project(pages=[Page(id="p", size="A5", width_mm=148.0, height_mm=210.0, items=[
        TextItem(id="words", x=74.0, y=105.0, w=60.0, h=60.0, text="\n".join(WORDS))])]), path)
    async with editor(path) as (app, pilot):
        before = words_shown(app)
        assert 3 <= len(before) < len(WORDS)  # the box is full: every row holds a word
        await pilot.press("tab")
        await pilot.pause()
        assert screen_of(app).selected_id == "words"
        assert "words" in preview_text(app)  # the id is shown...
        assert words_shown(app) == before  # ...and every row of text still is


async def test_a_regions_name_stays_readable_under_the_labels_of_its_items(tmp_path):
    """The region's name was written first, inside its corner, where the items confined to
    it sit: their labels (`n`, or the selected one's) and bodies covered it."""
    path = tmp_path / "r.toml"
    save_project(Project(pages=[Page(
        id="p", size="A5", width_mm=148.0, height_mm=210.0,
        regions=[Region("photos", 10.0, 10.0, 128.0, 120.0)],
        items=[TextItem(id="corner", x=40.0, y=27.0, w=56.0, h=30.0, text="x", region="photos"),
               TextItem(id="other", x=105.0, y=27.0, w=56.0, h=30.0, text="y",
                        region="photos")])]), path)
    async with editor(path) as (app, pilot):
        assert "photos" in preview_text(app)
        for keys in (["n"], ["tab"], ["n"]):  # every label, every label and the selected,
            await pilot.press(*keys)         # then the selected one's alone
            await pilot.pause()
            shown = preview_text(app)
            assert "photos" in shown, shown
            assert "corner" in shown and "other" in shown or not screen_of(app).labels
        assert screen_of(app).selected_id == "corner" and "corner" in preview_text(app)


def toasts(app) -> list[str]:
    """The toasts the top screen shows, by their text."""
    return [str(toast.render()) for toast in app.screen.query("Toast")]


async def test_a_toast_never_covers_an_open_dialog(project_path):
    """Textual draws toasts on the top screen: "saved …" and an export's answer came over
    the form being typed in (at 80x24 the form is the whole screen)."""
    app = make_app(project_path, autostart=False)
    async with app.run_test(size=(80, 24), notifications=True) as pilot:  # toasts drawn
        screen = screen_of(app)
        # each step waits for what it waits for (0.2 s each was an idle machine's time)
        await pilot.press("ctrl+s")
        assert await until(pilot, lambda: any("saved" in toast for toast in toasts(app)))
        # the toast the form is to take along: the save's lasts 3 s, which a slow runner spent
        # before the form was up (it was gone, rightly, and "saved" was missed at the end)
        screen.notify("lined up as settle does", timeout=60)
        assert await until(pilot, lambda: any("lined up" in toast for toast in toasts(app)))
        await pilot.press("tab", "enter")  # the title's form
        assert await until(pilot, lambda: app.screen is not screen and app.screen.query("Input")
                           and toasts(app) == []), toasts(app)  # the toast left with the editor
        screen.notify("PDF written to card.pdf", title="PDF exported", timeout=8)  # as an
        await pilot.pause(0.2)                                # export's worker does
        assert toasts(app) == []
        await pilot.press("escape")
        assert await until(pilot, lambda: app.screen is screen
                           and "PDF written" in " ".join(toasts(app))), toasts(app)
        shown = " ".join(toasts(app))
        assert "lined up" in shown and "PDF written to card.pdf" in shown  # held, not lost


def crowded_page(path):
    """25 blocks on an A5 page, each grown by the 3 mm gutter 96% of the room inside the
    margins: no layout keeps the gutter, and `check` says so."""
    save_project(Project(pages=[Page(id="p", size="A5", width_mm=148.0, height_mm=210.0, items=[
        BlockItem(id=f"b{i}", x=20.0 + 25 * (i % 5), y=20.0 + 25 * (i // 5), w=27.0, h=35.0,
                  color="#3366aa") for i in range(25)])]), path)
    subprocess.run([sys.executable, "-m", "floatpage.cli.main", "settle", str(path)],
                   capture_output=True)
    return path


def status(app) -> str:
    return str(screen_of(app).query_one("#status").render())


async def test_the_status_line_says_what_gave_way_and_why_as_check_does(tmp_path):
    """"some gaps narrow" said neither which guarantee gave way nor why; `check` did."""
    path = crowded_page(tmp_path / "full.toml")
    check = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "check", str(path)],
                           capture_output=True, text=True).stdout
    assert "gutter may not fit" in check and "96%" in check
    async with editor(path, size=(100, 34)) as (app, pilot):
        assert await until(pilot, lambda: "too full" in status(app))
        first, second = status(app).splitlines()[:2]
        assert "some gaps narrow" not in second
        assert re.search(r"gutter \d\.\d of 3 mm: page too full \(96% of the room\)", second)
        assert "v details" in second and len(second) <= 100 - 2
        await pilot.press("v")  # the details view: check's own sentence, whole
        await pilot.pause()
        shown = " ".join(status(app).split())
        reason = next(line for line in check.splitlines() if "gutter may not fit" in line)
        assert " ".join(reason.split()) in shown
        await pilot.press("v")
        await pilot.pause()
        assert len(status(app).splitlines()) == 2  # and back to two lines


async def test_a_thin_captions_id_covers_neither_its_words_nor_its_neighbours(tmp_path):
    """The flyer's subtitle at 80x24 is a box less than two cells tall: its words take the row
    holding its top, and its id went on that very row ("shop-subtitlethis…")."""
    folder = tmp_path / "shop-flyer"
    shutil.copytree(ROOT / "sample_projects" / "shop-flyer", folder)
    async with editor(folder / "shop-flyer.toml", size=(80, 24)) as (app, pilot):
        before = preview_text(app)
        assert "Fresh offers" in before and "The Corner Shop" in before
        app.session.select("shop-subtitle")
        screen_of(app).after_edit()
        await pilot.pause()
        shown = preview_text(app)
        assert "shop-subtitle" in shown
        assert "Fresh offers" in shown and "The Corner Shop" in shown


async def test_with_every_id_shown_the_selected_one_is_shown_once(project_path):
    """With `n`, the selected picture showed its id twice: on its frame and over its top."""
    async with editor(project_path) as (app, pilot):
        await pilot.press("n")
        app.session.select("photo")
        screen_of(app).after_edit()
        await pilot.pause()
        assert len(re.findall(r"\bphoto\b", preview_text(app))) == 1
        assert re.search(r"\bblock\b", preview_text(app))  # the others keep theirs


async def test_a_new_regions_size_is_said_to_a_tenth_of_a_mm(tmp_path):
    """"made region "region-1" (127 × 135.47 mm)": two thirds of a 5x8 in card's height."""
    path = tmp_path / "c.toml"
    save_project(Project(pages=[Page(id="p", size="5x8in", width_mm=127.0, height_mm=203.2,
                                     items=[TextItem(id="t", x=60.0, y=170.0, w=50.0, h=20.0,
                                                     text="Hi")])]), path)
    async with editor(path) as (app, pilot):
        await pilot.press("R")
        assert app.screen.id == "region-dialog"
        await pilot.press("enter")
        assert await back_on_editor(pilot, app)
        said = [notification.message for notification in app._notifications]
        assert app.session.page.regions and any("made region" in m for m in said), said
        assert any('"region-1" (127 × 135.5 mm)' in m for m in said), said


async def test_at_60_columns_the_status_line_keeps_the_why(tmp_path):
    """At 60 columns the reason was cut at "(96% of t…"; the parts a user can spare go first."""
    path = crowded_page(tmp_path / "full.toml")
    async with editor(path, size=(60, 20)) as (app, pilot):
        assert await until(pilot, lambda: "too full" in status(app))
        second = status(app).splitlines()[1]
        assert "page too full (96% of the room)" in second
        assert len(second) <= 60 - 2  # the line fits: nothing of it is cut with "…"


async def test_the_top_bar_counts_one_item_in_the_singular(tmp_path):
    path = tmp_path / "one.toml"
    save_project(Project(pages=[Page(id="p", size="A5", width_mm=148.0, height_mm=210.0, items=[
        TextItem(id="t", x=74.0, y=105.0, w=60.0, h=20.0, text="Hi")])]), path)
    async with editor(path) as (app, pilot):
        bar = "".join(text for text, _ in screen_of(app).page_bar_runs())
        assert "1 item" in bar and "1 items" not in bar


async def test_a_pictures_id_beside_a_region_name_hides_no_caption(tmp_path):
    """A region made around the album's first photo puts its name on the row above the photo;
    the photo's id then went below it, over its caption's words, where the photo's own top
    row (no words there) was free."""
    folder = tmp_path / "photo-album"
    shutil.copytree(ROOT / "sample_projects" / "photo-album", folder)
    async with editor(folder / "photo-album.toml", size=(80, 24)) as (app, pilot):
        app.session.select("p1-photo-1")
        screen_of(app).after_edit()
        await pilot.press("R")
        assert app.screen.id == "region-dialog"
        await pilot.press("enter")
        assert await back_on_editor(pilot, app)
        assert app.session.page.regions and app.session.selected_id == "p1-photo-1"
        shown = preview_text(app)
        assert "region-1" in shown and "p1-photo-1" in shown
        words = app.session.page.item("p1-photo-1-caption").text.split()[0][:4]
        assert words in shown, (words, shown)


async def test_two_pinned_items_on_each_other_are_named_on_the_status_line(tmp_path):
    """Overlap, the last guarantee to give way, with its count and the items that force it."""
    path = tmp_path / "pinned.toml"
    save_project(Project(pages=[Page(id="p", size="A5", width_mm=148.0, height_mm=210.0, items=[
        TextItem(id="left", x=60.0, y=100.0, w=50.0, h=30.0, text="a",
                 anchor=PointAnchor(x=60.0, y=100.0, hard=True)),
        TextItem(id="right", x=80.0, y=100.0, w=50.0, h=30.0, text="b",
                 anchor=PointAnchor(x=80.0, y=100.0, hard=True))])]), path)
    async with editor(path) as (app, pilot):
        assert await until(pilot, lambda: "meet" in status(app)), status(app)
        second = status(app).splitlines()[1]
        assert second.startswith('1 overlap: pinned "left" and "right" meet'), second
