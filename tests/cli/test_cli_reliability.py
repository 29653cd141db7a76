"""Issue 12's failures, each on real files through the real command: nothing lost, nothing
written where it must not be, no internal error.  Devices, symlinks and locks are made in a
scratch folder, never on the real /dev."""

from __future__ import annotations

import math
import os
import re
import stat
import struct
import subprocess
import sys
import tempfile
import tomllib
import zlib
from pathlib import Path

import pytest
from PIL import Image

from floatpage.model import BlockItem, Page, PictureItem, Project, TextItem, save_project
from floatpage.model.project_lock import ProjectLock

ROOT = Path(__file__).resolve().parents[2]


def run(*args: str, cwd: Path = ROOT, timeout: float = 300) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "floatpage.cli.main", *args], capture_output=True,
                          text=True, timeout=timeout, cwd=cwd, stdin=subprocess.DEVNULL)


def card(folder: Path, *items, name: str = "card.toml", paper: bool = False) -> Path:
    """A small A5 card with a block and a text, plus any extra items."""
    path = folder / name
    save_project(Project(title="Card", pages=[Page(id="front", size="A5", width_mm=148.0,
                                                   height_mm=210.0, items=[
        BlockItem(id="block", x=30.0, y=40.0, w=30.0, h=30.0, color="#3366aa"),
        TextItem(id="title", x=60.0, y=100.0, w=60.0, h=20.0, text="Hello"),
        *items])]), path)
    if paper:
        path.write_text(path.read_text().replace('mode = "fast"', 'mode = "paper"', 1))
    return path


def all_numbers_finite(path: Path) -> bool:
    def walk(value) -> bool:
        if isinstance(value, float):
            return math.isfinite(value)
        if isinstance(value, dict):
            return all(walk(v) for v in value.values())
        if isinstance(value, list):
            return all(walk(v) for v in value)
        return True
    return walk(tomllib.loads(path.read_text()))


# 1. settle never writes NaN -------------------------------------------------------------------

def test_a_huge_item_is_refused_before_the_physics_and_the_file_is_untouched(tmp_path):
    path = card(tmp_path)
    path.write_text(path.read_text().replace("h = 30.0", "h = 1e308", 1))
    before = path.read_bytes()
    result = run("settle", str(path))
    assert result.returncode == 1, result.stderr
    assert 'item "block"' in result.stderr and "beyond what can be laid out" in result.stderr
    assert "Traceback" not in result.stderr
    assert path.read_bytes() == before


def test_paper_mode_with_huge_alpha_and_dt_is_refused(tmp_path):
    path = card(tmp_path, paper=True)
    text = path.read_text()
    text = text.replace("alpha = 150.0", "alpha = 1e308").replace("dt = 0.005", "dt = 1e308")
    path.write_text(text)
    result = run("settle", str(path))
    assert result.returncode == 1
    assert '"alpha" must be at most' in result.stderr and '"dt" must be at most' in result.stderr


@pytest.mark.parametrize("alpha,dt", [(1e6, 1.0), (1e6, 0.5), (5e5, 1.0)])
def test_the_largest_allowed_alpha_and_dt_settle_to_finite_numbers(tmp_path, alpha, dt):
    path = card(tmp_path, paper=True)
    path.write_text(path.read_text().replace("alpha = 150.0", f"alpha = {alpha}")
                    .replace("dt = 0.005", f"dt = {dt}"))
    result = run("settle", str(path))
    assert result.returncode == 0, result.stderr
    assert all_numbers_finite(path)


def test_saving_a_non_finite_position_is_refused_and_keeps_the_file(tmp_path):
    from floatpage.model import FloatpageError, load_project

    path = card(tmp_path)
    before = path.read_bytes()
    project = load_project(path)
    project.pages[0].items[0].x = float("nan")
    with pytest.raises(FloatpageError, match='item "block" x would be written as inf or NaN'):
        save_project(project)
    assert path.read_bytes() == before


# 2, 3. render writes only new paths or regular files that are not inputs -----------------------

@pytest.mark.parametrize("option", ["-o", "--tex", "--fragment"])
def test_render_refuses_to_write_over_the_project(tmp_path, option):
    path = card(tmp_path)
    before = path.read_bytes()
    args = ["render", str(path), option, str(path)]
    if option != "-o":
        args += ["-o", str(tmp_path / "out.pdf")]
    result = run(*args)
    assert result.returncode == 1
    assert "is an input of this render" in result.stderr
    assert path.read_bytes() == before
    assert not (tmp_path / "out.pdf").exists() and not (tmp_path / "card.toml.bak").exists()


@pytest.mark.parametrize("name,holds", [("card.toml.bak", "the project's backup"),
                                        (".card.toml.recover", "the editor's unsaved edits"),
                                        (".card.toml.lock", "the project's lock")])
