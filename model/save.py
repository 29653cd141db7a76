"""Write a project back to TOML: stable key order, 0.01 mm rounding, comments kept, atomic.

Saving edits the tomlkit document the project was read from, touching only
values that changed, so an unchanged project saves byte-identical and a
user's comments survive. The file is replaced atomically, and the previous
version is kept beside it as `NAME.bak`.
"""

from __future__ import annotations

import math
import re
from dataclasses import fields
from pathlib import Path
from typing import Any

# tomlkit is imported by the functions that build or edit its documents: `check`, `render`
# and a `settle` that patches positions into the text never need it (importing it took a
# tenth of a second, a twentieth of `settle` on the 2,000-anchor chain file).
from floatpage.model.document import (
    Background, ItemAnchor, Page, PhysicsSettings, PointAnchor, Project, Region,
)
from floatpage.model.atomic_file import atomic_write, write_chunks  # noqa: F401 (re-exported)
from floatpage.model.errors import FloatpageError
from floatpage.model.page_sizes import CUSTOM, canonical_size_name
from floatpage.model.written_forms import (
    as_read, in_written_form, indent_like_the_others, written_entries, written_in_pieces,
)

Pairs = list[tuple[str, Any, Any]]  # (key, value, default); value None = absent
UTF8_BOM = b"\xef\xbb\xbf"
LONE_LF = re.compile(r"(?<!\r)\n")
WRITTEN_ONLY_WHEN_TRUE = {"bleed"}  # rare flags: a file names them only where they are set
WRITTEN_ONLY_WHEN_SET = {"align", "size_pt"}  # newer keys: a file names them only where not the default
# Names that are empty for "none": a new item in no region or group has no such key (every
# item the editor added said `region = ""` and `group = ""`), while a user's own `region = ""`
# means the same and is kept as written, so an unchanged file still saves byte-identical.
WRITTEN_ONLY_WHEN_NAMED = {"region", "group", "role"}
KEEP = object()  # a pair's value meaning "leave whatever the user wrote, if anything"
ANCHOR_DEFAULTS = {"dx": 0.0, "dy": 0.0, "gamma": 1.0, "hard": False}
ARRAYS_SYNCED_APART = {"items", "regions"}  # a page's arrays of tables, synced by sync_array


def mm(value: float) -> float:
    """Lengths are stored to 0.01 mm: enough for print, short enough to diff."""
    return round(float(value), 2) + 0.0  # + 0.0 turns -0.0 into 0.0


def same(a: Any, b: Any) -> bool:
    if isinstance(a, bool) or isinstance(b, bool):
        return a is b or a == b and type(a) is type(b)
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return abs(float(a) - float(b)) < 0.005
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    return a == b


def physics_pairs(settings: PhysicsSettings) -> Pairs:
    defaults = PhysicsSettings()
    return [(f.name, getattr(settings, f.name), getattr(defaults, f.name))
            for f in fields(PhysicsSettings)]


def page_pairs(page: Page) -> Pairs:
    custom = page.size == CUSTOM
    return [
        ("id", page.id, None),
        ("size", page.size, "A4"),
        ("orientation", None if custom else page.orientation, "portrait"),
        # A named size ignores width_mm and height_mm; a user's own are kept as written.
        ("width_mm", mm(page.width_mm) if custom else KEEP, None),
        ("height_mm", mm(page.height_mm) if custom else KEEP, None),
        ("background", background_value(page.background), None),
    ]


def background_value(background: Background | None) -> dict | None:
    if background is None:
        return None
    if background.picture:
        return {"picture": background.picture}
    if background.color:
        return {"color": background.color}
    return None


def anchor_value(anchor) -> dict | None:
    if isinstance(anchor, PointAnchor):
        value = {"x": mm(anchor.x), "y": mm(anchor.y), "gamma": float(anchor.gamma)}
        if anchor.hard:
            value["hard"] = True
        return value
    if isinstance(anchor, ItemAnchor):
        return {"to": anchor.to, "dx": mm(anchor.dx), "dy": mm(anchor.dy)}
    return None


def region_pairs(region: Region) -> Pairs:
    return [("id", region.id, None), ("left", mm(region.left), None), ("top", mm(region.top), None),
            ("w", mm(region.w), None), ("h", mm(region.h), None)]


