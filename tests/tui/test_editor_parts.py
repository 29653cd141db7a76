"""The editor's UI-free parts: reading order, history, frame meter, key labels, the canvas."""

from __future__ import annotations

from dataclasses import dataclass

import pytest

from floatpage.tui.cell_canvas import UPPER_HALF, CellCanvas, Glyph, StripCache
from floatpage.tui.frame_meter import FrameMeter
from floatpage.tui.history import History, Snapshot
from floatpage.tui import item_forms
from floatpage.tui.keymap import COMMANDS, bindings, key_label
from floatpage.tui.reading_order import reading_order, step_through


@dataclass
class Box:
    id: str
    x: float
    y: float
    h: float = 10.0


def test_reading_order_reads_rows_left_to_right_even_when_slightly_staggered():
    boxes = [Box("right", 150, 22), Box("left", 40, 20), Box("below", 40, 60),
             Box("middle", 95, 24)]
    assert reading_order(boxes) == ["left", "middle", "right", "below"]


def test_step_through_wraps_and_starts_at_either_end():
    order = ["a", "b", "c"]
    assert step_through(order, None, 1) == "a"
    assert step_through(order, None, -1) == "c"
    assert step_through(order, "c", 1) == "a"
    assert step_through(order, "a", -1) == "c"
    assert step_through([], None, 1) is None


def test_history_undo_redo_and_a_new_edit_clears_redo():
    history = History(limit=3)
    snap = lambda label: Snapshot.take(label, [], 0, None)  # noqa: E731
    for label in "abcd":
        history.record(snap(label))
    assert [s.label for s in history.undo_stack] == ["b", "c", "d"]  # bounded
    assert history.undo(snap("now")).label == "d"
    assert history.redo(snap("d")).label == "now"
    history.undo(snap("now"))
    history.record(snap("e"))
    assert not history.redo_stack


def test_frame_meter_counts_frames_and_steps_over_the_window():
    meter = FrameMeter(window_s=1.0)
    for frame in range(31):
        meter.record(frame / 30, 10, 0.005)
    assert meter.fps == pytest.approx(30)
    assert meter.steps_per_s == pytest.approx(300)


def test_frame_meter_counts_frames_held_back_over_the_window():
    meter = FrameMeter(window_s=1.0)
    for tick in range(60):  # two seconds: every third frame drawn, the others held back
        if tick % 3 == 0:
            meter.record(tick / 30, 10, 0.005)
        else:
            meter.record_held(tick / 30)
    assert meter.held == 21  # ticks 29-59: the window holds both its ends
    assert meter.fps == pytest.approx(10, rel=0.1)


def test_key_labels_read_as_typed():
    assert key_label("plus,equals_sign") == "+ ="
    assert key_label("shift+left,H") == "Shift+\u2190 H"
    assert key_label("right_square_bracket,pagedown") == "] pgdn"
    assert all("ctrl+shift" not in command.keys for command in COMMANDS)


def test_a_typed_colour_is_written_as_the_model_writes_it():
    assert item_forms.colour("1F77B4") == item_forms.colour(" #1f77b4 ") == "#1f77b4"
    for wrong in ("#12345", "##1f77b4", "red"):
        with pytest.raises(ValueError, match="#rrggbb"):
            item_forms.colour(wrong)


def test_the_forms_refuse_what_the_loader_refuses_in_its_words():
    """The editor's forms check values with the model's own field checks, not copies."""
    with pytest.raises(ValueError, match=r"^the opacity must be between 0.0 and 1.0$"):
        item_forms.parse_edit({"opacity": "1.5"})
    with pytest.raises(ValueError, match="the year must be between 1 and 9999"):
        item_forms.parse_calendar({"year": "0", "month": 1})
    with pytest.raises(ValueError, match="the width must be between 10.0 and 5000.0"):
        item_forms.parse_custom_size({"width_mm": "5", "height_mm": "100"})
    with pytest.raises(ValueError, match="the text holds 20001 characters"):
        item_forms.parse_new_text({"text": "x" * 20_001})
    assert item_forms.parse_edit({"opacity": "0.5", "gamma": "1"}) == {"opacity": 0.5, "gamma": 1.0}


