"""Typeset tests keep their picture cache in a temporary folder, not the user's ~/.cache."""

import os

import pytest


@pytest.fixture(scope="session", autouse=True)
def picture_cache(tmp_path_factory):
    folder = tmp_path_factory.mktemp("picture-cache")
    previous = os.environ.get("FLOATPAGE_CACHE_DIR")
    os.environ["FLOATPAGE_CACHE_DIR"] = str(folder)
    yield folder
    if previous is None:
        os.environ.pop("FLOATPAGE_CACHE_DIR", None)
    else:
        os.environ["FLOATPAGE_CACHE_DIR"] = previous
