"""Dialogs fit the terminal they are shown on (user walk 5).

At 40 x 12 the Insert dialog showed three of its five choices and no hint, at 20 x 6 none at
all, and the edit form showed 11 rows of fields on any terminal, however tall.  Now the list
or the fields take the height there is and scroll, a short or narrow terminal drops the
padding, and below 20 x 6 the dialog says the terminal is too small.
"""

from __future__ import annotations

from textual.widgets import Input, OptionList

from editor_helpers import back_on_editor, dialog_shown, editor, screen_of, until, words_in


def on_screen(widget, size) -> bool:
    region = widget.region
    return region.height > 0 and region.width > 0 \
        and region.right <= size[0] and region.bottom <= size[1]


def option_rows_shown(options: OptionList) -> int:
    """How many options the list shows at once: its height without border and padding."""
    return options.scrollable_content_region.height


async def test_insert_dialog_at_40x12_shows_every_choice_and_its_hint(project_path):
    size = (40, 12)
    async with editor(project_path, size=size) as (app, pilot):
        await pilot.press("i")
        await pilot.pause()
        options = app.screen.query_one(OptionList)
        assert option_rows_shown(options) >= 5  # all five choices, not three
        hint = app.screen.query_one(".dialog-hint")
        assert on_screen(hint, size)
        assert "Esc cancels" in str(hint.render())


async def test_insert_dialog_at_20x6_is_still_usable(project_path):
    size = (20, 6)
    async with editor(project_path, size=size) as (app, pilot):
        await pilot.press("i")
        await pilot.pause()
        options = app.screen.query_one(OptionList)
        assert option_rows_shown(options) >= 3
        assert on_screen(options, size)
        hint = app.screen.query_one(".dialog-hint")
        assert on_screen(hint, size) and str(hint.render()) == "Esc cancels"
        await pilot.press("down", "down", "enter")  # Colour block: its form, at 20 x 6
        assert await dialog_shown(pilot, app, "block-dialog")
        colour = app.screen.query_one("#field-color", Input)
        assert await until(pilot, lambda: on_screen(colour, size))  # once laid out
        assert on_screen(app.screen.query_one("#ok"), size)
        assert on_screen(app.screen.query_one("#cancel"), size)
        await pilot.press("enter")
        assert await until(pilot, lambda: sum(item.kind == "block"
                                              for item in app.session.page.items) == 3)


async def test_a_terminal_below_20x6_says_it_is_too_small(project_path):
    size = (18, 5)
    async with editor(project_path, size=size) as (app, pilot):
        await pilot.press("i")
        await pilot.pause()
        notice = app.screen.query_one(".too-small")
        assert notice.display and on_screen(notice, size)
        assert "20 × 6" in str(notice.render()) and "18 × 5" in str(notice.render())
        assert not app.screen.query_one(".dialog").display
        await pilot.resize_terminal(19, 5)
        assert await until(pilot, lambda: "(now 19 × 5)" in words_in(app, ".too-small"))
        await pilot.resize_terminal(30, 10)
        assert await until(pilot, lambda: not notice.display)
        assert app.screen.query_one(".dialog").display
        # opened too small, it had no focus; it takes it once shown (0.2 s on an idle machine)
        assert await until(pilot, lambda: isinstance(app.screen.focused, OptionList)), \
            app.screen.focused
        await pilot.press("escape")
        assert await back_on_editor(pilot, app)


async def test_the_edit_form_uses_a_tall_terminal(project_path):
    size = (100, 60)
    async with editor(project_path, size=size) as (app, pilot):
        screen_of(app).selected_id = "title"
        await pilot.press("enter")
        assert await dialog_shown(pilot, app, "edit-dialog")
        fields = app.screen.query_one(".form-fields")
        assert await until(pilot, lambda: fields.size.height > 11)  # once laid out
        assert fields.max_scroll_y == 0  # every field of a text box in view at once
        assert on_screen(app.screen.query_one("#ok"), size)


async def test_the_edit_form_scrolls_on_a_short_terminal(project_path):
    size = (80, 24)
    async with editor(project_path, size=size) as (app, pilot):
        screen_of(app).selected_id = "title"
        await pilot.press("enter")
        assert await dialog_shown(pilot, app, "edit-dialog")
        fields = app.screen.query_one(".form-fields")
        assert await until(pilot, lambda: fields.max_scroll_y > 0)  # once laid out
        assert on_screen(app.screen.query_one("#ok"), size)
        for _ in range(12):  # Tab to the last field: it scrolls into view
            await pilot.press("tab")
        # the scroll to the focused field comes after a refresh
        assert await until(pilot, lambda: app.screen.focused is not None
                           and on_screen(app.screen.focused, size))


async def test_a_refused_field_gets_the_cursor(project_path):
    """A width typed wrong, applied from the height field: the error names the width, and the
    cursor goes there (it stayed in the height field, where the user had to look for it)."""
    async with editor(project_path) as (app, pilot):
        await pilot.press("S", "end", "enter")  # Custom… page size
        assert await dialog_shown(pilot, app, "custom-size-dialog")
        app.screen.query_one("#field-width_mm", Input).value = "5"
        app.screen.query_one("#field-height_mm", Input).focus()
        assert await until(pilot, lambda: app.screen.focused.id == "field-height_mm")
        await pilot.press("enter")
        assert await until(pilot, lambda: "the width must be between"
                           in words_in(app, "#form-error"))
        width = app.screen.query_one("#field-width_mm")
        assert await until(pilot, lambda: app.screen.focused is width)


async def test_a_choice_field_opens_with_every_choice_at_40x12(project_path):
    """The font field's list, opened in the edit form at 40 x 12, shows serif, sans and
    display (the dialogs' own list rule once reached it and cut it to one row)."""
    from textual.widgets._select import SelectOverlay

    size = (40, 12)
    async with editor(project_path, size=size) as (app, pilot):
        screen_of(app).selected_id = "title"
        await pilot.press("enter")
        assert await dialog_shown(pilot, app, "edit-dialog")
        await pilot.press("tab", "enter")  # from the text to the font field, opened
        overlay = app.screen.query_one("#field-font").query_one(SelectOverlay)
        assert await until(pilot, lambda: overlay.display and option_rows_shown(overlay) >= 3)
        assert on_screen(overlay, size)

