"""Paint the small pictures bundled with the starters: landscapes, flowers and shop products.

Why paint them: the starters and the sample projects need pictures that anyone may copy, and
a painted picture has no licence to track and no download to go stale. Every picture comes
from a seeded generator and Pillow's drawing primitives, so a run gives the same files.

Pictures are drawn at twice their size and scaled down, which smooths the edges. Each stays
under 60 KB, and the set mixes landscape, portrait and square shapes, JPEG and PNG.

    .venv/bin/python tools/paint_sample_pictures.py [OUT_DIR]   # default: starters/bundled
"""

from __future__ import annotations

import math
import random
import sys
from pathlib import Path

from PIL import Image, ImageDraw, ImageFilter

SUPERSAMPLE = 2
MAX_BYTES = 60_000
DEFAULT_OUT = Path(__file__).resolve().parent.parent / "starters" / "bundled"

RGB = tuple[int, int, int]


def mix(a: RGB, b: RGB, t: float) -> RGB:
    """Colour a fraction t of the way from a to b."""
    return tuple(round(x + (y - x) * t) for x, y in zip(a, b))


def vertical_gradient(size: tuple[int, int], stops: list[tuple[float, RGB]]) -> Image.Image:
    """An image whose colour runs top to bottom through (position 0..1, colour) stops."""
    w, h = size
    column = Image.new("RGB", (1, h))
    for y in range(h):
        t = y / max(h - 1, 1)
        for (t0, c0), (t1, c1) in zip(stops, stops[1:]):
            if t0 <= t <= t1:
                column.putpixel((0, y), mix(c0, c1, (t - t0) / max(t1 - t0, 1e-9)))
                break
    return column.resize((w, h))


def ellipse_points(cx, cy, rx, ry, angle=0.0, n=48):
    """Polygon of an ellipse turned by `angle` radians (ImageDraw's ellipse cannot rotate)."""
    ca, sa = math.cos(angle), math.sin(angle)
    pts = []
    for k in range(n):
        t = 2 * math.pi * k / n
        x, y = rx * math.cos(t), ry * math.sin(t)
        pts.append((cx + x * ca - y * sa, cy + x * sa + y * ca))
    return pts


def ridge(rng: random.Random, w: int, base: float, rough: float, steps: int = 24) -> list:
    """A mountain or hill outline: a seeded random walk across the width."""
    pts, y = [], base
    for k in range(steps + 1):
        y += rng.uniform(-rough, rough)
        y = min(max(y, base - 3 * rough), base + 3 * rough)
        pts.append((w * k / steps, y))
    return pts


def wave(w: int, y_of, steps: int = 60) -> list:
    """Outline of a smooth curve y_of(x) across the full width, both ends included."""
    return [(w * k / steps, y_of(w * k / steps)) for k in range(steps + 1)]


def fill_below(draw: ImageDraw.ImageDraw, outline: list, h: int, colour: RGB) -> None:
    w = outline[-1][0]
    draw.polygon(outline + [(w, h), (0, h)], fill=colour)


def soft_clouds(img: Image.Image, rng: random.Random, count: int, top: float, bottom: float) -> None:
    """White puffs on a blurred layer, so they read as clouds rather than circles."""
    w, h = img.size
    layer = Image.new("L", img.size, 0)
    d = ImageDraw.Draw(layer)
    for _ in range(count):
        cx, cy = rng.uniform(0, w), rng.uniform(top * h, bottom * h)
        for _ in range(5):
            r = rng.uniform(0.03, 0.06) * w
            ox, oy = rng.uniform(-0.06, 0.06) * w, rng.uniform(-0.015, 0.015) * h
            d.ellipse((cx + ox - r, cy + oy - r * 0.6, cx + ox + r, cy + oy + r * 0.6), fill=200)
    layer = layer.filter(ImageFilter.GaussianBlur(w * 0.01))
    img.paste(Image.new("RGB", img.size, (255, 255, 255)), mask=layer)


