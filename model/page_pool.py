"""Settling a project's pages side by side, one process per core.

A project's pages are independent: each settles in its own Engine, from its own items, with a
generator seeded from the project's settings alone, so the order in which pages settle, and
where, changes no byte of the result.  A 200-page album of 2,000 photos took 20 CPU seconds one
page after another; over the cores it takes that time divided by their number.

Processes, not threads: the physics is NumPy calls on small arrays, which hold the GIL most of
the time.  The workers are forked from a fresh server process (multiprocessing's
"forkserver"), not from the command itself: the command's progress spinner runs a thread, and
a fork of a process with threads can inherit a lock another thread held.  The server imports
the physics once, so a worker starts in milliseconds; the server's own start, about half a
second of CPU, is why a small project settles in the command's own process.
"""

from __future__ import annotations

import multiprocessing
import os
import signal
import threading
from concurrent.futures import ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool

from floatpage.model.document import Item, Page, PhysicsSettings
from floatpage.model.errors import FloatpageError
from floatpage.model.lifeline import end_with
from floatpage.model.socket_folder import fit_socket_folder
from floatpage.physics import SettleReport

MIN_PAGES = 8  # fewer pages settle in the command's own process
MIN_ITEMS = 200  # and so do fewer items in all: their settle takes about the server's start
PRELOAD = ["floatpage.model.layout"]


def available_cores() -> int:
    """The cores this process may run on (a CI job's share, not the machine's count)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def worth_a_pool(pages: list[Page], jobs: int) -> bool:
    """Whether ``jobs`` processes would settle ``pages`` sooner than this one alone."""
    return (jobs > 1 and len(pages) >= MIN_PAGES
            and sum(len(page.items) for page in pages) >= MIN_ITEMS)


def settle_in_pool(pages: list[Page], settings: PhysicsSettings, max_steps: int,
                   jobs: int) -> list[SettleReport]:
    """Settle ``pages`` in ``jobs`` worker processes, each page's items written back as
    ``settle_page`` writes them; one report per page, in page order.  An error a page raises
    (a FloatpageError: the physics diverged, items piled up) is raised here, as it would be
    in one process."""
    try:
        fit_socket_folder()
        context = multiprocessing.get_context("forkserver")
        context.set_forkserver_preload(PRELOAD)
        pool = ProcessPoolExecutor(max_workers=min(jobs, len(pages)), mp_context=context,
                                   initializer=start_worker, initargs=(os.getpid(),))
    except (OSError, NotImplementedError, ValueError):  # no processes here (a sandbox
        return settle_here(pages, settings, max_steps)  # without semaphores): one by one
    # From here on, whatever stops the command (Ctrl+C, SIGTERM, a page's error) stops the
    # pool with it, in the workers' start too: otherwise the command's exit waits for every
    # page it has handed out.
    try:
        try:
            futures = [pool.submit(settle_one, page, settings, max_steps) for page in pages]
        except (OSError, NotImplementedError, ValueError):  # no worker could start
            stop_pool(pool)
            return settle_here(pages, settings, max_steps)
        settled = [future.result() for future in futures]
    except BrokenProcessPool:
        stop_pool(pool)
        raise FloatpageError(
            "a process settling pages stopped without a word (out of memory?); nothing was "
            "written. Run again with -j 1 to settle the pages one by one") from None
    except BaseException:  # no page more is started, and the pages under way are dropped
        stop_pool(pool)
        raise
    pool.shutdown()
    for page, (items, _) in zip(pages, settled):
        page.items = items
    return [report for _, report in settled]


def stop_pool(pool: ProcessPoolExecutor) -> None:
    """Stop the workers at once, then the pool: the workers ignore Ctrl+C
    (leave_interrupts_to_the_command), and the interpreter's exit would otherwise wait for
    the pages they are settling and those already queued to them (at load 6 the command
    stopped 13-40 s after the key).  The pool keeps its processes in ``_processes`` (Python
    3.8-3.13; 3.14 has terminate_workers), and forgets them on shutdown: they go first."""
    for process in list((getattr(pool, "_processes", None) or {}).values()):
        if process.is_alive():
            process.terminate()
    manager = getattr(pool, "_executor_manager_thread", None)
    pool.shutdown(wait=False, cancel_futures=True)
    wait_for_the_pools_thread(manager)


def wait_for_the_pools_thread(manager: threading.Thread | None) -> None:
    """Let the pool's manager thread finish before the command exits.  On a shutdown without
    waiting it is still closing its wake-up pipe when the interpreter's exit hook
    (concurrent.futures' ``_python_exit``, Python 3.8-3.11) writes to that pipe to wake it: one
    Ctrl+C in a few hundred printed "OSError: [Errno 9] Bad file descriptor" with a traceback
    under "floatpage: interrupted" (a fresh-clone CI run).  With its workers terminated the
    thread sees them gone and ends in milliseconds; the bound only keeps a wedged thread from
    holding the exit, which then risks the old message and nothing worse."""
    if manager is not None and manager is not threading.current_thread():
        manager.join(timeout=5.0)


def settle_here(pages: list[Page], settings: PhysicsSettings,
                max_steps: int) -> list[SettleReport]:
    """The pages one by one in this process (a small project, or no worker can start)."""
    from floatpage.model.layout import settle_page

    return [settle_page(page, settings, max_steps=max_steps) for page in pages]


def start_worker(command_pid: int) -> None:
    """A worker's start: Ctrl+C is the command's to handle, and a command killed outright
    takes the worker with it (model.lifeline)."""
    leave_interrupts_to_the_command()
    end_with(command_pid)


def leave_interrupts_to_the_command() -> None:
    """Ctrl+C reaches every process of the terminal's group: the command stops the pool and
    says "interrupted"; a worker that also raised would print a traceback of its own."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


def settle_one(page: Page, settings: PhysicsSettings,
               max_steps: int) -> tuple[list[Item], SettleReport]:
    """One page, in a worker: its settled items (the page itself stays in the worker) and
    its report."""
    from floatpage.model.layout import settle_page

    report = settle_page(page, settings, max_steps=max_steps)
    return page.items, report
