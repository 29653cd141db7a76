"""Random project files, from a TOML strategy that bends every key of a real project, through
`check` and `settle` in this process: no internal error, nothing escaping the CLI, and never
an inf or NaN in a saved file.  Fewer of them also go through `render` (each costs a TeX run),
under a timeout: what `check` accepts must never break the engine."""

from __future__ import annotations

import contextlib
import io
import math
import signal
import tempfile
import tomllib
from pathlib import Path

import tomlkit
from PIL import Image
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from floatpage.cli.main import main

NUMBERS = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.floats(-500, 500),
    st.integers(-2**63, 2**63 - 1),
    st.sampled_from([0, -0.0, 1e308, -1e308, 5e-324, 1e6, 1.0, 0.5]),
)
TEXTS = st.text(alphabet=st.characters(blacklist_categories=("Cs",)), max_size=60)
ANYTHING = st.one_of(NUMBERS, TEXTS, st.booleans(), st.lists(st.integers(), max_size=3),
                     st.dictionaries(st.sampled_from(["a", "x"]), st.integers(), max_size=2))


def maybe(value_strategy):
    """A sensible value: `corrupt` later bends a few of them into anything at all, so that
    many files load and reach the physics while each key is sometimes hostile."""
    return value_strategy


@st.composite
def corrupt(draw, document: dict) -> dict:
    """Replace 0-2 values anywhere in the document with anything TOML can hold."""
    for _ in range(draw(st.sampled_from([0, 0, 1, 2]))):
        places = []
        stack = [document]
        while stack:
            table = stack.pop()
            for key, value in table.items():
                places.append((table, key))
                if isinstance(value, dict):
                    stack.append(value)
                elif isinstance(value, list):
                    stack += [entry for entry in value if isinstance(entry, dict)]
        table, key = draw(st.sampled_from(places))
        table[key] = draw(ANYTHING)
    return document


@st.composite
def anchors(draw, ids):
    kind = draw(st.sampled_from(["point", "point", "item", "item", "item", "junk"]))
    ids = [i for i in ids if isinstance(i, str)] or ["none"]
    if kind == "point":
        return {"x": draw(maybe(st.floats(-50, 300))), "y": draw(maybe(st.floats(-50, 300))),
                "gamma": draw(maybe(st.floats(0, 1))), "hard": draw(maybe(st.booleans()))}
    if kind == "item":
        return {"to": draw(maybe(st.sampled_from(ids))), "dx": draw(maybe(st.floats(-100, 100))),
                "dy": draw(maybe(st.floats(-100, 100)))}
    return draw(st.dictionaries(TEXTS, ANYTHING, max_size=3))


@st.composite
def documents(draw) -> dict:
    count = draw(st.integers(0, 8))
    ids = [f"i{k}" for k in range(count)] + [draw(TEXTS)]
    items = []
    for k in range(count):
        kind = draw(st.sampled_from(["text", "block", "calendar", "picture"]))
        item = {"id": ids[k], "kind": kind,
                "x": draw(maybe(st.floats(-20, 250))), "y": draw(maybe(st.floats(-20, 300))),
                "w": draw(maybe(st.floats(0.1, 200))), "h": draw(maybe(st.floats(0.1, 200)))}
        by_kind = {"text": {"text": maybe(TEXTS)}, "block": {"opacity": maybe(st.floats(0, 1))},
                   "calendar": {"year": maybe(st.integers(1, 9999)),
                                "month": maybe(st.integers(1, 12))},
                   "picture": {"path": st.sampled_from(["p.png", "good.png", "../p.png",
                                                        "/etc/passwd", ""])}}
        extras = {"z": maybe(st.integers(-3, 3)), "decorative": maybe(st.booleans()),
                  "anchor": anchors(ids),
                  **by_kind[kind]}
        if draw(st.sampled_from([False] * 9 + [True])):
            extras[draw(TEXTS) or "junk"] = ANYTHING
        for key, strategy in extras.items():
            if draw(st.booleans()) or key == "path":
                item[key] = draw(strategy)
        if draw(st.sampled_from([False] * 9 + [True])):
            item.pop(draw(st.sampled_from(list(item))), None)
        items.append(item)
    physics = {key: draw(maybe(strategy)) for key, strategy in {
        "mode": st.sampled_from(["fast", "paper"]), "alpha": st.floats(1, 1e6),
        "beta": st.floats(0, 10), "delta": st.floats(0, 1), "dt": st.floats(1e-4, 1),
        "steps_per_frame": st.integers(1, 1000), "heat_decay": st.floats(0, 0.5),
        "gutter_mm": st.floats(0, 20), "seed": st.integers(0, 2**32)}.items()
        if draw(st.booleans())}
    page = {"id": "p", "size": draw(st.sampled_from(["A4", "a5", " letter ", "custom", "A7"])),
            "items": items}
    if page["size"] == "custom" or draw(st.booleans()):
        page["width_mm"] = draw(maybe(st.floats(10, 600)))
        page["height_mm"] = draw(maybe(st.floats(10, 600)))
    document = {"format": 1, "title": draw(TEXTS), "physics": physics, "pages": [page]}
    return draw(corrupt(document))


