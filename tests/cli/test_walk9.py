"""What user-walk-9 found in the command line, each run as a user runs it: the real
`floatpage` process on a real project file (and real LuaLaTeX for `render`)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path


def floatpage(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "floatpage.cli.main", *args],
                          capture_output=True, text=True, timeout=300, cwd=cwd,
                          stdin=subprocess.DEVNULL)


def card_with_an_empty_page(folder: Path, background: str = "") -> Path:
    """A greeting card from `floatpage new`, with a third page holding no item (an `N` too
    many in the editor)."""
    folder.mkdir(parents=True, exist_ok=True)
    assert floatpage("new", "card", "card.toml", cwd=folder).returncode == 0
    path = folder / "card.toml"
    with path.open("a") as file:
        file.write(f'\n[[pages]]\nid = "spare"\nsize = "5x8in"\n{background}')
    return path


def test_check_and_render_say_a_page_has_no_items_as_a_note_that_strict_lets_pass(tmp_path):
    """An empty page printed as a blank sheet, and `check` said of it only "0 overlaps ·
    even 1.00 · balance 1.00" and "0.00 edge lines per item". Now `check` (on stdout, with its
    other notes) and `render` (on stderr, with its own) name the page; a note, so `--strict`
    still passes: a blank page can be meant."""
    path = card_with_an_empty_page(tmp_path / "card")
    checked = floatpage("check", "card.toml", "--strict", cwd=path.parent)
    assert checked.returncode == 0, checked.stdout + checked.stderr
    assert "page spare: no items\n" in checked.stdout
    assert ('note: page "spare" has no items: it prints as a blank page; put something on '
            "it, or remove the page (D on it in the editor)") in checked.stdout
    assert "even 1.00 · balance 1.00" not in checked.stdout
    assert checked.stdout.count("no items") == 2  # the card's own pages are not named
    rendered = floatpage("render", "card.toml", "-o", "card.pdf", cwd=path.parent)
    assert rendered.returncode == 0, rendered.stderr
    assert 'note: page "spare" has no items' in rendered.stderr
    assert "3 page(s)" in rendered.stdout


def test_an_empty_page_with_a_background_is_said_to_print_only_its_background(tmp_path):
    path = card_with_an_empty_page(tmp_path / "card", 'background = {color = "#203040"}\n')
    checked = floatpage("check", "card.toml", cwd=path.parent)
    assert 'note: page "spare" has no items: it prints as only its background' \
        in checked.stdout


def test_a_postcard_in_a6_and_a_flyer_in_dl_are_known_sizes(tmp_path):
    """A6, the postcard and folded card size, was refused with 'did you mean "A5"?' (a page
    twice as large), and DL, the long flyer that fits an envelope, was unknown: both needed
    `custom` with millimetres typed by hand. Both are named sizes now, and print so."""
    import pikepdf

    path = card_with_an_empty_page(tmp_path / "card")
    text = path.read_text().replace('size = "5x8in"', 'size = "A6"')
    path.write_text(text.replace('id = "spare"\nsize = "A6"', 'id = "spare"\nsize = "dl"'))
    settled = floatpage("settle", "card.toml", cwd=path.parent)
    assert settled.returncode == 0, settled.stderr
    rendered = floatpage("render", "card.toml", "-o", "card.pdf", cwd=path.parent)
    assert rendered.returncode == 0, rendered.stderr
    with pikepdf.open(path.parent / "card.pdf") as pdf:
        sizes = [tuple(round(float(v) * 25.4 / 72) for v in page.mediabox[2:])
                 for page in pdf.pages]
    assert sizes == [(105, 148), (105, 148), (99, 210)]


def test_settle_says_what_it_could_not_mend_instead_of_only_settled(tmp_path):
    """A 5x8in card's size typed down to A6 by hand: settle said "settled" and then
    "already settled, nothing to write", while `check` said "run `floatpage settle` to fix
    the items off the page": a loop. Settle now names what is left on each page and sends
    the user to `check`, which says why; a page with nothing left gets no such line."""
    folder = tmp_path / "card"
    folder.mkdir()
    assert floatpage("new", "card", "card.toml", cwd=folder).returncode == 0
    path = folder / "card.toml"
    assert "still" not in floatpage("settle", "card.toml", cwd=folder).stdout
    path.write_text(path.read_text().replace('size = "5x8in"', 'size = "A6"'))
    for _ in range(2):
        settled = floatpage("settle", "card.toml", cwd=folder)
        assert settled.returncode == 0, settled.stderr
        lines = settled.stdout.splitlines()
        front = lines.index(next(line for line in lines if line.startswith("page front:")))
        assert lines[front + 1].startswith("  still ")
        assert "off the page: another settle changes nothing; `floatpage check card.toml` " \
               "says why and what to do" in lines[front + 1]
    assert "already settled, nothing to write" in settled.stdout


def test_the_commands_suggested_for_a_name_with_spaces_run_as_copied(tmp_path):
    """`floatpage new card "Geburtstag Oma.toml"` ended "next: floatpage edit Geburtstag
    Oma.toml": copied into a shell, that names two files. The path is quoted as typed."""
    made = floatpage("new", "card", "Geburtstag Oma.toml", cwd=tmp_path)
    assert made.returncode == 0, made.stderr
    suggested = made.stdout.split("next: ")[1].strip()
    assert suggested == "floatpage edit 'Geburtstag Oma.toml'"
    checked = subprocess.run(suggested.replace("floatpage edit", f"{sys.executable} -m "
                                               "floatpage.cli.main check", 1),
                             shell=True, cwd=tmp_path, capture_output=True, text=True,
                             timeout=120)
    assert checked.returncode == 0, checked.stderr
