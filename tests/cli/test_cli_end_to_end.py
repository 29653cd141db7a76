"""The headless workflow a Makefile runs: check, settle, render — on real files, with real LaTeX."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pdfplumber
import pytest

from floatpage.model import BlockItem, Page, Project, TextItem, load_project, save_project

ROOT = Path(__file__).resolve().parents[2]


def run(*args: str, cwd: Path = ROOT) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "floatpage.cli.main", *args], capture_output=True, text=True,
                          timeout=300, cwd=cwd, stdin=subprocess.DEVNULL)


@pytest.fixture
def crowded_project(tmp_path) -> Path:
    """Six items piled near one spot: check must see the overlaps, settle must remove them."""
    items = [BlockItem(id=f"block-{i}", x=100.0 + i, y=140.0 + i, w=50.0, h=40.0, color="#3366aa")
             for i in range(5)]
    items.append(TextItem(id="title", x=105.0, y=150.0, w=120.0, h=25.0, text="Spring sale!"))
    path = tmp_path / "crowded.toml"
    save_project(Project(title="Crowded", pages=[Page(id="front", items=items)]), path)
    return path


def test_check_reports_overlaps_and_strict_fails(crowded_project):
    result = run("check", str(crowded_project))
    assert result.returncode == 0, result.stderr
    assert "valid project" in result.stdout
    assert "page front:" in result.stdout and "overlap" in result.stdout
    strict = run("check", "--strict", str(crowded_project))
    assert strict.returncode == 1
    assert "floatpage settle" in strict.stdout


def test_strict_closing_line_names_what_settle_fixes_not_overlaps_there_are_none_of(tmp_path):
    """Two blocks 1 mm apart, no overlap: the closing line said "run `floatpage settle` to fix
    overlaps" under a report of 0 overlaps; the gutter was the problem."""
    path = tmp_path / "close.toml"
    save_project(Project(pages=[Page(id="p", items=[
        BlockItem(id="left", x=80.0, y=100.0, w=40.0, h=40.0),
        BlockItem(id="right", x=121.0, y=100.0, w=40.0, h=40.0)])]), path)
    strict = run("check", "--strict", str(path))
    assert strict.returncode == 1 and "0 overlaps" in strict.stdout, strict.stdout
    closing = strict.stdout.strip().splitlines()[-1]
    assert f"run `floatpage settle {path}`" in closing and "overlap" not in closing, closing
    assert "the gap under the gutter" in closing, closing


def test_settle_removes_overlaps_and_writes_back(crowded_project):
    before = crowded_project.read_text()
    result = run("settle", str(crowded_project))
    assert result.returncode == 0, result.stderr
    assert "page front: settled after" in result.stdout
    assert "steps in" in result.stdout
    assert result.stderr == "", "a pipe gets no progress output"
    assert crowded_project.read_text() != before
    assert run("check", "--strict", str(crowded_project)).returncode == 0
    # Settling again from a settled file is deterministic and leaves it as it is.
    settled = crowded_project.read_text()
    assert run("settle", str(crowded_project)).returncode == 0
    assert crowded_project.read_text() == settled


def test_settle_says_whether_it_wrote_the_file(crowded_project):
    """A Makefile log must not claim a write that did not happen: the second settle of a
    settled file writes nothing (the mtime stays), so it says the file was already settled."""
    first = run("settle", str(crowded_project))
    assert first.returncode == 0, first.stderr
    assert f"wrote positions to {crowded_project}" in first.stdout
    written = crowded_project.stat().st_mtime_ns
    again = run("settle", str(crowded_project))
    assert again.returncode == 0, again.stderr
    assert crowded_project.stat().st_mtime_ns == written
    assert "wrote" not in again.stdout
    assert f"{crowded_project}: already settled, nothing to write" in again.stdout


def test_settle_dry_run_writes_nothing(crowded_project):
    before = crowded_project.read_text()
    result = run("settle", "--dry-run", str(crowded_project))
    assert result.returncode == 0
    assert crowded_project.read_text() == before


def test_settle_dry_run_says_what_settle_would_do(crowded_project):
    """`--dry-run` ("report only") said how many steps it ran and nothing else: the report did
    not tell a file settle would rewrite from a settled one.  It now says which, and the
    verdict matches what settle then does."""
    result = run("settle", "--dry-run", str(crowded_project))
    last = result.stdout.splitlines()[-1]
    assert last.startswith(f"{crowded_project}: settle would move ") and \
        last.endswith("; nothing written (--dry-run)"), result.stdout
    moved = int(last.split("would move ")[1].split(" ")[0])
    assert 1 <= moved <= 6
    assert f"wrote positions to {crowded_project}" in run("settle", str(crowded_project)).stdout
    again = run("settle", "--dry-run", str(crowded_project))
    assert again.stdout.splitlines()[-1] == (
        f"{crowded_project}: already settled; settle would change nothing (--dry-run)")
    assert "already settled" in run("settle", str(crowded_project)).stdout


