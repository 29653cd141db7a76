"""Killing `render` mid-typesetting leaves no LuaLaTeX running, no partial PDF, and no build
folder for long: SIGTERM and SIGHUP clean up on the way out, and after SIGKILL the next render
does."""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SAMPLE = ROOT / "sample_projects" / "calendar-2027"


def engines_working_in(folder: Path) -> list[int]:
    """PIDs of live processes whose working folder lies inside ``folder``."""
    found = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            cwd = os.readlink(entry / "cwd")
            state = (entry / "stat").read_text().rsplit(")", 1)[1].split()[0]
        except OSError:
            continue
        if cwd.startswith(str(folder)) and state != "Z":
            found.append(int(entry.name))
    return found


def hang_ups_live() -> None:
    """In the render's process before it starts: SIGHUP and SIGTERM as a terminal's job has
    them.  Under `nohup` (a CI runner, a suite started over SSH) the suite and every process
    below it start with SIGHUP ignored, and the command rightly keeps it so: the render went
    on to write its PDF, and the SIGHUP case failed every run."""
    for stop in (signal.SIGHUP, signal.SIGTERM):
        signal.signal(stop, signal.SIG_DFL)


def start_render(project: Path, out: Path, scratch: Path) -> subprocess.Popen:
    env = {**os.environ, "TMPDIR": str(scratch), "FLOATPAGE_CACHE_DIR": str(scratch / "cache")}
    return subprocess.Popen([sys.executable, "-m", "floatpage.cli.main", "render", "--no-settle",
                             str(project), "-o", str(out)], env=env, cwd=ROOT,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                            preexec_fn=hang_ups_live)


def wait_until(condition, timeout: float) -> bool:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if condition():
            return True
        time.sleep(0.005)
    return False


@pytest.mark.parametrize("how", [signal.SIGTERM, signal.SIGHUP, signal.SIGKILL],
                         ids=["SIGTERM", "SIGHUP", "SIGKILL"])
def test_killing_render_stops_the_engine_and_cleans_up(tmp_path, how):
    project_folder = tmp_path / "calendar"
    shutil.copytree(SAMPLE, project_folder)
    project = project_folder / "calendar-2027.toml"
    scratch = tmp_path / "scratch"
    scratch.mkdir()
    out = tmp_path / "calendar.pdf"
    render = start_render(project, out, scratch)
    try:
        assert wait_until(lambda: engines_working_in(scratch), 120), "LuaLaTeX never started"
        os.kill(render.pid, how)
        render.wait(timeout=30)
    finally:
        if render.poll() is None:
            render.kill()
    # The engine has seconds of work left; dying with its parent takes milliseconds.
    assert wait_until(lambda: not engines_working_in(scratch), 0.5), "LuaLaTeX outlived render"
    assert not out.exists(), ("no partial PDF at the output path", render.returncode,
                              render.stderr.read())
    leftovers = list(scratch.glob("floatpage-build-*"))
    if how in (signal.SIGTERM, signal.SIGHUP):  # a closed terminal unwinds as a kill does
        assert render.returncode == 128 + how and "interrupted" in render.stderr.read()
        assert leftovers == []
    else:
        assert len(leftovers) == 1, "SIGKILL gives no chance to clean; the next run must"
        again = start_render(project, out, scratch)
        assert again.wait(timeout=300) == 0, again.stderr.read()
        assert list(scratch.glob("floatpage-build-*")) == []
        assert out.read_bytes().startswith(b"%PDF-")


IN_THE_FORK = """
import os, pathlib, runpy, sys, time
def slow_after_fork():
    # the engine's fork: its main.tex is written just before; stay in the hook a while
    if any(pathlib.Path(os.environ["TMPDIR"]).glob("floatpage-build-*/main.tex")):
        pathlib.Path(os.environ["FORK_MARK"]).write_text("in the hook")
        time.sleep(3)
os.register_at_fork(after_in_parent=slow_after_fork)
sys.argv[0] = "floatpage"
runpy.run_module("floatpage.cli.main", run_name="__main__", alter_sys=True)
"""


