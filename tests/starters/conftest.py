"""Shared, session-scoped renders: each sample and each starter is typeset once per test run.

A LaTeX run costs seconds, so the PDFs are made once and every check reads the same file.
Renders settle first, as every export does (the settle ends with the no-overlap pass).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import pdfplumber
import pytest


@dataclass
class Rendered:
    """A project and the PDF made from it, opened with pdfplumber."""

    project: object
    pdf: Path
    plumber: object


def render(project, out_pdf: Path) -> Rendered:
    from floatpage.model.layout import settle_project
    from floatpage.typeset import render_pdf

    settle_project(project)
    report = render_pdf(project, out_pdf)
    pdf = Path(getattr(report, "pdf", out_pdf))
    return Rendered(project, pdf, pdfplumber.open(pdf))


@pytest.fixture(scope="session")
def render_once(tmp_path_factory):
    """render_once(key, make_project) -> Rendered, made the first time a key is asked for."""
    cache: dict[str, Rendered] = {}
    out_dir = tmp_path_factory.mktemp("starter-pdfs")

    def get(key: str, make_project) -> Rendered:
        if key not in cache:
            cache[key] = render(make_project(), out_dir / f"{key}.pdf")
        return cache[key]

    yield get
    for rendered in cache.values():
        rendered.plumber.close()
