"""Realistic project files no one tuned on, driven through the real `floatpage` command: does
each keep floatpage's promises?

The other sweeps (anchored_pages, gutter_fits, fixed_point) draw one page of plain blocks.  A
user's file holds more: several pages of different sizes (business cards, postcards,
landscape A4, A3 posters), a background colour or picture, a decorative band behind, a
picture that bleeds off the edge, regions with the items confined to them, groups (a photo
and its caption moving as one, sometimes anchored), captions following photos, a title held
near the top by a soft anchor, a logo on a hard anchor, texts with real words, a month panel,
pages nearly empty and pages nearly full, and its own gutter, margin and guides.  This script
draws such files from a seed (``random_project``) and runs on each, as a user would:

1. ``floatpage settle`` twice: the second must change no byte (a fixed point);
2. ``floatpage check --strict``: a page may miss a guarantee only for a reason check names
   (``miss_reasons``; a settled page that check sends back to `settle` is a miss);
3. for every ``--render-every``-th file, ``floatpage render --tex``: the file keeps its bytes
   and every block and picture is typeset where the settled file puts it;
4. no command may end with an internal error.

    .venv/bin/python benchmarks/fresh_projects.py --seeds 1-200 [--render-every 10]

prints one line per file (its pages, the settle's CPU time, and each miss) and a table of the
misses by kind.
"""

from __future__ import annotations

import argparse
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path

import numpy as np

from floatpage.model import load_project, save_project
from floatpage.model.document import (
    Background, BlockItem, CalendarItem, ItemAnchor, Page, PhysicsSettings, PictureItem,
    PointAnchor, Project, Region, TextItem,
)
from floatpage.model.page_sizes import page_dimensions
from anchored_pages import page_verdict

ROOT = Path(__file__).resolve().parents[1]
FLOATPAGE = [sys.executable, "-m", "floatpage.cli.main"]  # the command, as PYTHONPATH has it
PICTURES = sorted((ROOT / "sample_projects" / "calendar-2027" / "pictures").glob("*.jpg"))[:4]
# The named sizes a page is drawn from, fixed: drawn from the model's table, every seed named
# other files once A6 and DL joined it (user-walk-9), and side-by-side runs of two commits
# compared different pages
NAMED_SIZES = ("A3", "A4", "A5", "Letter", "5x7in", "5x8in", "4x6in")
CUSTOM_SIZES = [(85.0, 55.0), (55.0, 85.0), (100.0, 100.0), (148.0, 105.0), (99.0, 210.0),
                (300.0, 100.0), (120.0, 120.0)]
FILLS = {"empty": (0.02, 0.08), "light": (0.08, 0.25), "medium": (0.25, 0.45),
         "full": (0.45, 0.65), "brim": (0.65, 0.85)}
PHRASES = ["Happy Birthday!", "Summer sale", "Fresh bread every morning",
           "With love, Sam", "Open Monday to Saturday, 8 to 18", "Our holiday in Portugal",
           "Grand opening", "Thank you for coming", "Ein schönes Wochenende!",
           "Joyeux anniversaire !", "Two for one on all pastries this week",
           "Call us: 0123 456 789", "Menu", "Concert in the park, 7 pm", "Save the date",
           "The Corner Shop", "Wishing you a year full of sunshine, flowers and good friends."]
COLOURS = ["#f2b84b", "#3a6ea5", "#c4473a", "#6a994e", "#fdf4e6", "#222222", "#e0e0e0"]


def random_project(seed: int, folder: Path) -> Path:
    """A project file of 1-4 pages drawn from ``seed`` in ``folder`` (with its pictures)."""
    rng = np.random.default_rng(seed)
    (folder / "pictures").mkdir(parents=True, exist_ok=True)
    for picture in PICTURES:
        shutil.copy(picture, folder / "pictures" / picture.name)
    physics = PhysicsSettings(
        gutter_mm=float(rng.choice([0.0, 2.0, 3.0, 3.0, 4.0, 6.0])),
        margin_mm=float(rng.choice([0.0, 3.0, 5.0, 5.0, 8.0, 12.0])),
        guides=float(rng.choice([0.0, 0.5, 1.0, 1.0])),
        distance=str(rng.choice(["axis", "axis", "euclidean"])),
        seed=int(rng.integers(0, 1000)))
    pages = [random_page(rng, f"p{index + 1}", physics)
             for index in range(int(rng.choice([1, 1, 2, 3, 4])))]
    path = folder / f"fresh-{seed}.toml"
    save_project(Project(title=f"fresh project {seed}", physics=physics, pages=pages), path)
    return path


