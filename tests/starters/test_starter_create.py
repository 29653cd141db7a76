"""starters.create, the CLI's entry point: refusals first, then each kind end to end."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from floatpage import starters
from floatpage.model import load_project
from floatpage.model.document import CalendarItem, PictureItem
from floatpage.model.errors import FloatpageError
from starter_pdf_checks import assert_page_sizes, check_month, day_marks
from floatpage.starters.pictures import bundled


@pytest.fixture
def photos(tmp_path) -> Path:
    folder = tmp_path / "my photos"
    folder.mkdir()
    for source in bundled(["seaside.jpg", "tulips.jpg", "night-sky.jpg", "apples.png", "rolling-hills.jpg"]):
        shutil.copyfile(source, folder / source.name)
    return folder


@pytest.mark.parametrize("kind, options, says", [
    ("poster", {}, "unknown starter 'poster'"),
    ("calendar", {"year": 0}, "--year"),
    ("calendar", {"lang": "klingon"}, "--lang"),
    ("calendar", {"first_weekday": "someday"}, "--first-weekday"),
    ("card", {"orientation": "diagonal"}, "--orientation"),
    ("card", {"photos": Path("/nonexistent/photos")}, "no such folder"),
])
def test_bad_options_are_refused_before_anything_is_written(tmp_path, kind, options, says):
    target = tmp_path / "new" / "project.toml"
    with pytest.raises(FloatpageError, match=says):
        starters.create(kind, target, settle=False, **options)
    assert not (tmp_path / "new").exists()


def test_an_album_without_photos_starts_with_the_bundled_ones_and_says_how_to_use_yours(tmp_path):
    target = tmp_path / "album.toml"
    done = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "new", "album", str(target)],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "--photos DIR" in done.stdout
    pictures = sorted(path.name for path in (tmp_path / "pictures").iterdir())
    assert pictures and set(pictures) <= set(starters.album.BUNDLED)


def test_a_folder_where_the_pictures_cannot_go_is_a_message_not_a_crash(tmp_path):
    """`floatpage new card /proc/x.toml`, or a folder holding a file named `pictures`, ended in
    "internal error: FileNotFoundError" (exit 70, a crash log) while copying the pictures."""
    (tmp_path / "pictures").write_text("my notes")
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "new", "card",
                             str(tmp_path / "card.toml")], capture_output=True, text=True,
                            timeout=120, stdin=subprocess.DEVNULL)
    assert result.returncode == 1, result.stderr
    assert result.stderr.startswith(f"floatpage: {tmp_path / 'card.toml'}: cannot create the "
                                    f"project there ({tmp_path / 'pictures'}: "), result.stderr
    assert "choose a folder you can write to" in result.stderr
    assert (tmp_path / "pictures").read_text() == "my notes"
    assert not (tmp_path / "card.toml").exists()


def test_an_existing_file_is_never_overwritten(tmp_path):
    target = tmp_path / "mine.toml"
    target.write_text("precious")
    with pytest.raises(FloatpageError, match="already exists"):
        starters.create("card", target, settle=False)
    assert target.read_text() == "precious"


def test_the_project_file_must_be_toml(tmp_path):
    with pytest.raises(FloatpageError, match=r"\.toml"):
        starters.create("card", tmp_path / "card.pdf", settle=False)


def test_empty_photos_folder_lists_the_formats(tmp_path):
    (tmp_path / "empty").mkdir()
    with pytest.raises(FloatpageError, match="JPG, PNG"):
        starters.create("album", tmp_path / "a.toml", photos=tmp_path / "empty", settle=False)


def test_user_photos_are_copied_beside_the_project(tmp_path, photos):
    project = starters.create("album", tmp_path / "out" / "album.toml", photos=photos, settle=False)
    used = {i.path for p in project.pages for i in p.items if isinstance(i, PictureItem)}
    assert used == {f"pictures/{p.name}" for p in photos.iterdir()}
    for path in used:
        assert (tmp_path / "out" / path).read_bytes() == (photos / Path(path).name).read_bytes()


def test_created_project_is_settled_and_saved(tmp_path):
    project = starters.create("flyer", tmp_path / "flyer.toml")
    loaded = load_project(tmp_path / "flyer.toml")
    assert project.path == tmp_path / "flyer.toml"
    for page, saved in zip(project.pages, loaded.pages):
        for item in page.items:
            assert saved.item(item.id).x == pytest.approx(item.x, abs=0.01)
            assert saved.item(item.id).y == pytest.approx(item.y, abs=0.01)


def test_created_calendar_is_at_rest(tmp_path):
    """create() settles: the physics moved the photos, and settling again barely moves anything."""
    from floatpage.model.layout import settle_project

    unsettled = starters.create("calendar", tmp_path / "raw.toml", year=2027, settle=False)
    starters.create("calendar", tmp_path / "settled.toml", year=2027)
    project = load_project(tmp_path / "settled.toml")
    positions = {i.id: (i.x, i.y) for page in project.pages for i in page.items}
    start = {i.id: (i.x, i.y) for page in unsettled.pages for i in page.items}
    moved = max(abs(positions[k][0] - start[k][0]) + abs(positions[k][1] - start[k][1]) for k in start)
    assert moved > 1.0
    settle_project(project)
    again = max(abs(i.x - positions[i.id][0]) + abs(i.y - positions[i.id][1])
                for page in project.pages for i in page.items)
    assert again < 0.5


def test_a_new_calendars_month_panels_sit_on_the_page_centre_as_wide_as_the_title(tmp_path):
    """The portrait panel was 8 mm narrower than the title and the photo band, so the guides
    lined up one of its edges with a photo's and left it 4 mm off the page centre (x = 101 or
    109 on most months of a new calendar), under a centred title.  As wide as the title, it
    lines up with the title and the photos on both sides, and stays centred."""
    starters.create("calendar", tmp_path / "cal.toml", year=2027)
    for page in load_project(tmp_path / "cal.toml").pages:
        title = page.item(f"{page.id}-title")
        panel = page.item(f"{page.id}-month")
        assert panel.x == pytest.approx(page.width_mm / 2, abs=0.01), page.id
        assert panel.w == pytest.approx(title.w, abs=0.01), page.id


CREATE_CASES = {
    "blank": {},
    "calendar": {"year": 2028, "first_weekday": "sunday", "lang": "de", "orientation": "landscape"},
    "card": {"lang": "fr"},
    "album": {"photos": True},
    "flyer": {"lang": "nl"},
}
EXPECTED = {"blank": (1, "A4"), "calendar": (12, "A4"), "card": (2, "5x8in"), "album": (2, "A4"),
            "flyer": (1, "A4")}


@pytest.fixture(params=list(CREATE_CASES))
def created(request, tmp_path_factory, render_once):
    kind = request.param

    def make():
        folder = tmp_path_factory.mktemp(f"new-{kind}")
        options = dict(CREATE_CASES[kind])
        if options.pop("photos", False):
            photos_dir = folder / "photos"
            photos_dir.mkdir()
            for source in bundled(["seaside.jpg", "tulips.jpg", "night-sky.jpg", "apples.png",
                                   "rolling-hills.jpg"]):
                shutil.copyfile(source, photos_dir / source.name)
            options["photos"] = photos_dir
        starters.create(kind, folder / "project" / f"{kind}.toml", **options)
        return load_project(folder / "project" / f"{kind}.toml")

    return kind, render_once(f"create-{kind}", make)


def test_each_starter_renders_its_pages(created):
    kind, rendered = created
    pages, size = EXPECTED[kind]
    assert len(rendered.project.pages) == pages
    assert {p.size for p in rendered.project.pages} == {size}
    assert_page_sizes(rendered.plumber, rendered.project.pages)
    if kind == "calendar":
        assert {p.orientation for p in rendered.project.pages} == {"landscape"}
        for page, plumber_page in zip(rendered.project.pages, rendered.plumber.pages):
            [panel] = [i for i in page.items if isinstance(i, CalendarItem)]
            check_month(day_marks(plumber_page, panel), 2028, panel.month, "sunday")


def new_under_a_file_size_limit(argv: list[str], limit_bytes: int) -> subprocess.CompletedProcess:
    """`floatpage new ...` in a process that may write no file larger than ``limit_bytes``
    (RLIMIT_FSIZE: a write past it fails with EFBIG, as a full disk fails with ENOSPC)."""
    import resource

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit_bytes, limit_bytes))

    return subprocess.run([sys.executable, "-m", "floatpage.cli.main", "new", *argv],
                          capture_output=True, text=True, timeout=120, preexec_fn=limit,
                          stdin=subprocess.DEVNULL)


def noisy_photos(folder: Path, sizes: list[int]) -> None:
    """PNGs of random pixels (they do not compress), ``size`` pixels square each."""
    import numpy as np
    from PIL import Image

    folder.mkdir()
    rng = np.random.default_rng(7)
    for number, size in enumerate(sizes):
        pixels = rng.integers(0, 256, (size, size, 3), dtype=np.uint8)
        Image.fromarray(pixels).save(folder / f"photo-{number}.png")


def test_a_new_album_that_fails_while_copying_its_photos_leaves_nothing(tmp_path):
    """The fourth photo cannot be written (as on a full disk): the three copied before it
    and the folder they went to stayed behind, and the next try named them photo-0-2.png."""
    noisy_photos(tmp_path / "photos", [40, 40, 40, 400, 40])
    result = new_under_a_file_size_limit(
        ["album", str(tmp_path / "out" / "album.toml"), "--photos", str(tmp_path / "photos")],
        100_000)
    assert result.returncode == 1, result.stderr
    assert "cannot create the project there" in result.stderr, result.stderr
    assert "photo-3.png" in result.stderr, result.stderr
    assert not (tmp_path / "out").exists()


def test_a_new_album_that_cannot_be_saved_leaves_only_what_was_there(tmp_path):
    """The photos copied, the project file not written: the copies went, the user's own
    picture in the same pictures/ folder stays, and so does the folder."""
    noisy_photos(tmp_path / "photos", [20, 20])
    (tmp_path / "pictures").mkdir()
    (tmp_path / "pictures" / "mine.png").write_bytes(b"my own")
    result = new_under_a_file_size_limit(
        ["album", str(tmp_path / "album.toml"), "--photos", str(tmp_path / "photos")], 1_500)
    assert result.returncode == 1, result.stderr
    assert "album.toml: could not save" in result.stderr, result.stderr
    assert sorted(path.name for path in tmp_path.iterdir()) == ["photos", "pictures"]
    assert [path.name for path in (tmp_path / "pictures").iterdir()] == ["mine.png"]


@pytest.mark.parametrize("length", [240, 251])
def test_a_name_too_long_to_save_is_refused_before_anything_is_written(tmp_path, length):
    """251 bytes + ".toml" ended in "internal error: OSError: File name too long"; 240 copied
    the pictures, then failed to save, its temporary's name being longer still."""
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "new", "card",
                             str(tmp_path / ("n" * length + ".toml"))], capture_output=True,
                            text=True, timeout=120, stdin=subprocess.DEVNULL)
    assert result.returncode == 1, result.stderr
    assert f"the file name is {length + 5} bytes long" in result.stderr, result.stderr
    assert "choose a shorter name" in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_a_photo_too_thin_to_lay_out_is_left_out_with_a_word(tmp_path):
    """A photo of 1 x 100,000 pixels became a box 0.0 mm tall: `new album` saved a project
    its own loader refused ("h" must be greater than 0)."""
    from PIL import Image

    photos = tmp_path / "photos"
    photos.mkdir()
    Image.new("L", (1, 30_000), 128).save(photos / "strip.png")
    Image.new("RGB", (30_000, 1), "red").save(photos / "line.jpg")
    Image.new("RGB", (300, 200), "blue").save(photos / "fine.png")
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "new", "album",
                             str(tmp_path / "album.toml"), "--photos", str(photos)],
                            capture_output=True, text=True, timeout=120, stdin=subprocess.DEVNULL)
    assert result.returncode == 0, result.stderr
    for name, size in (("line.jpg", "30000 × 1"), ("strip.png", "1 × 30000")):
        assert f"note: {photos / name} was left out: it is {size} pixels, its long side more " \
               "than 20 times its short one" in result.stderr, result.stderr
    project = load_project(tmp_path / "album.toml")
    used = [item.path for page in project.pages for item in page.items
            if isinstance(item, PictureItem)]
    assert used == ["pictures/fine.png"]


def test_a_pictures_link_out_of_the_folder_is_refused_before_anything_is_copied(tmp_path):
    """`pictures` a symlink to ../elsewhere: `new card` copied the pictures through it, and
    the project it saved failed its own check ("outside the project folder")."""
    (tmp_path / "elsewhere").mkdir()
    (tmp_path / "project").mkdir()
    (tmp_path / "project" / "pictures").symlink_to("../elsewhere")
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "new", "card",
                             str(tmp_path / "project" / "card.toml")], capture_output=True,
                            text=True, timeout=120, stdin=subprocess.DEVNULL)
    assert result.returncode == 1, result.stderr
    assert f"{tmp_path / 'project' / 'pictures'}: is a symbolic link to ../elsewhere, outside " \
           "the project's folder" in result.stderr, result.stderr
    assert list((tmp_path / "elsewhere").iterdir()) == []
    assert [path.name for path in (tmp_path / "project").iterdir()] == ["pictures"]
