"""Hostile and careless input found by a fresh attacker's eye (fifteenth session).

Each test is a case that lost a file or ended in "internal error" (exit 70) before its fix:
now it gets exit 1 and a message that names the file and what to do, and nothing is written.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from floatpage.model import BlockItem, Page, Project, TextItem, save_project

ROOT = Path(__file__).resolve().parents[2]


def run(*args: str, cwd: Path = ROOT, timeout: float = 300) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "floatpage.cli.main", *args], capture_output=True,
                          text=True, timeout=timeout, cwd=cwd, stdin=subprocess.DEVNULL)


def card(folder: Path, name: str = "card.toml") -> Path:
    path = folder / name
    save_project(Project(title="Card", pages=[Page(id="front", size="A5", width_mm=148.0,
                                                   height_mm=210.0, items=[
        BlockItem(id="block", x=30.0, y=40.0, w=30.0, h=30.0, color="#3366aa"),
        TextItem(id="title", x=60.0, y=100.0, w=60.0, h=20.0, text="Hello")])]), path)
    return path


def listing(folder: Path) -> dict[str, bytes | None]:
    return {str(path.relative_to(folder)): (path.read_bytes() if path.is_file() else None)
            for path in sorted(folder.rglob("*"))}


@pytest.mark.parametrize("option", ["-o", "--tex", "--fragment"])
@pytest.mark.parametrize("name", [".", "..", "out/", "./"])
def test_an_output_that_names_a_folder_is_refused_with_the_file_to_name(tmp_path, option, name):
    """`-o .` was an internal error (Path('.') has no name), and `-o out/` wrote a PDF
    called `out` where the user meant a folder."""
    folder = tmp_path / "work"
    folder.mkdir()
    card(folder)
    before = listing(tmp_path)
    args = ["render", "card.toml", option, name, *(["-o", "card.pdf"] if option != "-o" else [])]
    result = run(*args, cwd=folder)
    assert result.returncode == 1, result.stderr
    assert "internal error" not in result.stderr
    suffix = ".pdf" if option == "-o" else ".tex"
    assert result.stderr.startswith(f"floatpage: {name}: names a folder, and {option} writes one "
                                    f"file; name the file, e.g. {os.path.join(name, 'card' + suffix)}")
    assert listing(tmp_path) == before


def test_render_will_not_write_its_pdf_over_another_project(tmp_path):
    """`render card.toml -o other.toml` replaced the other project with the PDF."""
    card(tmp_path)
    other = card(tmp_path, "other.toml")
    before = other.read_bytes()
    result = run("render", str(tmp_path / "card.toml"), "-o", str(other))
    assert result.returncode == 1, result.stderr
    assert result.stderr.startswith(f"floatpage: {other}: will not write the PDF there, because "
                                    "it is a project file, which the PDF would replace; name the "
                                    f"output .pdf (e.g. -o {other.with_suffix('.pdf')})")
    assert other.read_bytes() == before
    fresh = run("render", str(tmp_path / "card.toml"), "-o", str(tmp_path / "new.TOML"))
    assert fresh.returncode == 1 and "a .toml name is a project's" in fresh.stderr
    assert not (tmp_path / "new.TOML").exists()


@pytest.fixture
def full_disk(tmp_path):
    """A real full disk: a 256 KiB tmpfs (root only) filled to the last byte by `filler`."""
    if os.geteuid() != 0:
        pytest.skip("mounting a small tmpfs needs root")
    mount = tmp_path / "full"
    mount.mkdir()
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=256k", "tmpfs", str(mount)],
                      capture_output=True).returncode:
        pytest.skip("this machine will not mount a tmpfs")
    try:
        yield mount
    finally:
        subprocess.run(["umount", "-l", str(mount)], check=True)


def fill(folder: Path) -> None:
    with open(folder / "filler", "wb", buffering=0) as handle:
        try:
            while True:
                handle.write(b"x" * 4096)
        except OSError:
            pass


def test_settle_on_a_full_disk_says_so_and_keeps_the_project(full_disk):
    """Writing the holder's PID into the lock file hit the full disk first: internal error."""
    path = card(full_disk)
    path.write_text(path.read_text().replace("x = 30.0", "x = 90.0"))  # settle must write
    before = path.read_bytes()
    fill(full_disk)
    result = run("settle", str(path))
    assert result.returncode == 1, result.stderr
    assert "internal error" not in result.stderr
    assert result.stderr.startswith(f"floatpage: {path}: could not save: No space left on device "
                                    "(the disk is full; free some space and save again: the "
                                    "file is unchanged)")
    assert path.read_bytes() == before


