"""Defects a user of greeting cards, calendars, albums and flyers met in a first week with the
editor (user-walk-11), each driven through the real app with Pilot, on a real project file."""

from __future__ import annotations

import shutil
import threading
from pathlib import Path

from editor_helpers import back_on_editor, editor, every_page_resized_and_saved, until, words_in

ROOT = Path(__file__).resolve().parents[2]


def turns(project) -> list[tuple[str, float, float]]:
    return [(page.orientation, page.width_mm, page.height_mm) for page in project.pages]


async def test_turning_every_page_is_one_undo_step_and_is_saved(project_path):
    """`o` turned the page on screen only, while `S` asks (a calendar turned landscape kept
    eleven pages portrait).  With several pages `o` asks the same question, "Every page"
    highlighted where the pages have one orientation; every page turns in its own size, its
    items moved in proportion, room is searched for on each, one Ctrl+Z turns them back, and
    the file saved holds the turn on every page."""
    from floatpage.model import load_project

    async with editor(project_path) as (app, pilot):
        greeting = app.session.project.pages[1].item("greeting")  # on the back
        x, y = greeting.x, greeting.y
        await pilot.press("o")
        assert await until(pilot, lambda: app.screen.id == "which-pages-dialog")
        assert app.screen.id == "which-pages-dialog"
        await pilot.press("enter")  # highlighted: every page (both are portrait)
        assert await back_on_editor(pilot, app)  # the answer has started the room searches
        await app.workers.wait_for_complete()
        project = app.session.project
        assert turns(project) == [("landscape", 210.0, 148.0)] * 2
        assert app.session.pages_edited >= {"front", "back"}
        back = project.pages[1].item("greeting")
        assert abs(back.x - x * 210 / 148) < 1.5 and abs(back.y - y * 148 / 210) < 1.5
        await pilot.press("ctrl+z")
        assert turns(app.session.project) == [("portrait", 148.0, 210.0)] * 2
        await pilot.press("ctrl+y", "ctrl+s")
        assert not app.session.unsaved
    assert turns(load_project(project_path)) == [("landscape", 210.0, 148.0)] * 2


async def test_turning_this_page_only_keeps_the_others_and_is_offered_first_then(project_path):
    """"This page only" turns the front and leaves the back; the next `o`, on the turned
    front, would turn it back to the orientation every other page has: nothing to ask."""
    async with editor(project_path) as (app, pilot):
        await pilot.press("o")
        assert await until(pilot, lambda: app.screen.id == "which-pages-dialog")
        await pilot.press("down", "enter")  # this page only
        assert await back_on_editor(pilot, app)
        assert turns(app.session.project) == [("landscape", 210.0, 148.0),
                                              ("portrait", 148.0, 210.0)]
        await pilot.press("o")
        await pilot.pause()
        assert app.screen is app.editor  # asked nothing: the back is portrait already
        assert turns(app.session.project) == [("portrait", 148.0, 210.0)] * 2
        await pilot.press("pagedown")  # to the back, portrait among portrait pages
        await pilot.pause()
        await pilot.press("o")
        assert await until(pilot, lambda: app.screen.id == "which-pages-dialog")
        options = app.screen.query_one("OptionList")
        assert str(options.get_option_at_index(options.highlighted).prompt) \
            == "Every page (2)"
        await pilot.press("escape")
        assert await back_on_editor(pilot, app)
        assert turns(app.session.project) == [("portrait", 148.0, 210.0)] * 2


def tree_names(app) -> set[str]:
    tree = app.screen.query_one("#picture-tree")
    return {str(node.label) for node in tree.root.children}


