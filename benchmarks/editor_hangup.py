"""Hang-up, as users meet it: the ssh client dies, or the tmux session is killed. Part of
benchmarks/editor.py (`hangup`).

    .venv/bin/python benchmarks/editor.py hangup

Each way starts `floatpage edit` on a copy of the greeting card, selects an item and moves it
(an unsaved edit), then takes the terminal away: over the loopback sshd by SIGKILL of the
local `ssh` client (sshd then closes the remote pty, as on a dropped link); in tmux, started
through `make run` as the README says, by `tmux kill-session`. It reports how long the editor
lived on, the CPU it used meanwhile, whether `.NAME.toml.recover` holds the move, and that the
project itself was not written.
"""

from __future__ import annotations

import argparse
import os
import shlex
import shutil
import signal
import subprocess
import tempfile
import time
from pathlib import Path

from loopback_sshd import LoopbackSshd
from terminal_probe import DOWN, Terminal

ROOT = Path(__file__).resolve().parents[1]
SAMPLE = "greeting-card"
GONE_WITHIN_S = 5.0
CLOCK_TICKS = os.sysconf("SC_CLK_TCK")


def editor_pid(project: Path, limit_s: float = 30.0) -> int:
    """The pid of the `floatpage edit` process whose command line names `project`."""
    deadline = time.monotonic() + limit_s
    while time.monotonic() < deadline:
        for entry in Path("/proc").iterdir():
            if not entry.name.isdigit():
                continue
            try:
                argv = (entry / "cmdline").read_bytes().split(b"\0")
            except OSError:
                continue
            if b"edit" in argv and str(project).encode() in argv and any(
                    part.endswith(b"floatpage") for part in argv[:2]):
                return int(entry.name)
        time.sleep(0.05)
    raise RuntimeError(f"no floatpage edit process for {project}")


def cpu_seconds(pid: int) -> float | None:
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except OSError:
        return None
    if fields[0] == "Z":
        return None
    return (int(fields[11]) + int(fields[12])) / CLOCK_TICKS


def watch_exit(pid: int) -> tuple[float | None, float]:
    """(seconds until `pid` is gone or None, CPU seconds it used meanwhile)."""
    start, used, first = time.monotonic(), 0.0, cpu_seconds(pid)
    while time.monotonic() - start < GONE_WITHIN_S:
        now = cpu_seconds(pid)
        if now is None:
            return time.monotonic() - start, used
        used = now - (first or 0.0)
        time.sleep(0.01)
    return None, used


def outcome(way: str, project: Path, before: bytes, gone_s: float | None, cpu_s: float) -> str:
    recovery = project.with_name(f".{project.name}.recover")
    lived = f"gone after {gone_s:.2f} s" if gone_s is not None else \
        f"STILL RUNNING after {GONE_WITHIN_S:.0f} s"
    cpu = f"{cpu_s:.2f} s of CPU meanwhile ({100 * cpu_s / (gone_s or GONE_WITHIN_S):.0f} %)"
    saved = "recovery file written" if recovery.is_file() and recovery.read_bytes() != before \
        else "NO RECOVERY FILE"
    untouched = "project untouched" if project.read_bytes() == before else "PROJECT WRITTEN"
    return f"{way}: editor {lived}, {cpu}, {saved}, {untouched}"


def copy_sample(scratch: Path, name: str) -> Path:
    folder = scratch / name
    shutil.copytree(ROOT / "sample_projects" / SAMPLE, folder)
    return next(folder.glob("*.toml"))


def over_ssh(scratch: Path) -> str:
    project = copy_sample(scratch, "ssh")
    before = project.read_bytes()
    editor = str(ROOT / ".venv" / "bin" / "floatpage")
    with LoopbackSshd() as sshd:
        command = (f"cd {shlex.quote(str(project.parent))} && exec env TERM=xterm-256color "
                   f"LANG=C.UTF-8 {shlex.join([editor, 'edit', str(project)])}")
        term = Terminal(sshd.ssh_argv(command), str(scratch),
                        {**os.environ, "TERM": "xterm-256color"}, 100, 32)
        try:
            term.until_seen(b"items")
            term.until_quiet(quiet_s=0.5)
            term.send(b"\t")
            for _ in range(5):
                term.pump(0.1)
                term.send(DOWN)
            term.until_quiet(quiet_s=1.0)
            pid = editor_pid(project)
            os.kill(term.pid, signal.SIGKILL)  # the client dies, as when a laptop drops off
            gone_s, cpu_s = watch_exit(pid)
        finally:
            term.close()
    return outcome("ssh client killed", project, before, gone_s, cpu_s)


def in_tmux(scratch: Path) -> str:
    project = copy_sample(scratch, "tmux")
    before = project.read_bytes()
    tmux = ["tmux", "-L", f"floatpage-bench-{os.getpid()}", "-f", "/dev/null"]
    command = f"make -C {shlex.quote(str(ROOT))} run SAMPLE={shlex.quote(str(project))}"
    subprocess.run([*tmux, "new-session", "-d", "-s", "bench", "-x", "100", "-y", "32",
                    command], check=True)
    try:
        deadline = time.monotonic() + 120
        while b"items" not in subprocess.run([*tmux, "capture-pane", "-p", "-t", "bench"],
                                             capture_output=True).stdout:
            if time.monotonic() > deadline:
                raise RuntimeError("the editor did not come up in tmux")
            time.sleep(0.2)
        subprocess.run([*tmux, "send-keys", "-t", "bench", "Tab"], check=True)
        for _ in range(5):
            time.sleep(0.1)
            subprocess.run([*tmux, "send-keys", "-t", "bench", "Down"], check=True)
        time.sleep(1.0)
        pid = editor_pid(project)
        subprocess.run([*tmux, "kill-session", "-t", "bench"], check=True)
        gone_s, cpu_s = watch_exit(pid)
    finally:
        subprocess.run([*tmux, "kill-server"], capture_output=True)
    return outcome("tmux session killed", project, before, gone_s, cpu_s)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--way", choices=["ssh", "tmux"], nargs="*", default=["ssh", "tmux"])


def run(args: argparse.Namespace) -> None:
    with tempfile.TemporaryDirectory() as folder:
        for way in args.way:
            print((over_ssh if way == "ssh" else in_tmux)(Path(folder)), flush=True)