def test_render_refuses_to_write_over_what_floatpage_keeps_beside_the_project(tmp_path, name,
                                                                             holds):
    """`-o card.toml.bak` replaced the only copy of the text from before the last settle."""
    path = card(tmp_path)
    (tmp_path / name).write_text("kept")
    for option in ("-o", "--tex"):
        args = ["render", str(path), option, str(tmp_path / name)]
        result = run(*args, *(["-o", str(tmp_path / "out.pdf")] if option == "--tex" else []))
        assert result.returncode == 1, result.stderr
        assert f"because it holds {holds}" in result.stderr
        assert (tmp_path / name).read_text() == "kept"


def test_render_refuses_to_write_over_a_picture(tmp_path):
    Image.new("RGB", (40, 30), "red").save(tmp_path / "photo.png")
    path = card(tmp_path, PictureItem(id="photo", x=60.0, y=60.0, w=40.0, h=30.0, path="photo.png"))
    before = (tmp_path / "photo.png").read_bytes()
    result = run("render", str(path), "-o", str(tmp_path / "photo.png"))
    assert result.returncode == 1 and "photo.png" in result.stderr
    assert (tmp_path / "photo.png").read_bytes() == before


def test_render_refuses_a_device_a_pipe_a_folder_and_a_symlink(tmp_path):
    path = card(tmp_path)
    targets = {"pipe": tmp_path / "pipe", "folder": tmp_path / "folder",
               "symbolic link": tmp_path / "link.tex"}
    os.mkfifo(targets["pipe"])
    targets["folder"].mkdir()
    (tmp_path / "real.tex").write_text("kept")
    targets["symbolic link"].symlink_to(tmp_path / "real.tex")
    if os.geteuid() == 0:  # only root may make a device node, here a copy of /dev/null's
        targets["device"] = tmp_path / "null"
        os.mknod(targets["device"], stat.S_IFCHR | 0o666, os.makedev(1, 3))
    for kind, target in targets.items():
        option = "--tex" if kind == "symbolic link" else "-o"
        args = ["render", str(path), option, str(target)]
        if option == "--tex":
            args += ["-o", str(tmp_path / "out.pdf")]
        result = run(*args)
        assert result.returncode == 1, (kind, result.stderr)
        assert f"it is a {kind}" in result.stderr, result.stderr
    assert stat.S_ISFIFO(os.lstat(targets["pipe"]).st_mode)
    assert targets["symbolic link"].is_symlink() and (tmp_path / "real.tex").read_text() == "kept"
    if "device" in targets:
        assert stat.S_ISCHR(os.lstat(targets["device"]).st_mode)


def test_a_refused_render_leaves_the_old_outputs_alone(tmp_path):
    path = card(tmp_path)
    (tmp_path / "old.tex").write_text("old tex")
    (tmp_path / "old.pdf").write_bytes(b"%PDF-old")
    result = run("render", str(path), "-o", str(tmp_path / "old.pdf"), "--tex",
                 str(tmp_path / "old.tex"), "--fragment", str(tmp_path / "missing" / "x.tex"))
    assert result.returncode == 1
    assert "missing" in result.stderr and "does not exist" in result.stderr
    assert (tmp_path / "old.tex").read_text() == "old tex"
    assert (tmp_path / "old.pdf").read_bytes() == b"%PDF-old"


# 4. symlinks and hard links --------------------------------------------------------------------

def test_settle_saves_through_a_symlink_to_the_real_file(tmp_path):
    real_folder = tmp_path / "real"
    real_folder.mkdir()
    target = card(real_folder)
    target.write_text(target.read_text().replace("x = 30.0", "x = 60.0"))  # overlap the text
    link = tmp_path / "link.toml"
    link.symlink_to(target)
    before = target.read_text()
    result = run("settle", str(link))
    assert result.returncode == 0, result.stderr
    assert link.is_symlink()
    assert target.read_text() != before, "the real file holds the settled layout"
    assert (real_folder / "card.toml.bak").read_text() == before


def test_settle_keeps_a_hard_link_whole(tmp_path):
    path = card(tmp_path)
    path.write_text(path.read_text().replace("x = 30.0", "x = 60.0"))
    other = tmp_path / "other-name.toml"
    os.link(path, other)
    result = run("settle", str(path))
    assert result.returncode == 0, result.stderr
    assert os.path.samefile(path, other)
    assert other.read_text() == path.read_text()


