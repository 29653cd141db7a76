"""What user-walk-13 found keeping projects in git and editing them by hand, each run as a
user runs it: the real `floatpage` process, real project files, a real git repository."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

SAMPLES = Path(__file__).resolve().parents[2] / "sample_projects"


def floatpage(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "floatpage.cli.main", *args],
                          capture_output=True, text=True, timeout=300, cwd=cwd,
                          stdin=subprocess.DEVNULL)


def card_copy(folder: Path, name: str) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    if not (folder / "pictures").exists():
        shutil.copytree(SAMPLES / "greeting-card" / "pictures", folder / "pictures")
    path = folder / name
    shutil.copy(SAMPLES / "greeting-card" / "greeting-card.toml", path)
    return path


def off_the_page(path: Path) -> Path:
    """The card with its front picture typed 40 mm above the page: a layout problem."""
    text = path.read_text()
    assert "y = 74.15\n" in text
    path.write_text(text.replace("y = 74.15\n", "y = -40.0\n", 1))
    return path


def test_check_takes_several_projects_and_exits_with_the_worst(tmp_path):
    """A pre-commit hook (or `floatpage check --strict $^` in a Makefile) names every project
    at once: `check` refused a second path, "unrecognized arguments", exit 2. Each is checked
    now, a file that cannot be read among them; under -q a sound project says nothing and
    a page with problems comes under its file's name."""
    card_copy(tmp_path, "sound.toml")
    off_the_page(card_copy(tmp_path, "off.toml"))
    (tmp_path / "broken.toml").write_text('format = 1\n[[pages]]\nid = "p"\n[[pages.items]\n')
    run = floatpage("check", "--strict", "-q", "sound.toml", "off.toml", "broken.toml",
                    cwd=tmp_path)
    assert run.returncode == 1, run.stdout + run.stderr
    assert "sound.toml" not in run.stdout
    assert run.stdout.startswith("off.toml: valid project, 2 page(s)\npage front:")
    assert "off.toml: 1 layout problem(s)" in run.stdout
    assert run.stderr.startswith("floatpage: broken.toml:4: TOML syntax error")
    both_sound = floatpage("check", "--strict", "-q", "sound.toml", "sound.toml", cwd=tmp_path)
    assert (both_sound.returncode, both_sound.stdout, both_sound.stderr) == (0, "", "")
    unread = floatpage("check", "sound.toml", "missing.toml", cwd=tmp_path)
    assert unread.returncode == 1 and "sound.toml: valid project" in unread.stdout
    assert "missing.toml: no such file" in unread.stderr


def test_check_as_a_git_pre_commit_hook_stops_a_commit_of_a_broken_project(tmp_path):
    """The hook a user writes: every staged project file, in one `check --strict -q`."""
    if shutil.which("git") is None:
        pytest.fail("git is part of the set-up (tools/setup.sh)")
    environment = {**os.environ, "GIT_AUTHOR_NAME": "a", "GIT_AUTHOR_EMAIL": "a@example.org",
                   "GIT_COMMITTER_NAME": "a", "GIT_COMMITTER_EMAIL": "a@example.org",
                   "PATH": f"{Path(sys.executable).parent}:{os.environ.get('PATH', '')}"}

    def git(*args: str) -> subprocess.CompletedProcess:
        return subprocess.run(["git", *args], cwd=tmp_path, capture_output=True, text=True,
                              env=environment, timeout=300)

    git("init", "-q")
    hook = tmp_path / ".git" / "hooks" / "pre-commit"
    hook.write_text("#!/bin/sh\ngit diff --cached --name-only --diff-filter=ACM -z -- '*.toml' "
                    f"| xargs -0 -r {sys.executable} -m floatpage.cli.main check --strict -q\n")
    hook.chmod(0o755)
    card_copy(tmp_path, "front.toml")
    off_the_page(card_copy(tmp_path, "back.toml"))
    git("add", ".")
    refused = git("commit", "-qm", "two cards")
    assert refused.returncode != 0, refused.stdout + refused.stderr
    assert "back.toml: 1 layout problem(s)" in refused.stdout + refused.stderr
    assert floatpage("settle", "-q", "back.toml", cwd=tmp_path).returncode == 0
    git("add", "back.toml")
    committed = git("commit", "-qm", "two cards")
    assert committed.returncode == 0, committed.stdout + committed.stderr


def test_settle_saves_a_file_with_dotted_physics_keys_and_a_multi_line_text(tmp_path):
    """`physics.seed = 0` with a `\"\"\"` text (which a settle saves the full way): exit 70,
    "internal error: AttributeError: 'dict' object has no attribute 'body'"."""
    path = card_copy(tmp_path, "card.toml")
    head, rest = path.read_text().split("[physics]\n", 1)
    block, rest = rest.split("\n\n", 1)
    text = head + "".join(f"physics.{line}\n" for line in block.splitlines()) + "\n" + rest
    text = text.replace('text = "Happy Birthday!"', 'text = """\nHappy\nBirthday!"""', 1)
    text = text.replace("y = 74.15\n", "y = 60.0\n", 1)
    path.write_text(text)
    settled = floatpage("settle", "card.toml", cwd=tmp_path)
    assert settled.returncode == 0, settled.stderr
    after = path.read_text()
    assert "physics.mode = \"fast\"\nphysics.alpha = 150.0\n" in after and "[physics]" not in after
    assert 'text = """\nHappy\nBirthday!"""' in after and "y = 60.0\n" not in after


