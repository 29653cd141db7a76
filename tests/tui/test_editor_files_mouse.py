"""Saving, exporting, quitting, the mouse, the help screen and the command palette."""

from __future__ import annotations

import shutil

import pytest

from editor_helpers import (
    back_on_editor, editor, item, position, press_then_quit, screen_of, told, until, words_in,
)
from floatpage.tui.app import make_app
from floatpage.tui.key_bar import KeyBar
from floatpage.model.errors import FloatpageError
from floatpage.model.project_file import load_project
from floatpage.tui.keymap import COMMANDS, key_label


def notifications(app) -> list[str]:
    return [n.message for n in app._notifications]


async def test_save_writes_every_edit_and_clears_unsaved(project_path):
    async with editor(project_path) as (app, pilot):
        await pilot.press("tab", "tab", "tab", "H")  # block
        screen_of(app).release_held()
        await pilot.press("t", "O", "k", "ctrl+s")  # in a form, Ctrl+S applies the form
        assert await back_on_editor(pilot, app)
        assert "text-1" in app.session.page.item_ids()
        moved = position(app, "block")
        assert app.session.unsaved and "unsaved" in str(screen_of(app).query_one("#page-bar").render())
        await pilot.press("ctrl+s")
        assert not app.session.unsaved
        assert await told(pilot, app, lambda said: any("saved" in words for words in said))
    saved = load_project(project_path)
    block = saved.page("front").item("block")
    assert (block.x, block.y) == pytest.approx(moved, abs=0.01)
    assert saved.page("front").item("text-1").text == "Ok"
    assert project_path.with_name(project_path.name + ".bak").exists()


async def test_a_failed_save_is_shown_not_crashed_on(project_path):
    async with editor(project_path) as (app, pilot):
        await pilot.press("tab", "d")
        shutil.rmtree(project_path.parent)  # the folder is gone: the save cannot happen
        await pilot.press("ctrl+s")
        await pilot.pause()
        assert app.session.unsaved
        assert any("could not save" in message for message in notifications(app))


async def test_export_reports_a_typesetting_error_and_the_editor_stays(project_path, monkeypatch):
    from floatpage import typeset
    def failing_render(project, out_pdf, *, progress=None):
        progress("page 1 of 2")
        raise FloatpageError("LaTeX stopped: missing font (see card.log)")

    monkeypatch.setattr(typeset, "render_pdf", failing_render, raising=False)
    async with editor(project_path) as (app, pilot):
        await pilot.press("ctrl+e")
        await app.workers.wait_for_complete()
        await pilot.pause()
        assert any("missing font" in message for message in notifications(app))
        assert screen_of(app).export_state is None
        await pilot.press("tab")  # still editing
        assert screen_of(app).selected_id == "title"


async def test_export_finalises_the_layout_and_writes_the_pdf(project_path):
    async with editor(project_path) as (app, pilot):
        await pilot.press("ctrl+e")
        assert screen_of(app).export_state is not None  # the status line says it is exporting
        await app.workers.wait_for_complete()
        await pilot.pause()
        pdf = project_path.with_suffix(".pdf")
        assert any("PDF exported" in (n.title or "") for n in app._notifications), notifications(app)
        assert pdf.exists() and pdf.read_bytes().startswith(b"%PDF")
        assert app.session.engine.quality().overlapping_pairs == ()


async def test_export_refused_by_a_symlinked_pdf_asks_for_another_name(project_path):
    """Ctrl+E with NAME.pdf a symbolic link said "name a new file or a regular file", which
    the editor had no way to do.  It now asks for a name (a free one offered), refuses there
    what render refuses, exports to the name given and keeps it for the next Ctrl+E; the
    link and the file it points to are untouched."""
    elsewhere = project_path.with_name("elsewhere.pdf")
    elsewhere.write_bytes(b"not yours")
    project_path.with_suffix(".pdf").symlink_to(elsewhere)
    async with editor(project_path) as (app, pilot):
        await pilot.press("ctrl+e")
        await pilot.pause()
        assert app.screen.id == "export-dialog"
        shown = " ".join(str(label.render()) for label in app.screen.query("Label"))
        assert "symbolic link" in shown
        field = app.screen.query_one("#field-name")
        assert field.value == "card-export.pdf"
        field.value = "card.pdf"  # the link again: refused in the dialog, which stays open
        await pilot.press("enter")
        assert await until(pilot, lambda: "symbolic link" in words_in(app, "#form-error"))
        assert app.screen.id == "export-dialog"
        field.value = "card-export"  # .pdf is added
        await pilot.press("enter")
        assert await back_on_editor(pilot, app)  # the answer has started the export
        await app.workers.wait_for_complete()
        pdf = project_path.with_name("card-export.pdf")
        assert pdf.read_bytes().startswith(b"%PDF"), notifications(app)
        pdf.unlink()
        await pilot.press("ctrl+e")  # the name is kept: no dialog again
        await app.workers.wait_for_complete()
        await pilot.pause()
        assert app.screen is screen_of(app)
        assert pdf.read_bytes().startswith(b"%PDF")
    assert project_path.with_suffix(".pdf").is_symlink()
    assert elsewhere.read_bytes() == b"not yours"


