"""Project files written by hand in forms TOML allows and floatpage's own saves never write
(user-walk-13): dotted keys, tables written inline, a merge conflict left in the file. Each
file is saved by the real save and read back by the real loader."""

from __future__ import annotations

import tomllib

import pytest

from floatpage.model import load_project, save_project
from floatpage.model.document import PointAnchor, Region
from floatpage.model.errors import ProjectFileError

ITEMS = '''
[[pages.items]]
id = "a"
kind = "block"
x = 50.0
y = 50.0
w = 20.0
h = 20.0

[[pages.items]]
id = "b"
kind = "block"
x = 50.0
y = 90.0
w = 20.0
h = 20.0
'''
DOTTED_PHYSICS = ('format = 1\nphysics.seed = 0  # same file, same layout\nphysics.alpha = 150.0\n\n'
                  '[[pages]]\nid = "p"\nsize = "A5"\n' + ITEMS)
INLINE_PAGE = ('format = 1\npages = [\n  { id = "p", size = "A5", items = [ { id = "a", kind = "block", '
               'x = 50.0, y = 50.0, w = 20.0, h = 20.0 }, { id = "b", kind = "block", x = 50.0, '
               'y = 90.0, w = 20.0, h = 20.0 } ] },  # the only page\n]\ntitle = "t"\n')


def test_a_physics_table_written_as_dotted_keys_is_saved_in_that_form(tmp_path):
    """`physics.seed = 0` and `physics.alpha = 150.0` (dotted keys, no `[physics]` header):
    every save, a settle's included, stopped with "internal error: AttributeError: 'dict'
    object has no attribute 'body'". A changed setting and a new one keep the dotted form."""
    path = tmp_path / "card.toml"
    path.write_text(DOTTED_PHYSICS)
    project = load_project(path)
    save_project(project)
    assert path.read_text() == DOTTED_PHYSICS
    project.physics.alpha = 120.0
    project.physics.gutter_mm = 4.0
    project.pages[0].items[0].x = 61.25
    save_project(project)
    text = path.read_text()
    assert "physics.alpha = 120.0\n" in text and "physics.gutter_mm = 4.0\n" in text
    assert "[physics]" not in text and "# same file, same layout" in text
    again = load_project(path)
    assert (again.physics.alpha, again.physics.gutter_mm, again.physics.seed) == (120.0, 4.0, 0)
    assert again.pages[0].items[0].x == 61.25


def add_item(project):
    page = project.pages[0]
    new = type(page.items[0])(id="c", x=50.0, y=130.0, w=20.0, h=20.0)
    page.items.append(new)


def delete_item(project):
    del project.pages[0].items[0]


def add_region(project):
    project.pages[0].regions.append(Region(id="top", left=0.0, top=0.0, w=148.0, h=100.0))


def reorder_items(project):
    project.pages[0].items.reverse()


@pytest.mark.parametrize("edit", [add_item, delete_item, add_region, reorder_items],
                         ids=lambda edit: edit.__name__)
def test_a_page_written_inline_takes_an_added_deleted_or_reordered_item(tmp_path, edit):
    """`pages = [{id = "p", items = [...]}]`: an item added (`i` in the editor) or deleted
    and saved was written as `[[pages.items]]` tables inside the page's braces, a file that
    no longer parsed ("TOML syntax error: Invalid value"), saved over the user's. The page
    stays inline, its items an inline array, the other entries as written."""
    path = tmp_path / "card.toml"
    path.write_text(INLINE_PAGE)
    project = load_project(path)
    edit(project)
    wanted = [(item.id, item.x, item.y) for item in project.pages[0].items]
    save_project(project)
    text = path.read_text()
    tomllib.loads(text)  # raises where the save wrote no TOML
    again = load_project(path)
    assert [(item.id, item.x, item.y) for item in again.pages[0].items] == wanted
    assert [region.id for region in again.pages[0].regions] == \
        [region.id for region in project.pages[0].regions]
    assert "[[pages" not in text and text.startswith("format = 1\npages = [\n  { id = \"p\"")
    if edit is not reorder_items:
        assert "},  # the only page\n]\ntitle = \"t\"\n" in text


