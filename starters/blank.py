"""A blank A4 page with a title to replace, and the user's photos if any, for the physics to spread."""

from __future__ import annotations

from floatpage.model.document import PictureItem, Project, TextItem
from floatpage.starters.options import Options
from floatpage.starters.pictures import Picture
from floatpage.starters.placement import Region, grid, new_page

PAGE_SIZE = "A4"
BUNDLED: list[str] = []


def build(options: Options, pictures: list[Picture]) -> Project:
    """One page with a title placeholder, and the given pictures (at most a dozen) below it."""
    page = new_page("page-1", PAGE_SIZE, options.orientation)
    page.items.append(TextItem(id="title", x=page.width_mm / 2, y=30.0, w=page.width_mm - 60.0, h=20.0,
                               text="Your title here", font="display", color="#333333",
                               align="centre"))
    shown = pictures[:12]
    region = Region(15.0, 50.0, page.width_mm - 15.0, page.height_mm - 15.0)
    for index, (picture, (x, y, w, h)) in enumerate(zip(shown, grid(region, [p.aspect for p in shown])), 1):
        page.items.append(PictureItem(id=f"picture-{index}", x=x, y=y, w=w, h=h, path=picture.path))
    return Project(title="Untitled", language=options.lang, pages=[page])