def test_settle_refuses_a_read_only_project_and_leaves_it_as_it_was(tmp_path):
    """The atomic rename needs only the folder's permission: a 0444 project was replaced
    (and a .bak written) as if writable, its protection gone."""
    path = card(tmp_path)
    path.write_text(path.read_text().replace("x = 30.0", "x = 60.0"))  # overlap: settle moves
    path.chmod(0o444)
    before, inode = path.read_bytes(), path.stat().st_ino
    link = tmp_path / "link.toml"
    link.symlink_to(path)
    for named in (path, link):
        result = run("settle", str(named))
        assert result.returncode == 1, result.stderr
        assert f"{named}" in result.stderr and "read-only" in result.stderr, result.stderr
        assert "chmod u+w" in result.stderr and "Traceback" not in result.stderr
    assert path.read_bytes() == before and path.stat().st_ino == inode
    assert stat.S_IMODE(path.stat().st_mode) == 0o444
    assert not (tmp_path / "card.toml.bak").exists()


@pytest.mark.skipif(os.geteuid() != 0 or not Path("/usr/bin/setpriv").exists(),
                    reason="needs root to run settle as another user")
def test_settle_of_someone_elses_file_says_whose_it_is_not_to_chmod_it():
    """A file writable by its owner only (0644, root's) was "read-only: chmod u+w", which
    the user who ran settle may not do."""
    import shutil
    import tempfile

    folder = Path(tempfile.mkdtemp(prefix="floatpage-owner-"))
    try:
        folder.chmod(0o755)
        path = card(folder)
        path.write_text(path.read_text().replace("x = 30.0", "x = 60.0"))
        path.chmod(0o644)
        before = path.read_bytes()
        result = subprocess.run(
            ["/usr/bin/setpriv", "--reuid=65534", "--regid=65534", "--clear-groups",
             sys.executable, "-m", "floatpage.cli.main", "settle", str(path)],
            capture_output=True, text=True, timeout=300, cwd="/", stdin=subprocess.DEVNULL,
            env={**os.environ, "PYTHONPATH": os.pathsep.join(sys.path)})
        if "Permission denied" in result.stderr and "not saved" not in result.stderr:
            pytest.skip(f"this checkout cannot be run by another user: {result.stderr[-200:]}")
        assert result.returncode == 1, result.stderr
        assert f"{path}: not saved, because you may not write it (it belongs to root)" \
            in result.stderr, result.stderr
        assert "chmod" not in result.stderr
        assert path.read_bytes() == before
        old_pdf = folder / "old.pdf"  # and render's output, before anything is made
        old_pdf.write_bytes(b"%PDF-old")
        old_pdf.chmod(0o644)
        result = subprocess.run(
            ["/usr/bin/setpriv", "--reuid=65534", "--regid=65534", "--clear-groups",
             sys.executable, "-m", "floatpage.cli.main", "render", str(path), "--no-settle",
             "-o", str(old_pdf)],
            capture_output=True, text=True, timeout=300, cwd="/", stdin=subprocess.DEVNULL,
            env={**os.environ, "PYTHONPATH": os.pathsep.join(sys.path), "HOME": str(folder)})
        assert result.returncode == 1, result.stderr
        assert f"{old_pdf}: will not write there, because you may not write it (it belongs " \
            "to root)" in result.stderr, result.stderr
        assert old_pdf.read_bytes() == b"%PDF-old"
    finally:
        shutil.rmtree(folder)


def test_render_refuses_a_read_only_output_before_the_engine_runs(tmp_path):
    path = card(tmp_path)
    old = tmp_path / "old.pdf"
    old.write_bytes(b"%PDF-old")
    old.chmod(0o444)
    result = run("render", str(path), "-o", str(old))
    assert result.returncode == 1, result.stderr
    assert f"{old}: will not write there, because the file is read-only" in result.stderr
    assert old.read_bytes() == b"%PDF-old" and stat.S_IMODE(old.stat().st_mode) == 0o444
    # the project as output is named as the project, not as a file to make writable
    path.chmod(0o444)
    result = run("render", str(path), "-o", str(path))
    assert result.returncode == 1 and "an input of this render" in result.stderr


# 5. one writer at a time ------------------------------------------------------------------------

def test_settle_refuses_while_the_project_is_being_edited(tmp_path):
    path = card(tmp_path)
    before = path.read_bytes()
    with ProjectLock(path, purpose="floatpage edit"):
        result = run("settle", str(path))
    assert result.returncode == 1
    assert f"is being edited by PID {os.getpid()} (floatpage edit)" in result.stderr
    assert path.read_bytes() == before
    assert run("settle", str(path)).returncode == 0


def test_two_settles_at_once_keep_the_version_from_before_both(tmp_path):
    path = card(tmp_path)
    path.write_text(path.read_text().replace("x = 30.0", "x = 60.0"))
    original = path.read_text()
    command = [sys.executable, "-m", "floatpage.cli.main", "settle", str(path)]
    processes = [subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                  text=True, cwd=ROOT) for _ in range(2)]
    results = [(p.wait(timeout=120), p.stderr.read()) for p in processes]
    for code, stderr in results:
        assert code == 0 or "is being written by PID" in stderr, stderr
    assert (tmp_path / "card.toml.bak").read_text() == original