CONFLICTED = '''format = 1

[[pages]]
id = "p"
size = "A5"

[[pages.items]]
id = "a"
kind = "text"
x = 50.0
y = 50.0
w = 60.0
h = 20.0
<<<<<<< HEAD
text = "Many happy returns!"
=======
text = "Happy Birthday, Ana!"
>>>>>>> other
'''


def test_a_merge_conflict_left_in_the_file_is_named_as_one(tmp_path):
    """A `git merge` that stopped on the project left its markers in it: every command said
    "TOML syntax error: Invalid statement (check quotes, brackets and `key = value` pairs on
    that line)" at the first marker, with nothing about the merge."""
    path = tmp_path / "card.toml"
    path.write_text(CONFLICTED + CONFLICTED[CONFLICTED.index("<<<<<<<"):])
    with pytest.raises(ProjectFileError) as raised:
        load_project(path)
    message = str(raised.value)
    assert f"{path}:14: a merge conflict is left in the file: 2 conflicts" in message
    assert "delete the marker lines" in message and "git checkout --ours" in message
    assert "Invalid statement" not in message


WINDOWS_MESSAGE = ('format = 1\r\ntitle = \'C:\\cards\'\r\n\r\n[[pages]]\r\nid = "p"\r\nsize = "A5"\r\n'
                   '\r\n[[pages.items]]\r\nid = "a"\r\nkind = "text"\r\nx = 50.0\r\ny = 50.0\r\n'
                   'w = 60.0\r\nh = 30.0\r\ntext = """\r\nDear Ana,\r\nhappy birthday"""\r\n')


def test_a_windows_files_multi_line_text_is_kept_as_written(tmp_path):
    """A multi-line text in a CRLF file: an unchanged project's save rewrote it as
    `text = "Dear Ana,\\nhappy birthday"` (tomlkit keeps the CRLF inside the string, the
    loader reads LF, so it looked changed), and so did every save of anything else."""
    path = tmp_path / "card.toml"
    path.write_bytes(WINDOWS_MESSAGE.encode())
    project = load_project(path)
    save_project(project)
    assert path.read_bytes() == WINDOWS_MESSAGE.encode()
    project.pages[0].items[0].x = 52.5
    save_project(project)
    assert path.read_bytes() == WINDOWS_MESSAGE.replace("x = 50.0", "x = 52.5").encode()


def test_a_changed_text_keeps_the_multi_line_or_literal_form_it_was_written_in(tmp_path):
    """A word changed in a hand-written `\"\"\"` message (in the editor's form) came back as
    one line of `\\n`s, and a literal `'C:\\cards'` title as `"C:\\\\cards"`."""
    path = tmp_path / "card.toml"
    path.write_bytes(WINDOWS_MESSAGE.encode())
    project = load_project(path)
    project.pages[0].items[0].text = "Dear Ana,\nhappy 50th birthday!"
    project.title = "D:\\cards"
    save_project(project)
    assert path.read_bytes() == WINDOWS_MESSAGE.replace("happy birthday", "happy 50th birthday!") \
        .replace("C:", "D:").encode()
    again = load_project(path)
    assert (again.pages[0].items[0].text, again.title) == \
        ("Dear Ana,\nhappy 50th birthday!", "D:\\cards")
    project.title = "Ana's card"  # no longer writable as a literal string: a basic one
    save_project(project)
    assert load_project(path).title == "Ana's card"


INLINE_ITEMS = ('format = 1\n\n[[pages]]\nid = "p"\nsize = "A5"\nitems = [\n'
                '  { id = "a", kind = "text", x = 50.0, y = 50.0, w = 60.0, h = 30.0, '
                "text = '''Dear Ana,\nhappy birthday''' },  # the message\n"
                '  { id = "b", kind = "block", x = 50.0, y = 120.0, w = 20.0, h = 20.0 },\n]\n')


def test_an_item_deleted_from_an_inline_items_array_leaves_the_others_as_written(tmp_path):
    """`items = [{...}, {...}]` under `[[pages]]`, one item deleted (Del in the editor) and
    saved: every other item was rewritten as a `[[pages.items]]` table with every key
    (`z = 0`, `decorative = false`, `color = "#000000"` ...), its comment dropped and its
    literal multi-line text made one line of `\\n`. Now the one entry goes, the rest stays;
    an added item is one more inline entry."""
    path = tmp_path / "card.toml"
    path.write_text(INLINE_ITEMS)
    project = load_project(path)
    del project.pages[0].items[1]
    save_project(project)
    assert path.read_text() == INLINE_ITEMS.replace(
        '  { id = "b", kind = "block", x = 50.0, y = 120.0, w = 20.0, h = 20.0 },\n', "")
    add_item(project)
    save_project(project)
    text = path.read_text()
    assert "[[pages.items]]" not in text and "},  # the message\n" in text
    assert [item.id for item in load_project(path).pages[0].items] == ["a", "c"]


