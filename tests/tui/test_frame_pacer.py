"""The link meter's account of output (tui/frame_pacer.py), on a clock of its own."""

from __future__ import annotations

from floatpage.tui.frame_pacer import LinkMeter


def test_bytes_written_at_once_count_but_never_wait():
    """A key's answer written at once (`HangupAwareDriver.write_prompt`) counts towards the
    byte budget, and is no output waiting to be flushed: counted as waiting, it was never
    flushed, and after 50 ms the pacer took the link for stuck and drew no more frames."""
    now = [0.0]
    link = LinkMeter(clock=lambda: now[0])
    link.queued(0, 5000)
    now[0] = 1.0
    assert link.bytes_written == 5000
    assert not link.write_stuck()
    link.queued(10, 10)  # handed to the writer thread, not flushed for 100 ms: stuck
    now[0] = 1.1
    assert link.write_stuck()
    link.flushed(10)
    assert not link.write_stuck()
