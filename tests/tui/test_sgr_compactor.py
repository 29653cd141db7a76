"""Following styles: the style after a code, and the shortest code from one style to another
(the shadow screen's tests check in a VT emulator that the screens drawn are the same)."""

from __future__ import annotations

from floatpage.tui.sgr_compactor import DEFAULT, Style, apply_sgr, transition


def test_transition_turns_off_only_what_must_go():
    have = Style(frozenset({"bold", "dim"}), "31", "42")
    want = Style(frozenset({"dim"}), "31", "44")
    assert transition(have, want) == "\x1b[22;2;44m"
    assert transition(want, want) == ""
    assert transition(None, want) == "\x1b[0;2;31;44m"


def test_styles_are_followed_and_codes_not_followed_make_them_unknown():
    bold_red = apply_sgr(DEFAULT, "1;38;2;200;0;0")
    assert bold_red == Style(frozenset({"bold"}), "38;2;200;0;0", None)
    assert apply_sgr(bold_red, "22;49") == Style(frozenset(), "38;2;200;0;0", None)
    assert apply_sgr(bold_red, "") == DEFAULT
    assert apply_sgr(bold_red, "4:3") is None  # a curly underline: not followed
    assert apply_sgr(None, "1") is None and apply_sgr(None, "0;1") == Style(frozenset({"bold"}))
