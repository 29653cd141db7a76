"""The paper's case study (section 6.1): a twelve-month calendar, one page per month.

Each page holds the month's panel, a title and the photos, which the physics spreads. The
title is the month's name in large display type (the panel repeats it small, with the year,
as its own heading) and is hard-anchored, so it stays centred at the top. The panel sits on a
stiff spring (section 4.5) and each photo on a soft one (PHOTO_GAMMA) to its starting slot:
the physics still moves them apart, but without the spring it would press photos flat against
the page edge, where a printer crops them. The user can drag or unanchor any of them.
"""

from __future__ import annotations

import math

from floatpage.model.document import Background, CalendarItem, PictureItem, PointAnchor, Project, TextItem
from floatpage.starters.options import Options
from floatpage.starters.pictures import Picture
from floatpage.physics.alignment import NEAR_MM
from floatpage.starters.placement import Region, grid, new_page
from floatpage.starters.words import month_name

PAGE_SIZE = "A4"
MARGIN_MM = 12.0
MAX_PHOTOS_PER_MONTH = 4
PHOTO_GAMMA = 0.6
MONTH_IDS = ("jan", "feb", "mar", "apr", "may", "jun", "jul", "aug", "sep", "oct", "nov", "dec")

# Two bundled pictures per month, chosen by season: the first is the month's lead picture.
BUNDLED_BY_MONTH = (
    ("winter-pines.jpg", "night-sky.jpg"),
    ("alpine-dawn.jpg", "winter-pines.jpg"),
    ("tulips.jpg", "rolling-hills.jpg"),
    ("daisy-meadow.jpg", "tulips.jpg"),
    ("rolling-hills.jpg", "daisy-meadow.jpg"),
    ("seaside.jpg", "sunflower.jpg"),
    ("lake-sunset.jpg", "seaside.jpg"),
    ("sunflower.jpg", "lake-sunset.jpg"),
    ("autumn-forest.jpg", "rolling-hills.jpg"),
    ("autumn-forest.jpg", "alpine-dawn.jpg"),
    ("lake-sunset.jpg", "autumn-forest.jpg"),
    ("night-sky.jpg", "winter-pines.jpg"),
)
BUNDLED = [name for pair in BUNDLED_BY_MONTH for name in pair]

# (page background, accent for the title and the panel), a quiet tint per season.
MONTH_COLOURS = (
    ("#eef3f8", "#2c4a6b"), ("#f1f1f7", "#3d3f73"), ("#f2f7ee", "#3f6b35"),
    ("#fbf4f6", "#8c2f55"), ("#f3f8ef", "#3a6e3a"), ("#eef7f9", "#17677a"),
    ("#fdf6ec", "#a1502a"), ("#fdf8e6", "#8a6410"), ("#f8f3ea", "#7a4a1e"),
    ("#fbf1e8", "#9b3d1c"), ("#f3f0ee", "#5a4638"), ("#eef0f7", "#243a6e"),
)


def photos_per_month(count: int) -> int:
    """Spread the photos over the year: all of them if they fit, at least one per month."""
    return max(1, min(MAX_PHOTOS_PER_MONTH, math.ceil(count / 12)))


def layout_regions(width: float, height: float, orientation: str) -> tuple:
    """Where the title, the panel and the photos start: (title rect, panel rect, photo region).

    Portrait: title on top, photos in the middle, the month along the bottom. Landscape: title
    on top, photos on the left, the month on the right.
    """
    m = MARGIN_MM
    title_h = 24.0
    title = (width / 2, m + title_h / 2, width - 2 * m, title_h)
    below_title = m + title_h + 6.0
    if orientation == "portrait":
        panel_w, panel_h = width - 2 * m, 88.0
        panel = (width / 2, height - m - panel_h / 2, panel_w, panel_h)
        photos = Region(m, below_title, width - m, height - m - panel_h - 6.0)
    else:
        panel_w, panel_h = 130.0, height - m - below_title
        panel = (width - m - panel_w / 2, height - m - panel_h / 2, panel_w, panel_h)
        photos = Region(m, below_title, width - m - panel_w - 8.0, height - m)
    return title, panel, photos


def as_wide_as_the_panel(rects: list, panel: tuple, region: Region) -> list:
    """Each photo centred over the panel whose width is near the panel's (edges 0.5-4 mm from
    the panel's, a near miss: physics.alignment) cut to the panel's width, or grown to it where
    the region has the height, else cut to leave its edges NEAR_MM inside.  A 4:3 photo on a
    portrait page came out 178.6 mm wide over the 178 mm panel; the physics could not close
    both edges and slid it 10.7 mm left, so a calendar of camera photos printed every month's
    photo off the page's centre (at 175 and 171 mm, 5.5 and 7.3 mm)."""
    px, _, pw, _ = panel
    found = []
    for x, y, w, h in rects:
        if abs(x - px) < 1e-6 and 0 < abs(w - pw) < 2 * NEAR_MM:
            new_w = pw if w > pw or h * pw / w <= region.height else pw - 2 * NEAR_MM
            x, y, w, h = x, y, new_w, h * new_w / w
        found.append((x, y, w, h))
    return found


def build(options: Options, pictures: list[Picture]) -> Project:
    """Twelve pages, January to December of options.year, with the pictures spread over them."""
    per_month = photos_per_month(len(pictures))
    pages = []
    for month in range(1, 13):
        mid = MONTH_IDS[month - 1]
        background, accent = MONTH_COLOURS[month - 1]
        page = new_page(mid, PAGE_SIZE, options.orientation, background=Background(color=background))
        title_rect, panel_rect, region = layout_regions(page.width_mm, page.height_mm,
                                                        options.orientation)
        x, y, w, h = title_rect
        page.items.append(TextItem(
            id=f"{mid}-title", x=x, y=y, w=w, h=h, text=month_name(month, options.lang),
            font="display", color=accent, bold=True, align="centre", role="month-name",
            anchor=PointAnchor(x=x, y=y, hard=True)))
        x, y, w, h = panel_rect
        page.items.append(CalendarItem(
            id=f"{mid}-month", x=x, y=y, w=w, h=h, year=options.year, month=month,
            first_weekday=options.first_weekday, language=options.lang, color=accent,
            anchor=PointAnchor(x=x, y=y, gamma=1.0)))
        start = (month - 1) * per_month
        chosen = [pictures[(start + i) % len(pictures)] for i in range(per_month)] if pictures else []
        rects = as_wide_as_the_panel(grid(region, [p.aspect for p in chosen], fill=0.96,
                                          stagger=0.7), panel_rect, region)
        for index, (picture, (x, y, w, h)) in enumerate(zip(chosen, rects), start=1):
            page.items.append(PictureItem(id=f"{mid}-photo-{index}", x=x, y=y, w=w, h=h,
                                          path=picture.path,
                                          anchor=PointAnchor(x=x, y=y, gamma=PHOTO_GAMMA)))
        pages.append(page)
    return Project(title=f"Calendar {options.year}", language=options.lang, pages=pages)