def test_render_no_settle_warns_of_overlaps_it_prints_and_says_what_to_do(crowded_project,
                                                                          tmp_path):
    """`render --no-settle` on a file whose items overlap made the PDF without a word; it
    still makes it (the user asked for the positions as saved) and names the page, the items
    and the way out.  A settled file gets no such warning."""
    pdf = tmp_path / "out.pdf"
    result = run("render", "--no-settle", str(crowded_project), "-o", str(pdf))
    assert result.returncode == 0, result.stderr
    assert pdf.read_bytes().startswith(b"%PDF")
    assert 'warning: page "front" was printed as saved (--no-settle) with ' in result.stderr
    assert '"block-0" and "block-1"' in result.stderr
    assert f"`floatpage check {crowded_project}` says why and what to do" in result.stderr
    assert run("settle", str(crowded_project)).returncode == 0
    again = run("render", "--no-settle", str(crowded_project), "-o", str(pdf))
    assert again.returncode == 0 and "warning" not in again.stderr, again.stderr


def test_render_writes_pdf_and_tex(crowded_project, tmp_path):
    pdf, tex = tmp_path / "out.pdf", tmp_path / "out.tex"
    result = run("render", str(crowded_project), "-o", str(pdf), "--tex", str(tex))
    assert result.returncode == 0, result.stderr
    with pdfplumber.open(pdf) as reader:
        assert len(reader.pages) == 1
        width, height = float(reader.pages[0].width), float(reader.pages[0].height)
        assert abs(width - 210 / 25.4 * 72) < 0.5 and abs(height - 297 / 25.4 * 72) < 0.5
        assert "Spring sale!" in reader.pages[0].extract_text()
    assert "\\documentclass" in tex.read_text()


def test_render_of_an_invalid_project_is_exit_1_and_keeps_the_old_pdf(crowded_project, tmp_path):
    pdf = tmp_path / "out.pdf"
    pdf.write_bytes(b"%PDF-1.5 the last good one")
    project = load_project(crowded_project)
    crowded_project.write_text(crowded_project.read_text().replace('kind = "block"', 'kind = "blob"', 1))
    result = run("render", str(crowded_project), "-o", str(pdf))
    assert result.returncode == 1
    assert 'unknown item kind "blob"' in result.stderr
    assert pdf.read_bytes() == b"%PDF-1.5 the last good one"
    assert project.pages[0].items  # the original parsed fine


def test_new_blank_then_the_whole_chain(tmp_path):
    path = tmp_path / "blank.toml"
    assert run("new", "blank", str(path)).returncode == 0
    assert load_project(path).pages
    again = run("new", "blank", str(path))
    assert again.returncode == 1, "new refuses to overwrite"
    assert run("check", "--strict", str(path)).returncode == 0


def test_check_says_why_no_settle_can_fix_a_page(tmp_path):
    """Two hard anchors pinned onto each other and a pair too large to part: `check` names the
    items, the numbers and what to change, instead of sending the user back to `settle`."""
    from floatpage.model.document import PointAnchor

    items = [BlockItem(id="logo", x=60.0, y=60.0, w=40.0, h=30.0,
                       anchor=PointAnchor(x=60.0, y=60.0, hard=True)),
             BlockItem(id="badge", x=80.0, y=70.0, w=30.0, h=30.0,
                       anchor=PointAnchor(x=80.0, y=70.0, hard=True)),
             BlockItem(id="tall", x=170.0, y=169.0, w=70.0, h=256.0),
             BlockItem(id="wide", x=105.0, y=200.0, w=199.5, h=75.0)]
    path = tmp_path / "stuck.toml"
    save_project(Project(title="Stuck", pages=[Page(id="front", items=items)]), path)
    assert run("settle", str(path)).returncode == 0
    result = run("check", str(path))
    assert result.returncode == 0, result.stderr
    out = result.stdout
    assert 'items "logo" and "badge" cannot move' in out and "overlap by 15.0 mm" in out
    assert 'items "tall" and "wide" cannot both fit' in out
    assert "they overlap wherever they go on this page" in out
    assert "overlapping:" not in out, "explained overlaps are not sent back to settle"


