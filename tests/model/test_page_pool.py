"""Pages settled side by side in worker processes (model.page_pool): the same bytes as one
after another, errors and Ctrl+C reported as the command reports them.  Real processes, real
files, a real `floatpage settle` for the interrupt."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from floatpage.model import load_project, save_project
from floatpage.model.document import BlockItem, Project
from floatpage.model.errors import FloatpageError
from floatpage.model.layout import settle_project
from floatpage.model.page_pool import MIN_ITEMS, MIN_PAGES, settle_in_pool, worth_a_pool
from merge_helpers import session_members  # tests/merge: the processes a command leaves

ROOT = Path(__file__).resolve().parents[2]


def album(pages: int, photos: int, seed: int = 3) -> Project:
    """Album pages of scattered photos, every third with a caption that follows it."""
    from seeded_scenes import album_pages

    rng = np.random.default_rng(seed)

    def photo(number: int, k: int, x: float, y: float) -> BlockItem:
        w, h = (float(v) for v in rng.uniform(25, 60, 2).round(2))
        return BlockItem(id=f"p{number}-{k}", x=x, y=y, w=w, h=h)

    return Project(title="album", pages=album_pages(pages, photos, photo, rng))


def settled_bytes(tmp_path: Path, name: str, jobs: int) -> bytes:
    """An album of small pages saved, loaded, settled with ``jobs`` worker processes (1: in
    this process) and saved again: the file's bytes."""
    path = tmp_path / f"{name}.toml"
    save_project(album(4, 8), path)
    project = load_project(path)
    if jobs > 1:
        settle_in_pool(project.pages, project.physics, 200_000, jobs)
    else:
        settle_project(project)
    save_project(project)
    return path.read_bytes()


def test_pages_settled_in_worker_processes_are_the_same_bytes(tmp_path):
    alone = settled_bytes(tmp_path, "alone", jobs=1)
    pooled = settled_bytes(tmp_path, "pooled", jobs=2)
    assert pooled == alone
    assert load_project(tmp_path / "pooled.toml").pages[0].items[0].x != album(1, 8).pages[0].items[0].x


def test_settle_project_pools_a_large_project():
    assert worth_a_pool(album(MIN_PAGES, 25).pages, 2)


def test_a_small_project_settles_in_the_commands_own_process():
    small = album(MIN_PAGES - 1, 40).pages
    assert not worth_a_pool(small, 8)  # too few pages
    few_items = album(MIN_PAGES, 3).pages
    assert sum(len(page.items) for page in few_items) < MIN_ITEMS
    assert not worth_a_pool(few_items, 8)
    assert not worth_a_pool(album(MIN_PAGES, 25).pages, 1)


def test_an_error_on_one_page_in_a_worker_is_the_users_error():
    project = album(3, 8)
    project.pages[1].items = [BlockItem(id=f"b{k}", x=100.0, y=100.0, w=10.0, h=10.0)
                              for k in range(700)]  # 244,650 pairs piled on one spot
    with pytest.raises(FloatpageError, match='page "page-2".*piled on each other'):
        settle_in_pool(project.pages, project.physics, 200_000, 2)


def ctrl_c_live() -> None:
    """In the command's process before it starts: Ctrl+C as a terminal has it.  A job that
    a script puts in the background (`cmd &`, as CI runners and `setsid bash -c '... &'` do)
    starts with SIGINT ignored, every process below it inherits that, and Python then leaves
    it ignored: the command settled all 12 pages and exited 0 (the fresh-clone CI run)."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def test_ctrl_c_stops_a_pooled_settle_with_one_message_and_the_file_untouched(tmp_path):
    path = tmp_path / "album.toml"
    save_project(album(120, 12), path)
    before = path.read_bytes()
    command = subprocess.Popen([sys.executable, "-m", "floatpage.cli.main", "settle", "-j", "2",
                                str(path)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True, start_new_session=True, preexec_fn=ctrl_c_live)
    # into the pages: the command, multiprocessing's resource tracker and forkserver, and the
    # two workers in the command's session (rather than a fixed 3 s, which a loaded machine
    # may spend starting them)
    started = time.monotonic()
    while len(session_members(command.pid)) < 5 and time.monotonic() - started < 60:
        assert command.poll() is None, command.communicate()
        time.sleep(0.1)
    time.sleep(1.0)
    assert command.poll() is None, command.communicate()
    os.killpg(command.pid, signal.SIGINT)  # as a terminal's Ctrl+C: the whole group
    # at once, not after the pages under way: the workers ignore Ctrl+C, and the command's
    # exit waited for their pages (13-40 s at load 6); 0.1 s once it stops them
    out, err = command.communicate(timeout=10)
    assert command.returncode == 130, (out, err)
    assert "interrupted" in err
    assert "Traceback" not in err and "KeyboardInterrupt" not in err, err
    assert path.read_bytes() == before


def sleep_for(seconds: float) -> None:
    """A worker's task that is still running when the pool is stopped."""
    time.sleep(seconds)


