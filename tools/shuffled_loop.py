"""A pytest plugin that runs the event loop's ready callbacks in a shuffled order, to find the
races a loaded machine finds by chance.

asyncio promises first-in, first-out only for callbacks one piece of code schedules in turn;
how the App's, the screens' and the widgets' tasks interleave is what load varies.  The
owner's CI run of d8b4f6b read a form's words before the keys already handed to it were
handled, which our runs on an idle machine never showed; with the order shuffled and the
machine slowed (below) it failed 2 of 46 runs, so a fix can be judged by a hundred runs in
minutes instead of a month of CI.

    PYTHONPATH=tools .venv/bin/python -m pytest -p shuffled_loop tests/tui

Set SHUFFLE_SEED (0), SHUFFLE_P (the share of turns that take a random ready callback, 0.5)
and SHUFFLE_SLOW (up to this many seconds of sleep before one callback in five, 0: a slow
machine, which makes deadlines bite).  The seed fixes the shuffle, not the threads' timing.

One guarantee is kept: a terminal driver hands keys over from its thread one scheduled
coroutine each, and a first-in, first-out loop starts them in the order typed, so here they
go straight to the App's queue.  Without that, `p` `l` typed over SSH arrive as `l` `p`,
which no real loop does.
"""

from __future__ import annotations

import asyncio
import collections
import os
import random
import time

from textual.driver import Driver

SEED = int(os.environ.get("SHUFFLE_SEED", "0"))
SHARE = float(os.environ.get("SHUFFLE_P", "0.5"))
SLOW_S = float(os.environ.get("SHUFFLE_SLOW", "0"))
chance = random.Random(SEED)


class ShuffledReady(collections.deque):
    """The loop's queue of ready callbacks, which hands out a random one now and then."""

    def popleft(self):
        if len(self) > 1 and chance.random() < SHARE:
            place = chance.randrange(len(self))
            self.rotate(-place)
            handle = super().popleft()
            self.rotate(place)
        else:
            handle = super().popleft()
        if SLOW_S and chance.random() < 0.2:
            time.sleep(chance.random() * SLOW_S)
        return handle


class ShuffledPolicy(asyncio.DefaultEventLoopPolicy):
    def new_event_loop(self):
        loop = super().new_event_loop()
        loop._ready = ShuffledReady()  # BaseEventLoop's own queue (CPython 3.4 onwards)
        return loop


def pytest_configure(config):
    asyncio.set_event_loop_policy(ShuffledPolicy())
    Driver.send_message = lambda self, message: self._app.post_message(message)