async def test_the_picture_dialog_does_not_offer_the_projects_own_pdf(project_path):
    """After Ctrl+E, `p` listed card.pdf, the card's own export, beside the pictures: put in,
    the card showed a picture of itself, and the next Ctrl+E refused to write over one of
    the project's inputs.  The tree leaves it out (a logo PDF stays), and typed, the dialog
    says what the file is."""
    import pikepdf

    folder = project_path.parent
    logo = pikepdf.new()
    logo.add_blank_page(page_size=(200, 100))
    logo.save(folder / "logo.pdf")
    async with editor(project_path) as (app, pilot):
        await pilot.press("ctrl+e")
        assert await until(pilot, lambda: (folder / "card.pdf").is_file()
                           and not app.editor.export_state, 120)
        await pilot.press("p")
        assert await until(pilot, lambda: app.screen.id == "picture-dialog"
                           and "logo.pdf" in tree_names(app))
        assert "card.pdf" not in tree_names(app) and "pictures" in tree_names(app)
        await pilot.press("tab")
        await pilot.press(*"card.pdf")
        assert await until(pilot, lambda: app.screen.query_one("#picture-path").value == "card.pdf")
        await pilot.press("enter")
        assert await until(pilot, lambda: "own PDF" in words_in(app, "#picture-error")), \
            words_in(app, "#picture-error")
        assert app.screen.id == "picture-dialog"
        await pilot.press("escape")
        assert await back_on_editor(pilot, app)
        assert "picture-1" not in app.session.page.item_ids()


async def test_a_smaller_size_on_every_page_keeps_the_gutter_where_settle_keeps_it(tmp_path):
    """`S` to A6 on every page of the calendar sample left five pages with 1.6-2.2 mm
    between the month and the photos, under the 3 mm gutter each page had kept: the room
    search shrank the items until nothing overlapped, no further, while `settle` keeps the
    gutter wherever it fits.  A page that kept the gutter before keeps it after (its items
    made a step smaller if need be); three of the sample's months, May and July among them,
    saved and read back."""
    from floatpage.model import load_project
    from floatpage.model.layout import engine_for_page

    path = three_months(tmp_path)
    project = load_project(path)
    assert all(engine_for_page(page, project.physics).quality().gutter_kept
               for page in project.pages)
    async with editor(path, autostart=True) as (app, pilot):  # running: the save settles
        await every_page_resized_and_saved(app, pilot, "A6 ")
    project = load_project(path)
    assert [page.width_mm for page in project.pages] == [105.0] * 3
    gaps = {page.id: engine_for_page(page, project.physics).quality() for page in project.pages}
    assert all(quality.gutter_kept for quality in gaps.values()), {
        page: quality.summary() for page, quality in gaps.items()}


def three_months(tmp_path) -> Path:
    """The calendar sample, its January, May and July: pages that need room at A6."""
    from floatpage.model import load_project, save_project

    folder = tmp_path / "calendar"
    shutil.copytree(ROOT / "sample_projects" / "calendar-2027", folder)
    path = folder / "calendar-2027.toml"
    project = load_project(path)
    project.pages = [page for page in project.pages if page.id in ("jan", "may", "jul")]
    project.source_text, project.parsed_source = None, None
    save_project(project, path)
    return path


def hold_room_searches(app) -> threading.Event:
    """The room searches wait (in their thread) until the event is set, then run as ever:
    the keys pressed meanwhile come while they run, however fast the machine."""
    gate, search = threading.Event(), app.session.room_scale

    def held(page, request):
        gate.wait(60)
        return search(page, request)

    app.session.room_scale = held
    return gate


async def every_page_a6(app, pilot) -> None:
    await pilot.press("S")
    assert await until(pilot, lambda: app.screen.id == "page-size-dialog")
    options = [str(option.prompt) for option in app.screen.query_one("OptionList").options]
    await pilot.press("home", *["down"] * next(
        index for index, option in enumerate(options) if option.startswith("A6 ")), "enter")
    assert await until(pilot, lambda: app.screen.id == "which-pages-dialog")
    await pilot.press("enter")  # every page
    assert await back_on_editor(pilot, app)


def overlaps_in(path: Path) -> dict[str, int]:
    from floatpage.model import load_project
    from floatpage.model.layout import engine_for_page

    project = load_project(path)
    return {page.id: len(engine_for_page(page, project.physics).quality().overlapping_pairs)
            for page in project.pages}


