"""The public pipeline: project -> .tex (pure) -> PDF (one engine run, atomic).

`render_tex` needs no TeX and is golden-tested; `render_pdf` prepares the
picture cache, compiles in a temporary folder and only then replaces the
output, so a failed render never overwrites the last good PDF.
"""

from __future__ import annotations

import hashlib
import re
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from pylatex.utils import NoEscape

from floatpage.model.document import Project
from floatpage.model.save import atomic_write
from floatpage.model.picture_files import decode_warning, is_merge_placeholder, read_header
from floatpage.typeset.build_folder import build_folder
from floatpage.typeset.compile import check_engine_settings, compile_pdf
from floatpage.typeset.contrast import contrast_notes
from floatpage.typeset.output_paths import check_outputs, project_companions, project_inputs
from floatpage.typeset.print_marks import for_print
from floatpage.typeset.errors import RenderError
from floatpage.typeset.fonts import FontNotFoundError
from floatpage.typeset.pictures import cache_dir
from floatpage.typeset.placed import (DocumentFits, PlacedDocument, materialize_pictures,
                                      place_document, text_warnings)
from floatpage.typeset.templates import make_environment


@dataclass
class RenderReport:
    pdf: Path
    pages: int
    warnings: list[str] = field(default_factory=list)
    seconds: float = 0.0
    engine_seconds: float = 0.0
    notes: list[str] = field(default_factory=list)  # said, not wrong: faint text (contrast)


def placed_document(project: Project, fits: DocumentFits | None = None) -> PlacedDocument:
    try:
        return place_document(project, fits)
    except FontNotFoundError as error:
        raise RenderError(str(error)) from None


def tex_from_placed(document: PlacedDocument, *, fragment: bool = False) -> str:
    env = make_environment()
    template = env.get_template("fragment.tex.j2" if fragment else "page.tex.j2")
    try:
        body = template.render(title=document.title or "untitled", pages=document.pages,
                               faces=document.faces, colors=document.colors,
                               picture_dir=document.picture_dir, trailer_id=NoEscape("0" * 32))
    except ValueError as error:  # a filter refused a value (a font path TeX cannot take...)
        raise RenderError(f"could not write the LaTeX: {error}") from None
    if fragment:
        return body
    # The PDF's ID is the hash of everything else, so equal projects give equal bytes; the
    # picture cache's folder is left out, so it does not matter whose cache the pictures are in.
    hashed = body.replace(str(document.picture_dir), "") if document.picture_dir else body
    trailer = hashlib.md5(hashed.encode("utf-8")).hexdigest().upper()
    return body.replace("<" + "0" * 32 + ">", f"<{trailer}>")


def render_tex(project: Project, *, fragment: bool = False) -> str:
    """The standalone .tex (or the TikZ-only fragment) for the project, positions as in the model."""
    return tex_from_placed(placed_document(project), fragment=fragment)


def document_fits(project: Project) -> DocumentFits:
    """Every text fitted and calendar laid out once, for the two passes of `floatpage check`
    below; a missing font is a RenderError, as text_fit_warnings said it before."""
    try:
        return DocumentFits.of(project)
    except FontNotFoundError as error:
        raise RenderError(str(error)) from None


def text_fit_warnings(project: Project, fits: DocumentFits | None = None) -> list[str]:
    """For `floatpage check`: texts too long for their box, glyphs a font lacks; each names its item."""
    try:
        return text_warnings(project, fits)
    except FontNotFoundError as error:
        raise RenderError(str(error)) from None


def faint_text_notes(project: Project, fits: DocumentFits | None = None) -> list[str]:
    """For `floatpage check`: texts too faint against what lies behind them
    (typeset.contrast); none for a merge template, whose pictures are not known yet."""
    try:
        return contrast_notes(placed_document(project, fits))
    except RenderError:
        return []


def count_pages(build: Path, expected: int) -> int:
    """Pages LuaLaTeX says it wrote ("Output written on main.pdf (12 pages, ...)")."""
    log = (build / "main.log").read_text(encoding="utf-8", errors="replace")
    found = re.search(r"Output written on main\.pdf \((\d+) pages?", log)
    return int(found.group(1)) if found else expected


def picture_warnings(project: Project) -> list[str]:
    """Pictures whose pixels do not decode cleanly (a truncated JPEG prints grey, silently)."""
    found = []
    for page in project.pages:
        for item in page.items:
            if item.kind == "picture" and not is_merge_placeholder(item.path, project.base_dir):
                problem = decode_warning(project.base_dir / item.path)
                if problem:
                    found.append(f'item "{item.id}" on page "{page.id}": picture '
                                 f'"{item.path}": {problem}')
        if page.background is not None and page.background.picture and \
                not is_merge_placeholder(page.background.picture, project.base_dir):
            problem = decode_warning(project.base_dir / page.background.picture)
            if problem:
                found.append(f'page "{page.id}" background "{page.background.picture}": {problem}')
    return found


