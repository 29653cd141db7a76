"""Defects a demanding user met in a first week with the editor (user-walk-8), each driven
through the real app with Pilot, on a real project file."""

from __future__ import annotations

import shutil
from pathlib import Path

from floatpage.model import load_project
from floatpage.tui.editor_screen import LOOK_AT_FILE_S

from editor_helpers import back_on_editor, editor, item, position, press_then_quit, until

ROOT = Path(__file__).resolve().parents[2]


def edited_elsewhere(path) -> str:
    """Change the title's words as a text editor (or a `git checkout`) would, behind the
    editor's back; return the file's new text."""
    text = path.read_text()
    changed = text.replace("Happy Birthday Anna", "Happy Birthday Anna and Ben")
    assert changed != text
    path.write_text(changed)
    return changed


async def nudged_then_saved_over(pilot, path) -> str:
    """An item nudged in the editor, the file changed behind its back, then Ctrl+S: the
    question the editor asks; returns the other program's text."""
    await pilot.press("tab", "right")
    await pilot.pause()
    theirs = edited_elsewhere(path)
    await pilot.press("ctrl+s")
    assert await until(pilot, lambda: pilot.app.screen.id == "changed-on-disk-dialog")
    return theirs


async def test_a_save_asks_before_replacing_changes_another_program_made_to_the_file(
        project_path):
    """With the editor open, the user mended a word in the file in vim; a nudge and Ctrl+S in
    the editor then wrote its own version over it without a word (only one `.bak` back). Now
    Ctrl+S asks, Esc keeps the file as the other program left it, and the replacement,
    chosen, keeps that version as the `.bak`."""
    async with editor(project_path) as (app, pilot):
        theirs = await nudged_then_saved_over(pilot, project_path)
        assert app.screen.id == "changed-on-disk-dialog"
        assert project_path.read_text() == theirs
        await pilot.press("escape")  # keep editing: nothing written, the edit still unsaved
        assert await back_on_editor(pilot, app)
        assert project_path.read_text() == theirs
        assert app.session.unsaved
        await pilot.press("ctrl+s")
        await pilot.pause()
        assert app.screen.id == "changed-on-disk-dialog"
        await pilot.press("home", "enter")  # "Replace it with the editor's version"
        assert await back_on_editor(pilot, app)
        assert await until(pilot, lambda: not app.session.unsaved)
        assert "and Ben" not in project_path.read_text()
        assert project_path.with_name("card.toml.bak").read_text() == theirs
        # the editor's own save is no change by another program: the next Ctrl+S just saves
        await pilot.press("right", "ctrl+s")
        await pilot.pause()
        assert app.screen is app.editor
        assert not app.session.unsaved


async def test_the_file_as_another_program_left_it_can_be_opened_in_its_place(project_path):
    """The title mended in vim while the editor was open: the question also opens the file as
    it now is (the editor's unsaved nudge and its undo go); a file left broken is named and
    the editor's version kept."""
    async with editor(project_path) as (app, pilot):
        theirs = await nudged_then_saved_over(pilot, project_path)
        await pilot.press("home", "down", "enter")  # "Open the file as it is now"
        assert await back_on_editor(pilot, app)
        assert project_path.read_text() == theirs
        assert app.session.project.pages[0].item("title").text == "Happy Birthday Anna and Ben"
        assert not app.session.unsaved and not app.session.history.undo_stack
        await pilot.press("right", "ctrl+s")  # their file is the editor's now: saved at once
        await pilot.pause()
        assert app.screen is app.editor and not app.session.unsaved
        assert "and Ben" in project_path.read_text()
        project_path.write_text(project_path.read_text() + "\n[[pages]\n")  # left broken
        await pilot.press("right", "ctrl+s")
        assert await until(pilot, lambda: app.screen.id == "changed-on-disk-dialog")
        await pilot.press("home", "down", "enter")
        assert await back_on_editor(pilot, app)
        assert app.session.unsaved  # the editor's version kept
        assert "and Ben" in app.session.project.pages[0].item("title").text


async def test_keep_editing_is_not_asked_again_for_the_same_change(project_path):
    """Ctrl+S asked about the file vim changed, and the user chose "Keep editing": a second
    later the editor's look at the file asked the same question again (it knew only of the
    changes it had told of itself; under load it came up between a test's keys). A change
    made after the answer is still asked about."""
    async with editor(project_path) as (app, pilot):
        await nudged_then_saved_over(pilot, project_path)
        assert app.screen.id == "changed-on-disk-dialog"
        await pilot.press("escape")  # keep editing
        assert await back_on_editor(pilot, app)
        await pilot.pause(3 * LOOK_AT_FILE_S)  # the look needs two to tell a change
        assert app.screen is app.editor, app.screen.id
        project_path.write_text(project_path.read_text().replace("and Ben", "and Bea"))
        assert await until(pilot, lambda: app.screen.id == "changed-on-disk-dialog")
        await pilot.pause()  # mounted before the app closes
        assert "changed card.toml just now" in app.screen.message  # the look's question