def page_size(rng: np.random.Generator) -> tuple[str, str, float, float]:
    if rng.random() < 0.3:
        width, height = CUSTOM_SIZES[rng.integers(len(CUSTOM_SIZES))]
        return "custom", "portrait", width, height
    size = str(rng.choice(NAMED_SIZES))
    orientation = "landscape" if rng.random() < 0.35 else "portrait"
    return (size, orientation, *page_dimensions(size, orientation))


class PageDraw:
    """The items of one page as they are drawn: a running id, the page's walls."""

    def __init__(self, rng: np.random.Generator, page_id: str, width: float, height: float,
                 margin: float):
        self.rng, self.page_id = rng, page_id
        self.width, self.height, self.margin = width, height, margin
        self.items: list = []

    def new_id(self, stem: str) -> str:
        return f"{self.page_id}-{stem}{len(self.items)}"

    def spot(self, w: float, h: float, box=None) -> tuple[float, float]:
        """A random centre for a w x h item in ``box`` (left, top, right, bottom), which it
        may overlap at the edge (a user drops items roughly)."""
        left, top, right, bottom = box or (0.0, 0.0, self.width, self.height)
        x = self.rng.uniform(left + w / 2, max(right - w / 2, left + w / 2))
        y = self.rng.uniform(top + h / 2, max(bottom - h / 2, top + h / 2))
        return round(float(x), 2), round(float(y), 2)

    def inside(self, w: float, h: float) -> tuple[float, float]:
        """A centre keeping the item inside the margins where it can (for hard anchors)."""
        inset = self.margin + 1.0
        box = (inset, inset, self.width - inset, self.height - inset)
        if box[2] - box[0] < w or box[3] - box[1] < h:
            return round(self.width / 2, 2), round(self.height / 2, 2)
        return self.spot(w, h, box)


def random_page(rng: np.random.Generator, page_id: str, physics: PhysicsSettings) -> Page:
    size, orientation, width, height = page_size(rng)
    page = Page(id=page_id, size=size, orientation=orientation, width_mm=width, height_mm=height)
    draw = PageDraw(rng, page_id, width, height, physics.margin_mm)
    roll = rng.random()
    if roll < 0.35:
        page.background = Background(color=str(rng.choice(COLOURS)))
    elif roll < 0.5:
        page.background = Background(picture=f"pictures/{PICTURES[0].name}")
    fill_name = str(rng.choice(list(FILLS), p=[0.12, 0.22, 0.28, 0.24, 0.14]))
    cover = float(rng.uniform(*FILLS[fill_name]))
    if rng.random() < 0.3:
        decoration(draw)
    if rng.random() < 0.15:
        bleeding_picture(draw)
    if rng.random() < 0.3:
        page.regions = regions_of(rng, width, height)
    units = [unit(draw) for _ in range(int(rng.integers(1, 16)))]
    scale_units(units, cover, width, height, physics, page.regions)
    for parts in units:
        place_unit(draw, parts, page.regions)
    page.items = draw.items
    return page


def decoration(draw: PageDraw) -> None:
    """A band behind the items, across the page at its top or bottom, sometimes bleeding."""
    rng = draw.rng
    h = float(rng.uniform(0.08, 0.3)) * draw.height
    y = h / 2 if rng.random() < 0.5 else draw.height - h / 2
    draw.items.append(BlockItem(id=draw.new_id("band"), x=draw.width / 2, y=round(y, 2),
                                w=draw.width, h=round(h, 2), z=-1, decorative=True,
                                color=str(rng.choice(COLOURS)), opacity=0.5,
                                bleed=bool(rng.random() < 0.5)))


def bleeding_picture(draw: PageDraw) -> None:
    """A header photo the full width of the page, flush with its top edge, that bleeds."""
    rng = draw.rng
    h = round(float(rng.uniform(0.15, 0.3)) * draw.height, 2)
    anchor = PointAnchor(x=draw.width / 2, y=h / 2, hard=True) if rng.random() < 0.6 else None
    draw.items.append(PictureItem(id=draw.new_id("header"), x=draw.width / 2, y=h / 2,
                                  w=draw.width, h=h, path=f"pictures/{PICTURES[1].name}",
                                  bleed=True, lock_aspect=False, anchor=anchor))


