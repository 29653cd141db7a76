"""The grid a save writes positions on: centres to 0.01 mm (model.layout.write_back), each
rounded towards the inside of the page where the nearest step would put an item past its edge
(model.layout.safe_round).

The alignment snap (physics.snapping) works on that grid: before its first move it puts every
group it may move onto it (where the move fits: _Snapper.onto_grid), and every move it scores
is a whole number of steps (snap_scoring_core.h, SAVE_STEPS_PER_MM), so the layout it leaves is
the layout saved.  Rounded only afterwards, features the snap had left 0.043-0.048 mm apart
(aligned: within snap_scoring.ALIGNED_MM) came back from the file 0.051-0.056 mm apart, near
misses, and the snap of the next probe moved items 2-10 mm to close them: the probe found the
page not at rest, and a settle took one probe more (benchmarks/guide_cost.py's fresh seeds
3027 and 4026, and 6 of the 11 pages that needed one on seeds 2000-4029).
"""

from __future__ import annotations

import numpy as np

STEPS_PER_MM = 100  # 0.01 mm: model.layout.POSITION_DECIMALS (tests/physics/test_save_grid.py)


def on_save_grid(centres: np.ndarray, halves: np.ndarray, page_mm: float) -> np.ndarray:
    """``centres`` along one axis rounded as a save rounds them (model.layout.safe_round): to
    the nearest step, but an item inside the page that the nearest step would put past an edge
    goes to the nearest step inside.  A new array."""
    step = 1.0 / STEPS_PER_MM
    centres = np.asarray(centres, float)
    halves = np.asarray(halves, float)
    nearest = np.floor(centres * STEPS_PER_MM + 0.5) / STEPS_PER_MM
    inside = ((centres - halves >= -1e-9) & (centres + halves <= page_mm + 1e-9)
              & (2 * halves <= page_mm))
    low = inside & (nearest - halves < 0)
    nearest[low] = np.ceil(np.round(halves[low] / step, 6)) / STEPS_PER_MM
    high = inside & (nearest + halves > page_mm)
    nearest[high] = np.floor(np.round((page_mm - halves[high]) / step, 6)) / STEPS_PER_MM
    return nearest + 0.0
