"""The README's editor picture: the real editor on a copy of a sample, an item selected, saved
as Textual's own SVG screenshot and turned into a PNG with rsvg-convert (Debian's librsvg2-bin).

    .venv/bin/python tools/editor_screenshot.py sample_projects/shop-flyer/shop-flyer.toml \
        docs/editor.svg docs/images/editor.png --tabs 2
"""

from __future__ import annotations

import argparse
import asyncio
import shutil
import subprocess
import tempfile
from pathlib import Path

from floatpage.tui.app import make_app


async def shoot(project: Path, svg: Path, size: tuple[int, int], tabs: int) -> None:
    app = make_app(project, autostart=False)
    async with app.run_test(size=size) as pilot:
        await pilot.pause(0.3)
        for _ in range(tabs):
            await pilot.press("tab")
        await pilot.pause(0.3)
        svg.write_text(app.export_screenshot(title="floatpage"), encoding="utf-8")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("project", type=Path)
    parser.add_argument("svg", type=Path)
    parser.add_argument("png", type=Path)
    parser.add_argument("--size", default="100x34", help="COLUMNSxROWS")
    parser.add_argument("--tabs", type=int, default=1, help="Tab presses: which item is selected")
    args = parser.parse_args()
    columns, rows = (int(part) for part in args.size.split("x"))
    with tempfile.TemporaryDirectory() as folder:  # the editor never touches the sample itself
        copy = Path(folder) / args.project.parent.name
        shutil.copytree(args.project.parent, copy)
        asyncio.run(shoot(copy / args.project.name, args.svg, (columns, rows), args.tabs))
    subprocess.run(["rsvg-convert", str(args.svg), "-o", str(args.png)], check=True)


if __name__ == "__main__":
    main()
