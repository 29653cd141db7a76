"""Regions and groups in the editor (issue 16), driven through the real app with Pilot: a group
is selected and moved as one, `G` puts an item in a group or takes it out, anchoring a member
anchors the group, and the preview draws regions and the selected item's group."""

from __future__ import annotations

import pytest

from floatpage.model import load_project, save_project
from floatpage.model.document import (
    BlockItem, ItemAnchor, Page, PointAnchor, Project, Region, TextItem,
)
from floatpage.tui.page_painter import GROUP, PAPER, REGION, mix
from editor_helpers import (
    editor, item, keys_go_straight_in, pixel, position, screen_of, type_text, until,
)


def messages(app) -> list[str]:
    return [notification.message for notification in app._notifications]


def select(app, item_id: str) -> None:
    screen_of(app).selected_id = item_id  # as a click on the item does


async def keys(pilot, *names: str) -> None:
    """Press the keys, then wait until the app has handled them: a dialog opened by one of
    them is open and has its keys, a dialog answered by one is closed and its answer (a
    callback on the App) has run. One pause left that callback for later on a loaded
    machine; the editor's own keys are handled while pressed."""
    await pilot.press(*names)
    assert await until(pilot, lambda: keys_go_straight_in(pilot.app))


def grouped_page(path):
    save_project(Project(pages=[Page(id="p", regions=[Region("top", 0.0, 0.0, 210.0, 140.0)],
                                     items=[
        TextItem(id="title", x=60.0, y=200.0, w=60.0, h=15.0, text="Title", group="head"),
        TextItem(id="sub", x=60.0, y=220.0, w=60.0, h=10.0, text="Sub", group="head"),
        BlockItem(id="box", x=150.0, y=60.0, w=40.0, h=30.0, region="top"),
    ])]), path)
    return path


async def test_an_arrow_on_any_member_moves_the_whole_group(tmp_path):
    path = grouped_page(tmp_path / "g.toml")
    async with editor(path) as (app, pilot):
        select(app, "sub")
        before = {name: position(app, name) for name in ("title", "sub")}
        for _ in range(5):
            await pilot.press("right")
        screen_of(app).release_held()
        after = {name: position(app, name) for name in ("title", "sub")}
        for name in ("title", "sub"):
            assert after[name][0] - before[name][0] > 5.0
        offset = (after["sub"][0] - after["title"][0], after["sub"][1] - after["title"][1])
        assert offset == (before["sub"][0] - before["title"][0],
                          before["sub"][1] - before["title"][1])
        # the group is anchored where it was put, and an undo names the group, not "title"
        # (its lead, which the user never selected)
        assert isinstance(item(app, "title").anchor, PointAnchor)
        assert 'group "head" anchored where you put it' in str(
            screen_of(app).query_one("#status").render())
        await keys(pilot, "ctrl+z")
        assert 'undid move group "head"' in messages(app)
        assert position(app, "sub") == pytest.approx(before["sub"])
        assert item(app, "title").anchor is None
        await keys(pilot, "ctrl+y")  # and deleting the lead says the group lost its anchor
        select(app, "title")
        await keys(pilot, "delete")
        assert 'deleted "title"; group "head" is no longer anchored (Ctrl+Z brings it back)' \
            in messages(app)


async def test_G_puts_the_selected_item_in_a_group_and_empty_takes_it_out(tmp_path):
    path = grouped_page(tmp_path / "g.toml")
    async with editor(path) as (app, pilot):
        select(app, "box")
        await keys(pilot, "G")
        assert app.screen.id == "group-dialog"
        await type_text(pilot, "head")
        await keys(pilot, "enter")
        assert item(app, "box").group == "head"
        await keys(pilot, "ctrl+s")
        assert load_project(path).pages[0].item("box").group == "head"
        await keys(pilot, "G")
        await keys(pilot, "backspace", "backspace", "backspace", "backspace", "enter")
        assert item(app, "box").group == ""


async def test_a_form_label_longer_than_the_dialog_wraps_instead_of_being_cut(tmp_path):
    """At 100 x 30 the group dialog's label read "Group name (this page has head); empty takes
    text-1 ou": a label was one line, cut at the dialog's edge."""
    path = tmp_path / "g.toml"
    save_project(Project(pages=[Page(id="p", items=[
        TextItem(id="title", x=60.0, y=200.0, w=60.0, h=15.0, text="Title", group="head"),
        BlockItem(id="text-1", x=150.0, y=60.0, w=40.0, h=30.0),
    ])]), path)
    async with editor(path, (100, 30)) as (app, pilot):
        select(app, "text-1")
        await keys(pilot, "G")
        label = app.screen.query(".field-label").first()
        words = str(label.render())
        assert words.endswith("empty takes text-1 out")
        lines = [strip.text.rstrip() for strip in label.render_lines(label.region.reset_offset)]
        assert " ".join(line.strip() for line in lines if line.strip()) == words
        assert label.region.right <= label.parent.region.right  # not cut by its container


