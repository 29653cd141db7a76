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
        assert render.returncode == 130 and "interrupted" in render.stderr.read()
        assert leftovers == []
    else:
        assert len(leftovers) == 1, "SIGKILL gives no chance to clean; the next run must"
        again = start_render(project, out, scratch)
        assert again.wait(timeout=300) == 0, again.stderr.read()
        assert list(scratch.glob("floatpage-build-*")) == []
        assert out.read_bytes().startswith(b"%PDF-")