def test_merge_onto_a_full_disk_names_the_file_it_could_not_write(full_disk):
    """The PDF's clear message was lost: report.csv's own failure to close on the full disk
    replaced it with an internal error."""
    sample = ROOT / "sample_projects" / "merge-offers"
    out = full_disk / "out"
    out.mkdir()
    fill(full_disk)
    result = run("merge", str(sample / "offer.toml"), str(sample / "customers.csv"), "-o",
                 str(out), "-q", "--workers", "1", timeout=600)
    assert result.returncode == 1, result.stderr
    assert "internal error" not in result.stderr
    assert "could not write it (No space left on device); check that the output folder is " \
           "writable and the disk not full" in result.stderr
    assert not list(out.glob("*.pdf"))


def test_a_background_filled_from_a_data_column_says_it_is_a_merge_template(tmp_path):
    """A picture item with `{photo}` said so; a background with one said "cannot be read: No
    such file or directory" of the path with its braces."""
    path = card(tmp_path)
    path.write_text(path.read_text().replace('size = "A5"', 'size = "A5"\n'
                                             'background = {picture = "pictures/{photo}"}', 1))
    result = run("render", str(path), "-o", str(tmp_path / "card.pdf"))
    assert result.returncode == 1, result.stderr
    assert result.stderr.startswith('floatpage: the background of page "front": picture '
                                    '"pictures/{photo}" is filled from a data column; this is a '
                                    "merge template: make its documents with `floatpage merge")
    assert not (tmp_path / "card.pdf").exists()


def test_a_picture_whose_file_name_has_braces_is_a_picture_not_a_merge_field(tmp_path):
    """`photo {1}.png` (a real file) passed check, and render refused it as a merge template."""
    from PIL import Image

    Image.new("RGB", (300, 200), "red").save(tmp_path / "photo {1}.png")
    Image.new("RGB", (300, 200), "blue").save(tmp_path / "back {x} % #.png")
    path = card(tmp_path)
    path.write_text(path.read_text().replace('size = "A5"', 'size = "A5"\n'
                                             'background = {picture = "back {x} % #.png"}', 1)
                    + '\n[[pages.items]]\nid = "photo"\nkind = "picture"\nx = 100.0\ny = 170.0\n'
                      'w = 30.0\nh = 20.0\npath = "photo {1}.png"\n')
    assert run("check", str(path)).returncode == 0
    result = run("render", str(path), "--no-settle", "-o", str(tmp_path / "card.pdf"))
    assert result.returncode == 0, result.stderr
    listed = subprocess.run(["pdfimages", "-list", str(tmp_path / "card.pdf")],
                            capture_output=True, text=True, check=True).stdout
    assert len([line for line in listed.splitlines() if " image " in line]) == 2, listed


@pytest.mark.parametrize("command", ["check", "render", "settle"])
def test_a_deleted_picture_whose_name_has_braces_is_named_as_missing(tmp_path, command):
    """`photo {1}.png`, deleted: `check` passed it as a merge field and `render` called the
    project a merge template; each now names the missing file, and the file is left alone."""
    path = card(tmp_path)
    path.write_text(path.read_text() + '\n[[pages.items]]\nid = "photo"\nkind = "picture"\n'
                    'x = 100.0\ny = 170.0\nw = 30.0\nh = 20.0\npath = "pictures/photo {1}.png"\n')
    before = listing(tmp_path)
    result = run(command, str(path), *(["-o", str(tmp_path / "card.pdf")] if command == "render"
                                       else []))
    assert result.returncode == 1, result.stdout + result.stderr
    assert 'item "photo": picture file "pictures/photo {1}.png" not found' in result.stderr, \
        result.stderr
    assert "fix the path or copy the file there" in result.stderr
    assert "internal error" not in result.stderr
    after = listing(tmp_path)
    after.pop(".card.toml.lock", None)  # settle's lock, kept by design (model.project_lock)
    assert after == before


