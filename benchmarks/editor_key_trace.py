"""Where a key's answer goes: `floatpage edit` over a real pty (or the loopback SSH link),
with a timestamp at each stage of the editor's answer to an arrow key, from rest.

    .venv/bin/python benchmarks/editor_key_trace.py                      # card, 100x32, pty
    .venv/bin/python benchmarks/editor_key_trace.py shop-flyer --size 80x24 --link ssh

The editor runs in a child process started by this same script (`--traced PROJECT`), which
wraps the stages' functions with timestamps written to a log; the parent types the keys as
benchmarks/terminal_probe.py does and reads the log afterwards. Per stage it prints the
median time in the stage and when it ended, counted from the key's arrival in the driver;
then the median time from the key to the first write flushed to the terminal (the preview,
painted past Textual since this session) and to the last before the physics frame it wakes
(the top bar, through Textual, until this session sent it with the preview). Only
flushes that carry bytes count. The wrappers cost a few microseconds each; the machine is
shared, so compare stages within one run.
"""

from __future__ import annotations

import argparse
import functools
import os
import shutil
import shlex
import statistics
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from terminal_probe import DOWN, QUIET_S, UP, Screen, Terminal, answer_times  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
KEY_WINDOW_S = 0.1


def run_traced(project: str, log_path: str) -> int:
    """The editor, with a timestamp before and after each stage (child process)."""
    from textual import _compositor, events
    from textual import screen as textual_screen
    from textual.widgets import Label

    from floatpage.cli.main import main
    from floatpage.tui import cell_canvas, direct_paint, editor_screen, page_painter, page_preview
    from floatpage.tui import session, shadow_screen, terminal_driver

    log = open(log_path, "w", buffering=1)

    def mark(name: str) -> None:
        log.write(f"{time.perf_counter():.6f} {name}\n")

    def stage(owner, attribute: str, name: str) -> None:
        original = getattr(owner, attribute)

        @functools.wraps(original)
        def timed(*args, **kwargs):
            mark(name + "+")
            try:
                return original(*args, **kwargs)
            finally:
                mark(name + "-")
        setattr(owner, attribute, timed)

    driver = terminal_driver.HangupAwareDriver
    process_message = driver.process_message

    def key_arrives(self, message) -> None:
        if isinstance(message, events.Key):
            mark("key")
        process_message(self, message)
    driver.process_message = key_arrives
    flush = terminal_driver.MeteredFile.flush

    def flushed(self) -> None:
        characters = self._unflushed
        flush(self)
        if characters:  # an empty write (all its cells already shown) reaches no terminal
            mark("flushed")
    terminal_driver.MeteredFile.flush = flushed
    write_prompt = getattr(driver, "write_prompt", None)
    if write_prompt is not None:  # written at once from the app's thread (the rest queued)
        def written_now(self, data: str) -> None:
            handed = self._handed
            write_prompt(self, data)
            if self._handed == handed:  # all of it written now; else the queued rest's
                mark("flushed")           # flush is marked when it comes
                mark("written at once")
        driver.write_prompt = written_now
    for owner, attribute, name in (
            (session.EditSession, "nudge", "the move (session)"),
            (editor_screen.EditorScreen, "page_view", "page view, guides"),
            (page_painter.PagePainter, "paint", "painting the page"),
            (cell_canvas.StripCache, "update", "finding changed cells"),
            (direct_paint.DirectPainter, "paint", "preview to the terminal"),
            (cell_canvas.StripCache, "segments", "  changed cells to segments"),
            (terminal_driver.HangupAwareDriver, "paint_cells", "  shadow screen, write queued"),
            (page_preview.PagePreview, "show", "preview, in all"),
            (Label, "update", "top bar text"),
            (editor_screen.EditorScreen, "redraw", "redraw, in all"),
            (editor_screen.EditorScreen, "action_nudge", "key's action, in all"),
            (_compositor.Compositor, "render_update", "Textual's compositor"),
            (_compositor.ChopsUpdate, "render_segments", "Textual's segments to text"),
            (shadow_screen.ShadowScreen, "rewrite", "shadow screen (Textual's output)"),
            (textual_screen.Screen, "_on_timer_update", "Textual's screen update, in all"),
            (editor_screen.EditorScreen, "tick", "tick")):
        stage(owner, attribute, name)
    return main(["edit", project])


