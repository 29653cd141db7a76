"""`floatpage check` fits each text and lays out each calendar once (typeset.placed.DocumentFits):
it did both twice, for its fit warnings and again for its contrast notes, with the same words."""

from __future__ import annotations

import contextlib
import io
from pathlib import Path

import pytest

import floatpage.typeset.placed as placed_module
import floatpage.typeset.roles as roles_module
from floatpage.cli.main import main
from floatpage.model import load_project
from floatpage.typeset.render import faint_text_notes, text_fit_warnings

ROOT = Path(__file__).resolve().parents[2]


def counted(monkeypatch, module, name: str, counts: dict) -> None:
    """Count the calls of ``module.name``, which still does its work."""
    original = getattr(module, name)

    def counting(*args, **kwargs):
        counts[name] = counts.get(name, 0) + 1
        return original(*args, **kwargs)

    monkeypatch.setattr(module, name, counting)


@pytest.mark.parametrize("sample", ["calendar-2027/calendar-2027.toml",
                                    "shop-flyer/shop-flyer.toml"])
def test_check_fits_each_text_and_lays_out_each_calendar_once(monkeypatch, sample):
    path = ROOT / "sample_projects" / sample
    project = load_project(path)
    once: dict[str, int] = {}
    counted(monkeypatch, roles_module, "fit_in_box", once)
    roles_module.RoleFits.of(project)  # what fitting every text once costs
    fits_once = once["fit_in_box"]
    calendars = sum(item.kind == "calendar" for page in project.pages for item in page.items)
    in_check: dict[str, int] = {}
    counted(monkeypatch, roles_module, "fit_in_box", in_check)
    counted(monkeypatch, placed_module, "layout_calendar", in_check)
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main(["check", str(path)]) == 0
    assert in_check["fit_in_box"] == fits_once
    assert in_check.get("layout_calendar", 0) == calendars
    # and the words are those of the two passes each fitting on its own
    words = [line.split(": ", 1)[1] for line in out.getvalue().splitlines()
             if line.startswith(("warning: ", "note: "))]
    apart = text_fit_warnings(project) + faint_text_notes(project)
    assert [line for line in words if line in apart] == [line for line in apart if line in words]
    assert set(apart) <= set(words)
