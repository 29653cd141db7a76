"""Rendering benchmark: a 12-page calendar, typeset as the CLI does, against a bare engine run.

    .venv/bin/python benchmarks/render.py                    # sample_projects/calendar-2027
    .venv/bin/python benchmarks/render.py --repeat 7 PROJECT.toml
    .venv/bin/python benchmarks/render.py --quality          # also: fit quality read from a PDF

For each of --repeat rounds (after one warm-up that fills the font and picture caches):
  * render:  typeset.render_pdf(project, out), wall-clock, everything included (layout,
             fitting, picture cache look-ups, templates, the engine, the atomic write);
  * bare:    the same .tex, compiled by a plain `lualatex` process in a fresh folder with the
             same flags and environment, wall-clock.
Engine runs are counted by wrapping the one function that starts the engine.  Fitting is
timed per text box (each text item plus each calendar label set), cold (a new font cache)
and warm.  The machine is shared and noisy: compare the ratio within one run.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path


import floatpage.typeset.compile as compile_module
from floatpage.model import load_project
from floatpage.model.document import TextItem
from floatpage.typeset import render_pdf, render_tex
from floatpage.typeset.fit import Box, fit_text
from floatpage.typeset.fonts import FontMetrics, font_path
from floatpage.typeset.pictures import cache_dir
from floatpage.typeset.text_layout import PT_PER_MM, face_for, printable_text

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_PROJECT = ROOT / "sample_projects" / "calendar-2027" / "calendar-2027.toml"


def bare_engine_seconds(tex: str) -> float:
    """One plain lualatex run on `tex`, in a fresh folder, with the flags render_pdf uses."""
    with tempfile.TemporaryDirectory(prefix="floatpage-bench-") as build:
        (Path(build) / "main.tex").write_text(tex, encoding="utf-8")
        started = time.perf_counter()
        subprocess.run(compile_module.engine_command(), cwd=build, stdin=subprocess.DEVNULL,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True,
                       env=compile_module.engine_environment(cache_dir()))
        return time.perf_counter() - started


def fit_times(project) -> tuple[list[float], list[float], int]:
    """Per-box fitting time in seconds, cold (fresh font objects) and warm; and the box count."""
    boxes = [(item.text, face_for(item.font, item.bold, item.italic), item.w, item.h)
             for page in project.pages for item in page.items if isinstance(item, TextItem)]
    # A calendar of only month panels still has 36 fitted boxes: the same text in sizes
    # from a caption to a poster title, so there is always something to time.
    for scale in range(1, 37):
        boxes.append((f"Our family calendar, month {scale}", face_for("display", True, False),
                      12.0 + 5 * scale, 5.0 + 2 * scale))
    cold, warm = [], []
    for text, face, w, h in boxes:
        metrics = FontMetrics(font_path(face))  # a new shaping cache: the first fit is cold
        clean, _ = printable_text(text, metrics)
        box = Box(w * PT_PER_MM, h * PT_PER_MM)
        started = time.perf_counter()
        fit_text(clean, box, metrics)
        cold.append(time.perf_counter() - started)
        runs = []
        for _ in range(20):
            started = time.perf_counter()
            fit_text(clean, box, metrics)
            runs.append(time.perf_counter() - started)
        warm.append(statistics.median(runs))
    return cold, warm, len(boxes)


def quality() -> None:
    """Typeset the typeset tests' 216 random boxes and read the PDF back (as the tests do)."""
    sys.path.insert(0, str(ROOT / "tests" / "typeset"))
    import pdfplumber
    from test_typeset_text_in_pdf import random_project
    from typeset_pdfcheck import BoxPt, chars_in, fill

    project = random_project()
    worst, fills = 0.0, []
    with tempfile.TemporaryDirectory(prefix="floatpage-bench-q-") as out_dir:
        out = Path(out_dir) / "boxes.pdf"
        render_pdf(project, out)
        with pdfplumber.open(out) as pdf:
            for page, pdf_page in zip(project.pages, pdf.pages):
                for item in page.items:
                    box = BoxPt.of_item(item)
                    chars = chars_in(pdf_page, box, margin_pt=4 * PT_PER_MM)
                    worst = max([worst] + [box.overflow(c) for c in chars])
                    fills.append(max(fill(chars, box)))
    fills.sort()
    print(f"fit quality over {len(fills)} random boxes: worst glyph overflow {worst:.4f} pt; "
          f"fill median {statistics.median(fills):.5f}, 5th percentile "
          f"{fills[int(0.05 * len(fills))]:.5f}, minimum {fills[0]:.5f}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("project", nargs="?", default=str(DEFAULT_PROJECT))
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--quality", action="store_true",
                        help="also typeset 216 random boxes and report overflow and fill")
    args = parser.parse_args()
    project = load_project(args.project)

    engine_runs = 0
    real_run_engine = compile_module.run_engine

    def counting_run_engine(*a, **k):
        nonlocal engine_runs
        engine_runs += 1
        return real_run_engine(*a, **k)

    compile_module.run_engine = counting_run_engine
    renders, bares, engines = [], [], []
    with tempfile.TemporaryDirectory(prefix="floatpage-bench-out-") as out_dir:
        out = Path(out_dir) / "calendar.pdf"
        report = render_pdf(project, out)  # warm-up: luaotfload and picture caches
        engine_runs = 0
        for _ in range(args.repeat):
            started = time.perf_counter()
            report = render_pdf(project, out)
            renders.append(time.perf_counter() - started)
            engines.append(report.engine_seconds)
            bares.append(bare_engine_seconds(render_tex(project)))
        size = out.stat().st_size
    compile_module.run_engine = real_run_engine
    cold, warm, boxes = fit_times(project)

    render_median, bare_median = statistics.median(renders), statistics.median(bares)
    print(f"project: {args.project} ({report.pages} pages, PDF {size / 1024:.0f} KiB)")
    print(f"engine runs per render: {engine_runs / args.repeat:g}")
    print(f"render_pdf, median of {args.repeat}: {render_median:.3f} s "
          f"(engine inside it {statistics.median(engines):.3f} s)")
    print(f"bare lualatex on the same .tex, median of {args.repeat}: {bare_median:.3f} s")
    print(f"ratio render / bare: {render_median / bare_median:.3f} (target <= 1.3)")
    outside = statistics.median(r - e for r, e in zip(renders, engines))
    print(f"time outside the engine run, median: {outside:.3f} s")
    print(f"fitting one text box ({boxes} boxes): median {statistics.median(warm) * 1e3:.3f} ms "
          f"warm, {statistics.median(cold) * 1e3:.3f} ms cold (first shaping); "
          f"max {max(cold) * 1e3:.3f} ms (target median < 1 ms)")
    if args.quality:
        quality()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
