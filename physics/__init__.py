"""Items that push each other apart like electric charges (Pinheiro et al.'s interaction model),
plus a faster, safer default mode.  Imports numpy only; no clocks, threads, logging or UI."""

from physics.engine import Engine, SettleReport
from physics.params import Params, page_scale
from physics.quality import Quality, measure_quality

__all__ = ["Engine", "Params", "Quality", "SettleReport", "measure_quality", "page_scale"]
