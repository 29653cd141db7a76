"""Suite-wide guard: the parts of floatpage import only as floatpage.X.

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
