"""A merge project in a temporary folder: the sample template and its pictures."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from merge_helpers import SAMPLE


@pytest.fixture
def merge_folder(tmp_path: Path) -> Path:
    folder = tmp_path / "project"
    folder.mkdir()
    shutil.copy(SAMPLE / "offer.toml", folder / "offer.toml")
    shutil.copytree(SAMPLE / "pictures", folder / "pictures")
    return folder