async def test_an_export_right_after_a_new_page_size_waits_for_the_room(tmp_path):
    """Ctrl+E pressed right after `S` to A6 on every page of the calendar printed the months
    with their photos piled on the title and the grid (the room searches not done), and the
    export's own pass then left the searches' answers unused: five overlaps stayed on the
    page on screen.  The export waits for the room, says so, and the PDF and the pages have
    no overlap."""
    import pdfplumber

    path = three_months(tmp_path)
    async with editor(path, autostart=True) as (app, pilot):
        gate = hold_room_searches(app)
        await every_page_a6(app, pilot)
        assert app.editor.room_searches
        await pilot.press("ctrl+e")
        assert "export once room is found" in app.editor.state_word()
        assert not path.with_suffix(".pdf").exists()
        gate.set()
        assert await until(pilot, lambda: path.with_suffix(".pdf").is_file()
                           and not app.editor.export_state and not app.editor.room_searches,
                           240)
        quality = app.session.engine.quality()
        assert quality.overlapping_pairs == (), quality.summary()
        await pilot.press("ctrl+s")
        assert await until(pilot, lambda: not app.session.unsaved, 120)
    assert overlaps_in(path) == {"jan": 0, "may": 0, "jul": 0}
    with pdfplumber.open(path.with_suffix(".pdf")) as pdf:
        assert [round(page.width * 25.4 / 72) for page in pdf.pages] == [105] * 3
        for page, month in zip(pdf.pages, ("January", "May", "July")):
            # the title and the grid's heading, each whole, none drawn over: the photos no
            # longer lie on the words (pdfplumber reads words under an image all the same,
            # so the page's pictures are checked to keep clear of its words)
            words = page.extract_words()
            assert sum(word["text"] == month for word in words) == 2, words
            for image in page.images:
                for word in words:
                    assert (image["x1"] <= word["x0"] or word["x1"] <= image["x0"]
                            or image["bottom"] <= word["top"]
                            or word["bottom"] <= image["top"]), (month, word["text"])


async def test_save_and_quit_right_after_a_new_page_size_waits_for_the_room(tmp_path):
    """`q`, "Save and quit" right after `S` on every page saved the pages with their items
    piled up and quit: the room searches' answers were lost with the editor.  The save waits
    for the room, then saves and quits."""
    path = three_months(tmp_path)
    async with editor(path, autostart=True) as (app, pilot):
        gate = hold_room_searches(app)
        await every_page_a6(app, pilot)
        assert app.editor.room_searches
        await pilot.press("q")
        assert await until(pilot, lambda: app.screen.id == "quit-dialog")
        await pilot.press("enter")  # Save and quit, highlighted
        assert await back_on_editor(pilot, app)
        assert "save and quit once room is found" in app.editor.state_word()
        assert app.session.unsaved
        gate.set()
        assert await until(pilot, lambda: not app.is_running, 240)
    assert overlaps_in(path) == {"jan": 0, "may": 0, "jul": 0}


async def test_photos_put_into_an_album_page_keep_its_gutter_and_margin(tmp_path):
    """Three more photos put into the album sample's first page with `p`: the second left
    2.9 mm of the 3 mm gutter, the third 1.6 mm, and a fourth put ten items into the print
    margin, the room search after an insert having looked for zero overlap only.  A page
    that kept the gutter and the margin keeps them: the new photo comes a step smaller
    instead.  Saved and read back."""
    from floatpage.model import load_project
    from floatpage.model.layout import engine_for_page
    from floatpage.physics.quality import GAP_TOLERANCE_MM

    folder = tmp_path / "album"
    shutil.copytree(ROOT / "sample_projects" / "photo-album", folder)
    path = folder / "photo-album.toml"
    pictures = sorted(path.parent.glob("pictures/*.jpg"))[:4]
    before = len(load_project(path).pages[0].items)
    async with editor(path, autostart=True) as (app, pilot):
        for picture in pictures:
            await pilot.press("p")
            assert await until(pilot, lambda: app.screen.id == "picture-dialog")
            await pilot.press("tab", *picture.relative_to(folder).as_posix(), "enter")
            assert await back_on_editor(pilot, app)
            assert await until(pilot, lambda: app.editor.at_rest, 120)
        await pilot.press("ctrl+s")
        assert await until(pilot, lambda: not app.session.unsaved, 120)
    project = load_project(path)
    quality = engine_for_page(project.pages[0], project.physics).quality()
    assert len(project.pages[0].items) == before + len(pictures)
    assert quality.overlapping_pairs == () and quality.in_margin == (), quality.summary()
    assert quality.min_gap_mm >= quality.gutter_mm - GAP_TOLERANCE_MM, quality.summary()