async def test_anchoring_a_member_anchors_the_group_by_its_lead(tmp_path):
    path = grouped_page(tmp_path / "g.toml")
    async with editor(path) as (app, pilot):
        select(app, "sub")
        await keys(pilot, "a")
        page = app.session.page
        assert isinstance(page.item("title").anchor, PointAnchor)
        assert page.item("sub").anchor is None


async def test_u_on_any_member_takes_the_groups_anchor_off(tmp_path):
    """`a` on any member anchors the group (by its lead); `u` on a member other than the lead
    said '"sub" is not anchored' and left the group anchored, and the top bar showed no anchor
    on that member at all (user-walk-2)."""
    path = grouped_page(tmp_path / "g.toml")
    async with editor(path) as (app, pilot):
        select(app, "sub")
        await keys(pilot, "a")
        screen = screen_of(app)
        bar = "".join(text for text, _ in screen.page_bar_runs())
        assert "sub (text, 60×10 mm, anchored γ 1 by title)" in bar
        await keys(pilot, "u")
        page = app.session.page
        assert page.item("title").anchor is None and page.item("sub").anchor is None
        assert "anchored" not in "".join(text for text, _ in screen.page_bar_runs())
        await keys(pilot, "ctrl+z")
        assert isinstance(app.session.page.item("title").anchor, PointAnchor)


async def test_a_held_item_stays_inside_its_region(tmp_path):
    """A region's edges are walls for its items, as the page's are; the editor keeps a held
    item on the page, but Shift+down carried a box confined to the top region 70 mm out of
    it, shoving the others, and floated it back when let go (user-walk-2, in tmux)."""
    path = grouped_page(tmp_path / "g.toml")
    async with editor(path) as (app, pilot):
        select(app, "box")
        lowest = 0.0
        for _ in range(10):
            await pilot.press("J")
            lowest = max(lowest, position(app, "box")[1] + 15.0)
        assert lowest <= 140.0 + 1e-6, "the box's bottom left its region (0-140 mm)"
        assert lowest > 130.0, "it went down to the region's edge"
        screen_of(app).release_held()
        await pilot.pause()
        select(app, "box")
        await pilot.press("J")
        assert await until(pilot, lambda: messages(app)[-1:] == [
            'box is at the edge of its region "top": no room to move that way']), messages(app)


async def test_a_smaller_page_size_keeps_regions_on_the_page_and_the_file_opens(tmp_path):
    """S, 4x6in on an A4 page with a region: the region kept its 210 x 140 mm and reached past
    the 101.6 x 152.4 mm page, and the file saved was one no command would open ("region
    reaches outside the page"); so could an item grown past its shrunk region (user-walk-2)."""
    path = tmp_path / "g.toml"
    save_project(Project(pages=[Page(id="p", regions=[Region("top", 0.0, 0.0, 210.0, 140.0)],
                                     items=[
        BlockItem(id="box", x=105.0, y=60.0, w=200.0, h=100.0, region="top"),
        TextItem(id="title", x=105.0, y=220.0, w=60.0, h=15.0, text="Title"),
    ])]), path)
    async with editor(path) as (app, pilot):
        await keys(pilot, "S")
        assert app.screen.id == "page-size-dialog"
        await keys(pilot, *["down"] * 5, "enter")  # from A4 to 4x6in
        assert app.session.page.size == "4x6in"
        await keys(pilot, "ctrl+s")
    page = load_project(path).pages[0]  # opens: every region on the page, every item in it
    left, top, right, bottom = page.region("top").box
    assert (left, top) == (0.0, 0.0) and right <= 101.6 and bottom <= 152.4
    assert bottom == pytest.approx(140.0 * 152.4 / 297.0, abs=0.01)  # its share of the page
    box = page.item("box")
    assert box.w <= right and box.h <= bottom


