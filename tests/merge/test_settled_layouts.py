"""Pages of the same geometry settle once per worker, and come out exactly as a settle would."""

import copy

from floatpage.merge.record_layout import fill_record
from floatpage.merge.settled_layouts import SettledLayouts, geometry_key
from floatpage.merge.template import MergeTemplate
from floatpage.model.document import Page, TextItem
from floatpage.model.layout import settle_page
from merge_helpers import COLUMNS, rows


def record(template: MergeTemplate, values: list[str]):
    return fill_record(template, dict(zip(COLUMNS, values)))


def test_a_remembered_layout_is_the_layout_a_settle_makes(merge_folder):
    template = MergeTemplate(merge_folder / "offer.toml")
    first, second = rows(2)
    second[5], second[6] = first[5], first[6]  # the same picture and note: the same geometry
    layouts = SettledLayouts()
    made = [record(template, values) for values in (first, second)]
    fresh = record(template, second)
    for project in made:
        assert layouts.settle(project.pages[0], project.physics) == ""
    settle_page(fresh.pages[0], fresh.physics)
    assert layouts.settled == 1  # the second record took the first one's layout
    placed = [(item.id, item.x, item.y, item.anchor) for item in made[1].pages[0].items]
    assert placed == [(item.id, item.x, item.y, item.anchor) for item in fresh.pages[0].items]
    title = made[1].pages[0].item("shop-title")  # a hard anchor holds
    assert (title.x, title.y) == (title.anchor.x, title.anchor.y) == (74.0, 13.0)


def test_the_key_ignores_words_and_paths_but_nothing_else(merge_folder):
    template = MergeTemplate(merge_folder / "offer.toml")
    page = template.project.pages[0]
    settings = template.project.physics
    reworded = copy.deepcopy(page)
    reworded.item("product").text = "Something else entirely"
    reworded.item("photo").path = "pictures/other.png"
    assert geometry_key(reworded, settings) == geometry_key(page, settings)
    for change in (lambda p: setattr(p.item("photo"), "w", 80.0),
                   lambda p: setattr(p.item("note"), "decorative", True),
                   lambda p: p.items.pop()):
        changed = copy.deepcopy(page)
        change(changed)
        assert geometry_key(changed, settings) != geometry_key(page, settings)


def test_a_page_too_full_fails_the_gate_and_is_remembered_failing(merge_folder):
    template = MergeTemplate(merge_folder / "offer.toml")
    settings = template.project.physics
    page = Page(id="tiny", width_mm=20.0, height_mm=20.0,
                items=[TextItem(id=name, x=10.0, y=10.0, w=18.0, h=18.0, text=name)
                       for name in ("a", "b", "c")])
    layouts = SettledLayouts()
    problem = layouts.settle(copy.deepcopy(page), settings)
    assert "still overlap after settling" in problem
    assert layouts.settle(copy.deepcopy(page), settings) == problem and layouts.settled == 1


def test_only_so_many_layouts_are_kept(merge_folder):
    template = MergeTemplate(merge_folder / "offer.toml")
    layouts = SettledLayouts(kept=2)
    for width in (80.0, 81.0, 82.0):
        page = copy.deepcopy(template.project.pages[0])
        page.item("photo").w = width
        layouts.settle(page, template.project.physics)
    assert len(layouts.layouts) == 2


def test_an_empty_column_leaves_out_a_background_picture_named_from_it(merge_folder):
    """A background `pictures/{photo}` with an empty photo was "pictures/", a folder, and
    failed the record; an empty column means no background picture, as an empty path did."""
    path = merge_folder / "offer.toml"
    path.write_text(path.read_text(encoding="utf-8").replace(
        'background = {color = "#fff8ea"}',
        'background = {picture = "pictures/{valid_until}"}'), encoding="utf-8")
    template = MergeTemplate(path)
    values = rows(2)
    values[0][7], values[1][7] = "bread.png", ""
    with_picture, without = (record(template, row) for row in values)
    assert with_picture.pages[0].background.picture == "pictures/bread.png"
    assert without.pages[0].background.picture is None