def test_every_binding_has_its_own_id():
    ids = [binding.id for binding in bindings()]
    assert None not in ids and len(set(ids)) == len(COMMANDS)


def test_canvas_rows_become_half_block_strips_and_later_fills_hide_glyphs():
    canvas = CellCanvas(4, 2, (0, 0, 0))
    canvas.fill(0, 0, 4, 1, (255, 0, 0))  # the top pixel row only
    canvas.write(0, 1, "ab", (255, 255, 255))
    canvas.fill(1, 2, 2, 4, (0, 0, 255))  # covers the "b"
    strips = StripCache().strips(canvas)
    assert strips[0].text == UPPER_HALF * 4
    assert strips[1].text == "a   "
    assert canvas.glyph_at(1, 1) is None and canvas.glyph_at(0, 1) == Glyph("a", (255, 255, 255))
    assert all(strip.cell_length == 4 for strip in strips)


def test_changes_far_apart_in_a_row_are_separate_spans_and_close_ones_one():
    """Two guide lines crossing a row change two cells; the cells between them (a calendar's
    digits) are not resent: only each change and a cell either side (wide characters)."""
    def painted(*cols: int) -> CellCanvas:
        canvas = CellCanvas(60, 2, (0, 0, 0))
        canvas.write(0, 0, "0123456789" * 6, (255, 255, 255))
        for col in cols:
            canvas.pixels[2, col] = (0, 190, 210)
        return canvas

    cache = StripCache()
    cache.update(painted())
    cache.update(painted(5, 40, 45))
    assert cache.changed == {1: ((4, 7), (39, 47))}
    assert "".join(segment.text for segment in cache.segments(1, 39, 47)[1]) == " ▀    ▀ "


def test_a_spans_runs_are_the_rows_cells_cell_by_cell_or_by_numpy():
    """Narrow spans are cut into runs cell by cell, wide ones with numpy: both give the
    row's own cells, a wide character whole, in the style the row's Strip gives them."""
    canvas = CellCanvas(60, 1, (0, 0, 0))
    canvas.fill(10, 0, 30, 1, (255, 0, 0))  # the top pixels of columns 10-29
    canvas.write(3, 0, "ab日本c", (255, 255, 255), (0, 0, 90), bold=True)  # 日本: columns 5-8
    canvas.write(40, 0, "xyz", (255, 255, 255))
    cache = StripCache()
    at_col = {}  # column -> the characters of the row's Strip from there, with their styles
    chars = [(char, segment.style) for segment in cache.strips(canvas)[0] for char in segment.text]
    col = 0
    for index, (char, _) in enumerate(chars):
        at_col[col] = chars[index:]
        col += 2 if char in "日本" else 1
    for first, end in ((0, 60), (2, 9), (6, 8), (7, 9), (9, 44), (38, 45)):
        start, runs = cache.runs(0, first, end)
        got = [(char, cache.style(fg, bg, bold)) for text, _, fg, bg, bold in runs
               for char in text]
        assert start == (first + 1 if first in (6, 8) else first)  # a second half: left out
        assert got == at_col[start][:len(got)], (first, end)
        assert start + sum(count for _, count, *_ in runs) == (end + 1 if end in (6, 8) else end)


def test_a_settled_copy_leaves_the_pages_anchors_alone():
    """The search for room settled `copy_of` the page in a thread, and a settle writes a hard
    anchor back with its item's rounded position: the copy shared its anchors with the live
    page, so the thread wrote into the page being edited."""
    from floatpage.model.document import BlockItem, Page, PhysicsSettings, PointAnchor
    from floatpage.model.layout import copy_of, settle_page

    page = Page(id="p", width_mm=100.0, height_mm=100.0, items=[
        BlockItem(id="held", x=30.004, y=30.004, w=10.0, h=10.0,
                  anchor=PointAnchor(x=30.004, y=30.004, hard=True)),
        BlockItem(id="free", x=31.0, y=31.0, w=10.0, h=10.0)])
    copy = copy_of(page)
    settle_page(copy, PhysicsSettings())
    assert (copy.items[0].anchor.x, copy.items[0].anchor.y) != (30.004, 30.004)
    assert (page.items[0].anchor.x, page.items[0].anchor.y) == (30.004, 30.004)
