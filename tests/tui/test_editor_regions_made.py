"""Regions are made, changed and removed in the editor with `R` (user walk 5).

The editor drew regions and let an item join one, but could not make one: "photos in the
top two-thirds" meant leaving the editor for a text editor.  Each refusal below is one the
project loader would make of the file, shown in the form, which stays open.
"""

from __future__ import annotations

from textual.widgets import Checkbox, Input, Label

from floatpage.model import load_project
from editor_helpers import answer_form, editor, item, screen_of


def form_error(app) -> str:
    return str(app.screen.query_one("#form-error", Label).render())


async def type_into(app, pilot, name: str, value: str) -> None:
    app.screen.query_one(f"#field-{name}", Input).value = value
    await pilot.pause()


async def region_form(app, pilot, selected: str | None = None) -> None:
    """R on the page, with ``selected`` the selected item first."""
    if selected is not None:
        screen_of(app).selected_id = selected
    await pilot.press("R")
    await pilot.pause()


async def submit(app, pilot) -> None:
    await answer_form(pilot, app, "enter")


async def test_a_new_region_with_nothing_selected_is_the_top_two_thirds(project_path):
    async with editor(project_path) as (app, pilot):
        screen_of(app).selected_id = None
        await region_form(app, pilot)
        assert app.screen.id == "region-dialog"
        assert not app.screen.query(Checkbox)  # no item to keep inside it
        await submit(app, pilot)
        page = app.session.page
        assert [(r.id, r.left, r.top, r.w, r.h) for r in page.regions] == \
            [("region-1", 0.0, 0.0, 148.0, 140.0)]


async def test_a_region_around_the_selected_photo_keeps_it_inside_and_is_saved(project_path):
    async with editor(project_path) as (app, pilot):
        await region_form(app, pilot, "photo")
        await type_into(app, pilot, "id", "photos")
        await submit(app, pilot)
        assert app.screen is screen_of(app)
        region = app.session.page.region("photos")
        photo = item(app, "photo")
        assert photo.region == "photos"
        left, top, right, bottom = region.box
        assert left <= photo.x - photo.w / 2 and photo.x + photo.w / 2 <= right
        assert top <= photo.y - photo.h / 2 and photo.y + photo.h / 2 <= bottom
        await pilot.press("ctrl+s")
        await pilot.pause()
    saved = load_project(project_path).pages[0]  # the loader takes what the editor made
    assert saved.item("photo").region == "photos" and saved.region("photos").w == region.w


async def test_a_region_too_small_or_past_the_page_keeps_the_form_open(project_path):
    async with editor(project_path) as (app, pilot):
        await region_form(app, pilot, "photo")
        await type_into(app, pilot, "w", "20")
        await submit(app, pilot)
        assert app.screen.id == "region-dialog"
        assert '"photo" is 60.0 x 45.0 mm, larger than the region' in form_error(app)
        await type_into(app, pilot, "w", "200")
        await submit(app, pilot)
        assert "reaches outside the page" in form_error(app)
        await type_into(app, pilot, "w", "abc")
        await submit(app, pilot)
        assert 'the width must be a number (not "abc")' in form_error(app)
        assert app.session.page.regions == [] and item(app, "photo").region == ""


async def test_a_region_is_renamed_resized_removed_and_brought_back(project_path):
    async with editor(project_path) as (app, pilot):
        await region_form(app, pilot, "photo")
        await type_into(app, pilot, "id", "photos")
        await submit(app, pilot)
        await pilot.press("R")  # the photo's own region, to change
        assert app.screen.id == "region-dialog"
        assert app.screen.query_one("#field-id", Input).value == "photos"
        await type_into(app, pilot, "id", "pictures")
        await type_into(app, pilot, "h", "100")
        await submit(app, pilot)
        page = app.session.page
        assert [r.id for r in page.regions] == ["pictures"] and page.regions[0].h == 100.0
        assert item(app, "photo").region == "pictures"
        await region_form(app, pilot)
        await type_into(app, pilot, "id", "")  # an empty name removes it
        await submit(app, pilot)
        assert app.session.page.regions == [] and item(app, "photo").region == ""
        await pilot.press("ctrl+z")
        await pilot.pause()
        assert [r.id for r in app.session.page.regions] == ["pictures"]
        assert item(app, "photo").region == "pictures"


async def test_two_regions_cannot_share_a_name(project_path):
    async with editor(project_path) as (app, pilot):
        screen_of(app).selected_id = None
        await region_form(app, pilot)
        await submit(app, pilot)
        await region_form(app, pilot, "block")
        await type_into(app, pilot, "id", "region-1")
        await submit(app, pilot)
        assert 'a region "region-1" already' in form_error(app)
