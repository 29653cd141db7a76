"""Run LuaLaTeX once on a .tex, safely, and turn its failures into errors a user can read.

Not PyLaTeX's `generate_pdf`: it runs latexmk (two runs for a multi-page
document from a clean folder) and gives no control over the environment, the
timeout or the log. We call the engine directly, once:

- in a build folder given by the caller (a fresh temporary one), stdin closed;
- `-no-shell-escape`, `openin_any=p`/`openout_any=p` (no absolute, parent or
  hidden paths); pictures are found by bare name through TEXINPUTS;
- SOURCE_DATE_EPOCH fixed, so the PDF's dates never change (the caller's own, if set), and
  TZ and the locale fixed too, so a laptop in Paris, a CI runner in UTC and a Docker image whose
  LANG names a locale it lacks make the same bytes (see engine_environment);
- a timeout that kills the whole process group (`\\def\\x{\\x}\\x` runs forever);
- the engine dies with its parent (Linux's PR_SET_PDEATHSIG), so a killed `render` leaves no
  LuaLaTeX running, and runs under a memory limit (`engine_memory_mb`, of address space).
"""

from __future__ import annotations

import contextlib
import os
import shutil
import signal
import subprocess
import threading
import time
from pathlib import Path
from typing import Iterator

from floatpage.typeset.errors import (EngineDidNotStart, LatexCompileError, LogError,
                                      RenderError, TexNotFoundError)
from floatpage.typeset.latex_log import errors_with_items

ENGINE = "lualatex"
# 2026-01-01T00:00:00Z: any fixed instant works; a changing one breaks reproducibility.
DEFAULT_SOURCE_DATE_EPOCH = "1767225600"
MAIN = "main.tex"
ENGINE_OUTPUT = "engine-output.txt"  # what LuaLaTeX printed: all it says if it ends before a log
# Address space, not resident memory: LuaTeX maps its font caches, so it reserves more than it
# touches. A real page takes ~0.4 GB of address space; 1 MB of text in one box took 2.5 GB.
# FLOATPAGE_ENGINE_MEMORY_MB changes it, for a machine with less (or a page that needs more).
DEFAULT_MEMORY_MB = 3072
MEMORY_VARIABLE = "FLOATPAGE_ENGINE_MEMORY_MB"
PR_SET_PDEATHSIG = 1


def engine_memory_mb() -> int:
    """The engine's memory limit in MB: $FLOATPAGE_ENGINE_MEMORY_MB, else 3072.  A value that
    is not a whole number of megabytes is refused, rather than ignored (no limit at all)."""
    text = os.environ.get(MEMORY_VARIABLE, "").strip()
    if not text:
        return DEFAULT_MEMORY_MB
    if not text.isdigit() or not 1 <= int(text) <= 1 << 30:
        raise RenderError(f"{MEMORY_VARIABLE}={text[:40]!r} is not a memory limit: give a whole "
                          f"number of megabytes, e.g. {MEMORY_VARIABLE}=4096, or unset it for "
                          f"{DEFAULT_MEMORY_MB}")
    return int(text)


def limit_engine(memory_bytes: int, parent: int) -> None:
    """Run in the child between fork and exec: die with the parent, and cap memory.

    The death signal is asked for only here, after the fork: a parent killed before that
    (SIGKILL at that moment: the kill test's SIGKILL case once, at load 7) never sends it, and the
    engine typeset on, an orphan. So the child then looks whether ``parent`` is still its
    parent, and leaves at once if not (prctl(2) says to)."""
    try:
        import ctypes

        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
    except (OSError, AttributeError):
        pass  # not Linux: the timeout still stops a runaway engine
    if os.getppid() != parent:
        os._exit(1)
    try:
        import resource

        resource.setrlimit(resource.RLIMIT_AS, (memory_bytes, memory_bytes))
    except (ImportError, ValueError, OSError):
        pass


def engine_path() -> str:
    path = shutil.which(ENGINE)
    if path is None:
        raise TexNotFoundError(
            "LuaLaTeX is not installed, so no PDF can be made. On Debian/Ubuntu install "
            "texlive-luatex texlive-latex-extra texlive-fonts-recommended texlive-fonts-extra "
            "fonts-texgyre (the project's Makefile does this)")
    return path


