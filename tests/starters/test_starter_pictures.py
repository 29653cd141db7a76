"""Finding the user's photos and copying them beside the project."""

from pathlib import Path

import pytest
from PIL import Image

from floatpage.model.errors import FloatpageError
from floatpage.starters.pictures import bundled_dir, copy_beside, displayed_size, find_photos


def picture(path: Path, size=(40, 30), colour=(200, 80, 40), exif_orientation=None) -> Path:
    img = Image.new("RGB", size, colour)
    exif = Image.Exif()
    if exif_orientation is not None:
        exif[0x0112] = exif_orientation
    img.save(path, exif=exif.tobytes()) if path.suffix in (".jpg", ".png") else img.save(path)
    return path


def test_find_photos_keeps_readable_pictures_in_name_order(tmp_path):
    picture(tmp_path / "b.png")
    picture(tmp_path / "a.jpg")
    picture(tmp_path / "c.webp")
    (tmp_path / "notes.txt").write_text("not a picture")
    (tmp_path / "broken.jpg").write_bytes(b"not really a jpeg")
    picture(tmp_path / ".hidden.png")
    assert [p.name for p in find_photos(tmp_path)] == ["a.jpg", "b.png", "c.webp"]


def test_missing_folder_is_reported(tmp_path):
    with pytest.raises(FloatpageError, match="no such folder"):
        find_photos(tmp_path / "nope")


def test_a_file_is_not_a_photos_folder(tmp_path):
    with pytest.raises(FloatpageError, match="is a file"):
        find_photos(picture(tmp_path / "a.jpg"))


def test_folder_without_pictures_lists_accepted_formats(tmp_path):
    (tmp_path / "notes.txt").write_text("hello")
    with pytest.raises(FloatpageError, match=r"no picture files.*JPG, PNG, WEBP"):
        find_photos(tmp_path)


def test_folder_of_unreadable_pictures_says_so(tmp_path):
    (tmp_path / "broken.jpg").write_bytes(b"\xff\xd8 nope")
    with pytest.raises(FloatpageError, match="none could be read"):
        find_photos(tmp_path)


def test_exif_quarter_turn_swaps_the_shape(tmp_path):
    upright = picture(tmp_path / "upright.jpg", size=(60, 20))
    turned = picture(tmp_path / "turned.jpg", size=(60, 20), exif_orientation=6)
    assert displayed_size(upright) == (60, 20)
    assert displayed_size(turned) == (20, 60)


def test_copies_are_relative_to_the_project_and_keep_content(tmp_path):
    (tmp_path / "in").mkdir()
    source = picture(tmp_path / "in" / "x.JPEG")
    project_dir = tmp_path / "project"
    [copied] = copy_beside([source], project_dir)
    assert copied.path == "pictures/x.jpg"
    assert (project_dir / copied.path).read_bytes() == source.read_bytes()
    assert (copied.width_px, copied.height_px) == (40, 30)


def test_existing_different_file_is_never_overwritten(tmp_path):
    (tmp_path / "in").mkdir()
    source = picture(tmp_path / "in" / "x.png", colour=(0, 0, 255))
    project_dir = tmp_path / "project"
    (project_dir / "pictures").mkdir(parents=True)
    theirs = picture(project_dir / "pictures" / "x.png", colour=(0, 255, 0))
    before = theirs.read_bytes()
    [copied] = copy_beside([source], project_dir)
    assert copied.path == "pictures/x-2.png"
    assert theirs.read_bytes() == before


def test_identical_file_and_repeats_are_reused(tmp_path):
    (tmp_path / "in").mkdir()
    source = picture(tmp_path / "in" / "x.png")
    project_dir = tmp_path / "project"
    first = copy_beside([source, source], project_dir)
    again = copy_beside([source], project_dir)
    assert [p.path for p in first + again] == ["pictures/x.png"] * 3
    assert sorted(p.name for p in (project_dir / "pictures").iterdir()) == ["x.png"]


def test_photos_already_in_the_pictures_folder_stay_put(tmp_path):
    (tmp_path / "pictures").mkdir()
    source = picture(tmp_path / "pictures" / "x.png")
    [copied] = copy_beside([source], tmp_path)
    assert copied.path == "pictures/x.png"
    assert sorted(p.name for p in (tmp_path / "pictures").iterdir()) == ["x.png"]


def test_a_symlink_in_the_pictures_folder_is_never_written_through(tmp_path):
    """pictures/x.png, a link to a file not made yet elsewhere: the copy went through the
    link and landed outside the project (and the project named the link)."""
    (tmp_path / "in").mkdir()
    (tmp_path / "elsewhere").mkdir()
    source = picture(tmp_path / "in" / "x.png")
    project_dir = tmp_path / "project"
    (project_dir / "pictures").mkdir(parents=True)
    (project_dir / "pictures" / "x.png").symlink_to(tmp_path / "elsewhere" / "x.png")
    [copied] = copy_beside([source], project_dir)
    assert copied.path == "pictures/x-2.png"
    assert (project_dir / copied.path).read_bytes() == source.read_bytes()
    assert not (project_dir / copied.path).is_symlink()
    assert list((tmp_path / "elsewhere").iterdir()) == []


def test_bundled_pictures_are_small_and_mixed():
    files = sorted(bundled_dir().iterdir())
    shapes = {displayed_size(f)[0] > displayed_size(f)[1] for f in files}
    assert len(files) >= 12
    assert all(f.stat().st_size < 60_000 for f in files)
    assert shapes == {True, False}  # landscape and portrait
    assert {f.suffix for f in files} == {".jpg", ".png"}


def test_new_album_names_each_photo_it_leaves_out_and_why(tmp_path):
    """Two photos cut short and a phone's .HEIC among the rest made an album without them,
    and without a word; a notes file is passed over quietly, as before."""
    import subprocess
    import sys

    photos = tmp_path / "photos"
    photos.mkdir()
    picture(photos / "a.jpg")
    picture(photos / "b.png")
    (photos / "broken.jpg").write_bytes(b"not really a jpeg")
    (photos / "IMG_0001.HEIC").write_bytes(b"ftypheic")
    (photos / "notes.txt").write_text("not a picture")
    result = subprocess.run([sys.executable, "-m", "floatpage.cli.main", "new", "album",
                             str(tmp_path / "album.toml"), "--photos", str(photos), "-j", "1"],
                            capture_output=True, text=True, timeout=300,
                            stdin=subprocess.DEVNULL)
    assert result.returncode == 0, result.stderr
    notes = [line for line in result.stderr.splitlines() if line.startswith("note: ")]
    assert len(notes) == 2, result.stderr
    assert f"note: {photos / 'IMG_0001.HEIC'} was left out: floatpage reads JPG" in notes[0]
    assert f"note: {photos / 'broken.jpg'} was left out: it cannot be read" in notes[1]
