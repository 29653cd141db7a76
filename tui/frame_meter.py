"""Frames per second and physics steps per second over the last second of frames."""

from __future__ import annotations

from collections import deque


class FrameMeter:
    """Rolling window of (time, steps) per drawn frame."""

    def __init__(self, window_s: float = 1.0):
        self.window_s = window_s
        self.frames: deque[tuple[float, int]] = deque()
        self.last_frame_s = 0.0  # physics + drawing time of the latest frame

    def record(self, now: float, steps: int, frame_s: float) -> None:
        self.frames.append((now, steps))
        self.last_frame_s = frame_s
        while self.frames and now - self.frames[0][0] > self.window_s:
            self.frames.popleft()

    @property
    def fps(self) -> float:
        if len(self.frames) < 2:
            return 0.0
        span = self.frames[-1][0] - self.frames[0][0]
        return (len(self.frames) - 1) / span if span > 0 else 0.0

    @property
    def steps_per_s(self) -> float:
        if len(self.frames) < 2:
            return 0.0
        span = self.frames[-1][0] - self.frames[0][0]
        return sum(steps for _, steps in list(self.frames)[1:]) / span if span > 0 else 0.0
