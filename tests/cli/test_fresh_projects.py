"""Project files drawn by benchmarks/fresh_projects.py that once broke a promise, cut down to
what still broke it: through the real `floatpage` command, a settle then a second settle
changes no byte, and `check --strict` passes on the settled file, or (files named limit-*)
fails with a reason no settle can fix and never sends the user back to `settle`."""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

FILES = Path(__file__).parent / "fresh_projects"


def floatpage(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "floatpage.cli.main", *args], cwd=cwd,
                          capture_output=True, text=True, timeout=600, stdin=subprocess.DEVNULL)


def settle(name: str, folder: Path) -> None:
    done = floatpage("settle", "-q", "-j", "1", name, cwd=folder)
    assert done.returncode == 0, done.stdout + done.stderr


def settled_and_checked(name: str, folder: Path):
    """The cut-down file copied into ``folder``, settled and checked: check's result."""
    shutil.copy(FILES / name, folder / name)
    settle(name, folder)
    return floatpage("check", name, cwd=folder)


@pytest.mark.parametrize("name", sorted(path.name for path in FILES.glob("*.toml")))
def test_a_settled_fresh_project_keeps_its_promises(tmp_path, name):
    path = tmp_path / name
    shutil.copy(FILES / name, path)
    settle(name, tmp_path)
    first = path.read_bytes()
    settle(name, tmp_path)
    assert path.read_bytes() == first, "the second settle moved items"
    check = floatpage("check", "--strict", name, cwd=tmp_path)
    assert "internal error" not in check.stderr
    if name.startswith("limit-"):
        assert check.returncode == 1
        assert "floatpage settle" not in check.stdout, check.stdout
        assert "no settle fixes them: see the reasons above" in check.stdout
    else:
        assert check.returncode == 0, check.stdout


def test_check_names_captioned_photos_that_must_stand_in_one_row(tmp_path):
    """Each photo with its caption is taller than half the card: no two stand one above the
    other, and the four side by side are wider than the card.  check names the four groups
    by their photos, and says they cannot stand above each other (it said "beside", and
    then "so they must stand side by side")."""
    name = "limit-stacked-groups-19.toml"
    check = settled_and_checked(name, tmp_path)
    assert ('items "p1-grouped5", "p1-captioned2", "p1-captioned0", "p1-photo4" are each too '
            "tall to stand above another of them with the 3 mm gutter, so they must stand "
            "side by side, and that is 159.1 mm wide") in check.stdout, check.stdout


def test_check_names_a_row_that_hard_anchors_leave_no_room_for(tmp_path):
    """Three photos too tall for two to stand one above the other, and a hard block and a
    hard photo in their row: check names the row and the anchors in its way, says the margin
    must give way (not overlap), and settle keeps them apart (it left 16.8 mm of overlap and
    check sent the page back to settle)."""
    name = "limit-pinned-stack-17.toml"
    check = settled_and_checked(name, tmp_path)
    assert ('items "p2-grouped8", "p2-photo3", "p2-captioned1" are too tall to stand above one '
            "another with the 4 mm gutter, so they must stand side by side, and the items that "
            'cannot move ("p2-block4", "p2-grouped5") leave no such row of the 136.0 mm inside '
            "the margins: none of them passes above or below those; they can be parted only by "
            "giving up the margin") in check.stdout, check.stdout
    assert "page p2: 0 overlaps" in check.stdout, check.stdout


def test_check_names_a_row_across_regions_and_settle_parts_it(tmp_path):
    """A words region's text, a free text and two items of the photos region, each too tall
    to stand above another, must stand in one row: check names the four (it named false
    Crossings between items of the two regions), and settle keeps them apart (the pass left
    two overlaps of 13.9 mm)."""
    name = "row-across-rooms-118.toml"
    check = settled_and_checked(name, tmp_path)
    assert ('items "p1-text2", "p1-grouped0", "p1-photo3", "p1-text4" are too tall to stand '
            "above one another with the 3 mm gutter, each inside its region or the margins, so "
            "they must stand side by side, and no such row of them fits in the 283.4 mm they "
            "span") in check.stdout, check.stdout
    assert "page p1: 0 overlaps" in check.stdout and "cannot both fit" not in check.stdout


def test_items_that_must_stand_in_the_margin_keep_the_gutter(tmp_path):
    """Where the margin gives way, only the items that need it stand in it, and every pair
    still keeps the gutter: the search for the widest gap had given the margin up for four
    items and left three bars 0.1 mm apart."""
    check = settled_and_checked("limit-margin-bars-2611.toml", tmp_path)
    gap = re.search(r"gap (\d+\.\d+) mm", check.stdout)
    assert gap and float(gap.group(1)) >= 3.0 and "< 3" not in check.stdout, check.stdout
    assert '2 item(s) inside the 5.0 mm print-safe margin: "bar-177", "tall"' in check.stdout
    assert "they can be parted only by giving up the margin" in check.stdout


def test_where_not_even_the_margin_makes_room_for_the_gutter_the_widest_gap_holds(tmp_path):
    """With the margin dropped, 2.95 mm is the widest gap three stacked bars can keep on the
    page (291.1 mm of items in 297); settle had left 0.1 mm."""
    check = settled_and_checked("limit-margin-widest-404.toml", tmp_path)
    gap = re.search(r"gap (\d+\.\d+) mm", check.stdout)
    assert gap and float(gap.group(1)) >= 2.9, check.stdout
    assert "they can be parted only by giving up the margin" in check.stdout


def test_check_names_a_few_items_that_no_arrangement_keeps_the_gutter_apart(tmp_path):
    """Each three of the four keep the gutter inside A4's margins, all four in no arrangement:
    check sent the user back to settle, and now says why no settle helps."""
    check = settled_and_checked("arrangement-1011.toml", tmp_path)
    assert "floatpage settle" not in check.stdout, check.stdout
    assert ('items "i0", "i1", "i2", "i3" cannot all stand 3 mm apart in the 200.0 x 287.0 mm '
            "inside the margins") in check.stdout
    assert "the widest gap they can all keep is 2.5 mm" in check.stdout


def test_settle_gives_up_the_margin_before_it_overlaps_around_hard_anchors(tmp_path):
    """Six units of a photos region around two hard-anchored texts: no layout inside the
    margins (check names the rows that rule it out), one with the margin given up.  Settle
    kept 12 mm overlaps, as no order relocation tried set every unit down; now none."""
    check = settled_and_checked("limit-margin-rows-9.toml", tmp_path)
    assert "page p1: 0 overlaps" in check.stdout, check.stdout


def test_check_names_a_column_of_a_free_text_and_a_regions_photos(tmp_path):
    """A free text narrow for the page but too wide to stand beside any photo of the photos
    region, each nearly as wide as it: the three must stand one above another and do not fit.
    check names them (it sent the page back to settle: the text is not wide in its own room,
    the only items the mixed candidate took)."""
    check = settled_and_checked("limit-column-across-rooms-7114.toml", tmp_path)
    assert ('items "p1-text0", "p1-captioned2", "p1-block1" are too wide to stand beside one '
            "another with the 3 mm gutter, each inside its region or the margins, so they must "
            "stand one above another, and no such row of them fits in the 414.0 mm they span"
            ) in check.stdout, check.stdout