def test_a_lock_file_that_is_not_a_file_is_refused_with_a_message(tmp_path):
    """A pipe, folder, symlink or device where `.NAME.toml.lock` belongs: a pipe was an
    internal error, and a device got the PID written into it."""
    leftovers = {"pipe": os.mkfifo, "folder": os.mkdir,
                 "symbolic link": lambda p: p.symlink_to(tmp_path / "elsewhere")}
    if os.geteuid() == 0:  # a copy of /dev/full in the scratch folder: writes there fail
        leftovers["device"] = lambda p: os.mknod(p, stat.S_IFCHR | 0o666, os.makedev(1, 7))
    for kind, make in leftovers.items():
        folder = tmp_path / kind.replace(" ", "-")
        folder.mkdir()
        path = card(folder)
        before = path.read_bytes()
        make(folder / ".card.toml.lock")
        result = run("settle", str(path), timeout=60)
        assert result.returncode == 1, (kind, result.stderr)
        assert ".card.toml.lock: cannot lock the project" in result.stderr, result.stderr
        assert "remove it and try again" in result.stderr
        assert path.read_bytes() == before
    assert not (tmp_path / "elsewhere").exists(), "nothing was made through the link"


def test_a_lock_file_left_by_a_dead_editor_does_not_lock(tmp_path):
    path = card(tmp_path)
    path.write_text(path.read_text().replace("x = 30.0", "x = 60.0"))
    (tmp_path / ".card.toml.lock").write_text(f"{dead_pid()} floatpage edit\n")
    result = run("settle", str(path))
    assert result.returncode == 0, result.stderr


def test_the_editor_refuses_a_project_another_process_holds(tmp_path):
    path = card(tmp_path)
    with ProjectLock(path, purpose="floatpage settle"):
        result = run("edit", str(path), timeout=60)
    assert result.returncode == 1
    # a settle is waited for, not closed: "is being edited by … (floatpage settle); close it
    # there" sent the user looking for an editor (user-walk-8)
    assert f"is being written by PID {os.getpid()} (floatpage settle); wait for it to finish" \
        in result.stderr
    assert "close it there" not in result.stderr


# 6. leftovers of a killed save --------------------------------------------------------------------

def test_a_save_removes_stale_temporaries_and_keeps_fresh_ones(tmp_path):
    path = card(tmp_path)
    stale = tmp_path / ".card.toml.999.deadbeef.floatpage-tmp"
    stale_backup = tmp_path / ".card.toml.999.deadbeef.floatpage-tmp.bak"
    fresh = tmp_path / f".card.toml.{os.getpid()}.cafecafe.floatpage-tmp"  # a live writer
    for leftover in (stale, stale_backup, fresh):
        leftover.write_bytes(b"partial")
    old = os.stat(path).st_mtime - 3600
    os.utime(stale, (old, old))
    os.utime(stale_backup, (old, old))
    path.write_text(path.read_text().replace("x = 30.0", "x = 60.0"))
    assert run("settle", str(path)).returncode == 0
    assert not stale.exists() and not stale_backup.exists()
    assert fresh.exists(), "a live writer's young temporary may belong to a save in progress"


def dead_pid() -> int:
    """The PID of a process that has run and been reaped (not reused within a test)."""
    finished = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                              capture_output=True, text=True, check=True)
    return int(finished.stdout)


def test_a_fresh_temporary_of_a_dead_writer_goes_at_the_next_save(tmp_path):
    path = card(tmp_path)
    leftover = tmp_path / f".card.toml.{dead_pid()}.0badf00d.floatpage-tmp"
    leftover.write_bytes(b"half a save, killed a moment ago")
    path.write_text(path.read_text().replace("x = 30.0", "x = 60.0"))
    assert run("settle", str(path)).returncode == 0
    assert not leftover.exists()


def test_a_save_killed_by_sigkill_leaves_nothing_after_the_next_save(tmp_path):
    path = card(tmp_path)
    path.write_text(path.read_text().replace("x = 30.0", "x = 60.0"))
    writer = subprocess.Popen([sys.executable, "-c", f"""
import time
from floatpage.model import atomic_file
def slow(handle, data, chunk=1):
    handle.write(data[:10]); handle.flush(); print("writing", flush=True); time.sleep(60)
atomic_file.write_chunks = slow
atomic_file.atomic_write({str(path)!r}, b"x" * 100_000)
"""], stdout=subprocess.PIPE, text=True, cwd=ROOT)
    assert writer.stdout.readline().strip() == "writing"
    writer.kill()
    writer.wait()
    assert len(list(tmp_path.glob("*.floatpage-tmp"))) == 1, "the kill left its temporary"
    assert run("settle", str(path)).returncode == 0
    assert list(tmp_path.glob("*.floatpage-tmp")) == []


