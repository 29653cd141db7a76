"""`render` typesets a settled file while it checks that it is settled (typeset.while_settling):
the same PDF as settling first, nothing left behind when the settle changes the page or is
stopped.  Real LuaLaTeX, real PDFs, real signals."""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

from floatpage.model import BlockItem, Page, Project, TextItem, load_project, save_project
from floatpage.model.layout import settle_project
from floatpage.typeset import render_pdf
from floatpage.typeset.while_settling import render_while_settling

from test_typeset_kill import engines_working_in, wait_until

ROOT = Path(__file__).resolve().parents[2]
CARD = ROOT / "sample_projects" / "greeting-card"


def copied_card(tmp_path: Path) -> Path:
    shutil.copytree(CARD, tmp_path / "card")
    return next((tmp_path / "card").glob("*.toml"))


def unsettled(path: Path, count: int = 12) -> Path:
    """Blocks and a text piled near one spot: every settle moves them."""
    items = [BlockItem(id=f"b{k}", x=70.0 + k, y=100.0 + k, w=30.0, h=20.0, color="#336699")
             for k in range(count)]
    items.append(TextItem(id="t", x=74.0, y=104.0, w=60.0, h=15.0, text="Hello & 100 % {}"))
    save_project(Project(title="pile", pages=[Page(id="p", size="A5", width_mm=148.0,
                                                   height_mm=210.0, items=items)]), path)
    return path


def test_a_settled_file_is_typeset_while_it_settles_to_the_same_bytes(tmp_path):
    path = copied_card(tmp_path)
    saved = path.read_bytes()
    project = load_project(path)
    report = render_while_settling(project, tmp_path / "overlapped.pdf", settle_project,
                                   tex_out=tmp_path / "overlapped.tex", overlap=True)
    assert report.typeset_while_settling, "the file is settled: the overlapped run is kept"
    serial = load_project(path)
    settle_project(serial)
    render_pdf(serial, tmp_path / "serial.pdf", tex_out=tmp_path / "serial.tex")
    assert (tmp_path / "overlapped.pdf").read_bytes() == (tmp_path / "serial.pdf").read_bytes()
    assert (tmp_path / "overlapped.tex").read_bytes() == (tmp_path / "serial.tex").read_bytes()
    assert path.read_bytes() == saved


def test_an_unsettled_file_is_typeset_as_the_settle_left_it(tmp_path, monkeypatch):
    monkeypatch.setenv("TMPDIR", str(tmp_path))  # where the build folders go
    import tempfile
    monkeypatch.setattr(tempfile, "tempdir", None)
    path = unsettled(tmp_path / "pile.toml")
    project = load_project(path)
    report = render_while_settling(project, tmp_path / "overlapped.pdf", settle_project,
                                   tex_out=tmp_path / "overlapped.tex", overlap=True)
    assert not report.typeset_while_settling, "the settle moved items: that run is dropped"
    serial = load_project(path)
    settle_project(serial)
    render_pdf(serial, tmp_path / "serial.pdf", tex_out=tmp_path / "serial.tex")
    assert (tmp_path / "overlapped.tex").read_bytes() == (tmp_path / "serial.tex").read_bytes()
    assert (tmp_path / "overlapped.pdf").read_bytes() == (tmp_path / "serial.pdf").read_bytes()
    assert list(tmp_path.glob("floatpage-build-*")) == []
    assert engines_working_in(tmp_path) == []


def test_the_command_keeps_the_overlapped_run_of_a_settled_file(tmp_path):
    """Through the real command: `render` of a settled file gives the bytes `render
    --no-settle` gives (the saved positions, typeset once)."""
    path = copied_card(tmp_path)
    command = [sys.executable, "-m", "floatpage.cli.main", "render", str(path)]
    for extra, out in (([], "default.pdf"), (["--no-settle"], "saved.pdf")):
        done = subprocess.run(command + extra + ["-o", str(tmp_path / out)], cwd=ROOT,
                              capture_output=True, text=True, timeout=300)
        assert done.returncode == 0, done.stderr
    assert (tmp_path / "default.pdf").read_bytes() == (tmp_path / "saved.pdf").read_bytes()


def test_ctrl_c_while_settling_stops_the_overlapped_engine_and_writes_nothing(tmp_path):
    """Ctrl+C while the page settles and LuaLaTeX already typesets the saved layout: the
    engine goes at once, its build folder too, and no output is written."""
    path = unsettled(tmp_path / "pile.toml", count=400)  # a settle of seconds
    scratch = tmp_path / "scratch"
    scratch.mkdir()
    out = tmp_path / "pile.pdf"
    program = textwrap.dedent(f"""
        import signal, sys
        signal.signal(signal.SIGINT, signal.default_int_handler)
        from floatpage.model import load_project
        from floatpage.model.layout import settle_project
        from floatpage.typeset.while_settling import render_while_settling
        project = load_project({str(path)!r})
        try:
            render_while_settling(project, {str(out)!r}, settle_project, overlap=True)
        except KeyboardInterrupt:  # before this process exits (which would end them anyway)
            sys.path.insert(0, {str(Path(__file__).parent)!r})
            from pathlib import Path
            from test_typeset_kill import engines_working_in
            scratch = Path({str(scratch)!r})
            print("interrupted; engines", len(engines_working_in(scratch)), "folders",
                  len(list(scratch.glob("floatpage-build-*"))), file=sys.stderr)
            sys.exit(130)
        sys.exit(0)
    """)
    env = {**os.environ, "TMPDIR": str(scratch), "FLOATPAGE_CACHE_DIR": str(scratch / "cache")}
    render = subprocess.Popen([sys.executable, "-c", program], env=env, cwd=ROOT,
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    try:
        assert wait_until(lambda: engines_working_in(scratch), 120), "LuaLaTeX never started"
        time.sleep(0.2)
        assert render.poll() is None, "the settle ended before the Ctrl+C: make it longer"
        render.send_signal(signal.SIGINT)
        render.wait(timeout=60)
    finally:
        if render.poll() is None:
            render.kill()
    assert render.returncode == 130
    # the function itself stopped the engine and removed its folder, before returning
    assert "interrupted; engines 0 folders 0" in render.stderr.read()
    assert wait_until(lambda: not engines_working_in(scratch), 0.5), "LuaLaTeX outlived render"
    assert list(scratch.glob("floatpage-build-*")) == []
    assert not out.exists()
