"""`python -m tui PATH`: open the editor without the CLI (the CLI's `floatpage edit` does the same)."""

import sys

from model.errors import FloatpageError
from tui.app import make_app


def main() -> int:
    if len(sys.argv) != 2:
        print("usage: python -m tui PROJECT.toml", file=sys.stderr)
        return 2
    try:
        app = make_app(sys.argv[1])
    except FloatpageError as error:
        print(error, file=sys.stderr)
        return 1
    app.run()
    return 0


if __name__ == "__main__":
    sys.exit(main())
