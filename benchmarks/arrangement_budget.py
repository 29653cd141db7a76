"""How many steps the exact search of physics.arrangements needs on sets with twins, against its
budget (arrangements.NODE_BUDGET, 50,000).

Six items as the limit check meets them on a small page: two pairs of twins (items of one
size) and two more, in a 100 x 140 mm room, at a gap drawn from 0-6 mm, most just short of
fitting.  For each set the least budget that answers is found by bisection (up to
``--cap`` steps), so the same script measures any version of the search (run an older one
with its folder first on PYTHONPATH).  Prints how many sets need more than the budget, the
median and worst steps, and how many fit.

    .venv/bin/python benchmarks/arrangement_budget.py --sets 300 --seed 11
"""

from __future__ import annotations

import argparse

import numpy as np

from floatpage.physics import arrangements

ROOM = np.array([100.0, 140.0])
BUDGET = arrangements.NODE_BUDGET


def drawn_set(rng: np.random.Generator) -> tuple[np.ndarray, float]:
    first = rng.uniform([20, 20], [60, 80])
    second = rng.uniform([20, 20], [60, 80])
    others = rng.uniform([5, 5], [50, 60], size=(2, 2))
    sizes = np.array([first, first, second, second, *others])[rng.permutation(6)]
    return sizes, float(rng.uniform(0.0, 6.0))


def answer(sizes: np.ndarray, gap: float, budget: int) -> bool | None:
    arrangements.NODE_BUDGET = budget
    try:
        return arrangements.arranges(sizes, ROOM, gap)
    except arrangements.OutOfBudget:
        return None
    finally:
        arrangements.NODE_BUDGET = BUDGET


def steps_needed(sizes: np.ndarray, gap: float, cap: int) -> tuple[int | None, bool | None]:
    """The least budget that answers (None past ``cap``), and the answer."""
    found = answer(sizes, gap, cap)
    if found is None:
        return None, None
    low, high = 0, cap
    while low < high:
        middle = (low + high) // 2
        if answer(sizes, gap, middle) is None:
            low = middle + 1
        else:
            high = middle
    return low, found


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sets", type=int, default=300)
    parser.add_argument("--seed", type=int, default=11)
    parser.add_argument("--cap", type=int, default=400_000, help="most steps tried for one set")
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    steps, fits, past_cap = [], 0, 0
    for _ in range(args.sets):
        sizes, gap = drawn_set(rng)
        needed, found = steps_needed(sizes, gap, args.cap)
        if needed is None:
            past_cap += 1
            continue
        steps.append(needed)
        fits += bool(found)
    steps_array = np.array(steps)
    print(f"{args.sets} sets of six items with two pairs of twins (seed {args.seed}): "
          f"{fits} fit, {len(steps) - fits} do not, {past_cap} past {args.cap:,} steps")
    print(f"past the budget of {BUDGET:,} steps: {int((steps_array > BUDGET).sum()) + past_cap}")
    print(f"steps: median {int(np.median(steps_array)):,}, 90th percentile "
          f"{int(np.percentile(steps_array, 90)):,}, worst answered {int(steps_array.max()):,}")


if __name__ == "__main__":
    main()
