import pytest

from floatpage.merge.placeholders import PlaceholderError, fields_in, fill


def test_fields_are_found_in_order_once_each():
    assert fields_in("Hello {first}, {last} and {first} again") == ["first", "last"]
    assert fields_in("{ spaced name }") == ["spaced name"]


def test_doubled_braces_are_literal_braces():
    assert fields_in("{{not a field}} {x}") == ["x"]
    assert fill("{{literal}} {x}", {"x": "1"}) == "{literal} 1"


@pytest.mark.parametrize("text", ["a lone { brace", "a lone } brace", "empty {} field",
                                  "{nested {x}}"])
def test_malformed_placeholders_say_where(text):
    with pytest.raises(PlaceholderError, match="character"):
        fields_in(text)


def test_values_are_inserted_as_they_are_and_never_scanned_again():
    values = {"a": "{b}", "b": "never", "c": r"\input{/etc/passwd} 100% $x$"}
    assert fill("{a} {c}", values) == r"{b} \input{/etc/passwd} 100% $x$"


def test_a_missing_column_is_a_key_error():
    with pytest.raises(KeyError):
        fill("{nope}", {})