def regions_of(rng: np.random.Generator, width: float, height: float) -> list[Region]:
    """Two regions that split the page (photos above and words below, or a sidebar)."""
    if rng.random() < 0.5:
        split = round(float(rng.uniform(0.45, 0.7)) * height, 2)
        return [Region(id="photos", left=0.0, top=0.0, w=width, h=split),
                Region(id="words", left=0.0, top=split, w=width, h=round(height - split, 2))]
    split = round(float(rng.uniform(0.25, 0.4)) * width, 2)
    return [Region(id="words", left=0.0, top=0.0, w=split, h=height),
            Region(id="photos", left=split, top=0.0, w=round(width - split, 2), h=height)]


def unit(draw: PageDraw) -> dict:
    """One thing a user puts on a page, as relative sizes and how it holds on:
    a photo (maybe with a caption that follows it or is grouped with it), a text, a block,
    a month panel; with a soft or a hard anchor now and then."""
    rng = draw.rng
    kind = str(rng.choice(["photo", "photo", "captioned", "grouped", "text", "text", "block",
                           "calendar"], p=[0.2, 0.1, 0.15, 0.12, 0.2, 0.08, 0.1, 0.05]))
    aspect = float(np.exp(rng.uniform(np.log(0.5), np.log(2.2))))
    area = float(rng.uniform(0.4, 2.5))
    hold = str(rng.choice(["free", "soft", "hard"], p=[0.75, 0.15, 0.1]))
    return {"kind": kind, "aspect": aspect, "area": area, "hold": hold,
            "text": str(rng.choice(PHRASES)), "region": ""}


def unit_boxes(parts: dict) -> list[tuple[float, float]]:
    """The (w, h) of the unit's items at its scale: a caption is as wide as its photo and a
    fifth as tall (at least 6 mm)."""
    w = np.sqrt(parts["area"] * parts["aspect"]) * parts["scale"]
    h = np.sqrt(parts["area"] / parts["aspect"]) * parts["scale"]
    boxes = [(float(w), float(h))]
    if parts["kind"] in ("captioned", "grouped"):
        boxes.append((float(w), float(max(h / 5, 6.0))))
    return boxes


def scale_units(units: list[dict], cover: float, width: float, height: float,
                physics: PhysicsSettings, regions: list[Region]) -> None:
    """Sizes such that the items cover ``cover`` of the page, each within its room."""
    total = sum(parts["area"] * (1.3 if parts["kind"] in ("captioned", "grouped") else 1.0)
                for parts in units)
    scale = np.sqrt(cover * width * height / total)
    for parts in units:
        parts["scale"] = scale
        if regions and parts["hold"] == "free" and len(regions) > 1:
            wanted = "words" if parts["kind"] in ("text", "calendar") else "photos"
            parts["region"] = wanted
        room_w, room_h = width, height
        if parts["region"]:
            region = next(r for r in regions if r.id == parts["region"])
            room_w, room_h = region.w, region.h
        boxes = unit_boxes(parts)
        across = max(w for w, _ in boxes)
        down = sum(h for _, h in boxes) + (4.0 if len(boxes) > 1 else 0.0)
        shrink = min(1.0, 0.95 * room_w / across, 0.95 * room_h / down)
        parts["scale"] = scale * shrink


def rounded(value: float) -> float:
    return round(float(value), 2)