def pine(draw, x, base, height, colour: RGB, snow: RGB | None = None) -> None:
    """A pine tree of three stacked triangles, optionally with snow on each tier."""
    draw.rectangle((x - height * 0.04, base - height * 0.15, x + height * 0.04, base), fill=(80, 55, 40))
    for k in range(3):
        top = base - height * (1.0 - 0.25 * k)
        bottom = base - height * (0.45 - 0.2 * k) + height * 0.3 * (k == 2)
        half = height * (0.18 + 0.08 * k)
        draw.polygon([(x, top), (x - half, bottom), (x + half, bottom)], fill=colour)
        if snow:
            draw.polygon([(x, top), (x - half * 0.35, top + (bottom - top) * 0.35),
                          (x + half * 0.35, top + (bottom - top) * 0.35)], fill=snow)


# --- landscapes -------------------------------------------------------------------------

def alpine_dawn(w, h, rng):
    img = vertical_gradient((w, h), [(0, (250, 200, 170)), (0.45, (190, 215, 240)), (1, (120, 170, 210))])
    d = ImageDraw.Draw(img)
    d.ellipse((w * 0.62, h * 0.12, w * 0.74, h * 0.12 + w * 0.12), fill=(255, 236, 200))
    ranges = [(0.42, 0.07, (150, 165, 200)), (0.55, 0.06, (105, 125, 165)), (0.7, 0.04, (70, 95, 120))]
    for base, rough, colour in ranges:
        outline = ridge(rng, w, base * h, rough * h, steps=12)
        fill_below(d, outline, h, colour)
        for x, y in outline:  # snow caps on the highest points of the far ranges
            if base < 0.6 and y < (base - rough) * h:
                d.polygon([(x, y), (x - w * 0.03, y + h * 0.05), (x + w * 0.03, y + h * 0.05)],
                          fill=(245, 245, 250))
    d.rectangle((0, h * 0.82, w, h), fill=(110, 150, 110))
    return img


