"""A long editing session over a real pty: memory and CPU of the editor as keys pile up.

`floatpage edit PROJECT` runs on a pty (terminal_probe.Terminal, truecolour, 100 x 34); a
seeded user types KEYS keys (moves, resizes, Tab, page switches, undo and redo, anchors,
deletes, reheats) at a human pace, and every 50 keys the editor's resident memory (VmRSS)
and CPU seconds are printed; at the end, the CPU it uses over 30 s at rest. The undo
history (200 snapshots), the picture working copies (64) and the thumbnails (512) are
bounded, so the memory should level off; at rest the CPU should be about 0.

    .venv/bin/python benchmarks/editor_long_session.py PROJECT.toml [--keys 600] [--seed 1]

Never saves: the edits stay in memory and the editor is killed at the end (SIGKILL, so no
recovery file either); run it on a copy all the same.
"""

from __future__ import annotations

import argparse
import random
import sys
import time

from terminal_probe import DOWN, UP, Terminal

RIGHT, LEFT = b"\x1b[C", b"\x1b[D"
KEYS = ([b"\t"] * 6 + [RIGHT, LEFT, UP, DOWN] * 4
        + [b"\x1b[1;2C", b"\x1b[1;2B", b"+", b"-", b">", b"<", b"]", b"]", b"[",
           b"\x1a", b"\x1a", b"\x19", b"r", b"u", b"a", b"d", b"d"])
PAUSES_S = (0.05, 0.1, 0.3, 0.6)


def rss_mb(pid: int) -> int:
    for line in open(f"/proc/{pid}/status"):
        if line.startswith("VmRSS"):
            return int(line.split()[1]) // 1024
    return 0


def cpu_s(pid: int) -> float:
    fields = open(f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / 100


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("project")
    parser.add_argument("--keys", type=int, default=600)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    env = {"PATH": "/usr/bin:/bin", "HOME": "/tmp", "LANG": "C.UTF-8",
           "TERM": "xterm-256color", "COLORTERM": "truecolor"}
    term = Terminal([sys.executable, "-m", "floatpage.cli.main", "edit", args.project],
                    ".", env, 100, 34)
    try:
        term.until_seen(b"items", 60)
        term.until_quiet(2.0)
        pick = random.Random(args.seed)
        start, cpu0 = time.monotonic(), cpu_s(term.pid)
        print(f"opened: {rss_mb(term.pid)} MB")
        for done in range(1, args.keys + 1):
            term.send(pick.choice(KEYS))
            term.pump(pick.choice(PAUSES_S))
            if done % 50 == 0:
                print(f"{done} keys, {time.monotonic() - start:.0f} s: {rss_mb(term.pid)} MB, "
                      f"{cpu_s(term.pid) - cpu0:.1f} CPU s", flush=True)
        term.until_quiet(5.0, limit_s=120)
        before = cpu_s(term.pid)
        term.pump(30.0)
        print(f"at rest: {rss_mb(term.pid)} MB, {cpu_s(term.pid) - before:.2f} CPU s in 30 s")
    finally:
        term.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