async def test_quit_without_changes_exits_at_once(project_path):
    async with editor(project_path) as (app, pilot):
        assert await press_then_quit(pilot, "q")


async def test_quit_with_unsaved_changes_asks_first(project_path):
    async with editor(project_path) as (app, pilot):
        await pilot.press("tab", "d")
        await pilot.press("q")
        assert app.screen.id == "quit-dialog" and not app._exit
        await pilot.press("down", "down", "enter")  # Keep editing
        assert await back_on_editor(pilot, app)
        assert not app._exit
        await pilot.press("ctrl+q")
        assert app.screen.id == "quit-dialog"
        assert await press_then_quit(pilot, "enter")  # Save and quit
        assert not app.session.unsaved
    assert load_project(project_path).page("front").item("title").decorative


async def test_quit_discarding_changes_leaves_the_file_alone(project_path):
    before = project_path.read_text()
    async with editor(project_path) as (app, pilot):
        assert await press_then_quit(pilot, "tab", "d", "q", "down", "enter")
    assert project_path.read_text() == before


async def test_click_selects_and_drag_moves(project_path):
    async with editor(project_path) as (app, pilot):
        preview = screen_of(app).preview
        col, row = preview.cell_centre_of("block")
        # a mouse event reaches the editor as the preview's message, a turn or more later
        await pilot.click("#preview", offset=(col, row))
        assert await until(pilot, lambda: screen_of(app).selected_id == "block")
        x, y = position(app, "block")
        await pilot.mouse_down("#preview", offset=(col, row))
        await pilot.hover("#preview", offset=(col - 6, row + 3))
        assert await until(pilot, lambda: app.session.held_id == "block")
        await pilot.mouse_up("#preview", offset=(col - 6, row + 3))
        assert await until(pilot, lambda: app.session.held_id is None)
        new_x, new_y = item(app, "block").x, item(app, "block").y
        scale = preview.projection.scale
        assert new_x - x == pytest.approx(-6 / scale, abs=0.6 / scale)
        assert new_y - y == pytest.approx(6 / scale, abs=1.1 / scale)
        page = preview.projection
        await pilot.click("#preview", offset=(page.left + 1, page.top // 2 + 1))  # empty paper
        assert await until(pilot, lambda: screen_of(app).selected_id is None)


async def test_help_lists_every_command(project_path):
    async with editor(project_path) as (app, pilot):
        await pilot.press("question_mark")
        assert app.screen.id == "help"
        help_widget = app.screen.query_one("#help-text")

        def shown() -> str:
            lines = [strip.text
                     for strip in help_widget.render_lines(help_widget.region.reset_offset)]
            return " ".join(" ".join(lines).split())

        last = COMMANDS[-1]
        assert await until(pilot, lambda: key_label(last.keys) in shown())  # laid out
        text = shown()
        for command in COMMANDS:
            assert " ".join(command.help.split()) in text or command.help[:30] in text, command.help
            assert key_label(command.keys) in text
        await pilot.press("escape")
        assert await back_on_editor(pilot, app)


async def test_every_command_is_in_the_palette_and_runs_from_it(project_path):
    async with editor(project_path) as (app, pilot):
        titles = [command.title for command in app.get_system_commands(screen_of(app))]
        for command in COMMANDS:
            assert any(title.startswith(command.label + "  (") for title in titles), command.label
        await pilot.press("tab")
        await pilot.press("ctrl+p")
        await pilot.pause()
        await pilot.press(*"Anchor")
        # the palette searches in a worker: Enter before its answer runs nothing (or the
        # first command listed so far); 0.3 s was an idle machine's time for it
        assert await until(pilot, lambda: highlighted_prompt(app).startswith("Anchor  (")), \
            highlighted_prompt(app)
        await pilot.press("enter")
        assert await until(pilot, lambda: item(app, "title").anchor is not None)


def highlighted_prompt(app) -> str:
    """The command the palette's Enter would run now, by its title ("" when none is)."""
    from textual.command import CommandList

    found = app.screen.query(CommandList)
    if not found or found.first().highlighted is None:
        return ""
    commands = found.first()
    return str(commands.get_option_at_index(commands.highlighted).prompt)


async def test_the_palette_shows_each_commands_keys(project_path):
    """The palette reads titles as markup: "Anchor  [a]" showed as "Anchor", the key taken
    for a style tag, and so for u, i, n, A and more."""
    from textual.command import CommandList

    async with editor(project_path) as (app, pilot):
        await pilot.press("tab", "ctrl+p")
        await pilot.pause()
        await pilot.press(*"Unanchor")

        def prompts() -> list[str]:
            return [str(option.prompt) for option in app.screen.query_one(CommandList).options]

        # the search's worker answers when it answers (0.5 s was an idle machine's time)
        assert await until(pilot, lambda: any(prompt.startswith("Unanchor  (u)")
                                              for prompt in prompts())), prompts()


def test_every_command_names_an_action_the_screen_has():
    from floatpage.tui.editor_screen import EditorScreen

    for command in COMMANDS:
        assert hasattr(EditorScreen, f"action_{command.action_name}"), command.action
        assert "ctrl+shift" not in command.keys


def footer_actions(app) -> list[str]:
    return screen_of(app).query_one(KeyBar).actions


async def test_the_footer_fits_its_width_keeps_the_essentials_and_what_matters_now(project_path):
    for size in ((80, 24), (100, 32), (160, 40)):
        async with editor(project_path, size=size) as (app, pilot):
            page_footer = footer_actions(app)
            for essential in ("help", "save", "export_pdf", "quit"):
                assert essential in page_footer, (size, essential)
            bar = screen_of(app).query_one(KeyBar)
            drawn = bar.render()
            assert drawn.cell_len <= size[0], size  # nothing cut off
            assert all(f"{keys} {words} " in drawn.plain for keys, words, _, _ in bar.units)
            await pilot.press("tab")
            await pilot.pause()
            item_footer = footer_actions(app)
            for essential in ("help", "save", "export_pdf", "quit"):
                assert essential in item_footer, (size, essential)
            assert "nudge(-2.0,0.0)" in item_footer, size  # what matters now
            if size[0] >= 100:
                assert "edit" in item_footer
            if size[0] >= 160:
                assert "delete" in item_footer and "insert" not in item_footer[:8]


async def test_the_footer_fits_itself_again_when_the_terminal_is_resized(project_path):
    """Opened at 80 columns and widened to 160 (a tmux pane resized), the footer kept the 80
    column selection of keys until the next key; narrowed again, the keys it showed ran past
    the width (user-walk-2)."""
    async with editor(project_path, size=(80, 24)) as (app, pilot):
        narrow = footer_actions(app)
        await pilot.resize_terminal(160, 40)  # the footer hears of it a few messages later
        assert await until(pilot, lambda: len(footer_actions(app)) > len(narrow))
        wide = footer_actions(app)
        assert set(narrow) <= set(wide)
        await pilot.resize_terminal(80, 24)
        assert await until(pilot, lambda: footer_actions(app) == narrow)
        assert screen_of(app).query_one(KeyBar).render().cell_len <= 80


async def test_the_top_bar_keeps_the_unsaved_mark_and_the_anchor_state_at_80_columns(project_path):
    async with editor(project_path, size=(80, 24)) as (app, pilot):
        await pilot.press("tab", "tab", "tab", "tab", "tab")  # through the items to an anchored one
        for _ in range(8):
            if app.session.selected_item and app.session.selected_item.anchor:
                break
            await pilot.press("tab")
        await pilot.press("right")
        await pilot.pause()
        bar = str(screen_of(app).query_one("#page-bar").render())
        assert "● unsaved" in bar
        assert "anchored" in bar or "follows" in bar or "hard anchor" in bar, bar
        assert len(bar) <= 80


async def test_brackets_in_titles_and_errors_are_shown_as_typed(project_path):
    text = project_path.read_text().replace('title = "Test card"', 'title = "[draft] card"')
    project_path.write_text(text)
    async with editor(project_path) as (app, pilot):
        assert "[draft] card" in str(screen_of(app).query_one("#page-bar").render())
        await pilot.press("b", "ctrl+a", "ctrl+k", *"[red", "enter")
        assert await until(pilot, lambda: '"[red"' in words_in(app, "#form-error"))
        await pilot.press("escape", "x")  # nothing selected: a plain-text warning
        await pilot.press("tab")
        screen_of(app).notify("[bold]literal[/bold]")
        assert await back_on_editor(pilot, app)


async def test_6_the_footer_is_there_from_the_first_frame_and_follows_a_key_at_once(project_path):
    """Defect 6: the footer was missing for 0.35-0.7 s after start and showed the old keys for
    0.2-0.3 s after Tab (Textual's Footer rebuilt its widgets a refresh later).  The key bar
    holds its keys before the first frame and takes the new ones while the key is handled."""
    app = make_app(project_path, autostart=False)
    async with app.run_test(size=(100, 32)) as pilot:
        bar = screen_of(app).query_one(KeyBar)
        assert {"help", "save", "export_pdf", "quit"} <= set(bar.actions)  # no pause needed
        before = list(bar.actions)
        await pilot.press("tab")  # returns once the key is handled, before any later refresh
        assert bar.actions != before and "nudge(-2.0,0.0)" in bar.actions
        assert "Move" in bar.render().plain


async def test_a_click_on_a_footer_key_runs_its_command(project_path):
    async with editor(project_path) as (app, pilot):
        bar = screen_of(app).query_one(KeyBar)
        bar.render()
        start, end, _ = next(span for span in bar.spans if span[2] == "help")
        await pilot.click(KeyBar, offset=(start + 1, 0))
        assert await until(pilot, lambda: app.screen.id == "help")
