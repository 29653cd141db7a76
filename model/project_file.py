"""Read a project file into the document model, reporting every problem clearly.

`load_project(path)` either returns a valid `Project` or raises
`ProjectFileError` listing each problem with file, line, item and advice.
Validation covers syntax, unknown keys (with "did you mean"), types, ranges,
page sizes, missing pictures, anchors to unknown ids and anchor cycles.
"""

from __future__ import annotations

import difflib
import errno
import os
import re
import shlex
import stat
import tomllib
from pathlib import Path
from typing import Any


from floatpage.model.document import (
    ITEM_CLASSES, ITEM_KINDS, Background, ItemAnchor, Page, PhysicsSettings, PointAnchor, Project,
    Region,
)
from floatpage.model.errors import Problem, ProjectFileError
from floatpage.model.locate import LineFinder
from floatpage.model.merge_conflicts import marker_lines, positions_only
from floatpage.model.picture_files import (
    fields_are_whole_names, is_merge_placeholder, is_outside, names_a_field, read_header,
)
from floatpage.model.page_sizes import CUSTOM, PAGE_SIZES_MM, canonical_size_name, page_dimensions
from floatpage.model.schema import (
    BACKGROUND_KEYS, COMMON_ITEM_KEYS, FILES_KEYS, ITEM_ANCHOR_KEYS, KIND_KEYS, PAGE_KEYS, PHYSICS_KEYS,
    POINT_ANCHOR_KEYS, REGION_KEYS, TOP_KEYS, TYPE_WORDS, Key, type_matches,
)
from floatpage.model.document import FORMAT_VERSION

MAX_FILE_BYTES = 16 * 1024 * 1024
MAX_PAGES_AWAY = 100  # sizes and places beyond this many page sizes cannot be laid out
# One page's items: the physics and check were measured to 10,000 (benchmarks/scaling.py);
# 100,000 blocks in one 8 MB file drove check past 20 GB.
MAX_ITEMS_PER_PAGE = 10_000
TEX_LONGEST_MM = 5700.0  # TeX's largest length, 16383.99 pt, is 5,758 mm


def reach(page_mm: float) -> tuple[float, float]:
    """The band along one axis that an item must stay in, in mm from the page's corner."""
    margin = min(MAX_PAGES_AWAY * page_mm, TEX_LONGEST_MM - page_mm)
    return -margin, page_mm + margin


def load_project(path: str | Path, *, allow_outside_files: bool = False,
                 missing_pictures_ok: bool = False, merge_template: bool | None = None) -> Project:
    """Parse and validate a project file; raise ProjectFileError naming every problem.

    Pictures must lie inside the project's folder unless ``allow_outside_files`` (the CLI's
    --allow-outside-files) or the file's own ``[files] allow_outside = true`` says otherwise.
    ``missing_pictures_ok`` (the editor) loads a project whose picture files are gone or
    cannot be used (a file that is no picture, one that cannot be read), and lists them, as
    "WHERE: picture file "PATH" is missing" (or what else is wrong with it), in
    ``project.missing_pictures``: the editor refused to open it at all, leaving the user to
    mend the file by hand, where it now has a field for the path.
    A merge template may name a picture by a placeholder (``pictures/{photo}``): that path
    is checked per record, once filled, by `floatpage merge`.  Whether the project is one is
    ``merge_template`` (True from `floatpage merge`), else whether any text names a data column
    (`texts_name_fields`) or the field is a whole file or folder name (`pictures/{photo}`,
    `{id}.jpg`): a picture `photo {1}.png` deleted from a project whose texts name none is a
    missing picture, which `check` passed and `render` called a merge template."""
    path = Path(path)
    text = read_text(path)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise ProjectFileError([syntax_problem(path, error, text)]) from None
    except RecursionError:
        raise too_deep(path) from None
    reader = _Reader(path, text, allow_outside=allow_outside_files,
                     missing_pictures_ok=missing_pictures_ok,
                     merge_template=texts_name_fields(data) if merge_template is None
                     else merge_template)
    reader.had_bom = starts_with_bom(path)
    project = reader.project(data)
    if reader.problems:
        raise ProjectFileError(reader.problems)
    project.source_text = text  # parsed by tomlkit only if the project is saved
    project.missing_pictures = reader.missing_pictures
    project.utf8_bom = reader.had_bom
    project.crlf = "\r\n" in text[:text.find("\n") + 1]  # as its first line ends
    return project