CUT_SHORT_CARD = ('format = 1\n\n[[pages]]\nid = "p"\nsize = "A5"\n\n[[pages.items]]\nid = "a"\n'
                  'kind = "text"\nx = 50.0\ny = 50.0\nw = 60.0\nh = 30.0\ntext = "Joyeux anniversaire, '
                  'Zoë ! 🎂"\n')


@pytest.mark.parametrize("cut", ["in a character", "in a key"])
def test_a_file_cut_short_is_told_as_one_with_its_line_and_what_to_restore(tmp_path, cut):
    """A save, copy or checkout that did not finish: cut inside its last character, it "is
    not UTF-8 text (byte 176) (save it as UTF-8)", of a UTF-8 file; cut inside a key, "TOML
    syntax error: Expected '=' after a key in a key/value pair (at end of document) (check
    quotes, brackets and `key = value` pairs on that line)", with no line."""
    data = CUT_SHORT_CARD.encode()
    end = data.index("🎂".encode()) + 2 if cut == "in a character" else data.index(b"text =") + 3
    path = tmp_path / "card.toml"
    path.write_bytes(data[:end])
    with pytest.raises(ProjectFileError) as raised:
        load_project(path)
    message = str(raised.value)
    assert message.startswith(f"{path}:14: ")  # the text line
    assert "git restore" in message and ".bak" in message
    assert "not UTF-8" not in message and "end of document" not in message


def test_a_key_added_to_a_table_indented_by_hand_is_indented_as_its_keys_are(tmp_path):
    """A user who indents each table's keys with a tab: the keys a save added (a setting, an
    anchor) stood at the line's start among them."""
    text = ('format = 1\n\n[physics]\n\tseed = 0\n\n[[pages]]\n\tid = "p"\n\tsize = "A5"\n\n'
            '[[pages.items]]\n\tid = "a"\n\tkind = "block"\n\tx = 50.0\n\ty = 50.0\n\tw = 20.0\n'
            '\th = 20.0\n')
    path = tmp_path / "card.toml"
    path.write_text(text)
    project = load_project(path)
    project.physics.alpha = 120.0
    project.pages[0].items[0].anchor = PointAnchor(x=50.0, y=50.0, gamma=1.0)
    save_project(project)
    written = path.read_text()
    assert "\tseed = 0\n\talpha = 120.0\n" in written
    assert "\th = 20.0\n\tanchor = {x = 50.0, y = 50.0, gamma = 1.0}\n" in written


@pytest.mark.parametrize("written, saved", [
    ("anchor = { x = 50.0, y = 90.0, gamma = 1.0 }  # kept here\n",
     "anchor = { x = 61.25, y = 90.0, gamma = 1.0 }  # kept here\n"),
    ("anchor.x = 50.0\nanchor.y = 90.0\nanchor.gamma = 1.0\n",
     "anchor.x = 61.25\nanchor.y = 90.0\nanchor.gamma = 1.0\n"),
], ids=["inline, spaced", "dotted"])
def test_a_moved_anchor_keeps_the_form_it_was_written_in(tmp_path, written, saved):
    """An anchor written `{ x = 50.0, y = 90.0, gamma = 1.0 }` (spaces inside the braces,
    as most people and formatters write them) came back `{x = 61.25, y = 90.0, gamma = 1.0}`
    after a move, and one written as dotted keys came back an inline table: a diff of the
    form on every anchor moved."""
    text = 'format = 1\n\n[[pages]]\nid = "p"\nsize = "A5"\n' + ITEMS + written
    path = tmp_path / "card.toml"
    path.write_text(text)
    project = load_project(path)
    project.pages[0].items[1].anchor = PointAnchor(x=61.25, y=90.0, gamma=1.0)
    save_project(project)
    assert path.read_text() == text.replace(written, saved)