def item_pairs(item) -> Pairs:
    """The item's keys in the order a person reads them: who, where, what, then the anchor."""
    pairs: Pairs = [("id", item.id, None), ("kind", item.kind, None)]
    pairs += [(name, mm(getattr(item, name)), None) for name in ("x", "y", "w", "h")]
    pairs += [("z", item.z, 0), ("decorative", item.decorative, False)]
    base_names = {"id", "x", "y", "w", "h", "z", "decorative", "anchor", "source_document",
                  "drop_if_empty"}
    defaults = type(item)(id="", x=0.0, y=0.0, w=1.0, h=1.0)
    for f in fields(item):
        if f.name in WRITTEN_ONLY_WHEN_TRUE:
            pairs.append((f.name, True if getattr(item, f.name) else None, None))
        elif f.name in WRITTEN_ONLY_WHEN_NAMED:
            pairs.append((f.name, getattr(item, f.name) or None, None))
        elif f.name in WRITTEN_ONLY_WHEN_SET:
            value = getattr(item, f.name)
            pairs.append((f.name, None if value == getattr(defaults, f.name) else value, None))
        elif f.name not in base_names:
            pairs.append((f.name, getattr(item, f.name), getattr(defaults, f.name)))
    pairs.append(("drop_if_empty", True if item.drop_if_empty else None, None))
    pairs.append(("anchor", anchor_value(item.anchor), None))
    return pairs


def inline(value: Any) -> Any:
    import tomlkit
    if isinstance(value, dict):
        table = tomlkit.inline_table()
        table.update(value)
        return table
    return value


def equivalent(key: str, current: Any, value: Any) -> bool:
    """Whether what the user wrote already says ``value``: `" a 4 "` says "A4", and a short
    anchor `{to = "b1"}` says dx = dy = 0.  Such spellings are kept, not rewritten."""
    if key == "size" and isinstance(current, str):
        return canonical_size_name(current) == value
    if key == "anchor" and isinstance(current, dict) and isinstance(value, dict):
        return same({**ANCHOR_DEFAULTS, **current}, {**ANCHOR_DEFAULTS, **value})
    return same(current, value)


def sync_table(table: Table, pairs: Pairs) -> None:
    """Make `table` hold `pairs`, changing only what differs, so comments and order survive."""
    wanted = {key for key, value, _ in pairs if value is not None}
    wanted |= {key for key in WRITTEN_ONLY_WHEN_NAMED if key in table and table[key] == ""}
    unwanted = [k for k in table if k not in wanted and k not in ARRAYS_SYNCED_APART]
    remember_places(table, unwanted)
    for key in unwanted:
        del table[key]
    for key, value, default in pairs:
        if value is None or value is KEEP:
            continue
        if key in table:
            written = table[key]
            if not equivalent(key, as_read(written), value) \
                    and not changed_in_place(written, value):
                table[key] = in_written_form(written, inline(value))
        elif default is None or not same(value, default):
            add_key(table, key, inline(value))


def changed_in_place(written: Any, value: Any) -> bool:
    """Set the values of a table the user wrote (`anchor = { x = 63.5, y = 179.01 }`, or as
    `anchor.x = 63.5` lines, or under `[pages.items.anchor]`) one by one, where ``value``
    has the same keys: replaced whole, it lost the user's spacing, `{x = 70.0, y = 179.01}`,
    or form on every move of an anchor (user-walk-13). False,
    with nothing changed, where keys come or go (tomlkit then leaves stray spaces)."""
    from tomlkit.container import OutOfOrderTableProxy
    from tomlkit.items import InlineTable, Table as TableItem
    if not isinstance(written, (InlineTable, TableItem, OutOfOrderTableProxy)) \
            or not isinstance(value, dict) or set(written) != set(value):
        return False
    for key, new in value.items():
        if not same(as_read(written[key]), new):
            written[key] = in_written_form(written[key], new)
    return True


PLACES = "_floatpage_places"  # a table's attribute: {removed key: the key that followed it}


def remember_places(table: Table, keys: list[str]) -> None:
    """Note which key followed each of ``keys`` (in the file's order, before any is taken
    out) as a save takes them out of ``table``, so that the save that puts one back puts it
    there (`add_key`): an anchor taken off (`u`), saved, then put back (`a`, or an undo)
    came at its table's end, after `role`, a diff the user did not ask for (user-walk-8).
    Kept on the table, which the editor saves into again."""
    order = [entry.key for entry, _ in written_entries(table) if entry is not None]
    places = table.__dict__.setdefault(PLACES, {})
    for key in keys:
        if key in order:
            following = order[order.index(key) + 1:]
            places[key] = following[0] if following else None