def texts_name_fields(data: dict) -> bool:
    """Whether any text item of the parsed file names a data column (`{first_name}`)."""
    pages = data.get("pages")
    for page in pages if isinstance(pages, list) else ():
        items = page.get("items") if isinstance(page, dict) else None
        for item in items if isinstance(items, list) else ():
            text = item.get("text") if isinstance(item, dict) else None
            if isinstance(text, str) and names_a_field(text):
                return True
    return False


def starts_with_bom(path: Path) -> bool:
    with open(path, "rb") as handle:
        return handle.read(3) == b"\xef\xbb\xbf"


def too_deep(path: Path) -> ProjectFileError:
    """Python's parsers recurse per level of nesting; thousands of levels exhaust the stack."""
    return ProjectFileError([Problem(path, None, "", "tables or arrays are nested too deeply",
                                     "a project file nests a few levels at most; is this the right file?")])


def read_text(path: Path) -> str:
    """The file's text, or a Problem that says why it cannot be read."""
    def fail(message: str, hint: str) -> ProjectFileError:
        return ProjectFileError([Problem(path, None, "", message, hint)])

    if not path.exists() and os.path.islink(path):  # "no such file" of a file that is there
        try:
            os.stat(path)
        except OSError as error:
            if error.errno == errno.ELOOP:
                raise fail("is a symbolic link that leads back to itself",
                           "point it at the project's .toml file") from None
        raise fail(f"is a symbolic link to {os.readlink(path)}, which does not exist",
                   "point it at the project's .toml file, or restore that file")
    if not path.exists():
        raise fail("no such file", "check the path, or create one with `floatpage new blank PATH`")
    if path.is_dir():
        raise fail("is a folder, not a project file", "name the .toml file inside it")
    try:
        # O_NONBLOCK and a bounded read: a pipe hung `check`, and /dev/zero filled memory.
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
        with os.fdopen(fd, "rb") as handle:
            if not stat.S_ISREG(os.fstat(handle.fileno()).st_mode):
                raise fail("is not a regular file (a device, pipe or socket)",
                           "name a project's .toml file")
            raw = handle.read(MAX_FILE_BYTES + 1)
    except OSError as error:
        raise fail(f"cannot be read: {error.strerror}", "check its permissions") from None
    if len(raw) > MAX_FILE_BYTES:
        raise fail("is larger than 16 MiB", "a project file holds text only; is this the right file?")
    if not raw.lstrip(b"\xef\xbb\xbf").strip():
        raise fail("is empty", "start a project with `floatpage new blank PATH`, or restore "
                   "the .bak beside it")
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        line = raw[:error.start].count(b"\n") + 1
        if error.reason == "unexpected end of data":
            # the last character cut in two: "is not UTF-8 text (byte 930) (save it as
            # UTF-8)" of a UTF-8 file whose save or copy did not finish (user-walk-13)
            raise ProjectFileError([Problem(
                path, line, "", "the file stops in the middle of a character, as a file cut "
                "short does (a save, copy or download that did not finish)",
                restore_help(path))]) from None
        raise fail(f"is not UTF-8 text (line {line}, byte {error.start})",
                   "save it as UTF-8") from None


def conflict_problem(path: Path, text: str, first: int) -> Problem:
    """A merge left its conflict markers in the project: every command said only "TOML
    syntax error: Invalid statement (check quotes, brackets ...)" at the first one
    (user-walk-13). Conflicts in positions only are the settle's to mend."""
    typed = shlex.quote(str(path))
    count = sum(1 for line in text.splitlines() if line.startswith("<<<<<<<"))
    message = (f"a merge conflict is left in the file: {count} conflict"
               f"{'s' if count != 1 else ''}, marked by lines <<<<<<<, ======= and >>>>>>>")
    if positions_only(text):
        return Problem(path, first, "", message,
                       "each is in x and y lines only, the positions a settle writes: "
                       f"`floatpage settle {typed}` keeps the first side of each and lays the "
                       "pages out again from both sides' other changes; then `git add` it")
    return Problem(path, first, "", message,
                   "between each <<<<<<< and >>>>>>> keep the lines you want, delete the "
                   "marker lines, then check the file again; or keep one side whole with "
                   f"`git checkout --ours {typed}` or `--theirs`")


