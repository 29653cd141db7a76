"""Lay out a month panel: title, weekday heads and a grid of day numbers, all computed.

The grid logic (which day sits in which cell, localised names) lives in
`model.calendar_month` so the editor's preview draws the same weeks.
"""

from __future__ import annotations

from dataclasses import dataclass

from floatpage.model.calendar_month import month_name, month_weeks, weekday_names, weekend_columns
from floatpage.model.document import CalendarItem
from floatpage.typeset.fit import Box, fit_text
from floatpage.typeset.fonts import FaceKey, metrics_for
from floatpage.typeset.text_layout import MM_PER_PT, PT_PER_MM, Run, RunGroup, face_for, place_lines

TITLE_SHARE = 0.2    # of the panel's height
HEADS_SHARE = 0.1
CELL_PADDING = 0.18  # of a cell's smaller side, kept clear around a day number
MOST_WEEKS = 6       # a month spans 4 to 6 rows of weeks
HEADS_TO_DAYS = 0.8  # weekday heads at most this share of the day numbers' size


@dataclass(frozen=True)
class Rect:
    left_mm: float
    top_mm: float
    right_mm: float
    bottom_mm: float


@dataclass(frozen=True)
class CalendarLayout:
    groups: tuple[RunGroup, ...]
    rules: tuple[tuple[float, float, float, float], ...]  # x1, y1, x2, y2 in mm
    weekend: tuple[Rect, ...]                              # tinted columns
    missing: tuple[str, ...]                               # characters the font lacks


def common_size(words: list[str], face: FaceKey, w_mm: float, h_mm: float) -> float:
    """The largest size at which every one of `words` fits a w x h box on one line."""
    metrics = metrics_for(face)
    box = Box(w_mm * PT_PER_MM, h_mm * PT_PER_MM)
    sizes = []
    for word in words:
        fit = fit_text(word, box, metrics)
        if len(fit.lines) > 1:  # a word that had to break: size it to one line instead
            sizes.append(box.w_pt / max(metrics.advance_em(word), 1e-6))
        sizes.append(fit.font_pt)
    return min(sizes)


def centred_runs(words: list[str], centres_x: list[float], centre_y: float, size: float,
                 face: FaceKey) -> tuple[Run, ...]:
    metrics = metrics_for(face)
    baseline = centre_y - size * MM_PER_PT / 2 + size * (1 - metrics.descent_em) * MM_PER_PT
    runs = []
    for word, x in zip(words, centres_x):
        width_pt = metrics.advance_em(word) * size
        runs.append(Run(x - width_pt * MM_PER_PT / 2, baseline, word, width_pt))
    return tuple(runs)


def layout_calendar(item: CalendarItem) -> CalendarLayout:
    weeks = month_weeks(item.year, item.month, item.first_weekday)
    left, top, w, h = item.x - item.w / 2, item.y - item.h / 2, item.w, item.h
    title_h, heads_h = h * TITLE_SHARE, h * HEADS_SHARE
    row_h = (h - title_h - heads_h) / len(weeks)
    col_w = w / 7
    bold, regular = face_for(item.font, True, False), face_for(item.font, False, False)
    pad = CELL_PADDING * min(col_w, row_h)
    # The title and the weekday heads are sized as in a month of six weeks, whatever this
    # month's rows: the twelve panels of a calendar then print them at one size (they went
    # from 15.9 to 18.3 pt with the rows of the month), and the bold heads stay smaller than
    # the day numbers of a six-week month instead of as large as them.
    six_row_h = (h - title_h - heads_h) / MOST_WEEKS
    head_pad = CELL_PADDING * min(col_w, six_row_h)

    title = f"{month_name(item.month, item.language)} {item.year}"
    title_metrics = metrics_for(bold)
    title_fit = fit_text(title, Box((w - 2 * head_pad) * PT_PER_MM,
                                    (title_h - head_pad) * PT_PER_MM), title_metrics)
    title_runs = place_lines(title_fit, title_metrics, left + head_pad, top,
                             title_h - head_pad / 2, widths_mm=w - 2 * head_pad, align="centre")

    centres = [left + col_w * (i + 0.5) for i in range(7)]
    heads = list(weekday_names(item.first_weekday, item.language))
    six_week_days = common_size([str(day) for day in range(1, 32)], regular,
                                col_w - 2 * head_pad, six_row_h - 2 * head_pad)
    heads_size = min(common_size(heads, bold, col_w - head_pad, heads_h - head_pad),
                     HEADS_TO_DAYS * six_week_days)
    heads_runs = centred_runs(heads, centres, top + title_h + heads_h / 2, heads_size, bold)

    numbers = [str(day) for week in weeks for day in week if day]
    day_size = common_size(numbers, regular, col_w - 2 * pad, row_h - 2 * pad)
    day_runs: list[Run] = []
    grid_top = top + title_h + heads_h
    for row, week in enumerate(weeks):
        cells = [(str(day), centres[col]) for col, day in enumerate(week) if day]
        day_runs += centred_runs([c[0] for c in cells], [c[1] for c in cells],
                                 grid_top + row_h * (row + 0.5), day_size, regular)

    rules = [(left, grid_top, left + w, grid_top)]
    rules += [(left, grid_top + row_h * r, left + w, grid_top + row_h * r)
              for r in range(1, len(weeks) + 1)]
    weekend = tuple(Rect(left + col_w * c, top + title_h, left + col_w * (c + 1), top + h)
                    for c in weekend_columns(item.first_weekday))
    groups = (RunGroup(bold, title_fit.font_pt, item.color, title_runs),
              RunGroup(bold, heads_size, item.color, heads_runs),
              RunGroup(regular, day_size, item.color, tuple(day_runs)))
    missing = {ch for text in [title] + heads for ch in metrics_for(bold).missing_chars(text)}
    return CalendarLayout(tuple(g for g in groups if g.runs), tuple(rules), weekend,
                          tuple(sorted(missing)))
