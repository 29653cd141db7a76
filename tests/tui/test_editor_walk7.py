"""Defects a demanding user met over SSH (user-walk-7), each driven through the real app:
keys typed ahead of a dialog, a new page's name, and a template's placeholder in a narrow box."""

from __future__ import annotations

import asyncio
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

from textual import events

from floatpage.model import load_project, save_project
from floatpage.model.document import Page, PictureItem, Project, TextItem
from floatpage.tui.cell_text import wrap_cells

from editor_helpers import editor, position, preview_text, screen_of, until

ROOT = Path(__file__).resolve().parents[2]


def type_ahead(app, *keys: str) -> None:
    """Send keys to the app the way a fast typist over SSH does: all of them in the driver's
    queue at once, none waiting for the screen the one before opens."""
    for key in keys:
        event = events.Key(key, {"space": " "}.get(key, key if len(key) == 1 else None))
        event.set_sender(app)
        app._driver.send_message(event)


async def test_keys_typed_ahead_of_a_dialog_go_to_the_dialog(project_path):
    """`p` then `l` at once moved the selected item right, instead of typing `l` into the
    picture dialog (its tree has the focus: `l` is no key there, so nothing at all moves)."""
    async with editor(project_path) as (app, pilot):
        await pilot.press("tab")
        await pilot.pause()
        chosen = screen_of(app).selected_id
        before = position(app, chosen)
        type_ahead(app, "p", "l")
        assert await until(pilot, lambda: keys_taken(app) and app.screen.id == "picture-dialog")
        assert position(app, chosen) == before


async def test_words_typed_ahead_of_a_form_are_typed_into_it_in_order(project_path):
    """`t` then the first letters: they came back to an App whose form was not yet mounted
    and were lost (or, `h` and `l`, moved the selected item)."""
    async with editor(project_path) as (app, pilot):
        await pilot.press("tab")
        await pilot.pause()
        chosen = screen_of(app).selected_id
        before = position(app, chosen)
        type_ahead(app, "t", "H", "e", "l", "l", "o", "space", "h", "i")
        assert await until(pilot, lambda: keys_taken(app) and app.screen.id == "text-dialog")
        assert await words_typed(pilot, app, "Hello hi") == "Hello hi"
        assert position(app, chosen) == before


async def test_a_choice_typed_ahead_reaches_the_dialog_the_one_before_opened(project_path):
    """`i` (insert), Enter (its first choice, a text box) and the words, at once: each key goes
    to the screen the key before it opened, through two dialogs."""
    async with editor(project_path) as (app, pilot):
        type_ahead(app, "i", "enter", "O", "k")
        assert await until(pilot, lambda: keys_taken(app) and app.screen.id == "text-dialog")
        assert await words_typed(pilot, app, "Ok") == "Ok"


async def test_keys_typed_ahead_wait_for_the_focus_the_new_dialog_asks_for(project_path,
                                                                        monkeypatch):
    """The same keys while the App is busy (a loaded machine): the text form mounted, and a
    drain of the waiting keys already in the App's queue ran before the focus the form's
    on_mount asked for, handing "Ok" to the form's scroll container, which dropped it (a
    fresh-clone CI run, and every run at load 8).  The App is kept busy here by a message
    that waits, as a slow turn of the App does, while the form mounts."""
    from floatpage.tui.editor_screen import EditorScreen

    choose = EditorScreen.action_insert_kind

    def choose_while_the_app_is_busy(self, kind):
        async def busy():
            await asyncio.sleep(0.3)
        self.app.call_later(busy)
        choose(self, kind)

    monkeypatch.setattr(EditorScreen, "action_insert_kind", choose_while_the_app_is_busy)
    async with editor(project_path) as (app, pilot):
        type_ahead(app, "i", "enter", "O", "k")
        assert await until(pilot, lambda: keys_taken(app) and app.screen.id == "text-dialog")
        assert await words_typed(pilot, app, "Ok") == "Ok"


def keys_taken(app) -> bool:
    """Every key typed ahead has gone to a screen (none waits in the App's queue)."""
    type_ahead = app.type_ahead
    return not type_ahead.waiting and type_ahead.opening is None and not type_ahead.answering


async def words_typed(pilot, app, words: str) -> str:
    """The focused field's words, once ``words`` have had their time to arrive: a key handed
    to the field waits in the field's own queue for a turn of the loop, and on a loaded
    machine the form read "" while "Ok" was still on its way (the owner's CI run; also with
    the event loop's ready callbacks run in a shuffled order)."""
    await until(pilot, lambda: app.screen.focused.text == words)
    return app.screen.focused.text


def top_bar(app) -> str:
    return app.editor.query_one("#page-bar").plain


async def test_a_page_added_is_named_by_its_place_and_the_top_bar_agrees(tmp_path):
    """`N` on the album's first page added a page at place 2 named "page-3" (the next free
    number), and the top bar read "page 2/3 page-3". Now it is "page-2", the album's old
    page-2 is "page-3", a page the user named keeps its name, and the file saves so."""
    album = tmp_path / "album"
    shutil.copytree(ROOT / "sample_projects" / "photo-album", album)
    path = album / "photo-album.toml"
    async with editor(path) as (app, pilot):
        await pilot.press("N")
        await pilot.pause()
        assert "page 2/3 page-2" in top_bar(app)
        assert [page.id for page in app.session.project.pages] == ["page-1", "page-2", "page-3"]
        assert len(app.session.project.pages[2].items) > 0  # the album's second page, moved up
        await pilot.press("ctrl+s")
        assert await until(pilot, lambda: not app.session.unsaved)  # saved, not 0.5 s later
    assert [page.id for page in load_project(path).pages] == ["page-1", "page-2", "page-3"]