def finite(path: Path) -> bool:
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8-sig"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError):
        return True  # what was never valid TOML is not ours to judge
    stack = [data]
    while stack:
        value = stack.pop()
        if isinstance(value, float) and not math.isfinite(value):
            return False
        if isinstance(value, dict):
            stack += value.values()
        elif isinstance(value, list):
            stack += value
    return True


def run(argv: list[str]) -> tuple[int, str]:
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        code = main(argv)
    return code, err.getvalue()


@contextlib.contextmanager
def scratch_project(document: dict):
    """The document as fuzz.toml in a scratch folder beside the pictures it may name (an
    empty p.png and a good one); None when tomlkit cannot write it (nothing to test)."""
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)
        path = folder / "fuzz.toml"
        try:
            path.write_text(tomlkit.dumps(document), encoding="utf-8")
        except (ValueError, TypeError):
            yield None
            return
        (folder / "p.png").write_bytes(b"")
        Image.new("RGB", (30, 20), "teal").save(folder / "good.png")
        yield path


FUZZ = dict(deadline=None, derandomize=True, database=None,
            suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


@settings(max_examples=150, **FUZZ)
@given(documents())
def test_random_files_get_a_clean_answer_and_never_a_non_finite_save(document):
    with scratch_project(document) as path:
        if path is None:
            return
        was_finite = finite(path)
        for command in (["check", str(path)], ["settle", "-q", str(path)]):
            code, err = run(command)
            assert code in (0, 1), err
            assert "internal error" not in err, err
            assert "\x1b" not in err
        if was_finite:
            assert finite(path), path.read_text()


RENDER_TIMEOUT_S = 180  # the engine's own limit is 120 s; past this the command hangs


class Hang(Exception):
    pass


def on_alarm(signum, frame):
    raise Hang


@settings(max_examples=30, **FUZZ)
@given(documents())
def test_random_files_through_check_settle_and_render_in_time(document):
    with scratch_project(document) as path:
        if path is None:
            return
        previous = signal.signal(signal.SIGALRM, on_alarm)
        signal.alarm(RENDER_TIMEOUT_S)
        try:
            checked, _ = run(["check", str(path)])
            run(["settle", "-q", str(path)])
            code, err = run(["render", "-q", str(path), "-o", str(path.with_suffix(".pdf"))])
        except Hang:
            raise AssertionError(f"a command ran past {RENDER_TIMEOUT_S} s") from None
        finally:
            signal.alarm(0)
            signal.signal(signal.SIGALRM, previous)
        assert code in (0, 1) and "internal error" not in err, err
        if checked == 0:
            assert "LaTeX reported" not in err and "LuaLaTeX" not in err, err