def test_a_stopped_pool_leaves_no_thread_for_the_exit_to_wake():
    """After a Ctrl+C the pool's manager thread must be gone before the command exits: the
    interpreter's exit hook wakes it through a pipe the thread is closing, and the race printed
    "OSError: [Errno 9] Bad file descriptor" with a traceback under "interrupted" (one
    fresh-clone CI run in several)."""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    from floatpage.model.page_pool import stop_pool

    pool = ProcessPoolExecutor(max_workers=2, mp_context=multiprocessing.get_context("forkserver"))
    futures = [pool.submit(sleep_for, 30) for _ in range(4)]
    started = time.monotonic()
    while not any(future.running() for future in futures) and time.monotonic() - started < 30:
        time.sleep(0.05)
    manager = pool._executor_manager_thread
    assert manager is not None and manager.is_alive()
    stop_pool(pool)
    assert not manager.is_alive()


def test_where_no_worker_process_can_start_the_pages_settle_here(monkeypatch):
    """A sandbox without POSIX semaphores refuses a process pool (OSError): the pages settle
    one by one in this process, to the same positions, instead of failing."""
    import floatpage.model.page_pool as page_pool

    def no_processes(*args, **kwargs):
        raise OSError(38, "Function not implemented")

    expected = album(3, 8)
    settle_project(expected)
    project = album(3, 8)
    monkeypatch.setattr(page_pool, "ProcessPoolExecutor", no_processes)
    reports = settle_in_pool(project.pages, project.physics, 200_000, 2)
    assert len(reports) == 3
    assert [(i.x, i.y) for p in project.pages for i in p.items] == [
        (i.x, i.y) for p in expected.pages for i in p.items]


def test_a_settle_killed_outright_leaves_no_process_behind(tmp_path):
    """user-walk-12b: `kill -9` of the command (a CI job's timeout, the out-of-memory
    killer) left its two workers, the fork server and the resource tracker waiting for good:
    the workers hold their own task queue's ends, so nothing ever told them."""
    path = tmp_path / "album.toml"
    save_project(album(120, 12), path)
    command = subprocess.Popen([sys.executable, "-m", "floatpage.cli.main", "settle", "-j", "2",
                                str(path)], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                               start_new_session=True)
    try:
        started = time.monotonic()
        while len(session_members(command.pid)) < 5 and time.monotonic() - started < 60:
            assert command.poll() is None
            time.sleep(0.1)
        assert len(session_members(command.pid)) >= 5
        command.kill()  # the command alone, as a runner's timeout kills it
        command.wait(timeout=10)
        deadline = time.monotonic() + 30
        while session_members(command.pid) and time.monotonic() < deadline:
            time.sleep(0.1)
        assert session_members(command.pid) == []
    finally:  # a failure leaves nothing running either
        for pid in session_members(command.pid):
            os.kill(pid, signal.SIGKILL)


LONG_TMPDIR_POOL = """
import sys, tempfile
from floatpage.model import page_pool
from floatpage.model.document import PhysicsSettings
import test_page_pool

def not_here(*args):
    raise SystemExit("settled in this process: the pool could not start")

page_pool.settle_here = not_here
pages = test_page_pool.album(2, 8).pages
page_pool.settle_in_pool(pages, PhysicsSettings(), 200_000, 2)
print(tempfile.gettempdir())
"""


def test_a_pool_starts_under_a_tmpdir_too_long_for_a_unix_socket(tmp_path):
    """The fork server's socket lives under $TMPDIR, and a socket's path holds 107 bytes: under
    a longer TMPDIR the pool failed at its first worker and settled in one process without a
    word (and `merge` ended in an internal error; tests/merge has its own test)."""
    long = tmp_path / ("t" * 60) / ("u" * 60)
    long.mkdir(parents=True)
    done = subprocess.run([sys.executable, "-c", LONG_TMPDIR_POOL], capture_output=True,
                          text=True, timeout=300, cwd=Path(__file__).parent,
                          env={**os.environ, "TMPDIR": str(long), "PYTHONPATH": os.pathsep.join(
                              str(ROOT / folder) for folder in ("tests/merge", "benchmarks"))})
    assert done.returncode == 0, done.stderr[-2000:]
    assert done.stdout.strip() == str(long)  # the command's own temporary files stay there
