"""The packages import in one direction only: physics <- model <- typeset, starters, merge <- tui
<- cli.

physics knows nothing of files, LaTeX or terminals, so it can be tested and benchmarked alone
and reused (the merge workers run it with no screen); the model knows nothing of LaTeX or the
editor. docs/architecture.md draws the same picture.
"""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MAY_IMPORT = {
    "physics": set(),
    "model": {"physics"},
    "latex_templates": set(),
    "typeset": {"physics", "model", "latex_templates"},
    "starters": {"physics", "model", "typeset"},
    # the editor reads a merge template's placeholders (merge.placeholders: plain text, no Dask)
    "tui": {"physics", "model", "typeset", "starters", "merge"},
    "merge": {"physics", "model", "typeset"},
    "cli": {"physics", "model", "typeset", "tui", "starters", "merge"},
}


def floatpage_imports(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    found = set()
    for node in ast.walk(tree):
        names = [alias.name for alias in node.names] if isinstance(node, ast.Import) else \
            [node.module or ""] if isinstance(node, ast.ImportFrom) else []
        for name in names:
            parts = name.split(".")
            if parts[0] == "floatpage" and len(parts) > 1:
                found.add(parts[1])
    return found


def test_every_package_imports_only_those_below_it():
    wrong = []
    for package, allowed in MAY_IMPORT.items():
        for path in (ROOT / package).rglob("*.py") if (ROOT / package).is_dir() else ():
            for imported in floatpage_imports(path) - allowed - {package}:
                wrong.append(f"{path.relative_to(ROOT)} imports floatpage.{imported}")
    assert not wrong, "\n".join(wrong)


def test_physics_imports_no_ui_and_no_latex_library():
    banned = {"textual", "rich", "pylatex", "jinja2", "PIL", "tomlkit", "tomllib"}
    wrong = []
    for path in (ROOT / "physics").rglob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                names = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom):
                names = [node.module or ""]
            else:
                continue
            wrong += [f"{path.name}: {name}" for name in names if name.split(".")[0] in banned]
    assert not wrong, wrong
