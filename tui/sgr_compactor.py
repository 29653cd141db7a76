"""Fewer bytes per frame: colour codes sent only when the colour changes.

Textual writes every run of same-styled cells as `ESC[<full style>m text ESC[0m`. The preview
is half-block pixels, nearly every cell a style of its own, so in truecolour a cell cost about
40 bytes, of which 3 are the character: one arrow press on the greeting card sent 15 KB, 12 KB
of them colour codes. Terminals keep the current style until told otherwise, so the stream
only has to say what changes from one cell to the next (as curses and mosh do).

This module follows styles: `apply_sgr` gives the style after a code, and `transition` the
shortest code from the style the terminal has to the one wanted. `shadow_screen` uses them to
send, just before a cell is written, only the change its style needs.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

FLAG_ON = {"1": "bold", "2": "dim", "3": "italic", "4": "underline", "5": "blink",
           "6": "blink2", "7": "reverse", "8": "conceal", "9": "strike",
           "21": "underline2", "51": "frame", "52": "encircle", "53": "overline"}
FLAG_CODE = {flag: code for code, flag in FLAG_ON.items()}
# Codes that turn flags off, and every flag each one turns off.
FLAG_OFF = {"22": ("bold", "dim"), "23": ("italic",), "24": ("underline", "underline2"),
            "25": ("blink", "blink2"), "27": ("reverse",), "28": ("conceal",), "29": ("strike",),
            "54": ("frame", "encircle"), "55": ("overline",)}
OFF_CODE = {flag: code for code, flags in FLAG_OFF.items() for flag in flags}
# Flags that make the foreground colour visible on a blank cell.
SHOWN_ON_BLANKS = frozenset({"underline", "underline2", "strike", "reverse", "overline", "frame",
                             "encircle"})


@dataclass(frozen=True)
class Style:
    """A terminal's graphic rendition: flags on, and the foreground and background as the
    parameters that set them ("38;2;1;2;3", "31"), None for the terminal's default."""

    flags: frozenset[str] = frozenset()
    fg: str | None = None
    bg: str | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "_hash", hash((self.flags, self.fg, self.bg)))

    def __hash__(self) -> int:
        """Computed once: the shadow screen looks styles up in its caches for every cell it
        writes, and hashing the fields each time was a sixth of painting a moved photo."""
        return self._hash


DEFAULT = Style()


@lru_cache(maxsize=8192)
def apply_sgr(style: Style | None, params: str) -> Style | None:
    """The style after `ESC[params m`; None when it holds a code this module does not follow."""
    if ":" in params:  # sub-parameters (curly underlines and the like): not followed
        return None
    codes = params.split(";") if params else ["0"]
    flags = set(style.flags) if style is not None else None
    fg = style.fg if style is not None else None
    bg = style.bg if style is not None else None
    index = 0
    while index < len(codes):
        code = codes[index].lstrip("0") or "0"
        if code == "0":
            flags, fg, bg = set(), None, None
        elif flags is None:  # unknown until a reset
            return None
        elif code in FLAG_ON:
            flags.add(FLAG_ON[code])
        elif code in FLAG_OFF:
            flags.difference_update(FLAG_OFF[code])
        elif code in ("38", "48"):
            kind = codes[index + 1] if index + 1 < len(codes) else ""
            size = {"2": 5, "5": 3}.get(kind)
            if size is None or index + size > len(codes):
                return None
            value = ";".join(codes[index:index + size])
            fg, bg = (value, bg) if code == "38" else (fg, value)
            index += size - 1
        elif code == "39":
            fg = None
        elif code == "49":
            bg = None
        elif code.isdigit() and (30 <= int(code) <= 37 or 90 <= int(code) <= 97):
            fg = code
        elif code.isdigit() and (40 <= int(code) <= 47 or 100 <= int(code) <= 107):
            bg = code
        else:
            return None
        index += 1
    if flags is None:
        return None
    return Style(frozenset(flags), fg, bg)


@lru_cache(maxsize=8192)
def transition(have: Style | None, want: Style) -> str:
    """The shortest SGR sequence (of two ways) that turns `have` into `want`; "" if equal."""
    if have == want:
        return ""
    full = ["0", *sorted(FLAG_CODE[flag] for flag in want.flags)]
    full += [part for part in (want.fg, want.bg) if part is not None]
    if have is None:
        return f"\x1b[{';'.join(full)}m"
    params = sorted({OFF_CODE[flag] for flag in have.flags - want.flags})
    cleared = {flag for code in params for flag in FLAG_OFF[code]}
    params += sorted(FLAG_CODE[flag] for flag in want.flags & cleared | want.flags - have.flags)
    if have.fg != want.fg:
        params.append(want.fg or "39")
    if have.bg != want.bg:
        params.append(want.bg or "49")
    diff = ";".join(params)
    if len(diff) > len(";".join(full)):
        diff = ";".join(full)
    return f"\x1b[{diff}m"
