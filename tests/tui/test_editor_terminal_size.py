"""The editor takes the size of the terminal it runs in, whatever $COLUMNS and $LINES say.

Textual asks `shutil.get_terminal_size`, which reads those variables before the terminal: an
exported COLUMNS=80 (a shell's rc file; pytest-xdist's workers export 80 x 24 to everything
they start) laid the editor out at 80 x 24 in a 100 x 32 window, and a resize changed nothing.
A real pty, the real `floatpage edit`, and a VT emulator reading what it drew."""

from __future__ import annotations

import os
import time

import pyte

from test_editor_hangup import Editor, project_file


def drawn(editor: Editor, columns: int, rows: int, settle_s: float = 1.0) -> list[str]:
    """The screen as a terminal of that size shows it, after ``settle_s`` without output."""
    editor.drain(settle_s)
    screen = pyte.Screen(columns, rows)
    pyte.ByteStream(screen).feed(editor.screen)
    return screen.display


def wait_for_bottom_line(editor: Editor, columns: int, rows: int, timeout: float = 60.0):
    """Until the key line ("? Help ...") is the terminal's last row; the screen then."""
    deadline = time.monotonic() + timeout
    while True:
        screen = drawn(editor, columns, rows, 0.3)
        if screen[-1].startswith("? Help"):
            return screen
        assert time.monotonic() < deadline, "\n".join(screen)


def test_the_editor_fills_its_terminal_and_follows_a_resize_under_an_exported_columns(tmp_path):
    editor = Editor(project_file(tmp_path), env={"COLUMNS": "80", "LINES": "24"})
    try:
        editor.read_until(b"items")
        screen = wait_for_bottom_line(editor, 100, 32)
        assert not screen[23].startswith("? Help"), "laid out for $LINES, not the terminal"
        editor.screen = b""  # what follows is a new drawing at the new size
        editor.resize(120, 40)
        screen = wait_for_bottom_line(editor, 120, 40)
        assert "items" in "\n".join(screen)
        editor.send(b"\x11")  # Ctrl+Q: nothing to save
        code, _ = editor.wait_exit(10.0)
    finally:
        editor.kill()
        os.close(editor.fd)
    assert code == 0
