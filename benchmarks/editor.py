"""The editor benchmark: what a user at the far end of an SSH link gets, against a trivial
Textual app over the same link in the same run.

    .venv/bin/python benchmarks/editor.py                   # link: over a real sshd, 100x32 and 80x24
    .venv/bin/python benchmarks/editor.py link --link pty   # the same over a bare pty (no sshd)
    .venv/bin/python benchmarks/editor.py frames            # headless frame time at N = 50 and 200
    .venv/bin/python benchmarks/editor.py hangup            # kill the ssh client / the tmux session
    .venv/bin/python benchmarks/editor.py link --baseline /tmp/base   # and another commit's editor

`--baseline DIR` adds rows for the editor of another checkout (e.g. `git archive COMMIT | tar
-x -C DIR`), run with this checkout's venv, in the same run: a before and after that share
the machine's load, which on a shared machine varies more than the change being measured.

`link` starts its own sshd on 127.0.0.1 (benchmarks/loopback_sshd.py: a throwaway host key and
client key in a temporary folder; it is stopped at the end, also on failure), then for each
terminal size runs, through `ssh -tt` on a pty of that size, a trivial Textual app (a label
showing the last key) and `floatpage edit` on each sample. Per session it counts (see
benchmarks/terminal_probe.py): one arrow press from rest, a 1 s held arrow (30 presses),
bytes a second while it is held, the seconds from the last key until nothing more is written
(2 s quiet), idle bytes, and the median time from a key to the first byte of its answer
and to the whole answer on the screen (the top line changed too: `terminal_probe.
answer_times`), each from 2 s of rest. The latency goal is checked on the whole answer.
The apps' keys are sent in turns, one app's key after another's (`terminal_probe.
interleaved_answers`, all the sessions open at once, idle between their keys), so that
every app's keys meet the same load on a shared machine; `--sequential` sends each app's
21 keys in one stretch, app after app, as the tables before the sixth session of
2026-11-26 were measured. The byte figures are measured app after app either way. The
remote end gets TERM=xterm-256color and COLORTERM=truecolor: every colour is sent in full,
the costliest case (`--colors 256` for a link that does not pass COLORTERM). The goals
are issue 11's, at 100x32. Compare within one run; the machine is shared.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import shlex
import shutil
import sys
import tempfile
import textwrap
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import editor_frames  # noqa: E402
import editor_hangup  # noqa: E402
from loopback_sshd import LoopbackSshd  # noqa: E402
from terminal_probe import (  # noqa: E402
    SessionFigures, Terminal, interleaved_answers, measure_session, median_p90)

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = ("greeting-card", "shop-flyer", "calendar-2027")
TRIVIAL_APP = textwrap.dedent("""
    from textual.app import App
    from textual.widgets import Label

    class Trivial(App):
        def compose(self):
            yield Label("press keys", id="last")
        def on_key(self, event):
            self.query_one("#last", Label).update(f"last key: {event.key}")
    Trivial().run()
