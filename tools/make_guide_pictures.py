"""Render the README's pictures of the samples as they are committed: each sample's page
(docs/images/sample-*.png) and, side by side, the same page settled without the alignment
guides and with them (docs/images/guides-*.png).

`tools/make_samples.py` makes the samples from the starters; this renders what is there, so the
pictures can follow a re-settle of the samples without remaking them.

    .venv/bin/python tools/make_guide_pictures.py
"""

from __future__ import annotations

import dataclasses
import shutil
import sys
import tempfile
from pathlib import Path

from PIL import Image, ImageDraw, ImageFont

from floatpage.model import load_project, save_project
from floatpage.model.layout import settle_project
from make_samples import render_png

ROOT = Path(__file__).resolve().parent.parent
IMAGES_DIR = ROOT / "docs" / "images"
LABEL_FONT = "/usr/share/fonts/truetype/noto/NotoSans-Regular.ttf"
# sample folder -> (README picture, page shown there, before/after pictures: name -> page)
PICTURES = {
    "calendar-2027": ("sample-calendar.png", 10, {"guides-calendar.png": 10}),
    "greeting-card": ("sample-card.png", 1, {"guides-card.png": 1}),
    "photo-album": ("sample-album.png", 1, {"guides-album.png": 1, "guides-album-2.png": 2}),
    "shop-flyer": ("sample-flyer.png", 1, {"guides-flyer.png": 1}),
}


def page_png(project_path: Path, page: int, scratch: Path, stem: str) -> Image.Image:
    """One page of the project, typeset as saved, as the README shows the samples."""
    png = scratch / f"{stem}.png"
    render_png(project_path, page, png)
    return Image.open(png).convert("RGB")


def without_guides(sample: Path, scratch: Path) -> Path:
    """A copy of the sample settled with `guides = 0`, as a user turning them off gets it."""
    folder = shutil.copytree(sample, scratch / f"{sample.name}-no-guides")
    path = next(folder.glob("*.toml"))
    project = load_project(path)
    project.physics = dataclasses.replace(project.physics, guides=0.0)
    settle_project(project)
    save_project(project, path)
    return path


def side_by_side(before: Image.Image, after: Image.Image) -> Image.Image:
    gap, label_h = 14, 26
    sheet = Image.new("RGB", (before.width + after.width + 3 * gap,
                              max(before.height, after.height) + label_h + gap), "#d9d9d9")
    draw = ImageDraw.Draw(sheet)
    font = ImageFont.truetype(LABEL_FONT, 15)
    for x, image, label in ((gap, before, "before: no guides"),
                            (2 * gap + before.width, after, "after: guides on")):
        draw.text((x, 4), label, fill="#222222", font=font)
        sheet.paste(image, (x, label_h))
    return sheet


def main() -> int:
    with tempfile.TemporaryDirectory() as scratch_name:
        scratch = Path(scratch_name)
        for name, (readme_png, readme_page, pairs) in PICTURES.items():
            sample = ROOT / "sample_projects" / name
            copy = shutil.copytree(sample, scratch / name)  # renders never write beside samples
            as_is = next(copy.glob("*.toml"))
            render_png(as_is, readme_page, IMAGES_DIR / readme_png)
            print(f"wrote docs/images/{readme_png}")
            plain = without_guides(sample, scratch)
            for picture, page in pairs.items():
                before = page_png(plain, page, scratch, f"{name}-{page}-before")
                after = page_png(as_is, page, scratch, f"{name}-{page}-after")
                side_by_side(before, after).save(IMAGES_DIR / picture, optimize=True)
                print(f"wrote docs/images/{picture}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
