"""Suite-wide: the parts of floatpage import only as floatpage.X, and the longest modules run
first.

`python -m pytest` puts the repo root on sys.path, where `physics/`, `starters/` ... would
import a second time under their bare folder names (a string such as
a resources lookup by the bare name did, unnoticed). This finder refuses those names for the whole run.
"""

from __future__ import annotations

import sys
from importlib.abc import MetaPathFinder

PARTS = frozenset({"physics", "model", "typeset", "tui", "cli", "starters", "latex_templates",
                   "merge"})


class BareNameGuard(MetaPathFinder):
    def find_spec(self, fullname, path=None, target=None):
        if fullname.split(".")[0] in PARTS:
            raise ImportError(f"import {fullname!r} as 'floatpage.{fullname}': the bare name "
                              "would load a second copy of the module")
        return None


sys.meta_path.insert(0, BareNameGuard())


# The modules that take longest (seconds of one CI run in one process, `--durations=0`, summed
# per file: 207, 180, 140, 117, 91, 75), run first. Under pytest-xdist each module goes whole to
# one worker (`make test`), and one of them handed out last kept a core busy alone at the end.
# Only the balance depends on this list: a module missing from it runs in its turn.
LONGEST_FIRST = ("tests/fuzz/test_fuzz_corpus.py", "tests/merge/test_merge_command.py",
                 "tests/tui/test_editor_walk11.py", "tests/cli/test_cli_reliability.py",
                 "tests/cli/test_fresh_projects.py", "tests/tui/test_editor_defects.py")


def pytest_collection_modifyitems(items) -> None:
    rank = {module: place for place, module in enumerate(LONGEST_FIRST)}
    items.sort(key=lambda item: rank.get(item.nodeid.split("::")[0], len(rank)))