""")
GOALS = {"one_key_kb": 10.0, "held_kb": 300.0, "steady_kb_s": 100.0, "still_after_s": 2.0,
         "idle_b_s": 0.0}
LATENCY_GOAL = 2.0  # times the trivial app's median


def remote_env(colors: str) -> dict[str, str]:
    env = {"TERM": "xterm-256color", "LANG": "C.UTF-8"}
    if colors == "truecolor":
        env["COLORTERM"] = "truecolor"
    return env


def open_terminal(link: str, sshd: LoopbackSshd | None, argv: list[str], cwd: Path,
                  size: tuple[int, int], colors: str) -> Terminal:
    """`argv` in `cwd`, on a pty of `size` (columns, rows): directly, or through ssh -tt."""
    env = remote_env(colors)
    if link == "pty":
        local = {k: v for k, v in os.environ.items() if k != "COLORTERM"}
        return Terminal(argv, str(cwd), {**local, **env}, *size)
    assert sshd is not None
    assignments = " ".join(f"{key}={shlex.quote(value)}" for key, value in env.items())
    command = f"cd {shlex.quote(str(cwd))} && exec env {assignments} {shlex.join(argv)}"
    local = {**os.environ, "TERM": env["TERM"]}
    return Terminal(sshd.ssh_argv(command), str(cwd), local, *size)


PACKAGE_DIRS = ("physics", "model", "typeset", "tui", "cli", "latex_templates", "starters", "merge")


def baseline_package(checkout: Path, scratch: Path) -> Path:
    """A folder to put first on PYTHONPATH so that `floatpage` is imported from `checkout`:
    floatpage/<package> links to each of its top-level package folders (pyproject.toml's
    package-dir), as the editable install does for this checkout."""
    root = scratch / "baseline-package"
    (root / "floatpage").mkdir(parents=True)
    for name in PACKAGE_DIRS:
        (root / "floatpage" / name).symlink_to(checkout.resolve() / name)
    return root


def sessions(scratch: Path, baseline: Path | None = None
             ) -> list[tuple[str, list[str], Path, bytes, bool]]:
    """(name, argv, folder, text that shows it is up, select an item first) for each app."""
    trivial = scratch / "trivial.py"
    trivial.write_text(TRIVIAL_APP)
    rows = [("trivial Textual app", [sys.executable, str(trivial)], scratch, b"press keys",
             False)]
    editor = str(ROOT / ".venv" / "bin" / "floatpage")
    for sample in SAMPLES:
        folder = scratch / sample
        shutil.copytree(ROOT / "sample_projects" / sample, folder)
        toml = next(folder.glob("*.toml"))
        rows.append((sample, [editor, "edit", str(toml)], folder, b"items", True))
    if baseline is not None:
        package = baseline_package(baseline, scratch)
        for sample in SAMPLES:
            folder = scratch / f"baseline-{sample}"
            shutil.copytree(baseline / "sample_projects" / sample, folder)
            toml = next(folder.glob("*.toml"))
            argv = ["env", f"PYTHONPATH={package}", sys.executable, "-m", "floatpage.cli.main",
                    "edit", str(toml)]
            rows.append((f"{sample}, baseline", argv, folder, b"items", True))
    return rows


@contextlib.contextmanager
def scratch_folder(tries: int = 10):
    """A temporary folder, removed at the end once the editors in it have gone: an editor
    whose session ends writes its recovery file (and lets go of its lock) within a second of
    the hang-up, and removing the folder meanwhile failed ("Directory not empty") after
    every table was printed: the run ended in a traceback and exit status 1."""
    folder = tempfile.mkdtemp(prefix="floatpage-editor-bench-")
    try:
        yield folder
    finally:
        for _ in range(tries):
            try:
                shutil.rmtree(folder)
                break
            except OSError:
                time.sleep(0.5)


def run_link(args: argparse.Namespace) -> None:
    sizes = [tuple(int(part) for part in size.split("x")) for size in args.size]
    with scratch_folder() as folder:
        sshd = LoopbackSshd() if args.link == "ssh" else None
        try:
            if sshd is not None:
                sshd.start()
            for size in sizes:  # fresh copies: a killed session leaves a recovery file behind
                scratch = Path(folder) / f"{size[0]}x{size[1]}"
                scratch.mkdir()
                apps = sessions(scratch, args.baseline)
                results: list[tuple[str, SessionFigures]] = []
                terms: list[Terminal] = []
                presses = 21 if args.sequential else 0
                try:
                    for name, argv, cwd, ready, select_first in apps:
                        term = open_terminal(args.link, sshd, argv, cwd, size, args.colors)
                        terms.append(term)
                        results.append((name, measure_session(term, ready=ready,
                                                              select_first=select_first,
                                                              presses=presses)))
                        if args.sequential:
                            term.close()
                            terms.remove(term)
                        print(f"  measured {name} at {size[0]}x{size[1]}", file=sys.stderr)
                    if not args.sequential:  # the keys, all apps in turns (the bytes above)
                        for (name, figures), (firsts, wholes) in zip(
                                results, interleaved_answers(terms)):
                            figures.latency_ms, figures.latency_p90_ms = median_p90(firsts)
                            figures.whole_ms, figures.whole_p90_ms = median_p90(wholes)
                        print(f"  measured the keys at {size[0]}x{size[1]}", file=sys.stderr)
                finally:
                    for term in terms:
                        term.close()
                print_table(args, size, results)
        finally:
            if sshd is not None:
                sshd.stop()


def print_table(args: argparse.Namespace, size: tuple[int, int],
                results: list[tuple[str, SessionFigures]]) -> None:
    """One row per app; the latency goal is checked on the whole answer."""
    floor, whole_floor = results[0][1].latency_ms, results[0][1].whole_ms
    print(f"\n{args.link} link, {size[0]}x{size[1]}, {args.colors} colours "
          f"(goals at 100x32; ✗ marks a miss)\n")
    print("| app | one arrow from rest | 1 s held arrow | steady motion | still after release "
          "| idle | key to first byte, median (p90) | key to whole answer, median (p90) |")
    print("|---|---|---|---|---|---|---|---|")
    for name, m in results:
        is_editor = name != results[0][0]

        def mark(key: str) -> str:
            return " ✗" if is_editor and getattr(m, key) > GOALS[key] else ""
        ratio, whole_ratio = m.latency_ms / floor, m.whole_ms / whole_floor
        late = " ✗" if is_editor and whole_ratio > LATENCY_GOAL else ""
        print(f"| {name} | {m.one_key_kb:.1f} KB{mark('one_key_kb')} "
              f"| {m.held_kb:.1f} KB{mark('held_kb')} | {m.steady_kb_s:.1f} KB/s"
              f"{mark('steady_kb_s')} | {m.still_after_s:.2f} s{mark('still_after_s')} "
              f"| {m.idle_b_s:.0f} B/s{mark('idle_b_s')} | {m.latency_ms:.1f} ms "
              f"({m.latency_p90_ms:.1f}) = {ratio:.1f}x | {m.whole_ms:.1f} ms "
              f"({m.whole_p90_ms:.1f}) = {whole_ratio:.1f}x{late} |")
    sys.stdout.flush()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parts = parser.add_subparsers(dest="part")
    link = parts.add_parser("link", help="bytes and latency over ssh or a pty (the default)")
    for target in (parser, link):
        target.add_argument("--link", choices=["ssh", "pty"], default="ssh")
        target.add_argument("--size", nargs="*", default=["100x32", "80x24"],
                            help="COLUMNSxROWS, one or more")
        target.add_argument("--colors", choices=["truecolor", "256"], default="truecolor")
        target.add_argument("--baseline", type=Path, default=None,
                            help="another checkout whose editor gets rows of its own")
        target.add_argument("--sequential", action="store_true",
                            help="each app's keys in one stretch, app after app (before "
                                 "2026-11-26's sixth session); the default: in turns")
    editor_frames.add_arguments(parts.add_parser("frames", help="headless frame time"))
    editor_hangup.add_arguments(parts.add_parser("hangup", help="hang-up over ssh and tmux"))
    args = parser.parse_args()
    if args.part == "frames":
        editor_frames.run(args)
    elif args.part == "hangup":
        editor_hangup.run(args)
    else:
        run_link(args)


if __name__ == "__main__":
    main()