async def test_save_and_quit_asks_too_and_quits_once_the_file_is_replaced(project_path):
    """The quit dialog's "Save and quit" goes through the same question."""
    async with editor(project_path) as (app, pilot):
        await pilot.press("tab", "right")
        await pilot.pause()
        moved = app.session.selected_id
        edited_elsewhere(project_path)
        await pilot.press("q")
        await pilot.pause()
        assert app.screen.id == "quit-dialog"
        await pilot.press("enter")  # "Save and quit" is highlighted
        assert await until(pilot, lambda: app.screen.id == "changed-on-disk-dialog")
        x_on_screen = position(app, moved)[0]
        assert await press_then_quit(pilot, "home", "enter")  # quit, once saved
    saved = load_project(project_path)
    assert "and Ben" not in project_path.read_text()
    assert abs(saved.pages[0].item(moved).x - x_on_screen) < 0.01


async def test_a_region_made_saved_undone_and_saved_again_is_saved(tmp_path):
    """A long session on the album, undone all the way back, would not save: "Not saved:
    KeyError: 'region'" (the save had added the key into the document it keeps)."""
    folder = tmp_path / "album"
    shutil.copytree(ROOT / "sample_projects" / "photo-album", folder)
    path = folder / "photo-album.toml"
    async with editor(path) as (app, pilot):
        await pilot.press("tab", "tab", "R")
        await pilot.pause()
        assert app.screen.id == "region-dialog"
        await pilot.press("enter")
        assert await back_on_editor(pilot, app)
        assert app.session.page.regions  # made
        await pilot.press("ctrl+s")
        assert "[[pages.regions]]" in path.read_text()
        await pilot.press("ctrl+z", "ctrl+s")
        await pilot.pause()
        assert not app.session.unsaved
    assert "region" not in path.read_text()
    assert len(load_project(path).pages) == 2


async def test_ctrl_s_on_an_unchanged_sample_writes_nothing_and_undone_edits_save_as_read(
        tmp_path):
    """Opened and saved at once, the album and the flyer were rewritten (and a `.bak` made):
    a caption follows its photo at the photo's position plus its offset, which rounds 0.01 mm
    from what the settled file says (76.44 + 36.36 against y = 112.81), and the save wrote
    the sum. A page edited elsewhere moved them too, and undoing every edit did not give the
    file back."""
    for sample in ("photo-album", "shop-flyer"):
        folder = tmp_path / sample
        shutil.copytree(ROOT / "sample_projects" / sample, folder)
        path = folder / f"{sample}.toml"
        original = path.read_bytes()
        async with editor(path) as (app, pilot):
            await pilot.press("ctrl+s")
            await pilot.pause()
            assert path.read_bytes() == original, sample
            assert not path.with_name(f"{sample}.toml.bak").exists()
            await pilot.press("tab", "tab", "right", "right", "ctrl+s")
            await pilot.pause()
            assert path.read_bytes() != original
            await pilot.press("ctrl+z", "ctrl+s")
            await pilot.pause()
            assert path.read_bytes() == original, sample


async def test_every_edit_undone_saves_the_file_as_it_was_read(tmp_path):
    """A caption unanchored (`u`), saved, then the edit undone and saved again: its anchor
    came back at the end of its table, after `role`, and a page added and removed left a
    blank line; after a long session undone all the way back, `git diff` showed them."""
    folder = tmp_path / "album"
    shutil.copytree(ROOT / "sample_projects" / "photo-album", folder)
    path = folder / "photo-album.toml"
    original = path.read_bytes()
    async with editor(path) as (app, pilot):
        await pilot.press("bracketright")
        await pilot.pause()
        app.session.select("p2-photo-1-caption")
        await pilot.press("u", "N", "ctrl+s")
        await pilot.pause()
        assert path.read_bytes() != original
        await pilot.press("ctrl+z", "ctrl+z", "ctrl+s")
        await pilot.pause()
        assert not app.session.history.undo_stack
        assert path.read_bytes() == original


def edge_gap(app, follower_id: str) -> float:
    """The space between a follower's top edge and the bottom edge of the item it follows."""
    follower = item(app, follower_id)
    target = item(app, follower.anchor.to)
    return (follower.y - follower.h / 2) - (target.y + target.h / 2)


async def test_a_photo_grown_or_its_caption_grown_keeps_the_space_between_them(tmp_path):
    """`+` on an album photo kept its caption's offset between centres: three presses and the
    photo came down over its caption's words, and `check` said 0 overlaps (a photo and its
    caption are one body, never parted). `+` on the caption did the same upwards."""
    folder = tmp_path / "album"
    shutil.copytree(ROOT / "sample_projects" / "photo-album", folder)
    path = folder / "photo-album.toml"
    async with editor(path) as (app, pilot):
        caption = "p1-photo-1-caption"
        before = edge_gap(app, caption)
        assert before > 0
        app.session.select("p1-photo-1")
        await pilot.press("plus", "plus", "plus")
        await pilot.pause()
        assert item(app, "p1-photo-1").h > 1.25 * 55.72
        assert abs(edge_gap(app, caption) - before) < 0.02
        app.session.select(caption)
        await pilot.press("plus", "plus")
        await pilot.pause()
        assert abs(edge_gap(app, caption) - before) < 0.02
        other = "p1-photo-2-caption"  # a height typed in the item's form
        gap = edge_gap(app, other)
        app.session.update_item("p1-photo-2", {"w": 90.0, "h": 67.5})
        assert abs(edge_gap(app, other) - gap) < 0.02
        await pilot.press("ctrl+s")
        await pilot.pause()
    saved = load_project(path).pages[0]
    photo, words = saved.item("p1-photo-1"), saved.item(caption)
    assert words.y - words.h / 2 - (photo.y + photo.h / 2) > before - 0.02
