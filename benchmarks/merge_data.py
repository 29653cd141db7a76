"""Generated customers for `floatpage merge`: varied names, products, prices and pictures.

Used by benchmarks/merge.py (1,000 records) and to write the sample's customers.csv (40).
Deterministic: the same seed gives the same file.
"""

from __future__ import annotations

import csv
import random
from pathlib import Path

FIRST = ["Ana", "Zoë", "Bartholomew-Maximilian", "Li", "Joe", "Siobhán", "Oluwaseun", "Mia",
         "Jean-Baptiste", "Åsa", "Priya", "Tomás", "Anastasiya", "Kai", "Émile", "Fatima",
         "Christopher", "Ingrid", "Yusuf", "Beatriz"]
LAST = ["Silva", "Müller", "Okonkwo-Fitzgerald", "Wang", "Doe", "Ní Bhriain", "Adeyemi", "Rossi",
        "de la Fontaine", "Lindqvist", "Raghunathan", "García Márquez", "Kuznetsova", "Tanaka",
        "Lefèvre", "Haddad", "Papadopoulos", "Johansson", "Yılmaz", "Costa"]
PRODUCTS = ["Williams pears", "Comté 24 months", "Sourdough loaf", "Peonies", "Beeswax candle",
            "Cold-pressed sparkling elderflower lemonade", "Earl Grey", "Olive oil from Crete",
            "Dark chocolate with sea salt and toasted hazelnuts", "Lemons", "Honey", "Tulips",
            "Handmade ceramic mug", "Smoked paprika", "Wild rocket"]
NOTES = ["", "", "Picked this morning in the valley.", "Our cheesemonger's favourite, cut to "
         "order.", "A bunch for the table", "", "Baked at 5 am by Marta.", "Two for the price "
         "of one on Saturdays, while stocks last.", ""]
PRICES = ["€2.40 a kilo", "£3.10", "€4.90", "$12", "€0.99", "£15.50 the pair", "$5", "€7.25"]
DAYS = ["31 May", "2 June", "3 June", "14 June", "1 July"]


def write_customers(path: Path, count: int, pictures: list[str], seed: int = 7) -> None:
    rng = random.Random(seed)
    with path.open("w", encoding="utf-8", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(["id", "first_name", "surname", "product", "price", "photo", "note",
                         "valid_until"])
        for number in range(count):
            writer.writerow([1001 + number, rng.choice(FIRST), rng.choice(LAST),
                             rng.choice(PRODUCTS), rng.choice(PRICES), rng.choice(pictures),
                             rng.choice(NOTES), rng.choice(DAYS)])


def draw_pictures(folder: Path, count: int, seed: int = 3) -> list[str]:
    """Plain pictures whose proportions run from 1:3 to 3:1."""
    from PIL import Image, ImageDraw

    rng = random.Random(seed)
    folder.mkdir(parents=True, exist_ok=True)
    names = []
    for index in range(count):
        aspect = 3 ** rng.uniform(-1, 1)
        w, h = (int(600 * aspect), 600) if aspect < 1 else (600, int(600 / aspect))
        image = Image.new("RGB", (w, h), tuple(rng.randrange(150, 250) for _ in range(3)))
        ImageDraw.Draw(image).ellipse((w * 0.2, h * 0.2, w * 0.8, h * 0.8),
                                      fill=tuple(rng.randrange(20, 160) for _ in range(3)))
        name = f"generated-{index:02d}.png"
        image.save(folder / name)
        names.append(name)
    return names


if __name__ == "__main__":  # the sample's data: 40 customers over its six pictures
    sample = Path(__file__).resolve().parents[1] / "sample_projects" / "merge-offers"
    pictures = sorted(p.name for p in (sample / "pictures").glob("*.png"))
    write_customers(sample / "customers.csv", 40, pictures)