def test_a_hang_up_while_the_engine_is_forked_is_not_lost(tmp_path):
    """Python runs its at-fork hooks in the parent (logging's lock is one), and an exception
    raised in one is printed and dropped: a SIGHUP that came while the engine was being
    forked raised KeyboardInterrupt there ("Exception ignored in: <function _releaseLock>"),
    and the render went on and wrote its PDF, exit 0 (1 run in 5 of the SIGHUP case above at
    load 9). Here a hook of the test's own holds the render in that moment for 3 s."""
    project_folder = tmp_path / "calendar"
    shutil.copytree(SAMPLE, project_folder)
    scratch = tmp_path / "scratch"
    scratch.mkdir()
    out = tmp_path / "calendar.pdf"
    mark = tmp_path / "in-the-fork"
    env = {**os.environ, "TMPDIR": str(scratch), "FLOATPAGE_CACHE_DIR": str(scratch / "cache"),
           "FORK_MARK": str(mark)}
    render = subprocess.Popen([sys.executable, "-c", IN_THE_FORK, "render", "--no-settle",
                               str(project_folder / "calendar-2027.toml"), "-o", str(out)],
                              env=env, cwd=ROOT, stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, text=True, preexec_fn=hang_ups_live)
    try:
        assert wait_until(mark.exists, 120), "the engine was never forked"
        os.kill(render.pid, signal.SIGHUP)
        render.wait(timeout=60)
    finally:
        if render.poll() is None:
            render.kill()
    said = render.stderr.read()
    assert render.returncode == 128 + signal.SIGHUP and "interrupted" in said, (
        render.returncode, said)
    assert "Exception ignored" not in said, said
    assert wait_until(lambda: not engines_working_in(scratch), 0.5), "LuaLaTeX outlived render"
    assert not out.exists()


BEFORE_THE_DEATH_SIGNAL = """
import os, pathlib, runpy, sys, time
def slow_in_the_child():
    # in the engine's child, before its preexec_fn asks for the death signal
    if any(pathlib.Path(os.environ["TMPDIR"]).glob("floatpage-build-*/main.tex")):
        pathlib.Path(os.environ["FORK_MARK"]).write_text(str(os.getpid()))
        time.sleep(3)
os.register_at_fork(after_in_child=slow_in_the_child)
sys.argv[0] = "floatpage"
runpy.run_module("floatpage.cli.main", run_name="__main__", alter_sys=True)
"""


def what_became_of(pid: int) -> str | None:
    """"gone" once the process has exited, "became the engine" once it runs LuaLaTeX, None
    while it is still the forked Python child."""
    try:
        exe = os.readlink(f"/proc/{pid}/exe")
    except OSError:  # exited (a zombie has no executable either)
        return "gone"
    return "became the engine" if "tex" in Path(exe).name else None


def test_a_render_killed_before_the_engine_asked_for_its_death_signal_leaves_no_engine(
        tmp_path):
    """The engine asks to die with the render (PR_SET_PDEATHSIG) between fork and exec; a
    render killed before that never sends the signal, and LuaLaTeX typeset on, an orphan
    (the SIGKILL case above, once at load 7). Here the child is held before that moment for
    3 s, by a hook of the test's own, while the render is killed."""
    project_folder = tmp_path / "calendar"
    shutil.copytree(SAMPLE, project_folder)
    scratch = tmp_path / "scratch"
    scratch.mkdir()
    mark = tmp_path / "child"
    env = {**os.environ, "TMPDIR": str(scratch), "FLOATPAGE_CACHE_DIR": str(scratch / "cache"),
           "FORK_MARK": str(mark)}
    render = subprocess.Popen([sys.executable, "-c", BEFORE_THE_DEATH_SIGNAL, "render",
                               "--no-settle", str(project_folder / "calendar-2027.toml"), "-o",
                               str(tmp_path / "calendar.pdf")],
                              env=env, cwd=ROOT, stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL)
    try:
        assert wait_until(lambda: mark.exists() and mark.read_text().strip(), 120), \
            "the engine was never forked"
        child = int(mark.read_text())
        render.kill()
        render.wait(timeout=30)
        # the child wakes 3 s later: it must leave then, not exec LuaLaTeX as an orphan
        deadline = time.monotonic() + 60
        while (became := what_became_of(child)) is None and time.monotonic() < deadline:
            time.sleep(0.05)
        assert became == "gone", f"the engine's child {became} after the render was killed"
    finally:
        if render.poll() is None:
            render.kill()
        for pid in engines_working_in(scratch):
            os.kill(pid, signal.SIGKILL)
