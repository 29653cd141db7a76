"""Every text a starter writes prints in every language: no missing glyphs, nothing tiny.

The typesetter's own check (`text_fit_warnings`) reports glyphs a font lacks and texts that
only fit below the legible minimum; a starter should never trigger either, in any language
or orientation.
"""

import pytest

from floatpage import starters
from floatpage.model.schema import CALENDAR_LANGUAGES
from floatpage.starters.options import Options
from floatpage.starters.pictures import bundled, copy_beside
from floatpage.typeset import text_fit_warnings


@pytest.fixture(scope="module")
def pictures(tmp_path_factory):
    folder = tmp_path_factory.mktemp("texts")
    names = sorted({name for module in starters.KINDS.values() for name in module.BUNDLED})
    return folder, dict(zip(names, copy_beside(bundled(names), folder)))


@pytest.mark.parametrize("lang", CALENDAR_LANGUAGES)
@pytest.mark.parametrize("kind", list(starters.KINDS))
def test_starter_texts_print_in_every_language(kind, lang, pictures):
    folder, by_name = pictures
    chosen = [by_name[name] for name in starters.KINDS[kind].BUNDLED] or list(by_name.values())[:3]
    for orientation in ("portrait", "landscape"):
        project = starters.build(kind, Options(year=2027, lang=lang, orientation=orientation), chosen)
        project.path = folder / "project.toml"
        assert text_fit_warnings(project) == [], (kind, lang, orientation)
        assert project.language == lang
