"""floatpage installs as one package, and every module is imported by one name only.

Seven generic top-level packages (`physics`, `tui`, ...) would collide with other
distributions in site-packages (PyPI has a `tui`), and a module reachable under two names
runs twice with two copies of its state.
"""

from __future__ import annotations

import re
import subprocess
import sys
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PARTS = ("physics", "model", "typeset", "tui", "cli", "starters", "latex_templates", "merge")
BARE_IMPORT = re.compile(rf"^\s*(?:from|import)\s+(?:{'|'.join(PARTS)})(?:[.\s]|$)", re.M)
BARE_NAME_STRING = re.compile(rf"""(?:"-m",\s*|files\()["'](?:{'|'.join(PARTS)})\b""")


def test_the_wheel_has_floatpage_as_its_only_top_level_package(tmp_path: Path) -> None:
    build = subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "--no-deps", "-v", "-w", str(tmp_path), str(ROOT)],
        check=True, capture_output=True, text=True, timeout=300,
    )
    # A data folder missing from `packages` is shipped today and dropped by a later setuptools.
    assert "absent from the `packages` configuration" not in build.stdout + build.stderr
    (wheel,) = tmp_path.glob("floatpage-*.whl")
    names = zipfile.ZipFile(wheel).namelist()
    top_level = {name.split("/")[0] for name in names if not name.split("/")[0].endswith(".dist-info")}
    assert top_level == {"floatpage"}
    for needed in ("floatpage/latex_templates/page.tex.j2", "floatpage/latex_templates/items/text.tex.j2",
                   "floatpage/tui/app.tcss", "floatpage/physics/engine.py"):
        assert needed in names
    bundled = {Path(name).name for name in names if name.startswith("floatpage/starters/bundled/")}
    assert bundled == {path.name for path in (ROOT / "starters" / "bundled").iterdir()}
    entry_points = next(n for n in names if n.endswith(".dist-info/entry_points.txt"))
    assert "floatpage = floatpage.cli.entry:main" in zipfile.ZipFile(wheel).read(entry_points).decode()


def test_no_module_imports_a_part_by_its_bare_folder_name() -> None:
    offenders = []
    for folder in (*PARTS, "tests", "benchmarks", "tools"):
        for path in (ROOT / folder).rglob("*.py"):
            text = path.read_text(encoding="utf-8")
            for match in [*BARE_IMPORT.finditer(text), *BARE_NAME_STRING.finditer(text)]:
                offenders.append(f"{path.relative_to(ROOT)}: {match.group(0).strip()}")
    assert not offenders, "import these as floatpage.X:\n" + "\n".join(offenders)


def test_the_installed_package_is_the_repo_folders() -> None:
    import floatpage.physics
    import floatpage.tui

    assert Path(floatpage.physics.__file__).resolve().parent == ROOT / "physics"
    assert Path(floatpage.tui.__file__).resolve().parent == ROOT / "tui"
    assert "physics" not in sys.modules and "tui" not in sys.modules


def test_the_font_family_type_names_the_model_vocabulary():
    """`FontFamily` is a Literal for type checkers; it must say what FONT_FAMILIES says."""
    from typing import get_args

    from floatpage.model.document import FontFamily
    from floatpage.model.key_specs import FONT_FAMILIES

    assert get_args(FontFamily) == FONT_FAMILIES


def test_settle_imports_no_editor_typesetting_or_picture_libraries(tmp_path) -> None:
    """`floatpage settle` on a project without pictures loads neither Textual, Jinja,
    PyLaTeX, Pillow nor tomlkit (a patched save needs no tomlkit document): on the
    2,000-anchor chain file Pillow and tomlkit were a tenth of the command's two seconds."""
    import subprocess

    project = tmp_path / "p.toml"
    project.write_text('format = 1\ntitle = "t"\n\n[[pages]]\nid = "p"\nsize = "A5"\n\n'
                       '[[pages.items]]\nid = "a"\nkind = "block"\nx = 30.123\ny = 40\nw = 20\n'
                       'h = 10\n', encoding="utf-8")
    script = (
        "import sys\n"
        "from floatpage.cli.main import main\n"
        f"assert main(['settle', '-q', {str(project)!r}]) == 0\n"
        "heavy = ('textual', 'jinja2', 'pylatex', 'PIL', 'tomlkit', 'rich')\n"
        "print(' '.join(sorted({name.split('.')[0] for name in sys.modules} & set(heavy))))\n")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[-1] == "", done.stdout
