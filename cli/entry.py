"""The `floatpage` console script: an error boundary for Ctrl+C from the first moment.

Importing the command line (floatpage.cli.main) brings in numpy and the engine, 0.2-0.6 s on
a busy machine, and main() parses the arguments before its own boundary. A Ctrl+C in that
time used to end in a KeyboardInterrupt traceback. Here nothing but the standard library is
loaded before the boundary, so an early Ctrl+C reads like a late one: "interrupted", exit 130.
"""

from __future__ import annotations

import sys

SIGINT = 2  # the signal module is not loaded yet: 128 + 2 = 130, as shells report Ctrl+C


def main() -> int:
    try:
        from floatpage.cli.main import main as run_command

        return run_command()
    except BaseException as error:
        stop = interrupted(error)
        if stop is None:
            raise
        print("floatpage: interrupted", file=sys.stderr)
        return interrupted_status(stop)


def interrupted_status(stop: BaseException) -> int:
    """The exit status of a command stopped by a signal, as shells give it: 128 + its number
    (Ctrl+C 130; SIGTERM 143 and SIGHUP 129 come as cli.main.Stopped, which carries it)."""
    return 128 + getattr(stop, "signum", SIGINT)


def interrupted(error: BaseException) -> KeyboardInterrupt | None:
    """The Ctrl+C (or SIGTERM, SIGHUP: cli.main raises a KeyboardInterrupt for them too)
    that ``error`` is, or was raised because of, else None. Python 3.11 wraps an exception
    raised in a descriptor's __set_name__, which every dataclass field has, in a RuntimeError:
    a Ctrl+C while a module of dataclasses was being imported ended in "RuntimeError: Error
    calling __set_name__ on 'Field' instance 'color' in 'BlockItem'" and a traceback (0.44 s
    into a settle, at load 7)."""
    seen: set[int] = set()
    while error is not None and id(error) not in seen:
        if isinstance(error, KeyboardInterrupt):
            return error
        seen.add(id(error))
        error = error.__cause__ or error.__context__
    return None


if __name__ == "__main__":
    sys.exit(main())
