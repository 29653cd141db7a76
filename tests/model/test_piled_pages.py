"""settle's count of overlapping pairs (model/layout.py `piled_pairs`), which decides whether a
page is piled past what settle takes on, against the quality measure's own count."""

from __future__ import annotations

import random

import numpy as np
import pytest

from floatpage.model import BlockItem, Page
from floatpage.model.document import ItemAnchor
from floatpage.model.layout import follow_roots, piled_pairs
from floatpage.physics.quality import measure_quality


@pytest.mark.parametrize("seed", range(12))
def test_the_sweep_counts_what_the_quality_measure_counts(seed):
    rng = random.Random(seed)
    count, spread = rng.choice([(50, 30), (400, 120), (900, 60)])
    items = [BlockItem(id=f"b{k}", x=rng.uniform(0, spread), y=rng.uniform(0, spread),
                       w=rng.uniform(0.5, 25), h=rng.uniform(0.5, 25),
                       decorative=rng.random() < 0.1) for k in range(count)]
    for k in range(1, count, 7):  # some follow chains
        items[k].anchor = ItemAnchor(to=items[k - 1].id)
    page = Page(id="p", items=items)
    centres = np.array([(item.x, item.y) for item in items])
    sizes = np.array([(item.w, item.h) for item in items])
    decorative = np.array([item.decorative for item in items])
    expected = measure_quality(210, 297, centres, sizes, decorative=decorative,
                               groups=follow_roots(page)).overlap_count
    assert piled_pairs(page) == expected


def test_a_follow_chain_on_one_spot_is_not_a_pile():
    items = [BlockItem(id=f"n{k}", x=70.0, y=100.0, w=4.0, h=4.0,
                       anchor=ItemAnchor(to=f"n{k - 1}", dx=0.1, dy=0.1) if k else None)
             for k in range(2000)]
    page = Page(id="p", items=items)
    assert set(follow_roots(page)) == {0}
    assert piled_pairs(page) == 0
    items.append(BlockItem(id="loose", x=70.0, y=100.0, w=4.0, h=4.0))
    assert piled_pairs(page) == 2000
