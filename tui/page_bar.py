"""The top bar: one line of plain and bold text, whose Strip is built here.

It was a Label fed markup ("[b]front[/b] · at 96, 175 mm"): on every arrow key Textual parsed
the markup and rendered it through its content pipeline, about 1.5 ms of a key's answer of
8-9 ms (issue 11: key to screen within 2x a trivial app's). The bar's text is a few runs,
each plain or bold in the widget's own colours, so the Strip is built from them directly,
with the same segments the Label gave (the text in the widget's style, the rest of the line
in its background), so that the screen and the snapshots stay as they were.
`direct_paint.DirectPainter.paint_lines` sends the line with a key's preview cells.
"""

from __future__ import annotations

from rich.segment import Segment
from rich.style import Style
from rich.text import Text
from textual.strip import Strip
from textual.widget import Widget

Run = tuple[str, bool]  # text, bold
BOLD = Style(bold=True)


class PageBar(Widget):
    """One line of runs; `show` changes it and refreshes only when the text changed."""

    def __init__(self, *, id: str | None = None):
        super().__init__(id=id)
        self.runs: tuple[Run, ...] = ()
        self._strip: tuple[tuple, Strip] | None = None  # (what it was built for, the strip)

    def show(self, runs: tuple[Run, ...], refresh: bool = True) -> bool:
        """Show these runs; False (and nothing to draw) when they are the ones shown.

        With `refresh=False` the caller paints the line itself (`DirectPainter.paint_lines`)
        and refreshes only if that fails: the lines Textual cached are dropped, so that
        whatever renders the bar next renders these runs, but no screen update is asked
        for. After each arrow key that update found the line on the terminal already and
        sent nothing, for 1.3-1.5 ms of CPU while the key's answer was on its way (issue 11:
        key to screen, on a shared 2-core machine)."""
        if runs == self.runs:
            return False
        self.runs = runs
        if refresh:
            self.refresh()
        else:
            self._styles_cache.clear()
        return True

    @property
    def plain(self) -> str:
        return "".join(text for text, _ in self.runs)

    def render(self) -> Text:
        """The bar as Rich text (what it shows, for tests and anything that asks)."""
        text = Text()
        for part, bold in self.runs:
            text.append(part, "bold" if bold else "")
        return text

    def render_line(self, y: int) -> Strip:
        width = self.size.width
        base = self.rich_style
        if y != 0:
            return Strip.blank(width, Style(bgcolor=base.bgcolor))
        key = (self.runs, width, base)
        if self._strip is not None and self._strip[0] == key:
            return self._strip[1]
        segments: list[Segment] = []
        bold = base + BOLD
        for text, is_bold in self.runs:  # same-styled neighbours in one segment, as Content
            style = bold if is_bold else base
            if segments and segments[-1].style == style:
                segments[-1] = Segment(segments[-1].text + text, style)
            elif text:
                segments.append(Segment(text, style))
        strip = Strip(segments).crop(0, width).extend_cell_length(
            width, Style(bgcolor=base.bgcolor))
        self._strip = (key, strip)
        return strip