# Below this a picture shows its pixels on paper (print wants about 300 dpi; the bundled
# photos print at 125-300 in the samples, soft but not blocky).
BLOCKY_DPI = 100


def print_dpi(path: Path, w_mm: float, h_mm: float) -> tuple[tuple[int, int], float] | None:
    """(pixel size, dots per inch) of a raster picture printed in a w x h mm box, or None for
    what has no pixels to count (a PDF) or cannot be used (the loader's header check says
    why). Sides are matched long to long, so a photo turned by its EXIF tag counts the same."""
    header = read_header(path)
    if header.problem or header.kind == "PDF" or min(w_mm, h_mm) <= 0:
        return None
    size = header.size
    dpi = min(max(size) / (max(w_mm, h_mm) / 25.4), min(size) / (min(w_mm, h_mm) / 25.4))
    return size, dpi


def resolution_notes(project: Project) -> list[str]:
    """Pictures that print below BLOCKY_DPI at their size, each with its item, its pixels and
    its dpi: a thumbnail stretched over half a page prints as squares, and nothing said so."""
    notes = []
    for page in project.pages:
        for item in page.items:
            if item.kind != "picture" or is_merge_placeholder(item.path, project.base_dir):
                continue
            found = print_dpi(project.base_dir / item.path, item.w, item.h)
            if found is not None and found[1] < BLOCKY_DPI:
                (px_w, px_h), dpi = found
                notes.append(f'item "{item.id}" on page "{page.id}": picture "{item.path}" has '
                             f"{px_w}×{px_h} pixels for {item.w:.0f}×{item.h:.0f} mm, so it "
                             f"prints at {dpi:.0f} dpi and will look blocky (about 300 dpi is "
                             "sharp: use a larger picture, or make the item smaller)")
    return notes


def write_output(path: Path, data: bytes) -> None:
    """Atomically replace `path` (a new file gets the umask's permissions, as any new file)."""
    atomic_write(path, data, backup=False)


def log_path_for(out_pdf: Path) -> Path:
    """Where a failed render leaves the LaTeX log: beside the PDF, named after it."""
    return out_pdf.with_name(out_pdf.name + ".log")


def check_pdf_output(project: Project, out_pdf: Path, tex_out: Path | None = None,
                     fragment_out: Path | None = None) -> None:
    """Refuse the outputs (RenderError) where render_pdf would, before anything is done: the
    editor asks for another name then, instead of saying "name a new file" after the work, and
    `floatpage render` before it settles."""
    out_pdf = Path(out_pdf)
    check_outputs([out_pdf, Path(tex_out) if tex_out else None,
                   Path(fragment_out) if fragment_out else None, log_path_for(out_pdf)],
                  project_inputs(project), project_companions(project))


def render_pdf(project: Project, out_pdf: Path, *, tex_out: Path | None = None,
               fragment_out: Path | None = None, timeout_s: float = 120.0,
               progress: Callable[[str], None] | None = None,
               print_bleed_mm: float | None = None) -> RenderReport:
    """Typeset the project into `out_pdf` with one LuaLaTeX run; keep the .tex if asked.

    ``print_bleed_mm`` makes the PDF a print shop's (`render --print`): bleed, crop marks,
    TrimBox and BleedBox (see typeset.print_marks); the fragment stays the bare page."""
    started = time.perf_counter()
    say = progress or (lambda message: None)
    out_pdf = Path(out_pdf)
    check_pdf_output(project, out_pdf, tex_out, fragment_out)
    check_engine_settings()
    if not project.pages:
        raise RenderError("the project has no pages; add a [[pages]] table")
    say("laying out text")
    document = placed_document(project)
    document.warnings.extend(picture_warnings(project))
    notes = contrast_notes(document)
    say("preparing pictures")
    materialize_pictures(document)
    fragment = tex_from_placed(document, fragment=True) if fragment_out is not None else ""
    if print_bleed_mm is not None:
        document = for_print(document, print_bleed_mm)
    tex = tex_from_placed(document)
    say("typesetting with LuaLaTeX")
    engine_started = time.perf_counter()
    with build_folder() as build:
        pdf = compile_pdf(tex, Path(build), labels=document.labels, timeout_s=timeout_s,
                          picture_dir=cache_dir(),
                          keep_log=log_path_for(out_pdf))
        data = pdf.read_bytes()
        pages = count_pages(Path(build), len(document.pages))
    engine_seconds = time.perf_counter() - engine_started
    # Only now, with the PDF made, is anything replaced: a failed render overwrites nothing.
    if tex_out is not None:
        write_output(Path(tex_out), tex.encode("utf-8"))
    if fragment_out is not None:
        write_output(Path(fragment_out), fragment.encode("utf-8"))
    write_output(out_pdf, data)
    log_path_for(out_pdf).unlink(missing_ok=True)  # a failed render's log is now stale
    say(f"wrote {out_pdf}")
    return RenderReport(out_pdf, pages, document.warnings,
                        time.perf_counter() - started, engine_seconds, notes)