def add_key(table: Table, key: str, value: Any) -> None:
    """Add ``key`` to ``table`` where it was before a save took it out (`remember_places`),
    else before the blank line that ends the table: put after it, a group joined in the
    editor was written apart from its item's other keys (user walk 5).

    Inserting uses tomlkit's internal `Container._insert_at` (tomlkit has no public insert;
    pyproject.toml bounds tomlkit to the releases this was checked against)."""
    from tomlkit.items import AoT, Table as TableItem
    if written_in_pieces(table):
        table[key] = value  # tomlkit writes it as one more piece: `physics.gutter_mm = 4.0`
        return
    body = table.value.body
    follower = table.__dict__.get(PLACES, {}).pop(key, None)
    place = next((index for index, (entry, item) in enumerate(body)
                  if entry is not None and entry.key == follower
                  and not isinstance(item, (TableItem, AoT))), None) if follower else None
    if place is None and trailing_space(table):
        place = len(body) - 1
    if place is not None and hasattr(table.value, "_insert_at"):
        table.value._insert_at(place, key, value)
        # The container holds the key now, but the Table (a dict) keeps its own copy of the
        # keys, which tomlkit's Table.append updates and `_insert_at` does not: the editor
        # saves into the same document again, and taking the key out there (an undo, a
        # group emptied) failed with "KeyError: 'region'".
        dict.__setitem__(table, key, table.value[key])
    else:
        table[key] = value
    indent_like_the_others(table, key)


def new_table(pairs: Pairs, *, inline_form: bool = False) -> Table:
    import tomlkit
    table = tomlkit.inline_table() if inline_form else tomlkit.table()
    for key, value, _ in pairs:
        if value is not None and value is not KEEP:
            table[key] = inline(value)
    return table


def sync_array(parent: Table, key: str, records: list, pairs_of, id_of, fill=None, *,
               at_end: bool = True) -> None:
    """Sync an array of tables by id: keep existing tables (and their comments), add new ones."""
    import tomlkit
    from tomlkit.items import AoT, InlineTable
    existing = parent.get(key)
    if is_inline_array(existing) and sync_inline_array(existing, records, pairs_of, id_of, fill):
        return
    if isinstance(parent, InlineTable) or (
            key in ARRAYS_SYNCED_APART and is_inline_array(existing) and len(existing)):
        sync_inline_array_in_place(parent, key, records, pairs_of, id_of, fill)
        return
    by_id: dict[str, Table] = {}
    if isinstance(existing, AoT):
        for table in existing:
            by_id.setdefault(str(table.get("id")), table)
    tables = []
    for record in records:
        table = by_id.get(id_of(record))
        if table is None:
            table = new_table(pairs_of(record))
        else:
            sync_table(table, pairs_of(record))
        if fill is not None:
            fill(table, record)
        tables.append(table)
    unchanged = isinstance(existing, AoT) and len(existing) == len(tables) and all(
        a is b for a, b in zip(existing, tables))
    if unchanged:
        return
    if isinstance(existing, AoT) and tables and edit_in_place(existing, tables):
        return
    if not tables:
        if key in parent:
            del parent[key]
        return
    array = tomlkit.aot()
    for table in tables:
        array.append(table)
    if existing is None:
        set_apart(parent, tables, at_end)
    parent[key] = array


def set_apart(parent: Table, tables: list, at_end: bool) -> None:
    """A new array of tables (a page's first region) goes after the parent's last one (its
    items): a blank line parts it from that one and, unless it ends the file (``at_end``),
    from the next page (it was written jammed against the next `[[pages]]`)."""
    from tomlkit.items import AoT
    import tomlkit
    before = [value for value in parent.values() if isinstance(value, AoT) and len(value)]
    if not before:
        return
    last = before[-1][-1]
    if not trailing_space(last):
        last.add(tomlkit.ws("\n"))
    if not at_end:
        tables[-1].add(tomlkit.ws("\n"))