def test_a_backup_name_taken_by_a_folder_is_named_and_nothing_changes(tmp_path):
    path = card(tmp_path)
    path.write_text(path.read_text().replace("x = 30.0", "x = 60.0"))
    before = path.read_bytes()
    (tmp_path / "card.toml.bak").mkdir()
    result = run("settle", str(path))
    assert result.returncode == 1
    assert "card.toml.bak: not saved" in result.stderr and "move it away" in result.stderr
    assert path.read_bytes() == before


# 8, 9. deep nesting and seeds ---------------------------------------------------------------------

@pytest.mark.parametrize("value", ["[" * 10_000 + "]" * 10_000, "{a=" * 10_000 + "1" + "}" * 10_000,
                                   "[{a=" * 5000 + "1" + "}]" * 5000])
def test_deep_nesting_is_a_clear_error(tmp_path, value):
    path = tmp_path / "deep.toml"
    path.write_text(f"format = 1\nx = {value}\n")
    for command in ("check", "settle", "render"):
        result = run(command, str(path))
        assert result.returncode == 1, result.stderr
        assert "nested too deeply" in result.stderr


def test_a_project_that_is_a_pipe_a_device_a_folder_or_empty_is_named_as_such(tmp_path):
    """A pipe named as the project hung every command; a device that never ends (a copy of
    /dev/zero, made in the scratch folder as root) filled memory into an internal error."""
    cases = {"pipe.toml": (os.mkfifo, "is not a regular file"),
             "folder.toml": (os.mkdir, "is a folder, not a project file"),
             "empty.toml": (lambda p: p.write_bytes(b"\xef\xbb\xbf \n"), "is empty")}
    if os.geteuid() == 0:
        cases["zero.toml"] = (lambda p: os.mknod(p, stat.S_IFCHR | 0o666, os.makedev(1, 5)),
                              "is not a regular file")
    for name, (make, words) in cases.items():
        make(tmp_path / name)
        for command in ("check", "settle", "render", "edit"):
            result = run(command, str(tmp_path / name), timeout=60)
            assert result.returncode == 1, (name, command, result.stderr)
            assert result.stderr.startswith(f"floatpage: {tmp_path / name}: {words}"), result.stderr


def test_a_negative_seed_is_a_clear_error(tmp_path):
    path = card(tmp_path)
    path.write_text(path.read_text().replace("seed = 0", "seed = -1"))
    result = run("settle", str(path))
    assert result.returncode == 1
    assert '"seed" must be at least 0' in result.stderr


# 10, 11. pictures ------------------------------------------------------------------------------------

def png_header_claiming(width: int, height: int) -> bytes:
    """A 45-byte PNG whose header claims a huge size (no pixel data follows)."""
    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
            + chunk(b"IEND", b""))


def test_a_picture_claiming_too_many_pixels_is_refused_by_every_command(tmp_path):
    (tmp_path / "bomb.png").write_bytes(png_header_claiming(100_000, 100_000))
    Image.new("1", (20_000, 20_000)).save(tmp_path / "big.png")
    for name in ("bomb.png", "big.png"):
        path = card(tmp_path, PictureItem(id="photo", x=60.0, y=60.0, w=40.0, h=30.0, path=name))
        for command in ("check", "settle", "render"):
            result = run(command, str(path))
            assert result.returncode == 1, (name, command, result.stderr)
            assert 'item "photo"' in result.stderr and "too large" in result.stderr, result.stderr
            assert "internal error" not in result.stderr


def test_a_background_bomb_is_refused_too(tmp_path):
    (tmp_path / "bomb.png").write_bytes(png_header_claiming(100_000, 100_000))
    path = card(tmp_path)
    path.write_text(path.read_text().replace('size = "A5"', 'size = "A5"\nbackground = {picture = "bomb.png"}'))
    result = run("check", str(path))
    assert result.returncode == 1 and "background" in result.stderr and "too large" in result.stderr


