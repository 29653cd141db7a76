"""A new card's colour bands, which run to the page's edges, bleed in `render --print`.

A band that stops exactly at the trim leaves a white hairline wherever the print shop's
knife wanders (a fraction of a millimetre is normal), so a print-ready card carries every
colour that meets an edge on into the bleed. The check renders `floatpage new card` with
the real CLI and LuaLaTeX, reads the TrimBox from the PDF, and compares pixels from
pdftoppm just inside and just outside the trim, where a band meets the page edge.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pdfplumber
import pytest
from PIL import Image

DPI = 150
PT_PER_MM = 72 / 25.4


def cli(*args: str, cwd: Path) -> None:
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", *args], cwd=cwd,
                            capture_output=True, text=True, timeout=300, stdin=subprocess.DEVNULL)
    assert result.returncode == 0, result.stdout + result.stderr


@pytest.fixture(scope="module", params=["portrait", "landscape"])
def printed_card(request, tmp_path_factory):
    """(trim boxes in mm from each sheet's top left, sheet images) of a new card printed."""
    folder = tmp_path_factory.mktemp(f"card-{request.param}")
    cli("new", "card", "card.toml", "--orientation", request.param, cwd=folder)
    cli("render", "card.toml", "--print", "-o", "card.pdf", "-q", cwd=folder)
    trims = []
    with pdfplumber.open(folder / "card.pdf") as pdf:
        for page in pdf.pages:
            left, bottom, right, top = (float(v) / PT_PER_MM for v in page.page_obj.attrs["TrimBox"])
            sheet_h = float(page.height) / PT_PER_MM
            trims.append((left, sheet_h - top, right - left, top - bottom))
    subprocess.run(["pdftoppm", "-r", str(DPI), "-png", str(folder / "card.pdf"), str(folder / "sheet")],
                   check=True)
    sheets = [Image.open(path).convert("RGB") for path in sorted(folder.glob("sheet-*.png"))]
    return request.param, trims, sheets


def colour(sheet: Image.Image, trim, x_mm: float, y_mm: float) -> tuple[int, int, int]:
    """The colour at (x, y) mm from the trim's top-left corner."""
    left, top, _, _ = trim
    scale = DPI / 25.4
    return sheet.getpixel((round((left + x_mm) * scale), round((top + y_mm) * scale)))


def edge_pairs(orientation: str, w: float, h: float):
    """(page, point just inside the trim on a band, the point 1.5 mm beyond it in the bleed)."""
    if orientation == "portrait":
        return [(0, (w / 2, h - 1.0), (w / 2, h + 1.5)),      # front band, bottom edge
                (0, (1.0, h - 20.0), (-1.5, h - 20.0)),       # its left edge
                (0, (w - 1.0, h - 20.0), (w + 1.5, h - 20.0)),  # its right edge
                (1, (w / 2, 1.0), (w / 2, -1.5))]             # inside band, top edge
    return [(0, (w - 1.0, h / 2), (w + 1.5, h / 2)),          # front band, right edge
            (0, (w - 20.0, 1.0), (w - 20.0, -1.5)),           # its top edge
            (0, (w - 20.0, h - 1.0), (w - 20.0, h + 1.5)),    # its bottom edge
            (1, (w / 2, 1.0), (w / 2, -1.5))]                 # inside band, top edge


def test_bands_that_meet_the_page_edge_run_on_into_the_bleed(printed_card):
    orientation, trims, sheets = printed_card
    _, _, w, h = trims[0]
    for page, inside, beyond in edge_pairs(orientation, w, h):
        on_band = colour(sheets[page], trims[page], *inside)
        in_bleed = colour(sheets[page], trims[page], *beyond)
        assert in_bleed == pytest.approx(on_band, abs=10), (
            f"page {page + 1}: the band is {on_band} at {inside} mm but the bleed beyond it, at "
            f"{beyond} mm, is {in_bleed}: a white or cream hairline after trimming")