def engine_command(main: str = MAIN) -> list[str]:
    return [engine_path(), "-no-shell-escape", "-interaction=nonstopmode", "-halt-on-error",
            "-file-line-error", main]


def source_date_epoch() -> str:
    """The instant written as the PDF's CreationDate and ModDate: $SOURCE_DATE_EPOCH (whole
    seconds since 1970, as reproducible-builds.org defines it), else 2026-01-01.  Set but
    empty counts as unset: LuaTeX read it as "now", and every PDF differed.  A value that is
    not a whole number is refused, as the specification asks: LuaTeX read "abc" as 1970."""
    text = os.environ.get("SOURCE_DATE_EPOCH", "").strip()
    if not text:
        return DEFAULT_SOURCE_DATE_EPOCH
    if not text.isascii() or not text.isdigit() or len(text) > 12:
        raise RenderError(f"SOURCE_DATE_EPOCH={text[:40]!r} is not a time: give whole seconds "
                          f"since 1970-01-01 UTC, e.g. SOURCE_DATE_EPOCH=$(git log -1 "
                          f"--format=%ct), or unset it for the fixed date floatpage writes")
    return text


def check_engine_settings() -> None:
    """Before any work: the engine is installed, and the environment's settings for it
    (memory, date) can be read; a bad one is said once, not once per record of a merge."""
    engine_path()
    engine_memory_mb()
    source_date_epoch()


def engine_environment(picture_dir: Path | None) -> dict[str, str]:
    """The engine's environment: the caller's (PATH, TEXMF settings), with the file access
    closed, the date fixed, and TZ and the locale fixed.  TZ reached the PDF's dates
    (TZ=Pacific/Kiritimati wrote "D:20260101140000+14'00'" where UTC wrote "...000000Z"), and
    LuaTeX stops at once, before a log, under a LANG or LC_ALL naming a locale the machine
    lacks ("Unable to read environment locale: exit now", a common Docker image's state).
    LC_ALL=C exists everywhere and makes the same PDF as C.UTF-8 (the multilingual card)."""
    env = dict(os.environ)
    env.update(openin_any="p", openout_any="p", shell_escape="f",
               SOURCE_DATE_EPOCH=source_date_epoch(), FORCE_SOURCE_DATE="1",
               TZ="UTC", LC_ALL="C")
    env.pop("TEXMFOUTPUT", None)
    if picture_dir is not None:
        # The trailing separator keeps TeX's own search path after the picture cache.
        env["TEXINPUTS"] = str(picture_dir) + os.pathsep
    return env


def run_engine(build_dir: Path, *, timeout_s: float, picture_dir: Path | None = None
               ) -> tuple[int | None, float]:
    """Run the engine on build_dir/main.tex; (exit code or None on timeout, seconds)."""
    memory_bytes = engine_memory_mb() << 20
    parent = os.getpid()
    start = time.perf_counter()
    process = None
    try:
        with stops_held() as held:
            with open(build_dir / ENGINE_OUTPUT, "wb") as said:
                process = subprocess.Popen(engine_command(), cwd=build_dir,
                                           stdin=subprocess.DEVNULL, stdout=said,
                                           stderr=subprocess.STDOUT,
                                           env=engine_environment(picture_dir),
                                           start_new_session=True,
                                           preexec_fn=lambda: limit_engine(memory_bytes, parent))
        if held:  # now, to the handler it was meant for (the command's raises KeyboardInterrupt)
            signal.raise_signal(held[0])
        code = process.wait(timeout=timeout_s)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.wait()
        code = None
    except BaseException:  # Ctrl+C or SIGTERM while typesetting: the engine goes too
        if process is not None:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
        raise
    return code, time.perf_counter() - start


STOPS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)


@contextlib.contextmanager
def stops_held() -> Iterator[list[int]]:
    """While the engine is forked, a Ctrl+C, SIGTERM or SIGHUP is noted, not raised; the list
    yielded holds those that came. Python runs its at-fork hooks in the parent (logging's
    lock), and an exception raised there is printed and dropped ("Exception ignored in:
    <function _releaseLock>"): a SIGHUP that came just then was lost, and the render went on
    to write its PDF (1 run in 5 of the kill test at load 9). Only the main thread handles
    signals, so elsewhere (the editor's export worker) nothing changes."""
    held: list[int] = []
    if threading.current_thread() is not threading.main_thread():
        yield held
        return
    previous = {stop: signal.getsignal(stop) for stop in STOPS}
    for stop, handler in previous.items():
        if callable(handler):  # ignored or default signals stay so
            signal.signal(stop, lambda signum, frame: held.append(signum))
    try:
        yield held
    finally:
        for stop, handler in previous.items():
            if callable(handler):
                signal.signal(stop, handler)


