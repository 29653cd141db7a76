"""Items that push each other apart like electric charges: the interaction model of Piccoli,
Chamun, Cogo, Oliveira and Manssour, plus a faster, safer default mode.  Imports numpy only;
no clocks, threads, logging or UI."""

from floatpage.physics.engine import Engine, SettleReport
from floatpage.physics.params import Params, page_scale
from floatpage.physics.quality import Quality, measure_quality

__all__ = ["Engine", "Params", "Quality", "SettleReport", "measure_quality", "page_scale"]