def edit_in_place(array: AoT, tables: list) -> bool:
    """Turn ``array`` into ``tables`` by deleting and appending only, when that is enough (an
    item deleted, an item added at the end): rebuilding the array made tomlkit write an extra
    blank line between every two tables of the page (editor defect 12).  False, with nothing
    changed, when the kept tables were reordered."""
    import tomlkit
    wanted = {id(table) for table in tables}
    kept = [table for table in array if id(table) in wanted]
    if [id(t) for t in kept] != [id(t) for t in tables[:len(kept)]]:
        return False
    for index in reversed(range(len(array))):
        if id(array[index]) not in wanted:
            del array[index]
    for table in tables[len(kept):]:
        # A table's trailing blank line is what separates it from the next: give an added
        # table the same as the one it follows.
        spacing = trailing_space(array[-1]) if len(array) else ""
        if len(array) and not spacing:  # the file's last table: a blank line before the new one
            array[-1].add(tomlkit.ws("\n"))
        array.append(table)
        if spacing:
            table.add(tomlkit.ws(spacing))
    return True


def trailing_space(table: Table) -> str:
    from tomlkit.items import Whitespace
    body = table.value.body
    if body and body[-1][0] is None and isinstance(body[-1][1], Whitespace):
        return body[-1][1].s
    return ""


def is_inline_array(value: Any) -> bool:
    from tomlkit.items import Array, InlineTable
    return isinstance(value, Array) and all(isinstance(entry, InlineTable) for entry in value)


def sync_inline_array(array: Array, records: list, pairs_of, id_of, fill) -> bool:
    """A user who wrote `pages = [{id = "p", items = [...]}]` keeps that form while the same
    records, in the same order, are only edited (a settle, a move).  Adding, removing or
    reordering pages falls back to [[tables]] (items and regions stay inline:
    `sync_inline_array_in_place`): returns False, having changed nothing."""
    by_id = {str(entry.get("id")): entry for entry in array}
    if [id_of(record) for record in records] != [str(entry.get("id")) for entry in array] \
            or len(by_id) != len(array):
        return False
    for entry, record in zip(array, records):
        sync_table(entry, pairs_of(record))
        if fill is not None:
            fill(entry, record)
    return True


def sync_inline_array_in_place(parent: Table, key: str, records: list, pairs_of, id_of,
                               fill) -> None:
    """Sync a page's items or regions written as an inline array (`items = [{...}, ...]`),
    and any array inside a table written inline (`pages = [{id = "p", items = [...]}]`),
    where only an inline array can stand: an item added to or deleted from such a page was
    written as `[[pages.items]]` tables inside the braces, a file that no longer parsed,
    saved over the user's; in a `[[pages]]` table, a Del rewrote every other item as a
    table of its own with every key, its comments dropped (user-walk-13). Entries are
    deleted and appended in place, so the others keep their spacing and comments; new ones
    are inline tables; a reordering empties the array and fills it again."""
    import tomlkit
    existing = parent.get(key)
    by_id: dict[str, Any] = {}
    if is_inline_array(existing):
        for entry in existing:
            by_id.setdefault(str(entry.get("id")), entry)
    entries = []
    for record in records:
        entry = by_id.pop(id_of(record), None)
        if entry is None:
            entry = new_table(pairs_of(record), inline_form=True)
        else:
            sync_table(entry, pairs_of(record))
        if fill is not None:
            fill(entry, record)
        entries.append(entry)
    if not entries:
        if key in parent:
            del parent[key]
        return
    if is_inline_array(existing):
        if not edit_inline_in_place(existing, entries):  # reordered: emptied and refilled,
            for index in reversed(range(len(existing))):  # which keeps it one entry a line
                del existing[index]
            for entry in entries:
                existing.append(entry)
        return
    array = tomlkit.array()
    for entry in entries:
        array.append(entry)
    parent[key] = array


def edit_inline_in_place(array: Array, entries: list) -> bool:
    """`edit_in_place` for an inline array: tomlkit's own delete and append keep the others'
    spacing and comments. False, with nothing changed, when kept entries were reordered."""
    wanted = {id(entry) for entry in entries}
    kept = [entry for entry in array if id(entry) in wanted]
    if [id(e) for e in kept] != [id(e) for e in entries[:len(kept)]]:
        return False
    for index in reversed(range(len(array))):
        if id(array[index]) not in wanted:
            del array[index]
    for entry in entries[len(kept):]:
        array.append(entry)
    return True