def git_in(folder: Path):
    environment = {**os.environ, "GIT_AUTHOR_NAME": "a", "GIT_AUTHOR_EMAIL": "a@example.org",
                   "GIT_COMMITTER_NAME": "a", "GIT_COMMITTER_EMAIL": "a@example.org"}

    def git(*args: str) -> subprocess.CompletedProcess:
        return subprocess.run(["git", *args], cwd=folder, capture_output=True, text=True,
                              env=environment, timeout=300)
    return git


def set_in_item(text: str, item_id: str, key: str, value: str) -> str:
    """``text`` with the first ``key = ...`` line after item ``item_id``'s id set to ``value``."""
    start = text.index(f'id = "{item_id}"\n')
    return text[:start] + re.sub(rf"\n{key} = [^\n]*\n", f"\n{key} = {value}\n",
                                 text[start:], count=1)


def flyer_changed_on_two_branches(folder: Path, *, both_change_a_price: bool = False) -> Path:
    """The shop flyer in git; on branch ana its lemons are made wider and settled, on the
    main branch its tulips taller and settled (and, if asked, one price changed on both,
    each its own way); then merged."""
    shutil.copytree(SAMPLES / "shop-flyer", folder)
    git = git_in(folder)
    path = folder / "shop-flyer.toml"
    assert git("init", "-q", "-b", "main").returncode == 0
    git("add", ".")
    git("commit", "-qm", "flyer")
    git("checkout", "-qb", "ana")
    text = set_in_item(path.read_text(), "product-2", "w", "50.0")
    if both_change_a_price:
        text = set_in_item(text, "product-7-price", "text", '"€4.99"')
    path.write_text(text)
    assert floatpage("settle", "-q", path.name, cwd=folder).returncode == 0
    git("commit", "-qam", "ana: lemons wider")
    git("checkout", "-q", "main")
    text = set_in_item(path.read_text(), "product-7", "h", "45.0")
    if both_change_a_price:
        text = set_in_item(text, "product-7-price", "text", '"€3.99"')
    path.write_text(text)
    assert floatpage("settle", "-q", path.name, cwd=folder).returncode == 0
    git("commit", "-qam", "ben: tulips taller")
    merged = git("merge", "ana")
    assert merged.returncode != 0 and "CONFLICT" in merged.stdout, merged.stdout
    return path


def test_settle_mends_a_merge_whose_conflicts_are_all_in_positions(tmp_path):
    """Two people each changed the flyer and settled it; merged, git left 8 conflicts, each
    in the x and y lines both settles wrote, while the two changes merged cleanly. Every
    command said "TOML syntax error: Invalid statement" at the first marker. `settle` now
    keeps the first side of each, lays the page out again with both changes, and keeps the
    conflicted file as the .bak; check passes and git can finish the merge."""
    path = flyer_changed_on_two_branches(tmp_path / "flyer")
    conflicted = path.read_text()
    assert conflicted.count("<<<<<<<") >= 2
    checked = floatpage("check", path.name, cwd=path.parent)
    assert checked.returncode == 1 and "in x and y lines only" in checked.stderr
    assert f"`floatpage settle {path.name}`" in checked.stderr
    settled = floatpage("settle", path.name, cwd=path.parent)
    assert settled.returncode == 0, settled.stderr
    assert "merge conflicts in item positions only" in settled.stderr
    text = path.read_text()
    assert "<<<<<<<" not in text and "=======" not in text
    assert path.with_name(path.name + ".bak").read_text() == conflicted
    lemons, tulips = text.index('id = "product-2"\n'), text.index('id = "product-7"\n')
    assert "\nw = 50.0\n" in text[lemons:tulips] and "\nh = 45.0\n" in text[tulips:]
    strict = floatpage("check", "--strict", "-q", path.name, cwd=path.parent)
    assert strict.returncode == 0, strict.stdout + strict.stderr
    assert floatpage("settle", path.name, cwd=path.parent).stdout.endswith(
        "already settled, nothing to write\n")
    git = git_in(path.parent)
    git("add", path.name)
    assert git("commit", "-qm", "merged").returncode == 0


def test_a_mended_merge_that_then_fails_to_load_keeps_the_conflicted_file(tmp_path):
    """The conflicts mended, the file then fails to load (a picture the merge names is not
    there): the file with its conflicts is already the .bak, where it was written only once
    the settle had saved, and was lost with the mended file written over it."""
    path = flyer_changed_on_two_branches(tmp_path / "flyer")
    conflicted = path.read_text()
    (path.parent / "pictures" / "lemons.png").rename(path.parent / "lemons-moved.png")
    settled = floatpage("settle", path.name, cwd=path.parent)
    assert settled.returncode == 1, settled.stderr
    assert "lemons.png" in settled.stderr
    assert path.with_name(path.name + ".bak").read_text() == conflicted
    assert "<<<<<<<" not in path.read_text()


def test_settle_leaves_a_conflict_in_anything_but_positions_to_the_user(tmp_path):
    """A conflict in a price as well: nothing is written, and the message says how to mend
    it by hand."""
    path = flyer_changed_on_two_branches(tmp_path / "flyer", both_change_a_price=True)
    conflicted = path.read_text()
    settled = floatpage("settle", path.name, cwd=path.parent)
    assert settled.returncode == 1
    assert "a merge conflict is left in the file" in settled.stderr
    assert "keep the lines you want" in settled.stderr
    assert path.read_text() == conflicted
