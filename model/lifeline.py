"""A worker process that ends when the command that started it ends, however that ends.

The pools (a pooled settle, `merge` on this machine) start their workers from
multiprocessing's fork server.  A command stopped by SIGKILL (a CI job's timeout, the
out-of-memory killer, `kill -9`) never stops them: each worker holds the fork server's
"alive" pipe and both ends of its own task queue, so no end of file ever reaches it, and it
waited on that queue for good, with the fork server and the resource tracker waiting on it
(user-walk-12b: four processes a `merge` killed after 22 s left, still there minutes later).
The kernel's parent-death signal does not reach them either: their parent is the fork
server, not the command.

So each worker watches the command itself: a thread waits on a pidfd of the command (Linux
5.3 and later), which becomes readable once the command has ended, and then ends the worker;
its LuaLaTeX dies with it (PR_SET_PDEATHSIG, typeset.compile).  Where there is no pidfd, the
thread looks once a second.
"""

from __future__ import annotations

import os
import select
import threading
import time

POLL_S = 1.0


def end_with(command_pid: int) -> None:
    """In a worker, at its start: end this process as soon as ``command_pid`` ends."""
    try:
        pidfd = os.pidfd_open(command_pid)
    except (AttributeError, OSError):  # not Linux, or a kernel before 5.3
        pidfd = None
    threading.Thread(target=watch, args=(command_pid, pidfd), name="floatpage-lifeline",
                     daemon=True).start()


def watch(command_pid: int, pidfd: int | None) -> None:
    if pidfd is not None:
        watcher = select.poll()  # not select(): no limit on the descriptor's number
        watcher.register(pidfd, select.POLLIN)
        while not watcher.poll():
            pass
    else:
        while is_running(command_pid):
            time.sleep(POLL_S)
    os._exit(1)


def is_running(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # there, but another user's: the number was reused
        return False
    return True