def test_a_template_that_names_a_column_in_a_picture_name_still_checks(tmp_path):
    """The other side of the rule: where a text names a data column, `product-{id}.png` is
    that column's picture, filled by `floatpage merge`, and `check` passes the template."""
    path = card(tmp_path)
    path.write_text(path.read_text().replace('text = "Hello"', 'text = "Hello {name}"')
                    + '\n[[pages.items]]\nid = "photo"\nkind = "picture"\nx = 100.0\n'
                      'y = 170.0\nw = 30.0\nh = 20.0\npath = "pictures/product-{id}.png"\n')
    result = run("check", str(path))
    assert result.returncode == 0, result.stdout + result.stderr


CORPUS_PICTURES = ROOT / "tests" / "fuzz" / "corpus" / "pictures"


def picture_card(folder: Path, picture: str) -> Path:
    import shutil

    shutil.copy(CORPUS_PICTURES / picture, folder / picture)
    path = card(folder)
    path.write_text(path.read_text() + '\n[[pages.items]]\nid = "photo"\nkind = "picture"\n'
                    f'x = 100.0\ny = 170.0\nw = 30.0\nh = 20.0\npath = "{picture}"\n')
    return path


@pytest.mark.parametrize("picture,size", [("pdf-page-10-metres.pdf", "10,000 x 35 mm"),
                                          ("pdf-crop-speck.pdf", "0.0035 x 0.0035 mm")])
def test_a_pdf_page_tex_cannot_place_is_refused_by_check_not_by_lualatex(tmp_path, picture,
                                                                        size):
    """Check passed them; LuaLaTeX stopped on "Dimension too large" or "Arithmetic overflow"."""
    path = picture_card(tmp_path, picture)
    for command in ("check", "render"):
        result = run(command, str(path))
        assert result.returncode == 1, result.stderr
        assert f'item "photo": picture file "{picture}" has a first page of {size}, a size TeX ' \
               "cannot place (0.35 mm to 5 m a side) (export it again at the size it should " \
               "print, or use PNG or JPEG)" in result.stderr
        assert "LaTeX" not in result.stderr


def test_a_damaged_pdf_is_printed_mended_and_check_says_so(tmp_path):
    """A PDF with a broken cross-reference table: qpdf opened it, so check passed it, and
    LuaLaTeX stopped with "reading image failed"."""
    path = picture_card(tmp_path, "pdf-broken-xref.pdf")
    checked = run("check", "--strict", str(path))
    assert checked.returncode == 1
    warning = ('item "photo" on page "front": picture "pdf-broken-xref.pdf": the PDF is damaged '
               "(xref not found); a mended copy is printed: look at it, or export the PDF again")
    assert f"warning: {warning}" in checked.stdout
    result = run("render", str(path), "--no-settle", "-o", str(tmp_path / "card.pdf"))
    assert result.returncode == 0, result.stderr
    assert warning in result.stderr
    listed = subprocess.run(["pdfimages", "-list", str(tmp_path / "card.pdf")],
                            capture_output=True, text=True, check=True).stdout
    assert len([line for line in listed.splitlines() if " image " in line]) == 1, listed


@pytest.mark.parametrize("name", [".", "..", "prints/", "/"])
def test_the_editors_export_name_that_is_a_folder_says_so(tmp_path, name):
    """The export dialog's check said "PosixPath('.') has an empty name" for `.`, and turned
    `prints/` into prints.pdf."""
    from floatpage.tui.item_forms import export_parser

    parse = export_parser(tmp_path, lambda path: None)
    with pytest.raises(ValueError) as refused:
        parse({"name": name})
    assert str(refused.value) == (f"{name} names a folder; type a file name, e.g. "
                                  f"{os.path.join(name, 'card-print.pdf')}")
    assert parse({"name": "prints/card"}) == tmp_path / "prints" / "card.pdf"


