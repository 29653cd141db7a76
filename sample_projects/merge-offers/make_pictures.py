"""Draw the sample's product pictures: simple shapes in several proportions (3:2, 2:3, 1:1,
16:9, 3:4, 1:2), so each record's photo box takes a different shape. Run once; the PNGs
are kept in the repo, so this only documents how they were made."""

from pathlib import Path

from PIL import Image, ImageDraw

PICTURES = {  # name: (width, height, background, shape colour, shape)
    "pears.png": (600, 400, "#e8f1d9", "#9bbf3b", "ellipse"),
    "bottle.png": (400, 600, "#dbe9f4", "#2f6fa3", "rectangle"),
    "cheese.png": (500, 500, "#fbf0d0", "#f0b429", "pieslice"),
    "bread.png": (640, 360, "#f3e3cf", "#b8742a", "rounded"),
    "flowers.png": (450, 600, "#f7dde6", "#d6457a", "ellipse"),
    "candle.png": (300, 600, "#ece4f6", "#8a63c9", "rectangle"),
}


def draw(name: str, w: int, h: int, background: str, colour: str, shape: str) -> None:
    image = Image.new("RGB", (w, h), background)
    pen = ImageDraw.Draw(image)
    box = (w * 0.2, h * 0.2, w * 0.8, h * 0.8)
    if shape == "ellipse":
        pen.ellipse(box, fill=colour)
    elif shape == "rectangle":
        pen.rectangle(box, fill=colour)
    elif shape == "pieslice":
        pen.pieslice(box, 20, 320, fill=colour)
    else:
        pen.rounded_rectangle(box, radius=min(w, h) // 8, fill=colour)
    pen.ellipse((w * 0.3, h * 0.3, w * 0.42, h * 0.42), fill="#ffffff")
    image.save(Path(__file__).with_name("pictures") / name, optimize=True)


if __name__ == "__main__":
    for picture, spec in PICTURES.items():
        draw(picture, *spec)