def lake_sunset(w, h, rng):
    img = vertical_gradient((w, h), [(0, (70, 60, 130)), (0.35, (230, 120, 110)), (0.58, (252, 200, 120)),
                                     (0.6, (120, 90, 140)), (1, (40, 40, 90))])
    d = ImageDraw.Draw(img)
    r = w * 0.09
    d.pieslice((w * 0.5 - r, h * 0.6 - r, w * 0.5 + r, h * 0.6 + r), 180, 360, fill=(255, 220, 140))
    for k in range(18):  # the sun's glitter on the water
        y = h * (0.62 + 0.02 * k)
        half = r * (1.0 - k / 20) * rng.uniform(0.6, 1.0)
        d.line((w * 0.5 - half, y, w * 0.5 + half, y), fill=(250, 190, 130), width=max(2, h // 150))
    hill = [(0, h * 0.5), (w * 0.12, h * 0.46), (w * 0.3, h * 0.56), (w * 0.34, h * 0.6), (0, h * 0.6)]
    d.polygon(hill, fill=(40, 30, 60))
    for k in range(7):
        pine(d, w * (0.02 + 0.045 * k), h * 0.6, h * rng.uniform(0.14, 0.22), (35, 28, 55))
    return img


def rolling_hills(w, h, rng):
    img = vertical_gradient((w, h), [(0, (120, 175, 230)), (0.5, (200, 225, 245)), (1, (200, 225, 245))])
    soft_clouds(img, rng, 5, 0.08, 0.35)
    d = ImageDraw.Draw(img)
    greens = [(150, 195, 110), (110, 170, 80), (80, 145, 65), (60, 120, 55)]
    for k, colour in enumerate(greens):
        base, amp, phase = h * (0.5 + 0.12 * k), h * 0.05, rng.uniform(0, 6)
        outline = wave(w, lambda x: base + amp * math.sin(x / w * 5 + phase))
        fill_below(d, outline, h, colour)
        if k == 1:  # a red-roofed farmhouse on the second hill
            x, y = w * 0.68, base + amp * math.sin(0.68 * 5 + phase) - h * 0.02
            d.rectangle((x - w * 0.035, y - h * 0.05, x + w * 0.035, y), fill=(245, 235, 215))
            d.polygon([(x - w * 0.045, y - h * 0.05), (x, y - h * 0.1), (x + w * 0.045, y - h * 0.05)],
                      fill=(190, 60, 50))
        if k == 2:
            for _ in range(6):
                x = rng.uniform(0.05, 0.5) * w
                y = base + amp * math.sin(x / w * 5 + phase)
                d.rectangle((x - 2 * SUPERSAMPLE, y - h * 0.05, x + 2 * SUPERSAMPLE, y), fill=(90, 70, 50))
                d.ellipse((x - w * 0.025, y - h * 0.11, x + w * 0.025, y - h * 0.04), fill=(50, 110, 50))
    return img


def seaside(w, h, rng):
    img = vertical_gradient((w, h), [(0, (110, 180, 235)), (0.45, (215, 235, 250)), (0.46, (40, 130, 170)),
                                     (0.72, (90, 185, 200)), (1, (90, 185, 200))])
    soft_clouds(img, rng, 4, 0.05, 0.3)
    d = ImageDraw.Draw(img)
    fill_below(d, wave(w, lambda x: h * 0.74 + h * 0.03 * math.sin(x / w * 7)), h, (240, 220, 170))
    for k in range(14):
        x, y = rng.uniform(0, w), rng.uniform(0.5, 0.7) * h
        d.arc((x - w * 0.03, y - h * 0.01, x + w * 0.03, y + h * 0.01), 200, 340, fill=(230, 245, 250),
              width=SUPERSAMPLE * 2)
    bx, by = w * 0.3, h * 0.5
    d.polygon([(bx - w * 0.06, by), (bx + w * 0.06, by), (bx + w * 0.045, by + h * 0.03),
               (bx - w * 0.045, by + h * 0.03)], fill=(150, 70, 50))
    d.polygon([(bx, by - h * 0.2), (bx, by - h * 0.01), (bx + w * 0.06, by - h * 0.01)], fill=(250, 250, 245))
    d.polygon([(bx - 3, by - h * 0.17), (bx - 3, by - h * 0.01), (bx - w * 0.04, by - h * 0.01)],
              fill=(240, 120, 90))
    return img


def autumn_forest(w, h, rng):
    img = vertical_gradient((w, h), [(0, (245, 220, 170)), (0.6, (235, 200, 150)), (1, (200, 140, 90))])
    d = ImageDraw.Draw(img)
    d.rectangle((0, h * 0.78, w, h), fill=(170, 110, 60))
    leaves = [(220, 90, 40), (240, 160, 40), (200, 60, 40), (230, 190, 70), (180, 100, 40)]
    for k in range(9):
        x = w * (0.06 + 0.11 * k) + rng.uniform(-w * 0.02, w * 0.02)
        base = h * rng.uniform(0.8, 0.86)
        top = h * rng.uniform(0.25, 0.4)
        d.rectangle((x - w * 0.012, top + h * 0.15, x + w * 0.012, base), fill=(90, 60, 45))
        for _ in range(12):
            cx, cy = x + rng.uniform(-0.06, 0.06) * w, top + rng.uniform(0, 0.22) * h
            r = rng.uniform(0.03, 0.05) * w
            d.ellipse((cx - r, cy - r, cx + r, cy + r), fill=rng.choice(leaves))
    for _ in range(60):
        x, y = rng.uniform(0, w), rng.uniform(0.8, 1.0) * h
        d.polygon(ellipse_points(x, y, w * 0.008, h * 0.004, rng.uniform(0, 3), 10), fill=rng.choice(leaves))
    return img


def winter_pines(w, h, rng):
    img = vertical_gradient((w, h), [(0, (175, 200, 230)), (0.6, (225, 235, 245)), (1, (240, 245, 250))])
    d = ImageDraw.Draw(img)
    fill_below(d, ridge(rng, w, h * 0.55, h * 0.02, 10), h, (200, 215, 235))
    fill_below(d, wave(w, lambda x: h * 0.72 + h * 0.03 * math.sin(x / w * 4)), h, (248, 250, 253))
    for k, (x, height) in enumerate([(0.2, 0.42), (0.55, 0.55), (0.82, 0.38), (0.38, 0.3), (0.7, 0.26)]):
        pine(d, w * x, h * (0.8 + 0.04 * (k % 2)), h * height, (40, 90, 70), snow=(245, 248, 252))
    for _ in range(140):
        x, y, r = rng.uniform(0, w), rng.uniform(0, h), rng.uniform(1, 2.5) * SUPERSAMPLE
        d.ellipse((x - r, y - r, x + r, y + r), fill=(255, 255, 255))
    return img


def night_sky(w, h, rng):
    img = vertical_gradient((w, h), [(0, (15, 20, 60)), (0.7, (50, 60, 120)), (1, (80, 80, 140))])
    d = ImageDraw.Draw(img)
    for _ in range(160):
        x, y = rng.uniform(0, w), rng.uniform(0, 0.7) * h
        r = rng.choice([0.6, 0.8, 1.0, 1.6]) * SUPERSAMPLE
        d.ellipse((x - r, y - r, x + r, y + r), fill=mix((255, 255, 255), (255, 230, 170), rng.random()))
    mx, my, mr = w * 0.68, h * 0.2, w * 0.1
    d.ellipse((mx - mr, my - mr, mx + mr, my + mr), fill=(250, 240, 200))
    d.ellipse((mx - mr * 0.6, my - mr * 1.1, mx + mr * 1.3, my + mr * 0.7), fill=mix((15, 20, 60), (50, 60, 120), 0.28))
    fill_below(d, ridge(rng, w, h * 0.72, h * 0.03, 10), h, (30, 35, 70))
    fill_below(d, ridge(rng, w, h * 0.84, h * 0.02, 8), h, (18, 22, 45))
    return img


# --- flowers ----------------------------------------------------------------------------

def flower(d, cx, cy, r, petal: RGB, centre: RGB, petals=12, length=1.0, width=0.35, turn=0.0):
    """A radial flower: rotated elliptical petals around a round centre."""
    for k in range(petals):
        a = turn + 2 * math.pi * k / petals
        px, py = cx + math.cos(a) * r * 0.55 * length, cy + math.sin(a) * r * 0.55 * length
        d.polygon(ellipse_points(px, py, r * 0.55 * length, r * width, a, 24), fill=petal)
    d.ellipse((cx - r * 0.35, cy - r * 0.35, cx + r * 0.35, cy + r * 0.35), fill=centre)


def sunflower(w, h, rng):
    img = vertical_gradient((w, h), [(0, (110, 170, 225)), (1, (190, 220, 240))])
    soft_clouds(img, rng, 3, 0.05, 0.5)
    d = ImageDraw.Draw(img)
    cx, cy, r = w * 0.5, h * 0.36, w * 0.34
    d.rectangle((cx - w * 0.025, cy, cx + w * 0.025, h), fill=(70, 130, 50))
    for side in (-1, 1):
        d.polygon(ellipse_points(cx + side * w * 0.16, h * 0.75, w * 0.16, w * 0.06, side * 0.5), fill=(80, 150, 60))
    flower(d, cx, cy, r, (245, 190, 30), (110, 70, 30), petals=22, width=0.2, turn=0.1)
    flower(d, cx, cy, r * 0.85, (250, 210, 60), (110, 70, 30), petals=22, width=0.18, turn=0.25)
    for k in range(260):  # seeds in a golden-angle spiral
        a, s = k * 2.39996, math.sqrt(k / 260) * r * 0.33
        x, y = cx + math.cos(a) * s, cy + math.sin(a) * s
        d.ellipse((x - 2.5, y - 2.5, x + 2.5, y + 2.5), fill=(70, 45, 20))
    return img


def tulips(w, h, rng):
    img = vertical_gradient((w, h), [(0, (250, 235, 240)), (1, (225, 240, 220))])
    d = ImageDraw.Draw(img)
    colours = [(220, 50, 70), (245, 150, 40), (240, 90, 140), (250, 210, 60), (170, 60, 150)]
    for k in range(5):
        x = w * (0.14 + 0.18 * k)
        top = h * (0.2 + 0.12 * ((k * 3) % 4) / 3)
        stem = [(x, h), (x + rng.uniform(-0.05, 0.05) * w, top + h * 0.1)]
        d.line(stem, fill=(70, 140, 70), width=int(w * 0.018))
        d.polygon(ellipse_points(x + w * 0.04, h * 0.8, w * 0.04, h * 0.14, 0.25), fill=(90, 160, 80))
        hx = stem[1][0]
        c = colours[k]
        d.ellipse((hx - w * 0.07, top, hx + w * 0.07, top + h * 0.14), fill=c)
        for dx in (-0.05, 0.0, 0.05):
            d.polygon([(hx + dx * w - w * 0.03, top + h * 0.04), (hx + dx * w, top - h * 0.02),
                       (hx + dx * w + w * 0.03, top + h * 0.04)], fill=c)
        d.ellipse((hx - w * 0.03, top + h * 0.02, hx, top + h * 0.08), fill=mix(c, (255, 255, 255), 0.35))
    return img


def daisy_meadow(w, h, rng):
    img = vertical_gradient((w, h), [(0, (160, 205, 240)), (0.35, (215, 235, 245)), (0.36, (140, 190, 90)),
                                     (1, (70, 140, 60))])
    d = ImageDraw.Draw(img)
    spots = sorted((rng.uniform(0, w), rng.uniform(0.38, 1.0) * h) for _ in range(70))
    for x, y in sorted(spots, key=lambda p: p[1]):  # far flowers first, so near ones overlap them
        r = w * 0.012 * (1 + 5 * (y / h - 0.38))
        flower(d, x, y, r, (252, 252, 245), (250, 200, 40), petals=11, width=0.28, turn=rng.uniform(0, 1))
    return img


# --- products (flat backgrounds, like catalogue shots) ----------------------------------

def product_backdrop(w, h, colour: RGB) -> tuple[Image.Image, ImageDraw.ImageDraw]:
    img = vertical_gradient((w, h), [(0, mix(colour, (255, 255, 255), 0.55)), (1, colour)])
    d = ImageDraw.Draw(img)
    d.ellipse((w * 0.15, h * 0.8, w * 0.85, h * 0.92), fill=mix(colour, (0, 0, 0), 0.15))  # shadow
    return img, d


def apples(w, h, rng):
    img, d = product_backdrop(w, h, (235, 225, 200))
    for x, y, c in [(0.33, 0.6, (200, 40, 40)), (0.67, 0.6, (215, 60, 45)), (0.5, 0.42, (120, 175, 50))]:
        cx, cy, r = w * x, h * y, w * 0.2
        d.ellipse((cx - r, cy - r * 0.9, cx + r, cy + r * 0.95), fill=c)
        d.ellipse((cx - r * 0.55, cy - r * 0.6, cx - r * 0.2, cy - r * 0.2), fill=mix(c, (255, 255, 255), 0.45))
        d.line((cx, cy - r * 0.8, cx + r * 0.1, cy - r * 1.15), fill=(90, 60, 30), width=int(w * 0.015))
        d.polygon(ellipse_points(cx + r * 0.3, cy - r * 1.05, r * 0.25, r * 0.1, -0.5), fill=(70, 140, 50))
    return img


def lemons(w, h, rng):
    img, d = product_backdrop(w, h, (170, 210, 220))
    for x, y, a in [(0.32, 0.62, 0.3), (0.66, 0.64, -0.2), (0.5, 0.42, 0.05)]:
        cx, cy = w * x, h * y
        d.polygon(ellipse_points(cx, cy, w * 0.2, w * 0.14, a), fill=(250, 215, 50))
        for side in (-1, 1):
            tx, ty = cx + side * math.cos(a) * w * 0.2, cy + side * math.sin(a) * w * 0.2
            d.ellipse((tx - w * 0.025, ty - w * 0.02, tx + w * 0.025, ty + w * 0.02), fill=(240, 200, 40))
        d.polygon(ellipse_points(cx - w * 0.06, cy - w * 0.05, w * 0.06, w * 0.025, a), fill=(255, 240, 150))
    d.polygon(ellipse_points(w * 0.62, h * 0.3, w * 0.1, w * 0.04, -0.6), fill=(80, 150, 60))
    return img


def coffee_mug(w, h, rng):
    img, d = product_backdrop(w, h, (225, 200, 180))
    left, right, top, bottom = w * 0.25, w * 0.65, h * 0.35, h * 0.82
    d.ellipse((right - w * 0.06, top + h * 0.08, right + w * 0.14, top + h * 0.32), outline=(40, 110, 150),
              width=int(w * 0.035))
    d.rectangle((left, top + h * 0.03, right, bottom - h * 0.03), fill=(50, 130, 170))
    d.ellipse((left, bottom - h * 0.07, right, bottom), fill=(50, 130, 170))
    d.ellipse((left, top, right, top + h * 0.07), fill=(40, 110, 150))
    d.ellipse((left + w * 0.02, top + h * 0.008, right - w * 0.02, top + h * 0.06), fill=(110, 70, 40))
    d.rectangle((left + w * 0.05, top + h * 0.12, left + w * 0.09, bottom - h * 0.08), fill=(120, 180, 210))
    for k in range(3):  # steam
        x = w * (0.36 + 0.09 * k)
        pts = [(x + w * 0.025 * math.sin(t / 3), top - h * 0.02 - t * h * 0.012) for t in range(14)]
        d.line(pts, fill=(255, 255, 255), width=int(w * 0.012), joint="curve")
    return img


def potted_plant(w, h, rng):
    img, d = product_backdrop(w, h, (200, 220, 200))
    cx = w * 0.5
    for k in range(11):
        a = -math.pi / 2 + (k - 5) * 0.22 + rng.uniform(-0.05, 0.05)
        length = h * rng.uniform(0.26, 0.36)
        px, py = cx + math.cos(a) * length * 0.5, h * 0.52 + math.sin(a) * length * 0.5
        d.polygon(ellipse_points(px, py, length * 0.5, w * 0.045, a), fill=mix((50, 130, 60), (120, 190, 90), k % 3 / 2))
    d.polygon([(w * 0.3, h * 0.52), (w * 0.7, h * 0.52), (w * 0.63, h * 0.86), (w * 0.37, h * 0.86)],
              fill=(205, 110, 70))
    d.rectangle((w * 0.28, h * 0.5, w * 0.72, h * 0.58), fill=(220, 125, 80))
    return img


def teapot(w, h, rng):
    img, d = product_backdrop(w, h, (240, 215, 220))
    body = (235, 240, 245)
    d.line([(w * 0.72, h * 0.52), (w * 0.84, h * 0.45), (w * 0.86, h * 0.62), (w * 0.74, h * 0.7)],
           fill=(90, 130, 170), width=int(w * 0.03))
    d.polygon([(w * 0.3, h * 0.62), (w * 0.14, h * 0.42), (w * 0.12, h * 0.38), (w * 0.2, h * 0.4), (w * 0.32, h * 0.55)],
              fill=body)
    d.ellipse((w * 0.26, h * 0.38, w * 0.76, h * 0.84), fill=body)
    d.ellipse((w * 0.38, h * 0.33, w * 0.64, h * 0.42), fill=(90, 130, 170))
    d.ellipse((w * 0.48, h * 0.28, w * 0.54, h * 0.34), fill=(90, 130, 170))
    for k in range(5):  # a painted band of little flowers
        flower(d, w * (0.34 + 0.085 * k), h * 0.6, w * 0.03, (90, 130, 170), (240, 190, 60), petals=6, width=0.4)
    return img


def cupcake(w, h, rng):
    img, d = product_backdrop(w, h, (200, 225, 240))
    d.polygon([(w * 0.28, h * 0.52), (w * 0.72, h * 0.52), (w * 0.64, h * 0.85), (w * 0.36, h * 0.85)],
              fill=(240, 170, 70))
    for k in range(1, 7):  # pleats, running from the wide rim to the narrow base
        t = k / 7
        d.line((w * (0.28 + 0.44 * t), h * 0.53, w * (0.36 + 0.28 * t), h * 0.84), fill=(215, 140, 50), width=4)
    for k, r in enumerate([0.24, 0.19, 0.13]):
        y = h * (0.48 - 0.09 * k)
        d.ellipse((w * 0.5 - w * r, y - h * 0.08, w * 0.5 + w * r, y + h * 0.06), fill=mix((250, 180, 200), (255, 235, 240), k / 3))
    d.ellipse((w * 0.45, h * 0.14, w * 0.55, h * 0.24), fill=(210, 30, 50))
    for _ in range(30):  # sprinkles
        x, y = w * rng.uniform(0.3, 0.7), h * rng.uniform(0.3, 0.5)
        a = rng.uniform(0, math.pi)
        d.line((x, y, x + math.cos(a) * w * 0.02, y + math.sin(a) * w * 0.02),
               fill=rng.choice([(80, 160, 220), (250, 220, 60), (120, 200, 120), (255, 255, 255)]), width=5)
    return img


# name -> (painter, width, height); sizes are the final pixels (drawn at SUPERSAMPLE times that)
PICTURES = {
    "alpine-dawn.jpg": (alpine_dawn, 640, 427),
    "lake-sunset.jpg": (lake_sunset, 640, 427),
    "rolling-hills.jpg": (rolling_hills, 640, 400),
    "seaside.jpg": (seaside, 640, 427),
    "autumn-forest.jpg": (autumn_forest, 640, 480),
    "winter-pines.jpg": (winter_pines, 427, 640),
    "night-sky.jpg": (night_sky, 427, 600),
    "sunflower.jpg": (sunflower, 480, 640),
    "tulips.jpg": (tulips, 480, 600),
    "daisy-meadow.jpg": (daisy_meadow, 640, 427),
    "apples.png": (apples, 400, 400),
    "lemons.png": (lemons, 400, 360),
    "coffee-mug.png": (coffee_mug, 400, 400),
    "potted-plant.png": (potted_plant, 360, 440),
    "teapot.png": (teapot, 400, 400),
    "cupcake.png": (cupcake, 360, 440),
}


def paint(name: str) -> Image.Image:
    """One picture at its final size; the seed is derived from the name, so each is stable."""
    painter, w, h = PICTURES[name]
    rng = random.Random(name)
    big = painter(w * SUPERSAMPLE, h * SUPERSAMPLE, rng)
    return big.resize((w, h), Image.LANCZOS)


def save(img: Image.Image, path: Path) -> None:
    """JPEG for photos; palette PNG for the flat product shots, which keeps them small."""
    if path.suffix == ".png":
        img.quantize(colors=96, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE).save(
            path, optimize=True)
    else:
        img.save(path, quality=84, optimize=True, progressive=False)
    size = path.stat().st_size
    if size > MAX_BYTES:
        raise SystemExit(f"{path} is {size} bytes, over the {MAX_BYTES}-byte budget")


def main(argv: list[str]) -> int:
    out = Path(argv[0]) if argv else DEFAULT_OUT
    out.mkdir(parents=True, exist_ok=True)
    for name in PICTURES:
        save(paint(name), out / name)
        print(f"{out / name}: {(out / name).stat().st_size // 1024} KB")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