def test_a_project_on_a_read_only_mount_is_named_as_such(full_disk):
    """A read-only mount (or card) was told "you may not write it (it belongs to alice)",
    alice being the user herself."""
    path = card(full_disk)
    path.write_text(path.read_text().replace("x = 30.0", "x = 90.0"))
    before = path.read_bytes()
    subprocess.run(["mount", "-o", "remount,ro", str(full_disk)], check=True)
    result = run("settle", str(path))
    assert result.returncode == 1, result.stderr
    assert result.stderr.startswith(f"floatpage: {path}: not saved, because its folder is on a "
                                    "read-only file system (a read-only mount, a CD or a locked "
                                    "card); copy the project to a writable folder")
    assert path.read_bytes() == before


def test_an_immutable_project_and_output_are_named_as_such(tmp_path):
    """`chattr +i`: its owner was told that it belongs to them, so they may not write it."""
    path = card(tmp_path)
    path.write_text(path.read_text().replace("x = 30.0", "x = 90.0"))
    out = tmp_path / "card.pdf"
    out.write_bytes(b"%PDF-old")
    flagged = [subprocess.run(["chattr", "+i", str(name)], capture_output=True).returncode == 0
               for name in (path, out)]
    if not all(flagged):
        pytest.skip("chattr +i needs root and a file system that keeps the flag")
    try:
        before = path.read_bytes()
        settled = run("settle", str(path))
        rendered = run("render", str(path), "-o", str(out))
    finally:
        subprocess.run(["chattr", "-i", str(path), str(out)], check=True)
    flag = ("the system keeps it from being written, although its permissions allow it "
            "(`lsattr` shows an immutable flag: `chattr -i` clears it)")
    assert settled.returncode == 1 and f"not saved, because {flag}" in settled.stderr
    assert rendered.returncode == 1 and f"will not write there, because {flag}" in rendered.stderr
    assert path.read_bytes() == before and out.read_bytes() == b"%PDF-old"


@pytest.mark.parametrize("command", ["settle", "edit"])
def test_a_project_that_is_not_there_leaves_no_lock_file_behind(tmp_path, command):
    """`settle nope.toml` left `.nope.toml.lock`, and `settle /dev/zero` (as root) made
    /dev/.zero.lock: the lock was taken before the load said there was nothing to lock."""
    os.mkfifo(tmp_path / "pipe.toml")
    (tmp_path / "link.toml").symlink_to("gone.toml")
    for name in ("nope.toml", "pipe.toml", "link.toml"):
        result = run(command, str(tmp_path / name))
        assert result.returncode == 1, result.stderr
    assert sorted(path.name for path in tmp_path.iterdir()) == ["link.toml", "pipe.toml"]


def test_a_project_link_that_leads_nowhere_says_where_it_leads(tmp_path):
    """Both were "no such file", of a name `ls` shows."""
    (tmp_path / "card.toml").symlink_to("moved-away.toml")
    (tmp_path / "a.toml").symlink_to("b.toml")
    (tmp_path / "b.toml").symlink_to("a.toml")
    dangling = run("check", str(tmp_path / "card.toml"))
    assert dangling.returncode == 1
    assert dangling.stderr.startswith(f"floatpage: {tmp_path / 'card.toml'}: is a symbolic link "
                                      "to moved-away.toml, which does not exist (point it at "
                                      "the project's .toml file, or restore that file)")
    looping = run("render", str(tmp_path / "a.toml"))
    assert looping.returncode == 1
    assert "is a symbolic link that leads back to itself" in looping.stderr


def test_new_album_takes_a_photo_whose_name_is_not_utf8(tmp_path):
    """`caf\\xe9.png` (Latin-1, from an old camera card): the name reached the project file as
    a surrogate escape, and saving it ended in an internal error (UnicodeEncodeError)."""
    from PIL import Image

    photos = tmp_path / "photos"
    photos.mkdir()
    Image.new("RGB", (400, 300), "red").save(os.fsdecode(os.fsencode(photos) + b"/caf\xe9.png"))
    Image.new("RGB", (400, 300), "blue").save(photos / "ok.png")
    result = run("new", "album", str(tmp_path / "album.toml"), "--photos", str(photos))
    assert result.returncode == 0, result.stderr
    text = (tmp_path / "album.toml").read_text(encoding="utf-8")
    assert 'path = "pictures/caf_.png"' in text and 'path = "pictures/ok.png"' in text
    assert run("check", str(tmp_path / "album.toml")).returncode == 0