async def test_a_smaller_page_size_scales_follow_offsets_and_keeps_followers_clear(tmp_path):
    """S, 4x6in on an A4 page: positions scaled, follow offsets did not, so a note 160 mm
    below its heading stood past the bottom of the 152.4 mm page, and the saved dy no longer
    matched the saved positions.  The offset scales as positions do; the space between a
    caption and its photo scales, and it stays clear of the photo (sizes do not scale)."""
    path = tmp_path / "f.toml"
    save_project(Project(pages=[Page(id="p", items=[
        BlockItem(id="head", x=105.0, y=40.0, w=60.0, h=20.0),
        BlockItem(id="note", x=105.0, y=200.0, w=60.0, h=20.0,
                  anchor=ItemAnchor(to="head", dx=0.0, dy=160.0)),
        BlockItem(id="photo", x=50.0, y=120.0, w=40.0, h=40.0),
        TextItem(id="caption", x=50.0, y=148.0, w=40.0, h=10.0, text="Caption",
                 anchor=ItemAnchor(to="photo", dx=0.0, dy=28.0)),
    ])]), path)
    async with editor(path) as (app, pilot):
        await keys(pilot, "S", *["down"] * 5, "enter")  # from A4 to 4x6in
        assert app.session.page.size == "4x6in"
        await keys(pilot, "ctrl+s")
    page = load_project(path).pages[0]
    shrink = 152.4 / 297.0
    head, note = page.item("head"), page.item("note")
    assert note.anchor.dy == pytest.approx(20.0 + 140.0 * shrink, abs=0.01)
    assert note.y - head.y == pytest.approx(note.anchor.dy, abs=0.02)
    assert note.y + note.h / 2 <= 152.4
    photo, caption = page.item("photo"), page.item("caption")
    gap = caption.anchor.dy - (photo.h + caption.h) / 2
    assert gap == pytest.approx(3.0 * shrink, abs=0.01)
    assert caption.anchor.dx == 0.0


async def test_a_smaller_page_size_keeps_a_groups_members_apart(tmp_path):
    """S, 4x6in on an A4 page with a title and subtitle grouped 4 mm apart: their centres
    scaled with the page but not their sizes, and the room search shrank their sizes but not
    the distance between them, so the subtitle ended 2.2 mm inside the title for good (a group
    moves as one body, so nothing ever parts them).  The space, clear of the near-miss band,
    stays clear of it (real-pages)."""
    from floatpage.tui.clear_spaces import CLEAR_MM

    path = tmp_path / "g.toml"
    save_project(Project(pages=[Page(id="p", items=[
        TextItem(id="title", x=105.0, y=100.0, w=100.0, h=12.0, text="Title", group="head"),
        TextItem(id="sub", x=105.0, y=115.0, w=100.0, h=10.0, text="Sub", group="head"),
        BlockItem(id="box", x=105.0, y=200.0, w=40.0, h=30.0),
    ])]), path)
    async with editor(path) as (app, pilot):
        await keys(pilot, "S", *["down"] * 5, "enter")  # from A4 to 4x6in
        assert app.session.page.size == "4x6in"
        await app.workers.wait_for_complete()
        await keys(pilot, "ctrl+s")
    page = load_project(path).pages[0]
    title, sub = page.item("title"), page.item("sub")
    gap = (sub.y - sub.h / 2) - (title.y + title.h / 2)
    # 4 mm is clear of the near-miss band, and stays clear rather than scaled to 1.85 mm
    # (tui.clear_spaces: a group is one rigid body to the snap, which could never open it)
    assert gap == pytest.approx(CLEAR_MM, abs=0.02)


async def test_a_page_too_small_for_a_photo_and_its_caption_shrinks_them_as_one(tmp_path):
    """S, a custom 100 x 100 mm page under an 84 x 105 mm photo whose caption follows 115 mm
    below: the room search shrank sizes but not the offset between them, so however small they
    got, the pair still reached past the page ("2 off the page", and the physics at rest).
    The caption now comes closer as the two shrink, and everything ends on the page."""
    path = tmp_path / "s.toml"
    save_project(Project(pages=[Page(id="p", items=[
        TextItem(id="title", x=105.0, y=33.0, w=150.0, h=20.0, text="Title"),
        BlockItem(id="photo", x=127.5, y=134.6, w=84.0, h=105.0),
        TextItem(id="caption", x=77.2, y=249.7, w=94.5, h=31.5, text="Sale 50% off",
                 anchor=ItemAnchor(to="photo", dx=-50.26, dy=115.04)),
    ])]), path)
    async with editor(path) as (app, pilot):
        await keys(pilot, "S", "end", "enter")  # Custom…, the last
        assert app.screen.id == "custom-size-dialog"
        app.screen.query_one("#field-width_mm").value = "100"
        app.screen.query_one("#field-height_mm").value = "100"
        await keys(pilot, "ctrl+s")
        await app.workers.wait_for_complete()
        engine = app.session.engine
        engine.advance(20_000)
        quality = engine.quality()
        assert not quality.off_page and not quality.overlapping_pairs, quality.summary()


async def test_the_preview_frames_regions_and_the_selected_group(tmp_path):
    path = grouped_page(tmp_path / "g.toml")
    async with editor(path) as (app, pilot):
        select(app, "title")
        await pilot.pause()
        preview = screen_of(app).preview
        canvas = preview.canvas
        colours = {tuple(int(v) for v in canvas.pixels[y, x])
                   for y in range(canvas.pixels.shape[0]) for x in range(canvas.cols)}
        assert mix(PAPER, REGION, 0.7) in colours
        text = "\n".join(preview.text_lines())
        assert "top" in text
        assert GROUP in colours and "group head" in text