def test_a_truncated_jpeg_renders_with_a_warning_naming_the_item(tmp_path):
    Image.effect_noise((400, 300), 60).convert("RGB").save(tmp_path / "whole.jpg", quality=90)
    data = (tmp_path / "whole.jpg").read_bytes()
    (tmp_path / "cut.jpg").write_bytes(data[: len(data) // 2])
    path = card(tmp_path, PictureItem(id="photo", x=60.0, y=60.0, w=40.0, h=30.0, path="cut.jpg"))
    checked = run("check", str(path))
    assert 'item "photo"' in checked.stdout and "do not decode cleanly" in checked.stdout
    result = run("render", "--no-settle", str(path), "-o", str(tmp_path / "card.pdf"))
    assert result.returncode == 0, result.stderr
    assert 'warning: item "photo" on page "front": picture "cut.jpg"' in result.stderr


def test_a_pdf_picture_is_opened_by_check_not_only_sniffed(tmp_path):
    """A PDF header followed by garbage passed check and stopped LuaLaTeX at render; a good
    PDF got a bogus "pixels do not decode" warning."""
    (tmp_path / "garbage.pdf").write_bytes(b"%PDF-1.4\n" + bytes(range(256)) * 4)
    Image.new("RGB", (100, 50), "green").save(tmp_path / "good.pdf")
    bad = card(tmp_path, PictureItem(id="photo", x=60.0, y=60.0, w=40.0, h=20.0,
                                     path="garbage.pdf"), name="bad.toml")
    for command in ("check", "settle", "render"):
        result = run(command, str(bad))
        assert result.returncode == 1, (command, result.stderr)
        assert 'item "photo": picture file "garbage.pdf" is not a PDF floatpage can read' \
            in result.stderr and "LaTeX" not in result.stderr
    good = card(tmp_path, PictureItem(id="photo", x=60.0, y=60.0, w=40.0, h=20.0,
                                      path="good.pdf"), name="good.toml")
    checked = run("check", str(good))
    assert checked.returncode == 0 and "warning" not in checked.stdout, checked.stdout
    rendered = run("render", "--no-settle", str(good), "-o", str(tmp_path / "good-out.pdf"))
    # (the card's photo overlaps its block: --no-settle warns of that, and only of that)
    assert rendered.returncode == 0 and "warning: item" not in rendered.stderr \
        and "decode" not in rendered.stderr, rendered.stderr


def test_pictures_outside_the_project_need_permission(tmp_path):
    outside = tmp_path / "elsewhere"
    outside.mkdir()
    Image.new("RGB", (40, 30), "blue").save(outside / "secret.png")
    project_folder = tmp_path / "project"
    project_folder.mkdir()
    (project_folder / "inside-link.png").symlink_to(outside / "secret.png")
    for reference in ("../elsewhere/secret.png", str(outside / "secret.png"), "inside-link.png"):
        path = card(project_folder, PictureItem(id="photo", x=60.0, y=60.0, w=40.0, h=30.0,
                                                path=reference))
        for command in ("check", "render"):
            result = run(command, str(path))
            assert result.returncode == 1, (reference, result.stderr)
            assert "outside the project folder" in result.stderr
            assert "--allow-outside-files" in result.stderr
        allowed = run("check", "--allow-outside-files", str(path))
        assert allowed.returncode == 0, allowed.stderr
        assert 'note: item "photo" uses' in allowed.stdout
        path.write_text(path.read_text() + "\n[files]\nallow_outside = true\n")
        assert run("check", str(path)).returncode == 0


# Text, messages and exit codes ----------------------------------------------------------------------

def test_a_megabyte_of_text_is_a_clear_error(tmp_path):
    path = card(tmp_path)
    path.write_text(path.read_text().replace('text = "Hello"', 'text = "' + "word " * 200_000 + '"'))
    result = run("render", str(path))
    assert result.returncode == 1
    assert "1000000 characters, more than the 20000" in result.stderr
    assert len(result.stderr) < 2000, "the message does not echo the text"


def test_control_characters_in_a_file_are_escaped_in_messages(tmp_path):
    path = card(tmp_path)
    path.write_text(path.read_text().replace('kind = "text"', 'kind = "te\\u001b[2J\\nxt"', 1))
    result = run("check", str(path))
    assert result.returncode == 1
    assert "\x1b" not in result.stderr and "\\x1b[2J\\n" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1, "no fake lines"


def test_a_file_name_with_control_characters_is_escaped_on_stdout_too(tmp_path):
    """A name is a user string as well: check, settle and render echoed it raw on stdout."""
    name = "card\x1b[2J\nfake line.toml"
    path = card(tmp_path, name=name)
    out_pdf = tmp_path / "out\x1b]0;title\x07.pdf"
    for args in (("check", str(path)), ("settle", str(path)),
                 ("render", str(path), "-o", str(out_pdf))):
        result = run(*args)
        assert result.returncode == 0, result.stderr
        assert "\x1b" not in result.stdout and "\x07" not in result.stdout, args
        assert "card\\x1b[2J\\nfake line.toml" in result.stdout or "out\\x1b]0;title\\x07.pdf" in result.stdout
        assert len(result.stdout.splitlines()) == len([line for line in result.stdout.split("\n") if line]), args
    assert out_pdf.read_bytes().startswith(b"%PDF-")


def test_a_long_list_of_problems_is_cut_at_twenty(tmp_path):
    items = "".join(f'\n[[pages.items]]\nid = "same"\nkind = "block"\nx = {10 + i % 50}.0\n'
                    f"y = 10.0\nw = 5.0\nh = 5.0\n" for i in range(780))
    path = tmp_path / "many.toml"
    path.write_text(f'format = 1\n\n[[pages]]\nid = "p"\n{items}')
    result = run("check", str(path))
    lines = result.stderr.strip().splitlines()
    assert result.returncode == 1
    assert len(lines) == 21
    assert lines[-1] == "… and 759 more like this"


def test_an_internal_error_has_its_own_exit_code_and_a_crash_log(tmp_path, monkeypatch, capsys):
    from floatpage.cli import main as cli

    def broken(args):
        raise RuntimeError("a bug of ours")

    monkeypatch.setattr(cli, "cmd_check", broken)
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))  # not one more log in /tmp a run
    code = cli.main(["check", str(card(tmp_path))])
    err = capsys.readouterr().err
    assert code == cli.EXIT_INTERNAL_ERROR == 70
    assert "internal error: RuntimeError: a bug of ours" in err and "please report it" in err
    log = Path(err.split("details are in ")[1].split()[0])
    assert log.parent == tmp_path and "RuntimeError" in log.read_text()


