"""The `floatpage` console script: an error boundary for Ctrl+C from the first moment.

Importing the command line (floatpage.cli.main) brings in numpy and the engine, 0.2-0.6 s on
a busy machine, and main() parses the arguments before its own boundary. A Ctrl+C in that
time used to end in a KeyboardInterrupt traceback. Here nothing but the standard library is
loaded before the boundary, so an early Ctrl+C reads like a late one: "interrupted", exit 130.
"""

from __future__ import annotations

import sys

EXIT_INTERRUPTED = 130  # 128 + SIGINT, as shells report a job stopped by Ctrl+C


def main() -> int:
    try:
        from floatpage.cli.main import main as run_command

        return run_command()
    except KeyboardInterrupt:
        print("floatpage: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED


if __name__ == "__main__":
    sys.exit(main())