def test_a_png_cut_short_that_must_be_converted_names_its_item(tmp_path):
    """A PNG whose header claims 9000 x 9000 pixels and whose data stops short passes the
    header check; converting it for print failed with 'picture "/abs/path" could not be
    converted: image file is truncated', naming no item and no fix."""
    import struct
    import zlib

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    (tmp_path / "short.png").write_bytes(
        b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 9000, 9000, 16, 6, 0, 0, 0))
        + chunk(b"IDAT", zlib.compress(b"\x00" * 100_000)) + chunk(b"IEND", b""))
    path = card(tmp_path)
    path.write_text(path.read_text() + '\n[[pages.items]]\nid = "photo"\nkind = "picture"\n'
                    'x = 100.0\ny = 170.0\nw = 30.0\nh = 20.0\npath = "short.png"\n')
    result = run("render", str(path), "--no-settle", "-o", str(tmp_path / "card.pdf"))
    assert result.returncode == 1, result.stderr
    assert result.stderr.startswith(
        'floatpage: item "photo" on page "front" (picture file "short.png"): the picture could '
        "not be converted (image file is truncated")
    assert "export it again, or use another picture" in result.stderr
    assert not (tmp_path / "card.pdf").exists()


def test_check_warns_of_a_text_picture_or_calendar_under_a_millimetre(tmp_path):
    """A 0.4 mm picture and a 0.5 mm calendar passed `check` without a word; a 0.3 mm block,
    a rule, is no problem."""
    from PIL import Image

    (tmp_path / "pictures").mkdir()
    Image.new("RGB", (300, 200), "red").save(tmp_path / "pictures" / "red.png")
    path = card(tmp_path)
    path.write_text(path.read_text() + "".join(
        f'\n[[pages.items]]\nid = "{name}"\nkind = "{kind}"\nx = {x}\ny = 180.0\nw = {w}\n'
        f"h = {h}\n{extra}\n"
        for name, kind, x, w, h, extra in [
            ("speck", "picture", 20.0, 0.4, 30.0, 'path = "pictures/red.png"'),
            ("month", "calendar", 60.0, 0.5, 0.5, "year = 2027\nmonth = 3"),
            ("rule", "block", 100.0, 40.0, 0.3, 'color = "#000000"')]))
    result = run("check", "--strict", str(path))
    assert result.returncode == 1, result.stdout + result.stderr
    assert 'warning: item "speck" on page "front": its box is 0.4 × 30 mm, under 1 mm wide, ' \
           "too small for a picture to be seen or printed" in result.stdout, result.stdout
    assert 'warning: item "month" on page "front": its box is 0.5 × 0.5 mm' in result.stdout
    assert not [line for line in result.stdout.splitlines()
                if line.startswith('warning: item "rule"')], result.stdout


@pytest.mark.parametrize("cut", ["half", "end chunk"])
def test_a_png_cut_short_prints_what_it_has_with_a_warning_naming_it(tmp_path, cut):
    """LuaTeX stopped at the page's end with "(writepng): reading chunk type failed", tied to
    no item ("line 37 of the .tex"), where a JPEG cut short prints with a warning."""
    import io

    import numpy as np
    from PIL import Image

    pixels = np.random.default_rng(5).integers(0, 256, (120, 160, 3), dtype=np.uint8)
    buffer = io.BytesIO()
    Image.fromarray(pixels).save(buffer, "PNG")
    data = buffer.getvalue()
    (tmp_path / "cut.png").write_bytes(data[:len(data) // 2] if cut == "half" else data[:-12])
    path = card(tmp_path)
    path.write_text(path.read_text() + '\n[[pages.items]]\nid = "photo"\nkind = "picture"\n'
                    'x = 100.0\ny = 170.0\nw = 30.0\nh = 20.0\npath = "cut.png"\n')
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "render", str(path),
                             "--no-settle", "-o", str(tmp_path / "card.pdf")],
                            capture_output=True, text=True, timeout=300, stdin=subprocess.DEVNULL,
                            env={**os.environ, "FLOATPAGE_CACHE_DIR": str(tmp_path / "cache")})
    assert result.returncode == 0, result.stderr
    assert 'warning: item "photo" on page "front": picture "cut.png": its pixels do not ' \
           "decode cleanly" in result.stderr, result.stderr
    listed = subprocess.run(["pdfimages", "-list", str(tmp_path / "card.pdf")],
                            capture_output=True, text=True, check=True).stdout
    assert [line.split()[3:5] for line in listed.splitlines() if " image " in line] == \
        [["160", "120"]], listed


