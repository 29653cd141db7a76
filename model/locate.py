"""Find the line of a table or key in a project file's text, for error messages.

TOML parsers give no positions for values, so this reads the text itself. It
understands the layout floatpage writes (`[physics]`, `[[pages]]`,
`[[pages.items]]`, one key per line), which is what users edit; for anything
else it answers None and the message goes without a line number.
"""

from __future__ import annotations

import bisect
import re

HEADER = re.compile(r"^\s*\[\[?\s*([A-Za-z0-9_.\" -]+?)\s*\]\]?\s*(#.*)?$")
BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")
KEY_LINE = re.compile(r"^\s*([A-Za-z0-9_-]+)\s*=")


class LineFinder:
    """Knows where each page table and item table starts, by their order in the file.

    Indexed once, so that each look-up is a dictionary or a bisection: scanning the headers per
    key made loading a 10,000-item file take 50 s."""

    def __init__(self, text: str):
        self.lines = text.splitlines()
        self.headers: list[tuple[int, str]] = []  # (1-based line, dotted name)
        for number, line in enumerate(self.lines, start=1):
            match = HEADER.match(line)
            if match:
                self.headers.append((number, match.group(1).replace(" ", "")))
        self.header_lines = [line for line, _ in self.headers]
        self.by_name: dict[str, list[int]] = {}
        for line, name in self.headers:
            self.by_name.setdefault(name, []).append(line)
        self._items_of_page: dict[tuple[int, str], list[int]] = {}
        self._keys_of_table: dict[int, dict[str, int]] = {}

    def table_line(self, name: str, index: int = 0) -> int | None:
        """Line of the index-th `[name]` / `[[name]]` header."""
        found = self.by_name.get(name, [])
        return found[index] if index < len(found) else None

    def item_line(self, page_index: int, item_index: int, array: str = "items") -> int | None:
        """Line of the item_index-th `[[pages.items]]` (or `[[pages.ARRAY]]`, e.g. regions)
        below the page_index-th `[[pages]]`."""
        items = self._items_of_page.get((page_index, array))
        if items is None:
            page_line = self.table_line("pages", page_index)
            if page_line is None:
                return None
            next_page = self.table_line("pages", page_index + 1) or len(self.lines) + 1
            every = self.by_name.get(f"pages.{array}", [])
            items = every[bisect.bisect_right(every, page_line):bisect.bisect_left(every, next_page)]
            self._items_of_page[(page_index, array)] = items
        return items[item_index] if item_index < len(items) else None

    def key_line(self, table_line: int | None, key: str) -> int | None:
        """Line of `key = ...` inside the table starting at table_line (0 = the top level)."""
        start = 0 if table_line is None else table_line
        if BARE_KEY.fullmatch(key):
            found = self.keys_of(start).get(key)
        else:
            found = self.scan_for(start, key)
        return found if found is not None else (table_line if table_line else None)

    def keys_of(self, start: int) -> dict[str, int]:
        """The first line of each bare key in the table starting at ``start``, read once: a
        scan per key made loading a 2,000-item file spend a second matching lines."""
        keys = self._keys_of_table.get(start)
        if keys is None:
            keys = {}
            for number in range(start + 1, self.table_end(start)):
                match = KEY_LINE.match(self.lines[number - 1])
                if match:
                    keys.setdefault(match.group(1), number)
            self._keys_of_table[start] = keys
        return keys

    def scan_for(self, start: int, key: str) -> int | None:
        pattern = re.compile(rf"^\s*{re.escape(key)}\s*=")
        for number in range(start + 1, self.table_end(start)):
            if pattern.match(self.lines[number - 1]):
                return number
        return None

    def table_end(self, start: int) -> int:
        """The line of the next header after ``start`` (or one past the end)."""
        following = bisect.bisect_right(self.header_lines, start)
        return self.header_lines[following] if following < len(self.header_lines) \
            else len(self.lines) + 1