def item_before_its_page(text: str) -> int | None:
    """The line of a `[[pages.items]]` (or any `pages.` table) above the file's first
    `[[pages]]`, which TOML refuses at the `[[pages]]` line as "Cannot overwrite a value"
    (user-walk-13: tables moved around by hand)."""
    for number, line in enumerate(text.splitlines(), start=1):
        header = line.strip().replace(" ", "")
        if header.startswith("[[pages]]"):
            return None
        if header.startswith(("[[pages.", "[pages.")):
            return number
    return None


def syntax_problem(path: Path, error: tomllib.TOMLDecodeError, text: str = "") -> Problem:
    message = str(error)
    line = getattr(error, "lineno", None)
    if line is None and "(at line " in message:
        try:
            line = int(message.split("(at line ")[1].split(",")[0])
        except (IndexError, ValueError):
            line = None
    short = message.split(" (at line")[0]
    conflict = marker_lines(text)
    if conflict:
        return conflict_problem(path, text, conflict[0])
    if "\r" in text.replace("\r\n", ""):
        # Lines ended by a bare carriage return (classic Mac OS, some exporters) are one
        # long line to TOML: "line 1: Expected newline" sent the user to a line that was fine.
        return Problem(path, line, "", f"TOML syntax error: {short}",
                       "the file ends lines with a bare carriage return (CR), which TOML does "
                       "not read as a line end; save it with LF or CRLF line ends")
    early = item_before_its_page(text) if "Cannot" in short else None
    if early is not None:
        return Problem(path, early, "", "an item or region table comes before any [[pages]] "
                       "header", "a page's [[pages.items]] and [[pages.regions]] follow its "
                       "[[pages]] header: move the [[pages]] line, with the page's keys, above "
                       "this line")
    first = repeated_key_line(text, line) if "Cannot overwrite" in short else None
    if first is not None:
        key = KEY_LINE.match(text.splitlines()[line - 1])["key"]
        return Problem(path, line, "", f'"{key}" is given twice in one table (line {first} and '
                       "this one)", "keep one of the two lines; both sides of a merge "
                       "conflict kept by hand give each key twice")
    if "(at end of document)" in message:
        # "Expected '=' after a key ... (at end of document)" with no line, and a hint about
        # "that line": a file whose save, copy or checkout did not finish (user-walk-13).
        short = short.replace(" (at end of document)", "")
        return Problem(path, len(text.splitlines()) or None, "",
                       f"TOML syntax error at the end of the file: {short}",
                       "the file stops in the middle of its last line; if it was cut short, by a "
                       f"save, copy or download that did not finish, {restore_help(path)}")
    return Problem(path, line, "", f"TOML syntax error: {short}",
                   "check quotes, brackets and `key = value` pairs on that line")


KEY_LINE = re.compile(r"\s*(?P<key>[A-Za-z0-9_-]+)\s*=")


def repeated_key_line(text: str, line: int | None) -> int | None:
    """The line above ``line`` in the same table that sets the key ``line`` sets again, which
    tomllib calls "Cannot overwrite a value" (user-walk-13: both sides of a merge conflict
    kept, `x = 181.34` then `x = 181.9`)."""
    lines = text.splitlines()
    if line is None or not 0 < line <= len(lines):
        return None
    match = KEY_LINE.match(lines[line - 1])
    if match is None:
        return None
    for number in range(line - 1, 0, -1):
        above = lines[number - 1]
        if above.lstrip().startswith("["):
            return None
        found = KEY_LINE.match(above)
        if found and found["key"] == match["key"]:
            return number
    return None


def restore_help(path: Path) -> str:
    """What to do about a file cut short: the versions a user still has of it."""
    return f"restore the .bak beside it, or git's version with `git restore {shlex.quote(str(path))}`"