def open_editor(args: argparse.Namespace, folder: Path, log: Path):
    columns, rows = (int(part) for part in args.size.split("x"))
    project = next(folder.glob("*.toml"))
    argv = [sys.executable, str(Path(__file__).resolve()), "--traced", str(project), str(log)]
    env = {"TERM": "xterm-256color", "COLORTERM": "truecolor", "LANG": "C.UTF-8"}
    if args.link == "pty":
        return Terminal(argv, str(folder), {**os.environ, **env}, columns, rows), None
    from loopback_sshd import LoopbackSshd

    sshd = LoopbackSshd()
    sshd.start()
    assignments = " ".join(f"{key}={shlex.quote(value)}" for key, value in env.items())
    command = f"cd {shlex.quote(str(folder))} && exec env {assignments} {shlex.join(argv)}"
    term = Terminal(sshd.ssh_argv(command), str(folder), {**os.environ, "TERM": env["TERM"]},
                    columns, rows)
    return term, sshd


def type_keys(term: Terminal, presses: int) -> list[tuple[float, float]]:
    """Select the first item, then arrows from rest (2 s quiet, as benchmarks/editor.py);
    the ms to the first byte of each answer and to the whole of it on the screen
    (`terminal_probe.answer_times`)."""
    screen = Screen(term, term.columns, term.rows)
    term.until_seen(b"items")
    term.until_quiet(1.0)
    term.send(b"\t")
    term.until_quiet(1.0)
    latencies = []
    for press in range(presses):
        term.until_quiet(QUIET_S)
        screen.catch_up()
        term.send(DOWN if press % 2 else UP)
        times = answer_times(term, time.monotonic(), screen)
        if times is not None:
            latencies.append((1000 * times[0], 1000 * times[1]))
    term.until_quiet(1.0)
    return latencies


def stage_times(log: Path, presses: int) -> dict[str, list[float]]:
    """Per stage, (ms in it, ms from the key to its end) for the last `presses` keys; each key
    counted until the physics frame it wakes (or KEY_WINDOW_S)."""
    events = [(float(when), name) for when, name in
              (line.rstrip("\n").split(" ", 1) for line in log.read_text().splitlines())]
    keys = [index for index, (_, name) in enumerate(events) if name == "key"][-presses:]
    times: dict[str, list[float]] = defaultdict(list)
    for index in keys:
        key_at = events[index][0]
        opened, flushes, at_once = {}, [], 0
        for when, name in events[index + 1:]:
            if name in ("key", "tick+") or when - key_at > KEY_WINDOW_S:
                break
            if name == "flushed":
                flushes.append(1000 * (when - key_at))
            elif name == "written at once":
                at_once += 1
            elif name.endswith("+"):
                opened[name[:-1]] = when
            elif name[:-1] in opened:
                times[name[:-1]].append(1000 * (when - opened.pop(name[:-1])))
                times[name[:-1] + "@"].append(1000 * (when - key_at))
        if flushes:
            times["key to the first write flushed"].append(flushes[0])
            times["key to the last write flushed"].append(flushes[-1])
            times["writes flushed (count)"].append(len(flushes))
            times["of which written at once (count)"].append(at_once)
    return times


def main() -> None:
    if sys.argv[1:2] == ["--traced"]:
        sys.exit(run_traced(sys.argv[2], sys.argv[3]))
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("sample", nargs="?", default="greeting-card")
    parser.add_argument("--size", default="100x32")
    parser.add_argument("--link", choices=["pty", "ssh"], default="pty")
    parser.add_argument("--presses", type=int, default=21)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch) / args.sample
        shutil.copytree(ROOT / "sample_projects" / args.sample, folder)
        log = Path(scratch) / "trace.log"
        term, sshd = open_editor(args, folder, log)
        try:
            latencies = type_keys(term, args.presses)
        finally:
            term.close()
            if sshd is not None:
                sshd.stop()
        times = stage_times(log, args.presses)
    print(f"{args.sample}, {args.size}, {args.link}: {len(latencies)} arrows from rest, medians")
    print(f"  key sent to the first byte back: "
          f"{statistics.median(first for first, _ in latencies):.1f} ms, to the whole answer "
          f"on the screen: {statistics.median(last for _, last in latencies):.1f} ms")
    print(f"  {'stage':36s} {'in it':>8s} {'ended, after the key':>22s}")
    for name, values in times.items():
        if name.endswith("@"):
            continue
        ended = times.get(name + "@")
        unit = "" if name.endswith("(count)") else " ms"
        print(f"  {name:36s} {statistics.median(values):6.2f}{unit}"
              + (f" {statistics.median(ended):17.2f} ms" if ended else ""))


if __name__ == "__main__":
    main()