async def test_pages_the_user_named_keep_their_names_when_pages_come_and_go(tmp_path):
    path = tmp_path / "card.toml"
    save_project(Project(pages=[Page(id="front", size="A5", width_mm=148.0, height_mm=210.0),
                                Page(id="page-2", size="A5", width_mm=148.0, height_mm=210.0),
                                Page(id="back", size="A5", width_mm=148.0, height_mm=210.0)]),
                 path)
    async with editor(path) as (app, pilot):
        await pilot.press("N")  # after "front": place 2, the old page-2 moves to place 3
        await pilot.pause()
        names = [page.id for page in app.session.project.pages]
        assert names == ["front", "page-2", "page-3", "back"]
        assert "page 2/4 page-2" in top_bar(app)
        await pilot.press("D", "down", "enter")  # remove the new page: page-3 is page-2 again

        def names() -> list[str]:
            return [page.id for page in app.session.project.pages]

        assert await until(pilot, lambda: names() == ["front", "page-2", "back"]), names()
        await pilot.press("ctrl+z")
        assert await until(pilot, lambda: names() == ["front", "page-2", "page-3", "back"]), \
            names()


async def test_a_placeholder_is_never_broken_in_a_narrow_box(tmp_path):
    """A merge template's picture in a narrow box read "pictures/{photo" over "}": the
    preview breaks beside a {placeholder}, never inside it, and shows one too wide for its
    box shortened ("{fi…}")."""
    path = tmp_path / "offer.toml"
    save_project(Project(pages=[Page(id="p", size="A5", width_mm=148.0, height_mm=210.0, items=[
        PictureItem(id="photo", x=40.0, y=60.0, w=22.0, h=40.0, path="pictures/{photo}"),
        TextItem(id="hello", x=110.0, y=60.0, w=16.0, h=40.0, text="Dear {first_name}")])]),
        path)
    async with editor(path) as (app, pilot):
        rows = preview_text(app).splitlines()
        assert any("{photo}" in row for row in rows)  # the picture's, whole
        assert any(re.search(r"\{fi\w*…\}", row) for row in rows)  # the text's, shortened
        for row in rows:  # no placeholder begun on one row and ended on another
            assert row.count("{") == row.count("}"), row


def test_a_placeholder_breaks_beside_it_and_shortens_only_when_it_must():
    assert wrap_cells("pictures/{photo}", 12) == ["pictures/", "{photo}"]
    assert wrap_cells("pictures/{photo}", 5) == ["pictu", "res/", "{ph…}"]
    assert wrap_cells("Dear {first name} x", 12) == ["Dear", "{first name}", "x"]
    assert wrap_cells("a lone { brace", 7) == ["a lone", "{ brace"]  # nothing to keep whole


class Tmux:
    """The real editor in a tmux pane of its own server, whose socket is in the test's own
    folder (other runs' tmux servers are never touched, and nothing is left behind)."""

    def __init__(self, project: Path, size=(100, 30)):
        self.socket = str(project.parent / "tmux.sock")
        floatpage = Path(sys.executable).parent / "floatpage"
        self.tmux("-f", "/dev/null", "new-session", "-d", "-x", str(size[0]), "-y",
                  str(size[1]), f"{floatpage} edit {project}")

    def tmux(self, *args: str) -> str:
        return subprocess.run(["tmux", "-S", self.socket, *args], check=True,
                              capture_output=True, text=True, timeout=10).stdout

    def screen(self) -> str:
        return self.tmux("capture-pane", "-p")

    def wait_for(self, wanted, timeout: float = 20.0) -> str:
        """The pane once `wanted(pane)` holds; fails with the pane shown after `timeout`."""
        deadline = time.monotonic() + timeout
        while True:
            pane = self.screen()
            if wanted(pane):
                return pane
            assert time.monotonic() < deadline, pane
            time.sleep(0.1)

    def close(self) -> None:
        subprocess.run(["tmux", "-S", self.socket, "kill-server"], capture_output=True)


def test_keys_sent_in_one_go_in_tmux_reach_the_dialog_they_open(project_path):
    """The walk's own steps in tmux: `send-keys p l` in one call moved the selected title
    (it came out anchored, 3 mm to the right) behind the picture dialog, and `send-keys t
    Hello` opened an empty text form and moved the title with the l's."""
    pane = Tmux(project_path)
    try:
        pane.wait_for(lambda shown: "6 items" in shown)
        pane.tmux("send-keys", "Tab")
        top = pane.wait_for(lambda shown: "title (text" in shown).splitlines()[0]
        assert "at 74, 25 mm" in top and "anchored" not in top
        pane.tmux("send-keys", "p", "l")
        pane.wait_for(lambda shown: "Insert a picture" in shown)
        time.sleep(0.5)  # where a stray `l` would have gone by now
        pane.tmux("send-keys", "Escape")
        top = pane.wait_for(lambda shown: "Insert a picture" not in shown).splitlines()[0]
        assert "at 74, 25 mm" in top and "anchored" not in top and "unsaved" not in top, top
        pane.tmux("send-keys", "t", "Hello")
        pane.wait_for(lambda shown: "Insert a text box" in shown)
        pane.wait_for(lambda shown: "Hello" in shown, timeout=5.0)
        pane.tmux("send-keys", "Escape")
        top = pane.wait_for(lambda shown: "Insert a text box" not in shown).splitlines()[0]
        assert "at 74, 25 mm" in top and "anchored" not in top, top
    finally:
        pane.close()
