"""A settle keeps the soundest layout it sees: a page whose first probe parts it is not saved
with the overlaps a full run from the same page leaves (model.layout.soundest_start)."""

from __future__ import annotations

import shutil
from pathlib import Path

from floatpage.model import load_project, save_project
from floatpage.model.layout import engine_for_page, settle_page

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


def test_a_layout_the_stuck_test_saw_is_not_lost_to_the_full_run(tmp_path):
    """Seed 148 p3: the probes of proves_stuck left a layout whose overlaps go 15.2 mm deep,
    with one item in the margin; the full run's go 17.5 mm deep, with three, and that was
    saved.  Now the sequence starts from the first, and a second settle changes no byte."""
    first, second = settled_twice(tmp_path, "stuck-probes-148.toml")
    assert second == first, "the second settle moved items"
    project = load_project(tmp_path / "stuck-probes-148.toml")
    quality = engine_for_page(project.pages[0], project.physics).quality()
    assert quality.overlap_count <= 3 and not quality.off_page
    assert quality.min_gap_mm >= -15.2 and len(quality.in_margin) <= 1, quality
