"""A settle keeps the soundest layout it sees: a page whose first probe parts it is not saved
with the overlaps a full run from the same page leaves (model.layout.soundest_start)."""

from __future__ import annotations

import shutil
from pathlib import Path

from floatpage.model import load_project, save_project
from floatpage.model import layout
from floatpage.model.layout import engine_for_page, settle_page, sound_as, soundness_key

PAGES = Path(__file__).parent / "settle_pages"


def settled_twice(tmp_path: Path, name: str) -> tuple[bytes, bytes]:
    path = tmp_path / name
    shutil.copy(PAGES / name, path)
    saved = []
    for _ in range(2):
        project = load_project(path)
        for page in project.pages:
            settle_page(page, project.physics)
        save_project(project, path)
        saved.append(path.read_bytes())
    return saved[0], saved[1]


def test_a_settle_that_parted_the_page_does_not_save_overlaps(tmp_path):
    """Seed 227 p1: saved with 6 overlaps (9.7 mm) that its first probe had parted; now with
    none, and a second settle changes no byte."""
    first, second = settled_twice(tmp_path, "soundest-start-227.toml")
    assert second == first, "the second settle moved items"
    project = load_project(tmp_path / "soundest-start-227.toml")
    quality = engine_for_page(project.pages[0], project.physics).quality()
    assert quality.overlap_count == 0, quality.min_gap_mm
    assert quality.min_gap_mm > 0.0


def test_a_rest_less_sound_than_a_layout_probed_before_it_is_not_saved(tmp_path):
    """Seed 74 p3: the probes from the full run's layout (every item out of the margin) came
    to rest with two items in the margin, and that was saved; now the full run's layout is,
    and a second settle changes no byte."""
    first, second = settled_twice(tmp_path, "rest-less-sound-74.toml")
    assert second == first, "the second settle moved items"
    project = load_project(tmp_path / "rest-less-sound-74.toml")
    quality = engine_for_page(project.pages[0], project.physics).quality()
    assert quality.overlap_count == 0 and not quality.off_page
    assert not quality.in_margin, quality.in_margin


def test_no_layout_the_settle_starts_from_is_sounder_than_the_one_saved(tmp_path, monkeypatch):
    """Seed 148 p3: the full run left overlaps 17.5 mm deep with three items in the margin,
    and the probes of proves_stuck had seen one 15.2 mm deep with one, yet the full run's was
    saved.  Whatever the settle weighs the candidates it starts its probe sequence from
    with (soundest_start: the full run's layout, the probes' before it, the page as it
    was), none is sounder than what is saved, and a second settle changes no byte."""
    seen = []
    measure = layout.soundness

    def recorded(page, settings):
        seen.append(measure(page, settings))
        return seen[-1]
    monkeypatch.setattr(layout, "soundness", recorded)
    first, second = settled_twice(tmp_path, "stuck-probes-148.toml")
    assert second == first, "the second settle moved items"
    assert seen, "the settle compared no layouts: the page no longer tests soundest_start"
    project = load_project(tmp_path / "stuck-probes-148.toml")
    saved = soundness_key(engine_for_page(project.pages[0], project.physics).quality())
    assert all(sound_as(saved, other) for other in seen), (saved, seen)


def test_seven_hairline_overlaps_are_kept_over_six_with_a_deep_one(tmp_path):
    """Seed 7062 p3: six overlaps, one 48.5 mm deep, were saved over seven of at most 0.77 mm
    (the count of pairs came first in all three orders: at rest, stuck and saved).  Now the
    hairline ones are, and a second settle changes no byte."""
    first, second = settled_twice(tmp_path, "hairline-not-deep-7062.toml")
    assert second == first, "the second settle moved items"
    project = load_project(tmp_path / "hairline-not-deep-7062.toml")
    quality = engine_for_page(project.pages[0], project.physics).quality()
    assert not quality.off_page
    assert quality.min_gap_mm > -1.0, quality.min_gap_mm
    assert quality.overlap_depth_mm < 10.0, quality.overlap_depth_mm


def test_the_summed_depth_not_the_deepest_alone_weighs_overlaps(tmp_path):
    """Seed 149 p1: by the deepest overlap alone, eight overlaps of up to 8.8 mm (59.0 mm
    summed, 3,290 mm2 hidden) beat two of 17.7 mm (35.4 mm, 1,827 mm2); summed they do not."""
    first, second = settled_twice(tmp_path, "summed-depth-149.toml")
    assert second == first, "the second settle moved items"
    project = load_project(tmp_path / "summed-depth-149.toml")
    quality = engine_for_page(project.pages[0], project.physics).quality()
    assert not quality.off_page
    assert quality.overlap_depth_mm < 50.0, (quality.overlap_count, quality.overlap_depth_mm)