class _Reader:
    """Walks parsed TOML against the schema, building the model and collecting problems."""

    def __init__(self, path: Path, text: str, *, allow_outside: bool = False,
                 missing_pictures_ok: bool = False, merge_template: bool = False):
        self.path = path
        self.merge_template = merge_template
        self.allow_outside = allow_outside
        self.missing_pictures_ok = missing_pictures_ok
        self.missing_pictures: list[str] = []
        self.lines = LineFinder(text)
        self.problems: list[Problem] = []
        self.named_regions: set[tuple[int, str]] = set()  # (page index, id) of every region table
        self.named_pictures: set[Path] = set()  # every picture file the project names

    def add(self, line: int | None, where: str, message: str, hint: str = "") -> None:
        self.problems.append(Problem(self.path, line, where, message, hint))

    def check_table(self, table: dict, keys: list[Key], where: str, table_line: int | None) -> dict:
        """Report unknown, missing, mistyped and out-of-range keys; return the good values."""
        known = {key.name: key for key in keys}
        good: dict[str, Any] = {}
        for name in table:
            if name not in known:
                close = difflib.get_close_matches(name, list(known), n=1, cutoff=0.6)
                hint = f'did you mean "{close[0]}"?' if close else \
                    misplaced_key_hint(name, where) or "allowed keys: " + ", ".join(known)
                self.add(self.lines.key_line(table_line, name), where, f'unknown key "{name}"', hint)
        for key in keys:
            if key.name not in table:
                if key.required and key.kind == "array":  # `pages = ...` is no way to write one
                    self.add(table_line, where, f'missing key "{key.name}"',
                             f"add a [[{array_header(key.name)}]] table")
                elif key.required:
                    self.add(table_line, where, f'missing key "{key.name}"',
                             f"add `{key.name} = ...`")
                continue
            value = table[key.name]
            # The key's line is looked up only for a message: a 2,000-item file has 30,000
            # good keys, and finding each one's line was a tenth of loading it.
            if key.kind == "array":
                if not (isinstance(value, list) and all(isinstance(v, dict) for v in value)):
                    self.add(self.lines.key_line(table_line, key.name), where,
                             f'"{key.name}" must be an array of tables',
                             f"write each entry as a [[{array_header(key.name)}]] table")
                    continue
            elif not type_matches(key.kind, value):
                self.add(self.lines.key_line(table_line, key.name), where,
                         f'"{key.name}" must be {TYPE_WORDS[key.kind]}, not {describe(value)}')
                continue
            if key.check is not None:
                complaint = key.check(value)
                if complaint:
                    self.add(self.lines.key_line(table_line, key.name), where,
                             f'"{key.name}" {complaint}', f"it is {short_repr(value)}")
                    continue
            good[key.name] = value
        return good

    def project(self, data: dict) -> Project:
        self.named_pictures = {self.path.parent / name for name in picture_names(data)}
        top = self.check_table(data, TOP_KEYS, "", None)
        fmt = top.get("format")
        if fmt is not None and fmt != FORMAT_VERSION:
            self.add(self.lines.key_line(None, "format"), "", f"format {fmt} is not supported",
                     f"this floatpage reads format {FORMAT_VERSION}; upgrade floatpage or fix the number")
        physics_line = self.lines.table_line("physics")
        physics_values = self.check_table(top.get("physics", {}), PHYSICS_KEYS, "[physics]",
                                          physics_line)
        files = self.check_table(top.get("files", {}), FILES_KEYS, "[files]",
                                 self.lines.table_line("files"))
        self.allow_outside = self.allow_outside or files.get("allow_outside", False)
        project = Project(path=self.path, title=top.get("title", ""),
                          language=top.get("language", "en"),
                          physics=PhysicsSettings(**physics_values),
                          allow_outside_files=self.allow_outside)
        pages = top.get("pages", [])
        if "pages" in top and not pages:
            self.add(None, "", "the project has no pages", "add a [[pages]] table")
        seen_pages: set[str] = set()
        seen_items: dict[str, str] = {}
        for page_index, page_table in enumerate(pages):
            page = self.page(page_table, page_index, seen_items)
            if page is None:
                continue
            if page.id in seen_pages:
                self.add(self.lines.table_line("pages", page_index), f'page "{page.id}"',
                         "this page id is used twice", "give every page its own id")
            seen_pages.add(page.id)
            project.pages.append(page)
        for page_index, page in enumerate(project.pages):
            self.check_anchors(page, page_index)
            self.check_extent(page, page_index)
            self.check_regions(page, page_index)
            self.check_groups(page, page_index)
        return project

    def page(self, table: dict, page_index: int, seen_items: dict[str, str]) -> Page | None:
        page_line = self.lines.table_line("pages", page_index)
        label = f'page "{table["id"]}"' if isinstance(table.get("id"), str) else f"page {page_index + 1}"
        values = self.check_table(table, PAGE_KEYS, label, page_line)
        if "id" not in values:
            return None
        page = Page(id=values["id"])
        size_name = values.get("size", "A4")
        size = canonical_size_name(size_name)
        if size is None:
            close = difflib.get_close_matches(size_name, list(PAGE_SIZES_MM), n=1, cutoff=0.5)
            hint = f'did you mean "{close[0]}"? ' if close else ""
            self.add(self.lines.key_line(page_line, "size"), label, f'unknown page size "{size_name}"',
                     hint + "known sizes: " + ", ".join(PAGE_SIZES_MM) + ', or "custom" with width_mm and height_mm')
            size = "A4"
        page.size = size
        page.orientation = values.get("orientation", "portrait")
        if size == CUSTOM and not ("width_mm" in values and "height_mm" in values):
            if not ("width_mm" in table and "height_mm" in table):  # else: a bad value, said
                self.add(page_line, label, "a custom page needs width_mm and height_mm",
                         "add both, in millimetres")
            size = page.size = "A4"
        page.width_mm, page.height_mm = page_dimensions(size, page.orientation,
                                                        values.get("width_mm"), values.get("height_mm"))
        if size == CUSTOM:
            page.orientation = "landscape" if page.width_mm > page.height_mm else "portrait"
        if "background" in values:
            page.background = self.background(values["background"], label,
                                              self.lines.key_line(page_line, "background"))
        for region_index, region_table in enumerate(values.get("regions", [])):
            region = self.region(region_table, page, page_index, region_index)
            if region is not None:
                page.regions.append(region)
        items = values.get("items", [])
        if len(items) > MAX_ITEMS_PER_PAGE:
            self.add(page_line, label, f"holds {len(items):,} items, more than the "
                     f"{MAX_ITEMS_PER_PAGE:,} one page can lay out",
                     "spread them over several pages")
            return page
        for item_index, item_table in enumerate(items):
            item = self.item(item_table, page_index, item_index)
            if item is None:
                continue
            if item.id in seen_items:
                self.add(self.lines.item_line(page_index, item_index), f'item "{item.id}"',
                         f'this id is already used on page "{seen_items[item.id]}"',
                         "give every item its own id")
                continue
            seen_items[item.id] = page.id
            page.items.append(item)
        return page

    def region(self, table: dict, page: Page, page_index: int, region_index: int
               ) -> Region | None:
        line = self.lines.item_line(page_index, region_index, "regions")
        label = f'region "{table["id"]}"' if isinstance(table.get("id"), str) else \
            f"region {region_index + 1} of page {page_index + 1}"
        values = self.check_table(table, REGION_KEYS, label, line)
        if isinstance(table.get("id"), str):
            self.named_regions.add((page_index, table["id"]))  # reported here, not again per item
        if not {"id", "left", "top", "w", "h"} <= values.keys():
            return None
        region = Region(id=values["id"], left=float(values["left"]), top=float(values["top"]),
                        w=float(values["w"]), h=float(values["h"]))
        if any(known.id == region.id for known in page.regions):
            self.add(line, label, f'this region id is used twice on page "{page.id}"',
                     "give every region of a page its own id")
            return None
        left, top, right, bottom = region.box
        if left < 0 or top < 0 or right > page.width_mm + 1e-9 or bottom > page.height_mm + 1e-9:
            self.add(line, label, f"reaches outside the page ({left:g}-{right:g} mm across, "
                     f"{top:g}-{bottom:g} mm down, on a page of {page.width_mm:g} x "
                     f"{page.height_mm:g} mm)",
                     "left and top are the region's top-left corner, from the page's; keep "
                     "left + w and top + h within the page")
            return None
        return region

    def check_regions(self, page: Page, page_index: int) -> None:
        """An item's region must be one of its page's, and the item must fit inside it."""
        regions = [region.id for region in page.regions]
        for index, item in enumerate(page.items):
            if not item.region:
                continue
            line = self.lines.key_line(self.lines.item_line(page_index, index), "region")
            where = f'item "{item.id}"'
            if item.region not in regions and (page_index, item.region) in self.named_regions:
                continue  # the region itself was refused, with its own message
            misfit = page.region_misfit(item, item.region)
            if misfit is None:
                continue
            if item.region in regions:
                hint = "make the item smaller or the region larger"
            else:
                close = difflib.get_close_matches(item.region, sorted(regions), n=1, cutoff=0.6)
                hint = (f'did you mean "{close[0]}"?' if close else
                        "name one of the page's [[pages.regions]]" + (
                            ": " + ", ".join(f'"{name}"' for name in regions) if regions else
                            ", or add one with id, left, top, w and h"))
            self.add(line, where, misfit, hint)

    def check_groups(self, page: Page, page_index: int) -> None:
        """A group moves as one body: it may hold one point anchor (the group's anchor), and
        its members may follow only each other."""
        lines = {item.id: self.lines.item_line(page_index, k) for k, item in enumerate(page.items)}
        for group in dict.fromkeys(item.group for item in page.items if item.group):
            members = page.group_members(group)
            names = {member.id for member in members}
            pinned = [member for member in members if isinstance(member.anchor, PointAnchor)]
            for extra in pinned[1:]:
                self.add(self.lines.key_line(lines[extra.id], "anchor"), f'item "{extra.id}"',
                         f'group "{group}" has a second anchor ("{pinned[0].id}" has the '
                         "first); a group moves as one body, held by one anchor",
                         "remove one of the two anchors")
            for member in members:
                anchor = member.anchor
                if isinstance(anchor, ItemAnchor) and anchor.to not in names:
                    self.add(self.lines.key_line(lines[member.id], "anchor"),
                             f'item "{member.id}"', f'is in group "{group}" but follows '
                             f'"{anchor.to}", outside it',
                             f'anchor the group by one member, or add "{anchor.to}" to the group')

    def background(self, table: dict, label: str, line: int | None) -> Background | None:
        values = self.check_table(table, BACKGROUND_KEYS, label + " background", line)
        if "color" in values and "picture" in values:
            self.add(line, label, "a background is a colour or a picture, not both",
                     "remove one of them")
        if "picture" in values:
            self.check_picture(values["picture"], label + " background", line)
        return Background(color=values.get("color"), picture=values.get("picture"))

    def check_picture(self, relative: str, where: str, line: int | None) -> None:
        braces = is_merge_placeholder(relative, self.path.parent)
        if braces and (self.merge_template or fields_are_whole_names(relative)):
            return
        picture = self.path.parent / relative
        header = read_header(picture)
        if braces and header.problem == "not found" and not self.missing_pictures_ok:
            self.add(line, where, f'picture file "{relative}" not found',
                     f"paths are relative to {folder_words(self.path)}; fix the path or copy "
                     "the file there; or, if its braces name a data column, this is a merge "
                     "template: make its documents with `floatpage merge TEMPLATE DATA -o "
                     "OUTDIR`")
            return
        renamed = similar_file(picture, self.named_pictures) \
            if header.problem == "not found" else None
        renamed_words = f'; there is "{printable_relative(renamed, self.path.parent)}" beside ' \
            "it: renamed?" if renamed else ""
        if header.problem and self.missing_pictures_ok:
            problem = "is missing" if header.problem == "not found" else header.problem
            self.missing_pictures.append(f'{where}: picture file "{relative}" {problem}'
                                         + renamed_words)
        elif header.problem == "not found":
            self.add(line, where, f'picture file "{relative}" not found' + renamed_words,
                     f"paths are relative to {folder_words(self.path)}; fix the path or copy "
                     "the file there")
        elif header.problem:
            self.add(line, where, f'picture file "{relative}" {header.problem}', header.hint)
        elif not self.allow_outside and is_outside(picture, self.path.parent):
            self.add(line, where, f'picture file "{relative}" is outside the project folder '
                     f"{self.path.parent}",
                     "copy it into the folder, or allow it with --allow-outside-files or "
                     "`[files] allow_outside = true`")

    def item(self, table: dict, page_index: int, item_index: int):
        line = self.lines.item_line(page_index, item_index)
        label = f'item "{table["id"]}"' if isinstance(table.get("id"), str) else \
            f"item {item_index + 1} of page {page_index + 1}"
        kind = table.get("kind")
        if kind not in ITEM_KINDS:
            if isinstance(kind, str):
                close = difflib.get_close_matches(kind, ITEM_KINDS, n=1, cutoff=0.5)
                hint = (f'did you mean "{close[0]}"? ' if close else "") + "kinds: " + ", ".join(ITEM_KINDS)
                self.add(self.lines.key_line(line, "kind"), label, f'unknown item kind "{kind}"', hint)
                return None
            keys = COMMON_ITEM_KEYS
        else:
            keys = COMMON_ITEM_KEYS + KIND_KEYS[kind]
        values = self.check_table(table, keys, label, line)
        if kind not in ITEM_KINDS or not {"id", "x", "y", "w", "h"} <= values.keys():
            return None
        anchor_table = values.pop("anchor", None)
        values.pop("kind")
        for key in ("x", "y", "w", "h", "opacity"):
            if key in values:
                values[key] = float(values[key])
        item = ITEM_CLASSES[kind](**values)
        if anchor_table is not None:
            item.anchor = self.anchor(anchor_table, label, self.lines.key_line(line, "anchor"))
        if kind == "picture":
            self.check_picture(item.path, label, self.lines.key_line(line, "path"))
        return item

    def anchor(self, table: dict, label: str, line: int | None):
        if "to" in table:
            values = self.check_table(table, ITEM_ANCHOR_KEYS, label + " anchor", line)
            if "to" not in values:
                return None
            return ItemAnchor(to=values["to"], dx=float(values.get("dx", 0.0)),
                              dy=float(values.get("dy", 0.0)))
        values = self.check_table(table, POINT_ANCHOR_KEYS, label + " anchor", line)
        if not {"x", "y"} <= values.keys():
            if not self.problems or "anchor" not in self.problems[-1].where:
                self.add(line, label, "an anchor needs either x and y (a page point) or to (an item id)")
            return None
        return PointAnchor(x=float(values["x"]), y=float(values["y"]),
                           gamma=float(values.get("gamma", 1.0)), hard=values.get("hard", False))

    def check_extent(self, page: Page, page_index: int) -> None:
        """Items, and anchors, that reach beyond what can be laid out are refused here, before
        the physics turns them into inf and NaN (h = 1e308 did) or TeX stops with "Dimension
        too large" (its longest length is 5,758 mm): each must stay within a band of
        MAX_PAGES_AWAY page sizes around the page, and within TEX_LONGEST_MM of its corner."""
        for index, item in enumerate(page.items):
            where = f'item "{item.id}"'
            line = self.lines.item_line(page_index, index)
            for axis, centre, half, size in (("x", item.x, item.w / 2, page.width_mm),
                                             ("y", item.y, item.h / 2, page.height_mm)):
                low, high = reach(size)
                points = {axis: (centre - half, centre + half)}
                if isinstance(item.anchor, PointAnchor):
                    anchored = getattr(item.anchor, axis)
                    points[f"anchor {axis}"] = (anchored - half, anchored + half)
                elif isinstance(item.anchor, ItemAnchor):
                    offset = getattr(item.anchor, "d" + axis)
                    points[f"anchor d{axis}"] = (offset, offset)
                    low, high = low - high, high - low  # an offset spans the band's width
                for name, (first, last) in points.items():
                    if first < low or last > high:
                        value = getattr(item, name) if name in ("x", "y") else None
                        self.add(line, where, f'reaches beyond what can be laid out ("{name}"'
                                 f"{f' = {value:g}' if value is not None else ''}, size "
                                 f"{2 * half:g} mm: it must stay between {low:g} and {high:g} mm)",
                                 "use millimetres, and keep items within a few pages of the page")
                        break

    def check_anchors(self, page: Page, page_index: int) -> None:
        """Item anchors must name an item on the same page and must not form a cycle."""
        follows = {item.id: item.anchor.to for item in page.items if isinstance(item.anchor, ItemAnchor)}
        ids = set(page.item_ids())
        item_lines = {item.id: self.lines.item_line(page_index, i) for i, item in enumerate(page.items)}
        for follower, target in follows.items():
            where = f'item "{follower}"'
            if target == follower:
                self.add(self.lines.key_line(item_lines[follower], "anchor"), where,
                         "is anchored to itself", "anchor it to another item or to a point")
            elif target not in ids:
                close = difflib.get_close_matches(target, sorted(ids), n=1, cutoff=0.6)
                hint = f'did you mean "{close[0]}"?' if close else \
                    "anchor to an item id on the same page"
                self.add(self.lines.key_line(item_lines[follower], "anchor"), where,
                         f'is anchored to "{target}", which is not on page "{page.id}"', hint)
        # Each item is walked once: a walk stops at an item an earlier walk finished (a chain of
        # 2,000 items walked from every item was 53 s of `check`).
        reported: set[str] = set()
        finished: set[str] = set()
        for start in follows:
            chain: list[str] = []
            place: dict[str, int] = {}
            node = start
            while node not in finished and node not in place:
                place[node] = len(chain)
                chain.append(node)
                if node not in follows or follows[node] not in ids:
                    break
                node = follows[node]
            else:
                if node in place:
                    cycle = chain[place[node]:] + [node]
                    if not reported & set(cycle) and len(cycle) > 2:
                        self.add(self.lines.key_line(item_lines[node], "anchor"), f'item "{node}"',
                                 "item anchors form a cycle: " + " -> ".join(
                                     cycle if len(cycle) <= 12 else cycle[:10] + ["…", cycle[-1]])
                                 + (f" ({len(cycle) - 1} items)" if len(cycle) > 12 else ""),
                                 "remove the anchor from one of these items")
                    reported |= set(cycle)
            finished.update(chain)


