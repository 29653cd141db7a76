"""Captions sit flush left under their photo, also under a photo narrower than a caption.

A caption box is at least 40 mm wide; centred under a 10 mm-wide portrait strip, its
left-aligned words started 15 mm left of the photo, under nothing. Read back from the PDF
that `floatpage new album --photos` and `floatpage render` make.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pdfplumber
from PIL import Image

from floatpage.model import load_project

PT_PER_MM = 72 / 25.4


def cli(*args: str, cwd: Path) -> None:
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", *args], cwd=cwd,
                            capture_output=True, text=True, timeout=300, stdin=subprocess.DEVNULL)
    assert result.returncode == 0, result.stdout + result.stderr


def test_every_caption_starts_at_its_photos_left_edge(tmp_path):
    photos = tmp_path / "photos"
    photos.mkdir()
    for name, size, colour in (("strip", (300, 3000), (40, 200, 180)),
                               ("wide", (3000, 1000), (200, 120, 40)),
                               ("square", (1500, 1500), (90, 40, 160))):
        Image.new("RGB", size, colour).save(photos / f"{name}.jpg")
    cli("new", "album", "album.toml", "--photos", str(photos), "-j", "1", cwd=tmp_path)
    cli("render", "album.toml", "-o", "album.pdf", "-q", cwd=tmp_path)
    project = load_project(tmp_path / "album.toml")
    with pdfplumber.open(tmp_path / "album.pdf") as pdf:
        for page, sheet in zip(project.pages, pdf.pages):
            words = sheet.extract_words()
            for photo in (i for i in page.items if i.kind == "picture"):
                caption = next(i for i in page.items if i.id == f"{photo.id}-caption")
                first = caption.text.split()[0]
                [word] = [w for w in words if w["text"] == first
                          and abs(w["top"] / PT_PER_MM - caption.y) < caption.h]
                left = word["x0"] / PT_PER_MM
                assert abs(left - photo.left) < 1.0, (
                    f"{caption.text!r} starts at {left:.1f} mm, its photo at {photo.left:.1f} mm")
