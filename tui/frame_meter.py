"""Frames per second and physics steps per second over the last second of frames, and how many
frames the link held back (the frame pacer's skips) over the same second."""

from __future__ import annotations

from collections import deque


class FrameMeter:
    """Rolling window of (time, steps) per drawn frame, and the times of frames held back."""

    def __init__(self, window_s: float = 1.0):
        self.window_s = window_s
        self.frames: deque[tuple[float, int]] = deque()
        self.held_at: deque[float] = deque()
        self.last_frame_s = 0.0  # physics + drawing time of the latest frame

    def record(self, now: float, steps: int, frame_s: float) -> None:
        self.frames.append((now, steps))
        self.last_frame_s = frame_s
        self._forget(now)

    def record_held(self, now: float) -> None:
        """A frame the physics computed and the pacer did not draw (the link was behind)."""
        self.held_at.append(now)
        self._forget(now)

    def _forget(self, now: float) -> None:
        while self.frames and now - self.frames[0][0] > self.window_s:
            self.frames.popleft()
        while self.held_at and now - self.held_at[0] > self.window_s:
            self.held_at.popleft()

    @property
    def held(self) -> int:
        """Frames held back for the link within a second of the latest frame drawn or held:
        a sign that does not hang on the machine's speed, as the frame rate does (a loaded
        machine draws fewer frames a second on any link, and holds none back on a fast one)."""
        return len(self.held_at)

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