def misplaced_key_hint(name: str, where: str) -> str | None:
    """Where a key that belongs to an enclosing table goes: in TOML a key belongs to the
    table whose header stands above it, so `title = "..."` typed at the file's end, under
    its last item, was "unknown key "title" (allowed keys: id, kind, x, ...)" of that
    item (user-walk-13)."""
    top = {key.name for key in TOP_KEYS if key.kind != "array"}
    if where and name in top:
        return (f'"{name}" belongs at the top of the file: in TOML a key belongs to the '
                f"table whose header is above it, so move the line above the first [header]")
    page = {key.name for key in PAGE_KEYS if key.kind != "array"}
    if where.startswith(("item ", "region ")) and name in page:
        return (f'"{name}" is a page\'s key: in TOML a key belongs to the table whose header '
                "is above it, so move the line up, under the page's [[pages]] header and "
                "above its first [[pages.items]]")
    return None


def picture_names(data: dict) -> list[str]:
    """Every picture path the parsed file names (items' and backgrounds'), as written."""
    names = []
    pages = data.get("pages")
    for page in pages if isinstance(pages, list) else ():
        if not isinstance(page, dict):
            continue
        background = page.get("background")
        if isinstance(background, dict) and isinstance(background.get("picture"), str):
            names.append(background["picture"])
        items = page.get("items")
        for item in items if isinstance(items, list) else ():
            if isinstance(item, dict) and isinstance(item.get("path"), str):
                names.append(item["path"])
    return names


