"""Issue 12's fuzz run: every hostile file in corpus/ through `check`, `settle` and `render`.

A file passes when no command gives an internal error or anything that escapes the CLI, none
hangs, a saved file never holds inf or NaN, and memory stays under 1 GB (the driver process
and the LuaLaTeX runs it started).  A clean refusal (exit 1 with a message) is a pass.
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).parent
CORPUS = HERE / "corpus"
WORKERS = 2
MEMORY_LIMIT_MB = 1024


@pytest.fixture(scope="module")
def results(tmp_path_factory) -> dict[str, dict]:
    folder = tmp_path_factory.mktemp("fuzz") / "corpus"
    shutil.copytree(CORPUS, folder)
    (folder.parent / "corpus-outside.png").write_bytes((CORPUS / "pictures" / "good.png").read_bytes())
    files = sorted(str(path) for path in folder.glob("*.toml"))
    chunks = [files[k::WORKERS] for k in range(WORKERS)]
    env = {"FLOATPAGE_CACHE_DIR": str(folder.parent / "cache")}
    import os

    processes = [subprocess.Popen([sys.executable, str(HERE / "drive.py"), *chunk],
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                  env={**os.environ, **env}, cwd=folder.parent)
                 for chunk in chunks]
    found: dict[str, dict] = {}
    for process in processes:
        out, err = process.communicate(timeout=1500)
        assert process.returncode == 0, err[-3000:]
        for line in out.splitlines():
            record = json.loads(line)
            found[record["file"]] = record
    assert len(found) == len(files)
    return found


def test_the_corpus_has_at_least_150_files():
    assert len(list(CORPUS.glob("*.toml"))) >= 150


def test_no_command_fails_internally_or_hangs(results):
    failures = []
    for name, record in results.items():
        for command in ("check", "settle", "render"):
            outcome = record[command]
            if outcome["code"] not in (0, 1):
                failures.append(f"{name}: {command} -> {outcome['code']}: {outcome['stderr'][-300:]}")
            elif "internal error" in outcome["stderr"] or "Traceback" in outcome["stderr"]:
                failures.append(f"{name}: {command}: {outcome['stderr'][-300:]}")
    assert not failures, "\n".join(failures)


def test_every_refusal_names_the_file_and_says_something(results):
    for name, record in results.items():
        for command in ("check", "settle", "render"):
            outcome = record[command]
            if outcome["code"] == 1 and command != "check" or outcome["code"] == 1 and outcome["stderr"]:
                assert outcome["stderr"].startswith("floatpage: "), (name, command, outcome)
                assert "\x1b" not in outcome["stderr"], (name, command)


def test_what_check_accepts_never_breaks_the_engine(results):
    """`check` saying yes means LuaLaTeX can set the file: a garbage PDF, a panorama or a
    U+FFFD that check let through stopped the engine at `render`."""
    broken = [f"{name}: {record['render']['stderr'][-300:]}" for name, record in results.items()
              if record["check"]["code"] == 0 and record["render"]["code"] == 1
              and ("LaTeX reported" in record["render"]["stderr"]
                   or "LuaLaTeX" in record["render"]["stderr"])]
    assert not broken, "\n".join(broken)


def test_settle_never_saves_a_non_finite_number(results):
    bad = {name: r["non_finite_after_settle"] for name, r in results.items()
           if r["non_finite_after_settle"]}
    assert not bad


def test_memory_stays_under_a_gigabyte(results):
    peak = max(record["peak_mb"] for record in results.values())
    assert peak < MEMORY_LIMIT_MB, where_memory_peaked(results)


def where_memory_peaked(results: dict[str, dict]) -> str:
    """The commands that took a driver's peak over the limit: the file, the command, and
    whether the driver itself or a child (LuaLaTeX) grew, so a failure says where to look."""
    raised = []
    for name, record in results.items():
        for command in ("check", "settle", "render"):
            outcome = record[command]
            own, children = outcome["peak_own_mb"], outcome["peak_children_mb"]
            if outcome["peak_before_mb"] < MEMORY_LIMIT_MB <= max(own, children):
                raised.append(f"{name} {command}: from {outcome['peak_before_mb']:.0f} MB to "
                              f"driver {own:.0f} MB, largest child {children:.0f} MB")
    return "; ".join(raised)


def test_the_corpus_is_what_make_corpus_writes():
    """The committed files are the generator's output, so the two cannot drift apart."""
    sys.path.insert(0, str(HERE))
    try:
        import make_corpus
    finally:
        sys.path.remove(str(HERE))
    expected = make_corpus.files()
    on_disk = {path.stem: path.read_bytes() for path in CORPUS.glob("*.toml")}
    assert on_disk == expected