def test_a_picture_renamed_by_a_colleague_is_offered_by_its_new_name(tmp_path):
    """`git mv pictures/sunflower.jpg pictures/sunflower-2027.jpg` pulled from a colleague:
    "not found", and a folder to search. A file of a close name no other item shows is
    named; one another item shows (the album's next photo) is not."""
    import shutil
    from pathlib import Path
    samples = Path(__file__).resolve().parents[2] / "sample_projects" / "greeting-card"
    shutil.copytree(samples / "pictures", tmp_path / "pictures")
    text = (samples / "greeting-card.toml").read_text()
    (tmp_path / "pictures" / "sunflower.jpg").rename(tmp_path / "pictures" / "sunflower-2027.jpg")
    path = tmp_path / "card.toml"
    path.write_text(text)
    with pytest.raises(ProjectFileError) as raised:
        load_project(path)
    assert 'picture file "pictures/sunflower.jpg" not found; there is ' \
        '"pictures/sunflower-2027.jpg" beside it: renamed?' in str(raised.value)
    assert 'is missing; there is "pictures/sunflower-2027.jpg"' in \
        load_project(path, missing_pictures_ok=True).missing_pictures[0]
    path.write_text(text.replace("pictures/tulips.jpg", "pictures/sunflower-2027.jpg"))
    with pytest.raises(ProjectFileError) as raised:
        load_project(path)
    assert "not found (paths are relative" in str(raised.value)


BLOCK = 'id = "a"\nkind = "block"\nx = 50.0\ny = 50.0\nw = 20.0\nh = 20.0\n'


@pytest.mark.parametrize("text, line, words", [
    ('format = 1\n\n[[pages]]\nid = "p"\n\n[[pages.items]]\n' + BLOCK + 'title = "My card"\n', 13,
     '"title" belongs at the top of the file'),
    ('format = 1\n\n[[pages]]\nid = "p"\n\n[[pages.items]]\n' + BLOCK + 'size = "A5"\n', 13,
     "\"size\" is a page's key"),
    ('format = 1\n\n[[pages.items]]\n' + BLOCK + '\n[[pages]]\nid = "p"\n', 3,
     "an item or region table comes before any [[pages]] header"),
    ('format = 1\n\n[[pages]]\nid = "p"\n\n[[pages.items]]\n' + BLOCK.replace(
        "x = 50.0\n", "x = 50.0\nx = 52.5\n"), 10, "\"x\" is given twice in one table (line 9"),
], ids=["title at the end", "page size under an item", "items above their page",
        "both sides of a conflict kept"])
def test_a_key_or_table_put_under_the_wrong_header_says_where_it_belongs(tmp_path, text, line,
                                                                         words):
    """Lines moved around by hand: a `title` typed at the file's end was an unknown key of
    the last item ("allowed keys: id, kind, x, ..."), and `[[pages.items]]` above the first
    `[[pages]]` was "TOML syntax error: Cannot overwrite a value" at the `[[pages]]` line, as
    was a key given twice (both sides of a merge conflict kept)."""
    path = tmp_path / "card.toml"
    path.write_text(text)
    with pytest.raises(ProjectFileError) as raised:
        load_project(path)
    message = str(raised.value)
    assert message.startswith(f"{path}:{line}: ") and words in message, message
    assert "allowed keys" not in message and "Cannot overwrite" not in message


def test_conflicts_in_positions_only_are_told_apart_and_keep_their_first_side():
    """diff3's base section and CRLF line ends included; a conflict with any other line,
    or markers that do not pair up, is not one a settle mends."""
    from floatpage.model.merge_conflicts import keep_first_sides, positions_only
    positions = ("id = \"a\"\r\n<<<<<<< HEAD\r\nx = 1.0\r\ny = 2.0\r\n||||||| base\r\nx = 0.5\r\n"
                 "=======\r\nx = 3.0  # theirs\r\ny = 4.0\r\n>>>>>>> ana\r\nw = 5.0\r\n")
    assert positions_only(positions) == 1
    assert keep_first_sides(positions) == "id = \"a\"\r\nx = 1.0\r\ny = 2.0\r\nw = 5.0\r\n"
    assert positions_only(positions.replace("y = 4.0", "w = 4.0")) == 0
    assert positions_only(positions.replace(">>>>>>> ana\r\n", "")) == 0
    assert positions_only("x = 1.0\n") == 0
