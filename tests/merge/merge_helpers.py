"""Data files for the merge tests: the sample template's columns, rows that vary."""

from __future__ import annotations

import csv
import shutil
from pathlib import Path

SAMPLE = Path(__file__).resolve().parents[2] / "sample_projects" / "merge-offers"
COLUMNS = ["id", "first_name", "surname", "product", "price", "photo", "note", "valid_until"]


def write_csv(path: Path, rows: list[list[str]], columns: list[str] = COLUMNS) -> Path:
    with path.open("w", encoding="utf-8", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(columns)
        writer.writerows(rows)
    return path


def rows(count: int) -> list[list[str]]:
    pictures = ["pears.png", "bottle.png", "cheese.png", "bread.png", "flowers.png",
                "candle.png"]
    names = ["Silva", "Müller", "Okonkwo-Fitzgerald", "Wang", "Doe", "Lindqvist", "Rossi"]
    return [[str(1001 + n), f"Person{n}", names[n % len(names)], f"Product number {n}",
             f"€{n}.50", pictures[n % len(pictures)], "A note" if n % 2 else "", "31 May"]
            for n in range(count)]


def session_members(session: int) -> list[int]:
    """The processes of a session (/proc/PID/stat's sixth field): a command started in a
    session of its own, and every process below it that did not leave it."""
    found = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                stat = (entry / "stat").read_text()
            except OSError:  # gone meanwhile
                continue
            if int(stat[stat.rindex(")") + 2:].split()[3]) == session:
                found.append(int(entry.name))
    return found