def place_unit(draw: PageDraw, parts: dict, regions: list[Region]) -> None:
    rng = draw.rng
    boxes = [(max(rounded(w), 4.0), max(rounded(h), 4.0)) for w, h in unit_boxes(parts)]
    w, h = boxes[0]
    box = None
    if parts["region"]:
        region = next(r for r in regions if r.id == parts["region"])
        box = region.box
    x, y = draw.spot(w, h + (boxes[1][1] + 4 if len(boxes) > 1 else 0.0), box)
    if len(boxes) > 1:
        y -= (boxes[1][1] + 4) / 2
    anchor = None
    if parts["hold"] == "soft":
        anchor = PointAnchor(x=rounded(rng.uniform(0, draw.width)),
                             y=rounded(rng.uniform(0, draw.height * 0.3)),
                             gamma=rounded(rng.uniform(0.1, 1.0)))
    elif parts["hold"] == "hard":
        x, y = draw.inside(w, h + (boxes[1][1] + 4 if len(boxes) > 1 else 0.0))
        if len(boxes) > 1:
            y -= (boxes[1][1] + 4) / 2
        anchor = PointAnchor(x=x, y=y, hard=True)
    x, y = rounded(x), rounded(y)
    common = {"region": parts["region"]}
    lead_id = draw.new_id(parts["kind"])
    if parts["kind"] in ("photo", "captioned", "grouped"):
        picture = PICTURES[int(rng.integers(len(PICTURES)))].name
        lead = PictureItem(id=lead_id, x=x, y=y, w=w, h=h, path=f"pictures/{picture}",
                           anchor=anchor, **common)
    elif parts["kind"] == "text":
        lead = TextItem(id=lead_id, x=x, y=y, w=w, h=h, text=parts["text"], anchor=anchor,
                        font=str(rng.choice(["serif", "sans", "display"])),
                        bold=bool(rng.random() < 0.3), **common)
    elif parts["kind"] == "calendar":  # large enough for its days, where its room allows
        left, top, right, bottom = box or (0.0, 0.0, draw.width, draw.height)
        lead = CalendarItem(id=lead_id, x=x, y=y, w=max(w, min(30.0, 0.95 * (right - left))),
                            h=max(h, min(25.0, 0.95 * (bottom - top))),
                            month=int(rng.integers(1, 13)), anchor=anchor, **common)
    else:
        lead = BlockItem(id=lead_id, x=x, y=y, w=w, h=h, color=str(rng.choice(COLOURS)),
                         anchor=anchor, **common)
    draw.items.append(lead)
    if len(boxes) > 1:
        cw, ch = boxes[1]
        dy = rounded(h / 2 + 4 + ch / 2)
        caption = TextItem(id=draw.new_id("caption"), x=x, y=rounded(y + dy), w=cw, h=ch,
                           text=parts["text"], font="sans", **common)
        if parts["kind"] == "captioned":
            caption.anchor = ItemAnchor(to=lead.id, dx=0.0, dy=dy)
        else:
            lead.group = caption.group = f"{lead_id}-group"
        draw.items.append(caption)


# --- the sweep ------------------------------------------------------------------------------