def test_the_engine_runs_under_a_memory_limit_and_says_so_when_it_is_hit(tmp_path):
    path = card(tmp_path)
    env = {**os.environ, "FLOATPAGE_ENGINE_MEMORY_MB": "40"}  # far below what LuaTeX needs
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "render", str(path)],
                            capture_output=True, text=True, timeout=300, cwd=ROOT, env=env)
    assert result.returncode == 1
    assert "memory limit of 40 MB" in result.stderr and "FLOATPAGE_ENGINE_MEMORY_MB" in result.stderr
    assert not (tmp_path / "card.pdf").exists()


def test_an_engine_that_ends_before_its_log_is_quoted_not_blamed_on_memory(tmp_path):
    """A TeX installation LuaLaTeX cannot start in (here kpathsea finds no texmf.cnf, so no
    format) ends before any log. floatpage said it had most likely run out of memory, and
    told the user to raise a limit that had nothing to do with it."""
    path = card(tmp_path)
    env = {**os.environ, "TEXMFCNF": str(tmp_path / "no-texmf-cnf-here")}
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "render", str(path)],
                            capture_output=True, text=True, timeout=300, cwd=ROOT, env=env)
    assert result.returncode == 1, result.stderr
    assert "before it wrote a log" in result.stderr and "lualatex.fmt" in result.stderr
    assert "memory" not in result.stderr and "Traceback" not in result.stderr
    assert not (tmp_path / "card.pdf").exists()


@pytest.mark.parametrize("value", ["abc", "-5", "0", "4096x"])
def test_a_memory_limit_that_is_not_a_number_is_refused_not_ignored(tmp_path, value):
    path = card(tmp_path)
    env = {**os.environ, "FLOATPAGE_ENGINE_MEMORY_MB": value}
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "render", str(path)],
                            capture_output=True, text=True, timeout=300, cwd=ROOT, env=env)
    assert result.returncode == 1, result.stderr
    assert f"FLOATPAGE_ENGINE_MEMORY_MB='{value}' is not a memory limit" in result.stderr
    assert not (tmp_path / "card.pdf").exists()


def blocks_on_one_spot(path: Path, count: int) -> Path:
    items = "".join(f'\n[[pages.items]]\nid = "b{k}"\nkind = "block"\nx = 50.0\ny = 50.0\n'
                    f"w = 1.0\nh = 1.0\n" for k in range(count))
    path.write_text(f'format = 1\n\n[[pages]]\nid = "p"\nsize = "A4"\n{items}')
    return path


def test_more_than_10000_items_on_a_page_is_a_clear_error(tmp_path):
    path = blocks_on_one_spot(tmp_path / "many.toml", 10_001)
    for command in ("check", "settle"):
        result = run(command, str(path))
        assert result.returncode == 1
        assert 'page "p": holds 10,001 items, more than the 10,000' in result.stderr
        assert len(result.stderr.splitlines()) == 1