def to_document(project: Project) -> tomlkit.TOMLDocument:
    """The project as a tomlkit document: its source document, edited, or a fresh one."""
    import tomlkit
    doc = project.source_document
    if doc is None:
        doc = tomlkit.document()
        doc.add(tomlkit.comment("floatpage project: items float on each page; units are mm,"))
        doc.add(tomlkit.comment("x and y are item centres measured from the page's top-left corner."))
    top: Pairs = [("format", project.format, None), ("title", project.title, ""),
                  ("language", project.language, "en")]
    for key, value, default in top:
        if key in doc:
            if not same(as_read(doc[key]), value):
                doc[key] = in_written_form(doc[key], value)
        elif default is None or not same(value, default) or project.source_document is None:
            doc[key] = value
    if "physics" in doc:
        sync_table(doc["physics"], physics_pairs(project.physics))
    elif project.source_document is None:
        doc["physics"] = new_table(physics_pairs(project.physics))  # a new file shows the knobs
    else:
        # The user's file had no [physics]: add only what differs from the defaults.
        changed = [pair for pair in physics_pairs(project.physics) if not same(pair[1], pair[2])]
        if changed:
            doc["physics"] = new_table(changed)

    def fill_page(table: Table, page: Page) -> None:
        sync_array(table, "regions", page.regions, region_pairs, lambda region: region.id,
                   at_end=page is project.pages[-1])
        sync_array(table, "items", page.items, item_pairs, lambda item: item.id)

    sync_array(doc, "pages", project.pages, page_pairs, lambda page: page.id, fill_page)
    return doc


def dump_project(project: Project) -> str:
    import tomlkit
    return tomlkit.dumps(to_document(project))


def non_finite_numbers(project: Project) -> list[str]:
    """Where the project holds inf or NaN: such a file would no longer load, so it is never saved."""
    found = []
    for page in project.pages:
        for number_name in ("width_mm", "height_mm"):
            if not math.isfinite(getattr(page, number_name)):
                found.append(f'page "{page.id}" {number_name}')
        for item in page.items:
            numbers = {name: getattr(item, name) for name in ("x", "y", "w", "h")}
            anchor = item.anchor
            if isinstance(anchor, PointAnchor):
                numbers |= {"anchor x": anchor.x, "anchor y": anchor.y, "anchor gamma": anchor.gamma}
            elif isinstance(anchor, ItemAnchor):
                numbers |= {"anchor dx": anchor.dx, "anchor dy": anchor.dy}
            found += [f'item "{item.id}" {name}' for name, value in numbers.items()
                      if not math.isfinite(value)]
    physics = project.physics
    found += [f"[physics] {f.name}" for f in fields(PhysicsSettings)
              if isinstance(getattr(physics, f.name), float)
              and not math.isfinite(getattr(physics, f.name))]
    return found


def unchanged_on_disk(target: Path, data: bytes) -> bool:
    """Whether the file already holds exactly ``data``: then a save writes nothing, and the
    `.bak` keeps the version from before the last real change (two settles in a row used to
    leave the settled text in both)."""
    try:
        return target.is_file() and target.stat().st_size == len(data) and target.read_bytes() == data
    except OSError:
        return False


def save_project(project: Project, path: str | Path | None = None) -> Path:
    """Save atomically to `path` (default: where it was loaded from) and remember the new path."""
    import tomlkit
    target = Path(path) if path is not None else project.path
    if target is None:
        raise FloatpageError("the project has no file name yet (save it with a path)")
    broken = non_finite_numbers(project)
    if broken:
        raise FloatpageError(
            f"{target}: not saved, because {broken[0]}"
            + (f" and {len(broken) - 1} more values" if len(broken) > 1 else "")
            + " would be written as inf or NaN (the file on disk is unchanged; "
            "lower [physics] alpha or dt, or report this as a bug)")
    try:
        doc = to_document(project)
    except RecursionError:
        raise FloatpageError(f"{target}: not saved: the file read nests tables or arrays too "
                             "deeply to edit in place (the file on disk is unchanged); "
                             "remove the deep nesting") from None
    text = tomlkit.dumps(doc)
    if project.crlf:  # tomlkit ends the lines it adds with \n: a Windows file got mixed ends
        text = LONE_LF.sub("\r\n", text)
    data = text.encode("utf-8")
    if project.utf8_bom:
        data = UTF8_BOM + data
    if not unchanged_on_disk(target, data):
        atomic_write(target, data)
    project.source_document = doc
    project.path = target
    return target