def test_check_gives_a_pinned_clash_as_the_reason_for_that_pair_only(tmp_path):
    """Two hard anchors on each other explain their own overlap, not a free item's lying on
    one of them: `check` names the clash and sends the free pair back to `settle` (it said
    nothing of the free item, on a random page whose settle left one 28.6 mm into a hard
    anchor, seed 11030)."""
    from floatpage.model.document import PointAnchor

    items = [BlockItem(id="logo", x=60.0, y=60.0, w=40.0, h=30.0,
                       anchor=PointAnchor(x=60.0, y=60.0, hard=True)),
             BlockItem(id="badge", x=80.0, y=70.0, w=30.0, h=30.0,
                       anchor=PointAnchor(x=80.0, y=70.0, hard=True)),
             BlockItem(id="note", x=50.0, y=55.0, w=20.0, h=20.0)]
    path = tmp_path / "clash.toml"
    save_project(Project(title="Clash", pages=[Page(id="front", items=items)]), path)
    out = run("check", str(path)).stdout
    assert 'items "logo" and "badge" cannot move' in out
    assert 'overlapping: "logo" and "note"; run `floatpage settle`' in out
    assert run("settle", str(path)).returncode == 0
    out = run("check", str(path)).stdout
    assert 'items "logo" and "badge" cannot move' in out
    assert "overlapping:" not in out and "in margin" not in out and "gutter fits" not in out


def test_check_names_an_item_with_no_room_among_hard_anchors(tmp_path):
    """Two hard-anchored pictures on a Letter page leave no place for a 108 x 73 mm block (a
    random page's, seed 1005): `check` names it and the anchored items, and says that no
    settle can help."""
    from floatpage.model.document import PointAnchor

    items = [BlockItem(id="block", x=180.0, y=143.0, w=107.82, h=73.43),
             BlockItem(id="photo", x=98.24, y=186.65, w=66.07, h=66.65,
                       anchor=PointAnchor(x=98.24, y=186.65, hard=True)),
             BlockItem(id="map", x=98.67, y=103.52, w=120.67, h=66.15,
                       anchor=PointAnchor(x=98.67, y=103.52, hard=True))]
    path = tmp_path / "letter.toml"
    save_project(Project(title="Letter", pages=[Page(id="front", size="Letter", items=items)]),
                 path)
    assert run("settle", str(path)).returncode == 0
    out = run("check", str(path)).stdout
    assert ('item "block" has no place inside the margins that keeps the 3 mm gutter from the '
            'items that cannot move ("photo", "map"); it overlaps them wherever it goes') in out
    assert "run `floatpage settle`" not in out and "overlapping:" not in out


def test_check_names_items_that_must_stack_taller_than_the_page(tmp_path):
    """Three pictures on an A6 card, no two narrow enough to stand side by side with the
    gutter, and one above another 3.3 mm too tall: `check` names them and the gap that is
    left, instead of sending the user back to `settle` (a random page's, seed 5017)."""
    items = [BlockItem(id=name, x=52.0, y=74.0, w=w, h=h) for name, (w, h) in
             {"sea": (55.08, 44.76), "boat": (36.45, 25.05), "dunes": (56.82, 52.7),
              "gulls": (55.93, 42.82)}.items()]
    path = tmp_path / "card.toml"
    save_project(Project(title="Card", pages=[Page(id="front", size="custom", width_mm=105.0,
                                                         height_mm=148.0, items=items)]), path)
    assert run("settle", str(path)).returncode == 0
    out = run("check", str(path)).stdout
    assert ('items "dunes", "sea", "gulls" are each too wide to stand beside another of them'
            in out)
    assert "they must stand one above another, and that is 146.3 mm tall" in out
    assert "the widest gap they can keep is at most 1.4 mm" in out
    assert "run `floatpage settle`" not in out


def test_a_picture_too_small_for_its_box_is_named_with_its_print_resolution(tmp_path):
    """A 40-pixel photo printed 60 mm wide is 17 dpi, a mosaic of squares on paper; check and
    render said nothing (an album from a phone's thumbnails printed blocky). Both now name the
    item, its pixels and its dpi, as a note: check --strict still passes on it."""
    from PIL import Image

    from floatpage.model import PictureItem

    (tmp_path / "pictures").mkdir()
    Image.new("RGB", (40, 40), (200, 60, 60)).save(tmp_path / "pictures" / "thumb.png")
    Image.new("RGB", (900, 900), (60, 60, 200)).save(tmp_path / "pictures" / "sharp.png")
    page = Page(id="front", items=[
        PictureItem(id="thumb", x=60.0, y=60.0, w=60.0, h=60.0, path="pictures/thumb.png"),
        PictureItem(id="sharp", x=150.0, y=200.0, w=60.0, h=60.0, path="pictures/sharp.png")])
    path = tmp_path / "album.toml"
    save_project(Project(title="Album", pages=[page]), path)
    checked = run("check", "--strict", str(path))
    assert checked.returncode == 0, checked.stdout + checked.stderr
    notes = [line for line in checked.stdout.splitlines() if "dpi" in line]
    assert len(notes) == 1, checked.stdout
    assert notes[0].startswith("note:") and '"thumb"' in notes[0] and "40×40 pixels" in notes[0]
    assert "17 dpi" in notes[0]
    rendered = run("render", str(path), "-o", str(tmp_path / "album.pdf"))
    assert rendered.returncode == 0, rendered.stderr
    assert '"thumb"' in rendered.stderr and "17 dpi" in rendered.stderr
    assert '"sharp"' not in rendered.stderr