def run(*args: str, cwd: Path) -> tuple[int, str, float]:
    """One `floatpage` command: exit code, stdout and stderr together, CPU seconds."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    done = subprocess.run([*FLOATPAGE, *args], cwd=cwd, capture_output=True, text=True,
                          env=dict(os.environ, COLUMNS="200"), timeout=900)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return done.returncode, done.stdout + done.stderr, cpu


def crashed(code: int, output: str) -> bool:
    return code not in (0, 1) or "Traceback" in output or "internal error" in output


SENT_BACK = "run `floatpage settle"


def miss_reasons(path: Path, check_output: str) -> list[str]:
    """The misses of a settled file: a page check sends back to `settle` (it names no reason
    no settle can fix), or a page that anchored_pages.page_verdict finds unexplained."""
    misses = []
    project = load_project(path)
    for page in project.pages:
        ok, reason = page_verdict(project, page)
        if reason == "UNEXPLAINED":
            misses.append(f"unexplained on {page.id}")
    page_id = None
    for line in check_output.splitlines():
        if line.startswith("page "):
            page_id = line.split(":")[0]
        elif not line.startswith("  "):
            page_id = None  # the warnings and the count after the pages
        elif page_id and SENT_BACK in line:
            misses.append(f"check sends {page_id} back to settle")
            page_id = None
    return misses


TEX_BLOCK = re.compile(r"% \[fp:\d+\] item \"([^\"]+)\" on page \"[^\"]+\"[^\n]*\n"
                       r"(?:\\begin\{scope\}\n\\clip [^\n]*\n)?"  # a picture cropped to its box
                       r"(?:\\fpblock\{[^}]*\}\{[^}]*\}\{([-\d.]+)\}\{([-\d.]+)\}\{([-\d.]+)\}"
                       r"\{([-\d.]+)\}|\\node\[[^\]]*\] at \(([-\d.]+), ([-\d.]+)\) "
                       r"\{\\includegraphics\[width=([-\d.]+)mm, height=([-\d.]+)mm\])")


def typeset_centres(tex: str) -> dict[str, tuple[float, float]]:
    """The centre of every block and picture in a .tex `render --tex` wrote, by item id (a
    picture that keeps its aspect ratio is centred in its box, and so is one cropped to a box
    of another shape: drawn larger, clipped to the box)."""
    centres = {}
    for match in TEX_BLOCK.finditer(tex):
        numbers = [float(value) for value in match.groups()[1:] if value is not None]
        if match.group(2) is not None:
            left, top, right, bottom = numbers
        else:
            left, top, width, height = numbers
            right, bottom = left + width, top + height
        centres[match.group(1)] = ((left + right) / 2, (top + bottom) / 2)
    return centres


def render_moves(path: Path, work: Path) -> tuple[list[str], float]:
    """Render ``path`` (settling first, as `render` does) and list what differs from the
    settled file: its bytes, or a block or picture typeset elsewhere than the file puts it."""
    before = path.read_bytes()
    tex = work / "render.tex"
    code, output, cpu = run("render", path.name, "-q", "-j", "1", "--tex", str(tex),
                            "-o", str(work / "render.pdf"), cwd=path.parent)
    if code != 0:
        return [f"render failed ({code}): {output.strip().splitlines()[-1:]}"], cpu
    misses = [] if path.read_bytes() == before else ["render changed the file"]
    project = load_project(path)
    items = {item.id: item for page in project.pages for item in page.items}
    centres = typeset_centres(tex.read_text())
    shown = [item for item in items.values() if item.kind in ("block", "picture")]
    if len(centres) != len(shown):
        misses.append(f"render typeset {len(centres)} of {len(shown)} blocks and pictures")
    for item_id, (x, y) in centres.items():
        item = items[item_id]
        if abs(x - item.x) > 0.02 or abs(y - item.y) > 0.02:
            misses.append(f"render moved {item_id} to ({x:.2f}, {y:.2f}) from "
                          f"({item.x:.2f}, {item.y:.2f})")
    return misses, cpu


def sweep_one(seed: int, work: Path, render: bool) -> tuple[str, list[str], float]:
    folder = work / f"s{seed}"
    path = random_project(seed, folder)
    project = load_project(path)
    shape = " ".join(f"{page.width_mm:g}x{page.height_mm:g}/{len(page.items)}"
                     for page in project.pages)
    misses: list[str] = []
    code, output, cpu = run("settle", path.name, "-q", "-j", "1", cwd=folder)
    if crashed(code, output) or code:
        return shape, [f"settle failed ({code}): {output.strip()[-300:]}"], cpu
    settled = path.read_bytes()
    code, output, _ = run("settle", path.name, "-q", "-j", "1", cwd=folder)
    if crashed(code, output):
        misses.append("second settle crashed")
    if path.read_bytes() != settled:
        misses.append("second settle CHANGED the file")
        path.write_bytes(settled)
    code, output, _ = run("check", "--strict", path.name, cwd=folder)
    if crashed(code, output):
        misses.append(f"check crashed: {output.strip()[-300:]}")
    else:
        misses += miss_reasons(path, output)
    if render:
        found, _ = render_moves(path, folder)
        misses += found
    if not misses:  # a file that misses is kept for a look
        shutil.rmtree(folder, ignore_errors=True)
    return shape, misses, cpu


def seed_range(text: str) -> range:
    first, _, last = text.partition("-")
    return range(int(first), int(last or first) + 1)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=seed_range, default=seed_range("1-40"),
                        help="A-B: the seeds to draw files from")
    parser.add_argument("--render-every", type=int, default=10,
                        help="render (LaTeX) every N-th file; 0: never")
    parser.add_argument("--keep", type=Path, help="folder for the files that miss")
    args = parser.parse_args()
    work = args.keep or Path(tempfile.mkdtemp(prefix="floatpage-fresh-"))
    kinds: Counter = Counter()
    pages = missed = 0
    seconds = []
    for seed in args.seeds:
        render = bool(args.render_every) and seed % args.render_every == 0
        shape, misses, cpu = sweep_one(seed, work, render)
        pages += shape.count("/")
        seconds.append(cpu)
        missed += bool(misses)
        for miss in misses:
            kinds[re.sub(r" (on|to|from|\().*", "", miss)] += 1
        print(f"seed {seed}: {shape}; settle {cpu:.1f} s CPU{'; rendered' if render else ''}; "
              + ("; ".join(misses) if misses else "keeps every promise"), flush=True)
    print(f"\n{len(args.seeds)} files, {pages} pages, {missed} files with a miss "
          f"(kept in {work}); settle CPU median {float(np.median(seconds)):.2f} s, "
          f"total {sum(seconds):.0f} s")
    print(f"{'miss':<50} files")
    for kind, count in kinds.most_common():
        print(f"{kind:<50} {count}")


if __name__ == "__main__":
    main()
