"""What user-walk-10 found in the command line, each run as a user runs it: the real
`floatpage` process on a real project file."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from floatpage.model import load_project, save_project


def floatpage(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "floatpage.cli.main", *args],
                          capture_output=True, text=True, timeout=300, cwd=cwd,
                          stdin=subprocess.DEVNULL)


def card_typed_down_to_a6(folder: Path, pages: int) -> Path:
    """A 5x8in card from `floatpage new` whose first ``pages`` pages were typed down to A6
    (too small for its items), then settled: items stay off those pages."""
    folder.mkdir(parents=True, exist_ok=True)
    assert floatpage("new", "card", "card.toml", cwd=folder).returncode == 0
    path = folder / "card.toml"
    path.write_text(path.read_text().replace('size = "5x8in"', 'size = "A6"', pages))
    settled = floatpage("settle", "card.toml", cwd=folder)
    assert settled.returncode == 0, settled.stderr
    assert "another settle changes nothing" in settled.stdout, settled.stdout
    return path


def test_check_sends_no_one_to_settle_on_a_page_a_settle_leaves_as_it_is(tmp_path):
    """A card's size typed down to A6 and settled: settle said "still 3 items off the page:
    another settle changes nothing", and `check --strict` then ended "run `floatpage settle
    card.toml` to fix the items off the page" (and so did the page's own line): a loop.  It
    now says what helps (room: smaller items, a larger page, items on another page), with
    the same count and exit code."""
    path = card_typed_down_to_a6(tmp_path / "card", pages=2)
    checked = floatpage("check", "--strict", "card.toml", cwd=path.parent)
    assert checked.returncode == 1, checked.stdout + checked.stderr
    assert "floatpage settle" not in checked.stdout, checked.stdout
    assert "reach past the page's edge" in checked.stdout
    assert "a settle leaves them there" in checked.stdout
    closing = checked.stdout.strip().splitlines()[-1]
    assert closing.startswith("card.toml: 7 layout problem(s); no settle fixes them"), closing
    assert "choose a larger page size (S in the editor)" in closing
    assert "make items smaller" in closing and "another page" in closing
    plain = floatpage("check", "card.toml", cwd=path.parent)
    assert plain.returncode == 0 and "floatpage settle" not in plain.stdout


def test_check_sends_to_settle_only_the_page_a_settle_mends(tmp_path):
    """The front typed down to A6 and settled (stuck); then the inside page's items were
    piled on one spot (as a hand edit does), which a settle parts: the closing line sends the
    user to settle for the overlaps, and names the front as the page no settle fixes."""
    path = card_typed_down_to_a6(tmp_path / "card", pages=1)
    project = load_project(path)
    inside = project.pages[1]
    free = [item for item in inside.items if not item.decorative and item.anchor is None]
    assert len(free) >= 2
    for item in free:
        item.x, item.y = free[0].x, free[0].y
    save_project(project, path)
    checked = floatpage("check", "--strict", "card.toml", cwd=path.parent)
    assert checked.returncode == 1, checked.stdout + checked.stderr
    closing = checked.stdout.strip().splitlines()[-1]
    assert "run `floatpage settle card.toml` to fix the overlaps" in closing, closing
    assert "no settle fixes those on page front: see the reasons above" in closing, closing
    front = checked.stdout.split("page inside:")[0]
    assert "floatpage settle" not in front, front


def test_new_album_says_a_pdf_among_the_photos_was_left_out(tmp_path):
    """A logo.pdf in the photos folder: `new album --photos` left it out without a word (a
    phone's .HEIC got one), and the user looked for it on the page."""
    from PIL import Image

    photos = tmp_path / "photos"
    photos.mkdir()
    Image.new("RGB", (60, 40), (200, 40, 40)).save(photos / "sun.png")
    Image.new("RGB", (80, 20), (255, 255, 255)).save(photos / "logo.pdf")
    made = floatpage("new", "album", "album.toml", "--photos", "photos", "-j", "1",
                     cwd=tmp_path)
    assert made.returncode == 0, made.stderr
    assert ("note: photos/logo.pdf was left out: a PDF is no photo for the starter to lay "
            "out; a logo or a drawing goes in with `p` in the editor") in made.stderr, \
        made.stderr
    assert "logo.pdf" not in (tmp_path / "album.toml").read_text()


def test_render_warns_of_items_a_settle_leaves_past_the_edge(tmp_path):
    """The card typed down to A6: `render` settled it and printed the front's greeting past
    the page and the inside's words cut at its edge (read back from the PDF), and said only
    "wrote card.pdf".  It warns now, per page, naming the items; a card that fits gets no
    warning."""
    import pdfplumber

    path = card_typed_down_to_a6(tmp_path / "card", pages=2)
    rendered = floatpage("render", "card.toml", "-o", "card.pdf", cwd=path.parent)
    assert rendered.returncode == 0, rendered.stderr
    with pdfplumber.open(path.parent / "card.pdf") as pdf:
        inside = pdf.pages[1]
        cut = [char for char in inside.chars if char["x1"] > inside.width]
    assert cut, "the inside's words reach past the page's edge in the PDF"
    warnings = [line for line in rendered.stderr.splitlines() if line.startswith("warning:")]
    assert len(warnings) == 2, rendered.stderr
    assert warnings[0].startswith('warning: page "front" was printed with 3 item(s) past its '
                                  'edge ("front-band", "front-picture", "front-greeting"), '
                                  "which a settle leaves there; `floatpage check card.toml`")
    assert "choose a larger page size" in warnings[1]
    fits = tmp_path / "fits"
    fits.mkdir()
    assert floatpage("new", "card", "card.toml", cwd=fits).returncode == 0
    clean = floatpage("render", "card.toml", "-o", "card.pdf", cwd=fits)
    assert clean.returncode == 0 and "warning" not in clean.stderr, clean.stderr
