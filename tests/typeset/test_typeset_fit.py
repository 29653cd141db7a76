"""Fitting is pure: table tests with a monospace metric, properties with the real fonts."""

import pytest
from hypothesis import given, settings, strategies as st

from floatpage.typeset.fit import LEADING, MIN_PT, Box, fit_text, layout, paragraphs, segments_of
from floatpage.typeset.fonts import FaceKey, metrics_for


class Mono:
    """Every character 0.5 em, spaces too, ink = em box: easy to reason about by hand."""

    space_em = 0.5
    descent_em = 0.25

    def advance_em(self, word: str) -> float:
        return 0.5 * len(word)


@pytest.mark.parametrize("text, box, size, lines", [
    # One word, height binds: 10 pt tall box -> 10 pt type.
    ("ab", Box(100, 10), 10.0, ("ab",)),
    # One word, width binds: 4 chars * 0.5 em = 2 em in 20 pt -> 10 pt.
    ("abcd", Box(20, 100), 10.0, ("abcd",)),
    # Two lines stacked: 10 * (1 + 1.2) = 22 pt tall.
    ("ab\ncd", Box(100, 22), 10.0, ("ab", "cd")),
    # Greedy wraps: "aa bb cc" in 3 em per line at 10 pt -> "aa bb" is 2.5 em, fits.
    ("aa bb cc", Box(30, 22), 10.0, ("aa bb", "cc")),
    # Runs of spaces are one space; leading/trailing whitespace is ignored.
    ("  aa    bb  ", Box(25, 10), 10.0, ("aa bb",)),
])
def test_fit_table(text, box, size, lines):
    fit = fit_text(text, box, Mono())
    assert fit.font_pt == pytest.approx(size, rel=1e-4)
    assert fit.font_pt <= size + 1e-9
    assert fit.lines == lines


def test_empty_text_fits_nothing():
    assert fit_text("  \n ", Box(50, 50), Mono()).lines == ()


def test_blank_line_is_kept_as_an_empty_line():
    fit = fit_text("a\n\nb", Box(1000, 10 * (1 + 2 * LEADING)), Mono())
    assert fit.lines == ("a", "", "b")


def test_long_word_is_broken_with_hyphens_only_when_it_cannot_fit_at_min_size():
    word = "x" * 40  # 20 em: at 6 pt that is 120 pt, the box is 60 pt wide
    fit = fit_text(word, Box(60, 200), Mono())
    assert fit.broken_words == (word,)
    assert all(w <= 60 + 1e-9 for w in fit.line_widths_pt)
    assert "".join(line.rstrip("-") for line in fit.lines) == word
    assert fit.font_pt >= MIN_PT
    # The same word in a wide enough box is kept whole.
    assert fit_text(word, Box(130, 200), Mono()).lines == (word,)


def test_too_much_text_goes_below_minimum_and_says_so():
    fit = fit_text("word " * 400, Box(30, 30), Mono())
    assert fit.below_minimum
    assert fit.height_pt <= 30 + 1e-6
    assert max(fit.line_widths_pt) <= 30 + 1e-6


WORDS = st.text(alphabet="abcdefghijklmnopqrstuvwxyzéüñçøåœßABCDEFXYZ0123456789.,;!?-'()",
                min_size=1, max_size=14)


@settings(max_examples=150, deadline=None)
@given(words=st.lists(WORDS, min_size=1, max_size=60),
       w=st.floats(20, 600), h=st.floats(8, 500),
       family=st.sampled_from(["serif", "sans", "display"]),
       style=st.sampled_from(["regular", "bold", "italic", "bolditalic"]))
def test_fit_is_inside_and_maximal(words, w, h, family, style):
    metrics = metrics_for(FaceKey(family, style))
    box = Box(w, h)
    fit = fit_text(" ".join(words), box, metrics)
    assert max(fit.line_widths_pt) <= w * (1 + 1e-9)
    assert fit.height_pt <= h * (1 + 1e-9)
    if not fit.broken_words and not fit.below_minimum:
        # A hair larger does not fit: the size is the largest (ink can, rarely, make the
        # feasible sizes non-contiguous; then "a hair larger" may fit and we only check inside).
        segments, _ = segments_of(paragraphs(" ".join(words)), metrics, None)
        bigger = fit.font_pt * (1 + 2e-4)
        larger_fits = layout(segments, bigger, box, LEADING, metrics.descent_em) is not None
        assert bigger > min(1000.0, h) or not larger_fits or \
            layout(segments, fit.font_pt * 1.01, box, LEADING, metrics.descent_em) is None


@settings(max_examples=200, deadline=None)
@given(text=st.text(st.characters(blacklist_categories=("Cs",)), max_size=200),
       w=st.floats(0.01, 2000), h=st.floats(0.01, 2000))
def test_any_text_in_any_box_fits_without_crashing(text, w, h):
    from floatpage.typeset.text_layout import printable_text
    metrics = metrics_for(FaceKey("sans"))
    printable, _ = printable_text(text, metrics)
    fit = fit_text(printable, Box(w, h), metrics)
    if fit.lines and fit.font_pt > 0.25:
        assert max(fit.line_widths_pt) <= w * (1 + 1e-9)
        assert fit.height_pt <= h * (1 + 1e-9)


class TallAccent(Mono):
    """Like Mono, but "Ê" inks up to 1.0 em above the baseline and "j" 0.4 em below it."""

    def ink_em(self, word):
        from floatpage.typeset.fonts import Ink
        return Ink(0.0, 0.5 * len(word), 1.0 if "Ê" in word else 0.75,
                   0.4 if "j" in word else 0.25)


@pytest.mark.parametrize("text, box, size", [
    ("ab", Box(100, 10), 10.0),             # em box binds: 1 em tall
    ("Êb", Box(100, 10), 10 / 1.25),       # the accent: 1.0 + 0.25 em tall
    ("ab\nÊb", Box(100, 10), 10 / (1 + 1.2)),  # only the first line's ink counts upwards
    ("Êb\nja", Box(100, 10), 10 / (1.0 + 1.2 + 0.4)),  # ... and the last line's downwards
])
def test_ink_raises_the_top_and_lowers_the_bottom(text, box, size):
    fit = fit_text(text, box, TallAccent())
    assert fit.font_pt == pytest.approx(size, rel=1e-4)
    assert fit.height_pt <= box.h_pt + 1e-9
