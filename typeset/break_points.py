"""Where a line may break inside a run of text, beyond the spaces between words.

Chinese and Japanese break between characters; a French punctuation mark set after a space
never starts a line alone.  `pieces` is the one rule both line breakers follow: the
typesetter's (`typeset.fit`) and the editor's preview (`tui.cell_text`), so the preview
breaks a line where the PDF does.
"""

from __future__ import annotations

import unicodedata

# French (and Swiss German quotes) set a space before ! ? ; : » and after «, which a line must
# not break: "Joyeux anniversaire !" printed its "!" alone on the last line.  Such a lone
# mark is kept with its neighbour, the space between them kept as typed.
CLOSING_MARKS = frozenset("!?;:»›%‰")
OPENING_MARKS = frozenset("«‹")


def tied(words: list[str]) -> list[str]:
    """`words` with each word of closing marks only joined to the one before it, and each
    word of opening marks only to the one after it, by a space a line never breaks at."""
    out: list[str] = []
    pending = ""
    for word in words:
        if out and not pending and set(word) <= CLOSING_MARKS:
            out[-1] += " " + word
        elif set(word) <= OPENING_MARKS:
            pending += word + " "
        else:
            out.append(pending + word)
            pending = ""
    if pending:
        out.append(pending.rstrip(" "))
    return out


def clusters(word: str) -> list[str]:
    """Characters with their combining marks, so a break never separates an accent."""
    out: list[str] = []
    for char in word:
        if out and unicodedata.combining(char):
            out[-1] += char
        else:
            out.append(char)
    return out


# Chinese and Japanese are written without spaces and break between any two characters
# (Unicode's line breaking, UAX #14, class ID), except that a line never starts with closing
# punctuation, a small kana or a prolonged-sound mark, and never ends with opening punctuation
# (the Japanese kinsoku rules).  Without these break points a CJK sentence was one "word":
# fitted on one line at a tiny size, or split with a hyphen no CJK text has.
NO_BREAK_BEFORE = frozenset("、。，．・：；？！゛゜ヽヾゝゞ々〻ー‐゠–〜～）」』】〕〉》｝］｠〙〗〟’”"
                            "ぁぃぅぇぉっゃゅょゎゕゖァィゥェォッャュョヮヵヶㇰㇱㇲㇳㇴㇵㇶㇷㇸㇹㇺㇻㇼㇽㇾㇿ"
                            ",.:;?!)]}%…‥")
NO_BREAK_AFTER = frozenset("（「『【〔〈《｛［｟〘〖〝‘“([{")
CJK_RANGES = ((0x2E80, 0x2FDF), (0x3000, 0x303F), (0x3040, 0x30FF), (0x31C0, 0x31FF),
              (0x3200, 0x4DBF), (0x4E00, 0x9FFF), (0xF900, 0xFAFF), (0xFE30, 0xFE4F),
              (0xFF00, 0xFF60), (0x20000, 0x3FFFF))


def is_cjk(cluster: str) -> bool:
    """A Han character, kana or CJK punctuation: a line may break on either side of it."""
    code = ord(cluster[0])
    return any(low <= code <= high for low, high in CJK_RANGES)


def break_units(word: str) -> list[str]:
    """The pieces of a space-free `word` a line may break between: the word itself, unless
    it holds CJK characters, which may each end a line (see NO_BREAK_BEFORE)."""
    if all(ord(char) < 0x2E80 for char in word):
        return [word]
    units: list[str] = []
    previous = ""
    for cluster in clusters(word):
        if (units and (is_cjk(previous) or is_cjk(cluster))
                and cluster[0] not in NO_BREAK_BEFORE and previous[-1] not in NO_BREAK_AFTER):
            units.append(cluster)
        elif units:
            units[-1] += cluster
        else:
            units.append(cluster)
        previous = cluster
    return units


def pieces(line: str) -> list[tuple[str, bool]]:
    """What a line of text (no newline) may be broken into: each piece a line may start with,
    and whether it is joined to the piece before it (no space between them, as inside a
    CJK sentence).  Runs of spaces are one space; see `tied` and `break_units`."""
    out: list[tuple[str, bool]] = []
    for word in tied([word for word in line.split(" ") if word]):
        out.extend((unit, index > 0) for index, unit in enumerate(break_units(word)))
    return out