def similar_file(missing: Path, named: set[Path]) -> Path | None:
    """The file in a missing picture's folder whose name is closest to it, if one is close
    and no other item names it: a picture renamed in git (`git mv sunflower.jpg
    sunflower-2027.jpg`) by a colleague left the user with "not found" and a folder to
    search (user-walk-13); the album's `photo-2.jpg`, which its own item shows, is no
    answer for a missing `photo-1.jpg`."""
    try:
        names = sorted(entry.name for entry in missing.parent.iterdir()
                       if entry.is_file() and missing.parent / entry.name not in named)
    except OSError:
        return None
    close = difflib.get_close_matches(missing.name, names[:2000], n=1, cutoff=0.6)
    return missing.parent / close[0] if close else None


def printable_relative(path: Path, folder: Path) -> str:
    try:
        return path.relative_to(folder).as_posix()
    except ValueError:
        return str(path)


def folder_words(project: Path) -> str:
    """The project's folder as a message names it: "relative to ." read as a typo to a user
    who ran the command beside the project."""
    folder = project.parent
    return "the project's folder" + ("" if str(folder) == "." else f", {folder}")


def array_header(name: str) -> str:
    """The header a user writes for an array of tables: `pages` is top-level; a page's
    `items` and `regions` are written `[[pages.items]]` and `[[pages.regions]]`."""
    return name if name == "pages" else f"pages.{name}"


def short_repr(value: Any, limit: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[:limit - 1] + "…"


def describe(value: Any) -> str:
    if isinstance(value, bool):
        return f"the boolean {str(value).lower()}"
    if isinstance(value, str):
        return f'the string "{value if len(value) <= 60 else value[:59] + "…"}"'
    if isinstance(value, (int, float)):
        return f"the number {value}"
    if isinstance(value, dict):
        return "a table"
    if isinstance(value, list):
        return "an array"
    names = {"datetime": "a date and time", "date": "a date", "time": "a time of day"}
    return names.get(type(value).__name__, type(value).__name__)