def compile_pdf(tex: str, build_dir: Path, *, labels: list[str] | None = None,
                timeout_s: float = 120.0, picture_dir: Path | None = None,
                keep_log: Path | None = None) -> Path:
    """Compile `tex` in `build_dir` with one engine run; return the PDF's path there.

    On failure raise LatexCompileError with the log's errors tied to their items;
    the log is copied to `keep_log` (if given) so it outlives the build folder.
    """
    build_dir = Path(build_dir)
    (build_dir / MAIN).write_text(tex, encoding="utf-8")
    code, _ = run_engine(build_dir, timeout_s=timeout_s, picture_dir=picture_dir)
    pdf = build_dir / "main.pdf"
    log_file = build_dir / "main.log"
    if code == 0 and pdf.is_file():
        return pdf
    log_path = None
    log = log_file.read_text(encoding="utf-8", errors="replace") if log_file.is_file() else ""
    if log and keep_log is not None:
        try:
            shutil.copyfile(log_file, keep_log)
            log_path = keep_log
        except OSError:  # e.g. the output folder does not exist: say so without a log
            log_path = None
    elif log:
        log_path = log_file
    if code is None:
        raise LatexCompileError(log_path, [LogError(None, f"LuaLaTeX was still running after "
                                                    f"{timeout_s:g} s and was stopped")],
                                "The PDF was not made: typesetting took too long.")
    output = engine_output(build_dir)
    if not log and code > 0 and not out_of_memory(code, output):
        # A signal (code < 0: the out-of-memory killer's SIGKILL) is told as memory, below.
        raise EngineDidNotStart(
            f"No PDF could be made: the TeX installation could not start LuaLaTeX, which "
            f"ended (exit code {code}) before it wrote a log; it said: "
            f"{last_lines(output) or 'nothing'}. Try `lualatex --version` and `kpsewhich "
            f"lualatex.fmt` in this shell; a missing format is rebuilt with "
            f"`fmtutil-sys --byfmt lualatex`.")
    errors = errors_with_items(log, tex, labels or [])
    if out_of_memory(code, log) or not errors:
        # Under RLIMIT_AS an allocation that fails ends LuaTeX at once, mid-line in its log.
        raise LatexCompileError(log_path, [LogError(None, memory_message())],
                                "The PDF was not made: LuaLaTeX stopped without an error in "
                                "its log, which is how it fails when it runs out of memory.")
    raise LatexCompileError(log_path, errors, "The PDF was not made; LaTeX reported:")


def engine_output(build_dir: Path, tail_bytes: int = 65536) -> str:
    """The end of what the engine printed (kept in the build folder): the only words there
    are when LuaLaTeX ends before its log, where floatpage used to blame memory. Its end
    only: a run that printed for its whole two minutes leaves megabytes."""
    try:
        with open(build_dir / ENGINE_OUTPUT, "rb") as said:
            said.seek(max(0, os.fstat(said.fileno()).st_size - tail_bytes))
            return said.read().decode("utf-8", errors="replace")
    except OSError:
        return ""


def last_lines(output: str, lines: int = 4) -> str:
    kept = [line.strip() for line in output.splitlines() if line.strip()]
    return " / ".join(kept[-lines:])[:600]


def memory_message() -> str:
    return (f"it most likely reached its memory limit of {engine_memory_mb()} MB (very "
            "long texts or very many items on one page need more); set "
            "FLOATPAGE_ENGINE_MEMORY_MB to raise it")


def out_of_memory(code: int | None, log: str) -> bool:
    """LuaTeX says 'not enough memory' when an allocation fails under the limit, or dies."""
    tail = log[-4000:]
    return "not enough memory" in tail or "memory exhausted" in tail or \
        (code is not None and code < 0 and code in (-signal.SIGSEGV, -signal.SIGABRT))
