"""Regenerate sample_projects/ from the starters: one settled project of each kind.

The samples are what `floatpage new` would give a user, so they come from the same code
(`starters.create`), settled by the same physics. Each lives in its own folder with the
pictures it uses, so the folder alone opens, renders and round-trips.

    .venv/bin/python tools/make_samples.py            # rewrite all four samples
    .venv/bin/python tools/make_samples.py --pngs     # also render docs/images/sample-*.png
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

from floatpage import starters
from floatpage.starters.pictures import bundled

SAMPLES_DIR = ROOT / "sample_projects"
IMAGES_DIR = ROOT / "docs" / "images"
# The album is made of "the user's" photos, so it gets a folder of them, in album order.
ALBUM_PHOTOS = ["alpine-dawn.jpg", "sunflower.jpg", "seaside.jpg", "autumn-forest.jpg",
                "tulips.jpg", "lake-sunset.jpg", "winter-pines.jpg", "daisy-meadow.jpg"]

# folder name -> (kind, options for starters.create, page shown in the README, 1-based)
SAMPLES = {
    "calendar-2027": ("calendar", {"year": 2027}, 10),
    "greeting-card": ("card", {}, 1),
    "photo-album": ("album", {}, 1),
    "shop-flyer": ("flyer", {}, 1),
}


def album_photos(folder: Path) -> Path:
    """A folder of "the user's" photos; the album takes them in name order, as for a real user."""
    folder.mkdir()
    for source in bundled(ALBUM_PHOTOS):
        shutil.copyfile(source, folder / source.name)
    return folder


def make(name: str) -> Path:
    kind, options, _ = SAMPLES[name]
    folder = SAMPLES_DIR / name
    if folder.exists():
        shutil.rmtree(folder)
    with tempfile.TemporaryDirectory() as scratch:
        if kind == "album":
            options = dict(options, photos=album_photos(Path(scratch) / "photos"))
        project = starters.create(kind, folder / f"{name}.toml", **options)
    return project.path


def render_png(project_path: Path, page: int, out_png: Path) -> None:
    """Render the project and keep one page as a small PNG for the README."""
    from floatpage.model import load_project
    from floatpage.typeset import render_pdf

    with tempfile.TemporaryDirectory() as scratch:
        pdf = Path(scratch) / "sample.pdf"
        render_pdf(load_project(project_path), pdf)
        stem = Path(scratch) / "page"
        subprocess.run(["pdftoppm", "-png", "-r", "50", "-f", str(page), "-l", str(page),
                        "-singlefile", str(pdf), str(stem)], check=True)
        out_png.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(stem.with_suffix(".png"), out_png)


def merge_png(out_png: Path) -> None:
    """Three records of the merge sample side by side, with pictures of three shapes."""
    import csv

    from PIL import Image

    sample = ROOT / "sample_projects" / "merge-offers"
    with (sample / "customers.csv").open(encoding="utf-8") as handle:
        records = list(csv.DictReader(handle))
    picked, photos = [], set()
    for record in records:  # long names first: what a fixed frame cannot take
        if record["photo"] not in photos and len(picked) < 3 and (
                len(record["product"]) > 20 or len(picked) > 0):
            picked.append(record)
            photos.add(record["photo"])
    with tempfile.TemporaryDirectory() as scratch:
        data = Path(scratch) / "three.csv"
        with data.open("w", encoding="utf-8", newline="") as handle:
            writer = csv.DictWriter(handle, fieldnames=list(records[0]))
            writer.writeheader()
            writer.writerows(picked)
        subprocess.run([sys.executable, "-m", "floatpage.cli.main", "merge",
                        str(sample / "offer.toml"), str(data), "-o", str(Path(scratch) / "out"),
                        "--combined", "-q"], check=True, stdout=subprocess.DEVNULL)
        stem = Path(scratch) / "page"
        subprocess.run(["pdftoppm", "-png", "-r", "50", str(Path(scratch) / "out" /
                                                             "combined.pdf"), str(stem)],
                       check=True)
        pages = [Image.open(path) for path in sorted(Path(scratch).glob("page-*.png"))]
        gap = 12
        sheet = Image.new("RGB", (sum(p.width for p in pages) + gap * (len(pages) + 1),
                                  max(p.height for p in pages) + 2 * gap), "#d9d9d9")
        x = gap
        for page in pages:
            sheet.paste(page, (x, gap))
            x += page.width + gap
        sheet.save(out_png, optimize=True)


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pngs", action="store_true", help="also render docs/images/sample-*.png")
    parser.add_argument("names", nargs="*", help=f"samples to rebuild (default: all of {', '.join(SAMPLES)})")
    args = parser.parse_args(argv)
    names = args.names or list(SAMPLES)
    unknown = [n for n in names if n not in SAMPLES]
    if unknown:
        parser.error(f"unknown sample(s): {', '.join(unknown)}")
    for name in names:
        path = make(name)
        print(f"wrote {path.relative_to(ROOT)}")
        if args.pngs:
            kind, _, page = SAMPLES[name]
            png = IMAGES_DIR / f"sample-{kind}.png"
            render_png(path, page, png)
            print(f"wrote {png.relative_to(ROOT)} ({png.stat().st_size // 1024} KB)")
    if args.pngs and not args.names:
        png = IMAGES_DIR / "sample-merge.png"
        merge_png(png)
        print(f"wrote {png.relative_to(ROOT)} ({png.stat().st_size // 1024} KB)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
