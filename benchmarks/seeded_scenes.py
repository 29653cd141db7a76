"""Seeded scenes for the physics tests and benchmarks: mixed photos and text boxes on A4.

A scene is a page size and the items' centres and sizes, before any physics. Shared by
tests/physics (pytest's pythonpath holds this folder) and the benchmarks run from here, so
that both talk about the same pages; not part of the installed package.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from floatpage.physics.params import A4_H_MM, A4_W_MM

PHOTO_ASPECTS = (4 / 3, 3 / 4, 1.0, 3 / 2, 2 / 3)  # width / height
TEXT_ASPECTS = (2.5, 3.0, 4.0, 5.0)
TEXT_SHARE = 0.35  # share of items that are text boxes


@dataclass(frozen=True)
class Scene:
    """One seeded page of boxes: a name for the tables, the page, the centres and sizes."""

    name: str
    page_w_mm: float
    page_h_mm: float
    centres: np.ndarray  # (n, 2) mm
    sizes: np.ndarray  # (n, 2) mm

    @property
    def ids(self) -> tuple[str, ...]:
        return tuple(f"item{k}" for k in range(len(self.centres)))

    @property
    def coverage(self) -> float:
        return float(np.prod(self.sizes, axis=1).sum() / (self.page_w_mm * self.page_h_mm))


def mixed_sizes(count: int, coverage: float, page_w_mm: float, page_h_mm: float,
                rng: np.random.Generator) -> np.ndarray:
    """Sizes (count, 2) of photos and text boxes whose areas add up to ``coverage`` of the page.

    Areas vary by a factor of about 4, as on a real album page.
    """
    text = rng.random(count) < TEXT_SHARE
    aspects = np.where(text, rng.choice(TEXT_ASPECTS, count), rng.choice(PHOTO_ASPECTS, count))
    weights = rng.uniform(0.5, 2.0, count) * np.where(text, 0.5, 1.0)
    areas = weights / weights.sum() * coverage * page_w_mm * page_h_mm
    widths = np.sqrt(areas * aspects)
    return np.column_stack([widths, areas / widths])


def scattered_centres(sizes: np.ndarray, page_w_mm: float, page_h_mm: float,
                      rng: np.random.Generator) -> np.ndarray:
    """Random centres that keep each item inside the page where it fits."""
    extent = np.array([page_w_mm, page_h_mm])
    low = np.minimum(sizes / 2, extent / 2)
    high = np.maximum(extent - sizes / 2, extent / 2)
    return low + rng.random(sizes.shape) * (high - low)


def mixed_scene(count: int, coverage: float = 0.5, seed: int = 0, *,
                page_w_mm: float = A4_W_MM, page_h_mm: float = A4_H_MM) -> Scene:
    rng = np.random.default_rng(seed)
    sizes = mixed_sizes(count, coverage, page_w_mm, page_h_mm, rng)
    centres = scattered_centres(sizes, page_w_mm, page_h_mm, rng)
    return Scene(f"{count} items, {coverage:.0%}", page_w_mm, page_h_mm, centres, sizes)


def dropped_scene(count: int = 12, coverage: float = 0.4, seed: int = 0) -> Scene:
    """``count`` items dropped on one point of the page (all centres equal)."""
    rng = np.random.default_rng(seed)
    sizes = mixed_sizes(count, coverage, A4_W_MM, A4_H_MM, rng)
    centres = np.tile([A4_W_MM * 0.4, A4_H_MM * 0.6], (count, 1))
    return Scene(f"{count} dropped on one point", A4_W_MM, A4_H_MM, centres, sizes)


def big_item_scene(seed: int = 0) -> Scene:
    """One item larger than half the page among five small ones (about 58% coverage)."""
    rng = np.random.default_rng(seed)
    big = np.array([[160.0, 200.0]])
    small = np.column_stack([rng.uniform(25, 35, 5), rng.uniform(25, 35, 5)])
    sizes = np.vstack([big, small])
    centres = scattered_centres(sizes, A4_W_MM, A4_H_MM, rng)
    return Scene("one item > half the page", A4_W_MM, A4_H_MM, centres, sizes)


def load(engine, scene: Scene) -> None:
    """Insert every item of ``scene`` into ``engine`` (an Engine of the scene's page size)."""
    for item_id, (x, y), (w, h) in zip(scene.ids, scene.centres, scene.sizes):
        engine.insert(item_id, float(x), float(y), float(w), float(h))


def album_pages(pages: int, photos: int, photo, rng: np.random.Generator) -> list:
    """A photo album as a user starts one: ``pages`` A4 pages of ``photos`` photos dropped
    anywhere, every third with a caption following it just below.  ``photo(page, k, x, y)``
    makes the photo item (its id, size and kind are the caller's)."""
    from floatpage.model.document import ItemAnchor, Page, TextItem

    made = []
    for number in range(pages):
        items = []
        for k in range(photos):
            shot = photo(number, k, float(rng.uniform(20, 190)), float(rng.uniform(20, 277)))
            items.append(shot)
            if k % 3 == 0:
                below = round(shot.h / 2 + 5.0, 2)
                items.append(TextItem(id=f"{shot.id}-caption", x=shot.x, y=shot.y + below,
                                      w=shot.w, h=6.0, text="A caption",
                                      anchor=ItemAnchor(to=shot.id, dx=0.0, dy=below)))
        made.append(Page(id=f"page-{number + 1}", items=items))
    return made


def fresh_scenes(count: int, first_seed: int = 3000) -> list[Scene]:
    """Scenes no one tuned on: ``count`` seeded pages of 8 to 300 items covering 25-60 % of
    five page sizes, then 20 and 8 items dropped on one point and two pages with one item
    larger than half the page."""
    sizes = ((210.0, 297.0), (297.0, 210.0), (148.0, 210.0), (215.9, 279.4), (297.0, 420.0))
    rng = np.random.default_rng(4242)
    chosen = []
    for k in range(count):
        items = int(rng.choice([8, 15, 30, 40, 60, 80, 120, 300]))
        coverage = float(rng.uniform(0.25, 0.6))
        w, h = sizes[k % len(sizes)]
        chosen.append(replace(mixed_scene(items, coverage, seed=first_seed + k, page_w_mm=w,
                                          page_h_mm=h),
                              name=f"seed {first_seed + k}: {items} items, {w:g}x{h:g} mm"))
    return chosen + [replace(dropped_scene(20, seed=7), name="20 dropped on one point, seed 7"),
                     replace(dropped_scene(8, seed=8), name="8 dropped on one point, seed 8"),
                     replace(big_item_scene(seed=5), name="one item > half the page, seed 5"),
                     replace(big_item_scene(seed=6), name="one item > half the page, seed 6")]