def test_a_photo_under_floatpages_pixel_limit_draws_no_python_warning(tmp_path):
    """9,999 x 9,999 pixels is within floatpage's 100 megapixels, but over Pillow's 89.5: check
    and new printed "/.../PIL/Image.py:3593: DecompressionBombWarning: ... DOS attack"."""
    from PIL import Image

    (tmp_path / "photos").mkdir()
    Image.new("1", (9_999, 9_999), 1).save(tmp_path / "photos" / "big.png")
    created = run("new", "album", str(tmp_path / "album" / "album.toml"), "--photos",
                  str(tmp_path / "photos"))
    assert created.returncode == 0, created.stderr
    checked = run("check", str(tmp_path / "album" / "album.toml"))
    assert checked.returncode == 0, checked.stderr
    for result in (created, checked):
        assert "Warning" not in result.stderr and "Image.py" not in result.stderr, result.stderr


def test_a_png_libpng_refuses_is_named_with_what_to_do_not_internal_error(tmp_path):
    """A PNG with a chunk of a made-up critical kind reads well to Pillow, and LuaTeX stopped
    with "(readpng): internal error" and no advice."""
    import io
    import struct
    import zlib

    from PIL import Image

    buffer = io.BytesIO()
    Image.new("RGB", (60, 40), "red").save(buffer, "PNG")
    whole, chunk = buffer.getvalue(), b"QQQQ" + b"made up"
    (tmp_path / "odd.png").write_bytes(whole[:33] + struct.pack(">I", 7) + chunk
                                       + struct.pack(">I", zlib.crc32(chunk)) + whole[33:])
    path = card(tmp_path)
    path.write_text(path.read_text() + '\n[[pages.items]]\nid = "photo"\nkind = "picture"\n'
                    'x = 100.0\ny = 170.0\nw = 30.0\nh = 20.0\npath = "odd.png"\n')
    result = run("render", str(path), "--no-settle", "-o", str(tmp_path / "card.pdf"))
    assert result.returncode == 1, result.stderr
    assert 'item "photo" on page "front" (picture file "odd.png"): ' in result.stderr
    assert "the PNG could not be read; the file is damaged or of a kind LuaTeX does not " \
           "read: open it and save it again as PNG or JPEG" in result.stderr, result.stderr
    assert "internal error" not in result.stderr
    assert not (tmp_path / "card.pdf").exists()


@pytest.mark.parametrize("where", ["proc", "read-only mount"])
def test_an_output_folder_that_takes_no_new_file_is_refused_before_the_work(
        tmp_path, full_disk, where):
    """`render -o /proc/x.pdf` settled and typeset the whole document (seconds) before the
    save found that the folder takes no file; permission bits could not tell (root passes
    them, and /proc refuses root).  Now a probe file beside the output is made and removed
    first: the message is the probe's, and nothing is left behind."""
    from floatpage.model import load_project
    from floatpage.typeset.errors import RenderError
    from floatpage.typeset.render import check_pdf_output

    path = card(tmp_path)
    if where == "proc":
        out = Path("/proc/floatpage-card.pdf")
    else:
        out = full_disk / "card.pdf"
        subprocess.run(["mount", "-o", "remount,ro", str(full_disk)], check=True)
    before = listing(tmp_path)
    result = run("render", str(path), "-o", str(out))
    assert result.returncode == 1, result.stderr
    assert result.stderr.startswith(f"floatpage: {out}: cannot be written: "), result.stderr
    assert "internal error" not in result.stderr
    assert listing(tmp_path) == before
    with pytest.raises(RenderError, match="cannot be written"):  # no typesetting needed to say so
        check_pdf_output(load_project(path), out)