# The real CLI as `python -m floatpage.cli.main` would run it, which at exit writes its own
# peak resident memory (VmHWM, in kB) to the file named by FLOATPAGE_TEST_PEAK.  Not the
# ru_maxrss that os.wait4 reports: Linux carries a process's peak across exec, and a child
# that subprocess starts with vfork inherits the peak of the parent it was made from, so in a
# long test run the check of a 10,000-item file "used" the 1,042 MB of pytest itself.
PEAK_PROBE = """
import atexit, os, runpy, sys
def report():
    with open("/proc/self/status") as status:
        peak = next(line.split()[1] for line in status if line.startswith("VmHWM:"))
    with open(os.environ["FLOATPAGE_TEST_PEAK"], "w") as out:
        out.write(peak)
atexit.register(report)
sys.argv[0] = "floatpage"
runpy.run_module("floatpage.cli.main", run_name="__main__", alter_sys=True)
"""


def run_measured(folder: Path, *args: str) -> tuple[subprocess.CompletedProcess, int]:
    """Run the CLI with ``args``; what it did and its own peak memory in kB."""
    peak = folder / "peak-kb"
    done = subprocess.run([sys.executable, "-c", PEAK_PROBE, *args], capture_output=True,
                          text=True, cwd=ROOT, timeout=600,
                          env={**os.environ, "FLOATPAGE_TEST_PEAK": str(peak)})
    return done, int(peak.read_text())


def test_10000_items_piled_on_one_spot_stay_under_a_gigabyte(tmp_path):
    """50 million overlapping pairs: check counts them (it listed them all, gigabytes), and
    settle refuses before the physics holds them all (it failed past 4 GB)."""
    path = blocks_on_one_spot(tmp_path / "pile.toml", 10_000)
    before = path.read_bytes()
    for command, code in (("check", 0), ("settle", 1)):
        done, peak_kb = run_measured(tmp_path, command, str(path))
        out, err = done.stdout, done.stderr
        assert done.returncode == code, err
        assert peak_kb < 1024 * 1024, (command, f"{peak_kb / 1024:.0f} MB")
        if command == "check":
            assert "49995000 overlaps" in out
        else:
            assert "are piled on each other" in err and "49,995,000" in err
    assert path.read_bytes() == before


def test_check_of_a_10000_item_file_stays_under_a_gigabyte(tmp_path):
    import random

    rng = random.Random(1)
    path = tmp_path / "big.toml"
    save_project(Project(pages=[Page(id="p", items=[
        BlockItem(id=f"b{k}", x=rng.uniform(5, 205), y=rng.uniform(5, 292),
                  w=rng.uniform(1, 4), h=rng.uniform(1, 4)) for k in range(10_000)])]), path)
    done, peak_kb = run_measured(tmp_path, "check", str(path))
    assert done.returncode == 0, done.stderr
    assert "valid project" in done.stdout
    assert peak_kb < 1024 * 1024, f"{peak_kb / 1024:.0f} MB"


def test_a_deleted_current_folder_is_a_clear_error_not_an_internal_one(tmp_path):
    """A shell whose folder was deleted under it (a build folder cleaned by another job):
    `floatpage settle card.toml` failed as an internal error on the lock's path."""
    gone = tmp_path / "gone"
    gone.mkdir()
    card(tmp_path)
    script = (f"cd {gone} && rmdir {gone} && "
              f"exec {sys.executable} -m floatpage.cli.main settle card.toml")
    result = subprocess.run(["sh", "-c", script], capture_output=True, text=True, timeout=120,
                            stdin=subprocess.DEVNULL, env={**os.environ, "PYTHONSAFEPATH": "1"})
    assert result.returncode == 1, result.stderr
    assert "current folder no longer exists" in result.stderr
    assert "internal error" not in result.stderr


def without_times(text: str) -> str:
    """Command output without its timings ("798 steps in 0.04 s"): a run's seconds differ."""
    return re.sub(r"in \d+(\.\d+)? s\b", "in … s", text)


def test_check_settle_and_render_say_an_editor_left_unsaved_edits_beside_the_project(tmp_path):
    """After a dropped SSH link, `make` checked, settled and rendered the project without the
    edits the editor had kept in `.card.toml.recover`, and nothing said they were there
    (user-walk-8). A note on stderr names them; the exit code and stdout stay as they were."""
    path = card(tmp_path)
    assert run("settle", str(path)).returncode == 0  # settled: what follows changes nothing
    quiet = {command: run(command, str(path)) for command in ("check", "settle")}
    for result in quiet.values():
        assert "unsaved edits" not in result.stderr
    (tmp_path / ".card.toml.recover").write_text(path.read_text())
    for command in ("check", "settle", "render"):
        result = run(command, str(path))
        assert result.returncode == 0, result.stderr
        assert ".card.toml.recover holds unsaved edits from an editor that lost its terminal" \
            in result.stderr, (command, result.stderr)
        assert f"floatpage edit {path}` offers to restore" in result.stderr
        if command in quiet:  # the same words, but for how long the settle took
            assert without_times(result.stdout) == without_times(quiet[command].stdout)
