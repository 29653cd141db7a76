"""`floatpage render` of a settled file: LuaLaTeX typesets the saved layout while the physics
checks that it is settled, instead of after it.

A Makefile settles, then renders; render settles again, because a file may have been edited
since, and on a settled file that settle changes nothing (issue 10: a settled file is a fixed
point).  Run one after the other, the two add up: on the 2,000-item chain file 0.5 s of settle
and 0.8 s of LuaLaTeX, of a 2 s goal.  So the .tex of the positions as saved is compiled on
the second core while the settle runs, and kept if the settle left every page as it was, to
the last bit; otherwise that run is stopped and the settled project is typeset as before.  The
PDF is the same either way: both typeset the same project.

Only when the settle runs in this process (page_pool.worth_a_pool says no) and a second core
is free: a pooled settle uses every core, and an unsettled project would pay for a run it
throws away.  The engine's run is the only thing that overlaps; every output is written by
this thread, after the settle, so a discarded run writes nothing.
"""

from __future__ import annotations

import os
import signal
import subprocess
import threading
from pathlib import Path
from typing import Callable

from floatpage.model.document import Project
from floatpage.model.errors import FloatpageError
from floatpage.model.page_pool import available_cores, worth_a_pool
from floatpage.typeset.render import (
    PreparedRender, RenderReport, TypesetPdf, prepare_render, render_pdf, typeset_prepared,
    write_render,
)


def worth_overlapping(project: Project, jobs: int) -> bool:
    """Whether typesetting alongside the settle can use a core the settle leaves idle."""
    return available_cores() >= 2 and not worth_a_pool(project.pages, jobs)


def layout_of(project: Project) -> str:
    """Everything a settle may change, to compare before and after: the pages with every
    field of every item (reprs of dataclasses, floats to the last bit; 9 ms for 2,000 items,
    where writing the file out took 0.6 s)."""
    return repr(project.pages)


class EngineRun:
    """One LuaLaTeX run of a PreparedRender on a thread of its own, which can be stopped."""

    def __init__(self, prepared: PreparedRender, timeout_s: float):
        self.prepared, self.timeout_s = prepared, timeout_s
        self.result: TypesetPdf | None = None
        self.error: BaseException | None = None
        self.process: subprocess.Popen | None = None
        self.stopped = False
        self.lock = threading.Lock()
        self.thread = threading.Thread(target=self.run, name="floatpage-typeset", daemon=True)

    def start(self) -> "EngineRun":
        self.thread.start()
        return self

    def run(self) -> None:
        try:
            self.result = typeset_prepared(self.prepared, timeout_s=self.timeout_s,
                                           on_start=self.started)
        except BaseException as error:  # handed to the main thread, or dropped if stopped
            self.error = error

    def started(self, process: subprocess.Popen) -> None:
        with self.lock:
            self.process = process
            if self.stopped:
                self.kill()

    def kill(self) -> None:
        if self.process is not None and self.process.poll() is None:
            try:
                os.killpg(self.process.pid, signal.SIGKILL)  # its own session: the engine alone
            except ProcessLookupError:
                pass

    def stop(self) -> None:
        """Stop the run (if it still runs) and wait for its build folder to go."""
        with self.lock:
            self.stopped = True
            self.kill()
        self.thread.join()

    def outcome(self) -> TypesetPdf:
        """The run's PDF, once it ends; its error, as the serial render would have raised it."""
        self.thread.join()
        if self.error is not None:
            raise self.error
        assert self.result is not None
        return self.result


def render_while_settling(project: Project, out_pdf: Path, settle: Callable[[Project], None], *,
                          jobs: int = 1, tex_out: Path | None = None,
                          fragment_out: Path | None = None, timeout_s: float = 120.0,
                          progress: Callable[[str], None] | None = None,
                          print_bleed_mm: float | None = None,
                          overlap: bool | None = None) -> RenderReport:
    """Settle ``project`` with ``settle`` (in place) and typeset it into ``out_pdf``, as
    ``settle(project)`` then ``render_pdf`` would, overlapping the two where that pays
    (``overlap``: always, never, or None for where ``worth_overlapping``).  The report's
    ``typeset_while_settling`` says whether the PDF is the overlapped run's."""
    say = progress or (lambda message: None)
    options = dict(tex_out=tex_out, fragment_out=fragment_out, print_bleed_mm=print_bleed_mm,
                   timeout_s=timeout_s, progress=progress)

    def one_after_the_other() -> RenderReport:
        say("settling the layout…")
        settle(project)
        return render_pdf(project, out_pdf, **options)

    if not (worth_overlapping(project, jobs) if overlap is None else overlap):
        return one_after_the_other()
    saved = layout_of(project)
    try:
        prepared = prepare_render(project, out_pdf, tex_out=tex_out, fragment_out=fragment_out,
                                  progress=progress, print_bleed_mm=print_bleed_mm)
    except FloatpageError:  # reported as the render one after the other reports it
        return one_after_the_other()
    run = EngineRun(prepared, timeout_s).start()
    try:
        say("settling the layout…")
        settle(project)
        unchanged = layout_of(project) == saved
    except BaseException:
        run.stop()
        raise
    if not unchanged:  # the file was not settled: typeset what the settle made of it
        run.stop()
        return render_pdf(project, out_pdf, **options)
    say("typesetting with LuaLaTeX")
    try:
        typeset = run.outcome()
    except BaseException:
        run.stop()
        raise
    report = write_render(prepared, typeset, progress)
    report.typeset_while_settling = True
    return report
