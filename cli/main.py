"""`floatpage`: the command line, for people and for Makefiles.

Arguments are parsed here and nowhere else. One error boundary turns every
user-fixable error (a `FloatpageError`) into a short message and exit code 1;
misuse of the command line exits 2 (argparse's convention). Progress goes to
stderr only when stderr is a terminal, so pipes and CI logs stay quiet.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import sys
import time
from pathlib import Path
from typing import Callable, Iterator, Sequence

from floatpage.model.errors import FloatpageError, printable
from floatpage.model.key_specs import CALENDAR_LANGUAGES, WEEKDAYS

EXIT_OK, EXIT_USER_ERROR, EXIT_MISUSE = 0, 1, 2
EXIT_INTERNAL_ERROR = 70  # sysexits' EX_SOFTWARE: a bug of ours, never the user's mistake
STARTER_KINDS = ("blank", "calendar", "card", "album", "flyer")


@contextlib.contextmanager
def progress_line(quiet: bool) -> Iterator[Callable[[str], None]]:
    """``with progress_line(quiet) as show: show("settling…")``: rich's spinner and a line of
    text on a terminal, gone when the block ends (also by an error); silent in a pipe."""
    if quiet or not sys.stderr.isatty():
        yield lambda message: None
        return
    from rich.console import Console
    from rich.progress import Progress, SpinnerColumn, TextColumn

    with Progress(SpinnerColumn(), TextColumn("{task.description}"), transient=True,
                  console=Console(stderr=True)) as progress:
        task = progress.add_task("", total=None)
        yield lambda message: progress.update(task, description=message)


def cmd_new(args: argparse.Namespace) -> int:
    from floatpage import starters
    project = starters.create(
        args.kind, Path(args.path), year=args.year,
        photos=Path(args.photos) if args.photos else None,
        first_weekday=args.first_weekday or "monday", lang=args.lang,
        orientation=args.orientation, jobs=jobs_of(args),
    )
    # Only a calendar has a year and weeks: a Makefile that asked another kind for them
    # (meaning `calendar`) hears so, instead of a card that quietly took no notice.
    unused = [name for name, value in (("--year", args.year), ("--first-weekday", args.first_weekday))
              if value is not None]
    if unused and args.kind != "calendar":
        print(f"note: {' and '.join(unused)} only {'shape' if len(unused) > 1 else 'shapes'} a "
              f"calendar; ignored for `new {args.kind}`", file=sys.stderr)
    if args.photos:
        from floatpage.starters.pictures import left_out_photos

        for photo, why in left_out_photos(Path(args.photos)):
            print(f"note: {printable(str(photo))} was left out: {why}", file=sys.stderr)
    items = sum(len(page.items) for page in project.pages)
    print(f"created {printable(str(project.path))}: {len(project.pages)} page(s), {items} item(s)")
    print(f"next: floatpage edit {typed_path(project.path)}")
    if args.kind == "album" and not args.photos:
        print("it holds the bundled sample photos; for your own, start again with "
              f"`floatpage new album {args.path} --photos DIR`")
    return EXIT_OK


def cmd_edit(args: argparse.Namespace) -> int:
    from floatpage.model import load_project
    from floatpage.model.project_lock import ProjectLock

    # Fail here, with a clear message, before the screen is taken over; hold the project's lock
    # for the whole session, so a `settle` meanwhile refuses rather than being overwritten.
    with ProjectLock(args.path, wait_s=0.0, purpose="floatpage edit"):
        load_project(args.path, allow_outside_files=args.allow_outside_files,
                     missing_pictures_ok=True)
        refuse_without_terminal(args.path)
        refuse_without_utf8(args.path)
        from floatpage.tui.app import make_app
        from floatpage.tui.recovery import discard_recovery, pending_recovery

        recovered = ask_about_recovery(Path(args.path), pending_recovery(args.path))
        make_app(Path(args.path), seed=args.seed, allow_outside_files=args.allow_outside_files,
                 recovered=recovered).run()
        if recovered:
            discard_recovery(args.path)  # saved, or left unsaved at the quit question
    return EXIT_OK


def refuse_without_terminal(path: str) -> None:
    """The editor draws on a terminal and reads keys from one: run from a script, a pipe or
    cron, it wrote screen codes into the output and ended "floatpage: interrupted" (exit 130),
    which read as though someone had pressed Ctrl+C."""
    missing = [name for name, stream in (("input", sys.stdin), ("output", sys.stdout))
               if stream is None or not stream.isatty()]
    if missing:
        raise FloatpageError(
            f"{printable(str(path))}: floatpage edit needs a terminal, and its {' and '.join(missing)} "
            f"{'is' if len(missing) == 1 else 'are'} not one; run it in a terminal (over SSH: "
            "ssh -t), or use `floatpage settle`, `check` or `render` in scripts")


def refuse_without_utf8(path: str) -> None:
    """The preview is drawn in Unicode half blocks, and the editor's lines hold "·" and "…":
    under a locale (or PYTHONIOENCODING) that is not UTF-8, such as ISO-8859-1, each block
    went out as the six characters `\\u2580`, and the page was a screen of them, its rows
    pushed past the edge. A C or POSIX locale is no such case: Python writes UTF-8 there."""
    import codecs

    for stream in (sys.stdout, sys.__stderr__):  # Textual draws on stderr
        encoding = getattr(stream, "encoding", None) or "ascii"
        if codecs.lookup(encoding).name != "utf-8":
            raise FloatpageError(
                f"{printable(str(path))}: floatpage edit draws the page in Unicode and needs a "
                f"UTF-8 terminal, and this one's encoding is {encoding} (from LC_ALL, LC_CTYPE, "
                "LANG or PYTHONIOENCODING); set a UTF-8 locale, e.g. `LANG=C.UTF-8 floatpage "
                "edit ...`, in a terminal set to UTF-8")


def ask_about_recovery(project: Path, recovery: Path | None) -> bool:
    """Offer the edits a lost terminal left behind; True to open them. Discarding deletes them."""
    if recovery is None:
        return False
    from datetime import datetime

    from floatpage.tui.recovery import discard_recovery

    kept_at = recovery.stat().st_mtime
    when = datetime.fromtimestamp(kept_at).strftime("%Y-%m-%d %H:%M")
    print(f"{printable(str(project))} has unsaved edits from an editor that lost its terminal at {when} "
          f"(kept in {printable(recovery.name)}).")
    try:
        changed_at = project.stat().st_mtime
    except OSError:
        changed_at = kept_at
    from floatpage.tui.recovery import recovery_base
    from floatpage.tui.session import file_digest

    base = recovery_base(project)
    if changed_at <= kept_at and base is not None and base != file_digest(project):
        # changed by another program while the editor had it open, before it lost its
        # terminal: the dates cannot tell, the digest the recovery file keeps can
        when_changed = datetime.fromtimestamp(changed_at).strftime("%Y-%m-%d %H:%M")
        print(f"The project itself was changed by another program at {when_changed}, while "
              "the editor had it open: restored, these edits replace that version when you "
              f"save (Ctrl+S asks first; it is kept as {printable(project.name)}.bak); "
              "discard them to keep it.")
    elif changed_at > kept_at:
        # A project saved again since (another editor session, a settle, a `git pull`): the
        # kept edits were made to the file before that, and restoring them then saving
        # replaced the newer file without a word.
        later = datetime.fromtimestamp(changed_at).strftime("%Y-%m-%d %H:%M")
        print(f"The project itself was changed after that, at {later}: restored, these edits "
              "replace that version when you save (it is kept as "
              f"{printable(project.name)}.bak); discard them to keep it.")
    while True:
        try:
            answer = ask_letter("[r]estore them, [d]iscard them, or [q]uit and decide later? ")
        except EOFError:
            answer = "q"
        if answer in ("r", "restore"):
            return True
        if answer in ("d", "discard"):
            discard_recovery(project)
            return False
        if answer in ("q", "quit"):
            raise FloatpageError(f"{project}: not opened; the unsaved edits stay in {recovery}")


def note_kept_edits(path: str) -> None:
    """A note (on stderr: a Makefile's output stays as it was) that an editor which lost its
    terminal left unsaved edits beside the project: after a dropped SSH link, `make` checked,
    settled and rendered the file without them, and nothing said they were there."""
    from floatpage.tui.recovery import pending_recovery

    try:
        kept = pending_recovery(path)
    except OSError:
        return
    if kept is not None:
        print(f"note: {printable(str(path))}: {printable(kept.name)} holds unsaved edits from "
              "an editor that lost its terminal, not in the project file this command reads; "
              f"`floatpage edit {typed_path(path)}` offers to restore or discard them",
              file=sys.stderr)


def ask_letter(prompt: str) -> str:
    """One answer to a `[r]estore`-style question: on a terminal, the first key pressed, as
    the prompt's brackets promise (a user pressed r and waited: it wanted Enter too); else a
    line, as from a pipe."""
    if not sys.stdin.isatty():
        return input(prompt).strip().lower()
    import termios
    import tty

    fd = sys.stdin.fileno()
    saved = termios.tcgetattr(fd)
    try:
        tty.setcbreak(fd)  # before the prompt shows: a key typed in line mode waits for Enter
        print(prompt, end="", flush=True)
        key = os.read(fd, 1).decode(errors="replace")
        termios.tcflush(fd, termios.TCIFLUSH)  # an Enter after it is not the editor's first key
    finally:
        termios.tcsetattr(fd, termios.TCSADRAIN, saved)
    if not key or key == "\x04":  # end of input, or Ctrl+D
        print()
        raise EOFError
    print(key if key.isprintable() else "")
    return key.strip().lower()


def cmd_settle(args: argparse.Namespace) -> int:
    from floatpage.model import load_project
    from floatpage.model.position_patch import Positions, save_settled
    from floatpage.model.project_lock import ProjectLock

    if args.dry_run:
        project = load_project(args.path, allow_outside_files=args.allow_outside_files)
        read = Positions.of(project)
        settle_and_report(project, args)
        print(would_move(read, Positions.of(project), args.path))
        return EXIT_OK
    with ProjectLock(args.path, purpose="floatpage settle"):
        conflicted = mend_position_conflicts(Path(args.path))
        project = load_project(args.path, allow_outside_files=args.allow_outside_files)
        read = Positions.of(project)
        settle_and_report(project, args)
        before = file_identity(project.path)
        save_settled(project, read)
        written = file_identity(project.path) != before or conflicted is not None
        if conflicted is not None:
            keep_conflicted_as_backup(Path(args.path), conflicted)
    # A settled file is left as it is (its mtime too, so make sees nothing new): say so
    # rather than claim a write that never happened.
    if written:
        print(f"wrote positions to {printable(str(project.path))}")
    else:
        print(f"{printable(str(project.path))}: already settled, nothing to write")
    return EXIT_OK


def mend_position_conflicts(path: Path) -> bytes | None:
    """Where a merge left conflicts in item positions only, keep the first side of each
    (`model.merge_conflicts.mend_positions`) and say so; the file with its conflicts is
    returned, to be kept as NAME.bak once the settle is saved (the settle's own save would
    keep the file between the two)."""
    from floatpage.model.merge_conflicts import mend_positions

    mended = mend_positions(path)
    if mended is None:
        return None
    conflicted, count = mended
    print(f"note: {printable(str(path))}: {count} merge conflict{'s' if count != 1 else ''} in "
          "item positions only: kept the first side of each, and the settle lays the pages "
          f"out again (the file with the conflicts is kept as {printable(path.name)}.bak); "
          f"`git add {typed_path(str(path))}` then finishes the merge", file=sys.stderr)
    return conflicted


def keep_conflicted_as_backup(path: Path, conflicted: bytes) -> None:
    from floatpage.model.atomic_file import atomic_write

    atomic_write(path.with_name(path.name + ".bak"), conflicted, backup=False)


def would_move(read, settled, path: str) -> str:
    """What `settle --dry-run` would have written: it only said how many steps it ran, so
    a user could not tell a settled file from one a settle would rewrite."""
    from floatpage.model.save import mm, same

    moved = []  # as the save tells a moved number (model.position_patch.patched_text)
    for page_before, page_after in zip(read.pages, settled.pages):
        for (item_id, x0, y0), (_, x1, y1) in zip(page_before, page_after):
            if not (same(x0, mm(x1)) and same(y0, mm(y1))):
                moved.append((max(abs(mm(x1) - x0), abs(mm(y1) - y0)), item_id))
    if not moved:
        return f"{printable(path)}: already settled; settle would change nothing (--dry-run)"
    farthest, item_id = max(moved)
    return (f"{printable(path)}: settle would move {len(moved)} item(s), "
            f'"{printable(item_id)}" the farthest, {farthest:.2f} mm; nothing written '
            "(--dry-run)")


def file_identity(path) -> tuple[int, int, int] | None:
    """What changes when a file is written: the atomic rename's new inode, or (a hard-linked
    project saved in place) its modification time and size."""
    try:
        status = os.stat(path)
    except OSError:
        return None
    return status.st_ino, status.st_mtime_ns, status.st_size


def settle_and_report(project, args: argparse.Namespace) -> int:
    from floatpage.model.layout import settle_project

    with progress_line(args.quiet) as show:
        show(f"settling {len(project.pages)} page(s)…")
        started = time.perf_counter()
        reports = settle_project(project, jobs=jobs_of(args))
        elapsed = time.perf_counter() - started
    for page, report in zip(project.pages, reports):
        state = "settled" if report.settled else "NOT settled (stopped at the step limit)"
        print(f"page {page.id}: {state} after {report.steps} steps, final energy {report.energy:.3g}")
        left = problems_left(page, project.physics) if report.fixed_point else ""
        if left:
            print(f"  still {left}: another settle changes nothing; "
                  f"`floatpage check {typed_path(args.path)}` says why and what to do")
    steps = sum(report.steps for report in reports)
    print(f"{steps} steps in {elapsed:.2f} s")
    return EXIT_OK


def typed_path(path) -> str:
    """``path`` as it is typed into a shell, for the commands the messages suggest: "next:
    floatpage edit Geburtstag Oma.toml", copied, ran `edit` on two files (user-walk-9)."""
    import shlex

    return printable(shlex.quote(str(path)))


def problems_left(page, physics) -> str:
    """The problems `check` counts that a settled page still has, in words ("3 items off
    the page"), or "". A page too small for its items (a card's size typed down to A6 by
    hand) settled with items off it; settle said only "settled", then "already settled,
    nothing to write", while `check` sent the user back to `settle` (user-walk-9)."""
    from floatpage.model.layout import engine_for_page

    quality = engine_for_page(page, physics).quality()
    counts = ((quality.overlap_count, "overlap"), (len(quality.off_page), "off the page"),
              (len(quality.in_margin), "in the print-safe margin"),
              (len(quality.outside_region), "outside its region"))
    words = [f"{count} overlap{'s' if count > 1 else ''}" if what == "overlap"
             else f"{count} item{'s' if count > 1 else ''} {what}"
             for count, what in counts if count]
    return ", ".join(words)


def cmd_render(args: argparse.Namespace) -> int:
    from floatpage.model import load_project
    from floatpage.model.layout import settle_project
    from floatpage.typeset import render_pdf
    from floatpage.typeset.render import check_pdf_output

    for option, name in (("-o", args.output), ("--tex", args.tex), ("--fragment", args.fragment)):
        refuse_no_file_name(option, name, Path(args.path).stem)
        refuse_folder_name(option, name, Path(args.path).stem)
    out = Path(args.output) if args.output else Path(args.path).with_suffix(".pdf")
    refuse_other_format(out, args.path)
    for option, name in (("--tex", args.tex), ("--fragment", args.fragment)):
        refuse_not_tex(option, name, args.path)
    project = load_project(args.path, allow_outside_files=args.allow_outside_files)
    check_pdf_output(project, out, args.tex, args.fragment)  # before a settle of seconds
    with progress_line(args.quiet) as show:
        if not args.no_settle:
            show("settling the layout…")
            settle_project(project, jobs=jobs_of(args))
        report = render_pdf(project, out, tex_out=Path(args.tex) if args.tex else None,
                            fragment_out=Path(args.fragment) if args.fragment else None,
                            progress=show,
                            print_bleed_mm=(3.0 if args.bleed is None else args.bleed)
                            if args.print else None)
    for warning in report.warnings + unsettled_warnings(project, args.path,
                                                        settled=not args.no_settle):
        print(f"warning: {printable(warning)}", file=sys.stderr)
    from floatpage.model.page_report import empty_page_notes
    from floatpage.typeset.render import resolution_notes

    for note in empty_page_notes(project) + resolution_notes(project) + report.notes:
        print(f"note: {printable(note)}", file=sys.stderr)
    print(f"wrote {printable(str(report.pdf))} ({report.pages} page(s), {report.seconds:.2f} s)")
    return EXIT_OK


def unsettled_warnings(project, path: str, *, settled: bool = False) -> list[str]:
    """What `render --no-settle` printed that a settle may have mended: overlapping items and
    items past the page's edge went into the PDF without a word.  Check, not settle, is named:
    on a page too full for its items no settle mends them, and check says so.  ``settled``:
    what the settle before the PDF left (a card's size typed down to A6 printed its greeting
    past the page and its inside's words cut at the edge, and render said only "wrote
    card.pdf", user-walk-10)."""
    from floatpage.model.layout import engine_for_page

    warnings = []
    for page in project.pages:
        quality = engine_for_page(page, project.physics).quality()
        if not (quality.overlap_count or quality.off_page):
            continue
        ids = page.items
        found = [f"{quality.overlap_count} overlap(s)" if quality.overlap_count else "",
                 f"{len(quality.off_page)} item(s) past its edge" if quality.off_page else ""]
        named = [f'"{printable(ids[a].id)}" and "{printable(ids[b].id)}"'
                 for a, b in quality.overlapping_pairs[:3]]
        named += [f'"{printable(ids[k].id)}"' for k in quality.off_page[:3]]
        more = ", …" if quality.overlap_count + len(quality.off_page) > len(named) else ""
        warnings.append(f'page "{printable(page.id)}" was printed '
                        + ("" if settled else "as saved (--no-settle) ") + "with "
                        f"{' and '.join(part for part in found if part)} "
                        f"({', '.join(named)}{more})"
                        + (", which a settle leaves there" if settled else "")
                        + f"; `floatpage check {typed_path(path)}` says why and what to do"
                        + (" (most often the page is too full: make items smaller, choose a "
                           "larger page size, or move some to another page)" if settled
                           else " (most often: settle first)"))
    return warnings


# Output names that promise another format: `render -o card.png` wrote a PDF called card.png.
# (A .toml is refused by refuse_toml_output; the project itself is left to render's own check,
# which says that it is an input.)
NOT_PDF = {".png": "pdftoppm -png", ".jpg": "pdftoppm -jpeg", ".jpeg": "pdftoppm -jpeg",
           ".svg": "pdftocairo -svg", ".tex": "--tex", ".eps": "pdftops -eps"}


# --tex and --fragment names that promise something else: `--tex card.pdf` wrote LaTeX
# source into a file named as a PDF (the options swapped), and a .toml one into the project's
# own kind (render's own check refuses the project itself).
NOT_TEX = {".pdf", ".png", ".jpg", ".jpeg", ".svg", ".eps", ".toml"}


def refuse_toml_output(out: Path, project: str) -> None:
    """`render card.toml -o other.toml` replaced another project with the PDF: a .toml name
    is a project's, never a PDF's."""
    if os.path.exists(out) and os.path.exists(project) and os.path.samefile(out, project):
        return
    what = ("it is a project file, which the PDF would replace" if os.path.exists(out)
            else "a .toml name is a project's")
    raise FloatpageError(f"{out}: will not write the PDF there, because {what}; name the "
                         f"output .pdf (e.g. -o {out.with_suffix('.pdf')})")


def refuse_not_tex(option: str, name: str | None, project: str) -> None:
    """Refuse LaTeX source named as another format (`--tex card.pdf`: the options swapped).
    The project itself is left to render's own check, which says that it is an input."""
    if not name or Path(name).suffix.lower() not in NOT_TEX:
        return
    if os.path.exists(name) and os.path.samefile(name, project):
        return
    raise FloatpageError(f"{name}: {option} writes LaTeX source; name it .tex (the PDF goes "
                         "to -o)")


PROJECT_PATH_HELP = "the project's .toml file"


def refuse_no_file_name(option: str, name: str | None, stem: str) -> None:
    """`-o -` wrote a file called `-` (a user of Unix tools meant standard output), and
    `-o ""` (a Makefile's variable left empty) wrote NAME.pdf beside the project without a
    word, where the Makefile then looked for its target in vain."""
    example = stem + (".pdf" if option == "-o" else ".tex")
    if name == "-":
        raise FloatpageError(f"{option} -: render writes files, not to standard output; name "
                             f"the file, e.g. {option} {example} (and `cat {example}` into a "
                             f"pipe)")
    if name is not None and not name.strip():
        raise FloatpageError(f"{option} {name!r} names no file (an empty variable in a "
                             f"Makefile?); name the file, e.g. {option} {example}"
                             + (", or leave -o out for the project's name with .pdf"
                                if option == "-o" else ""))


def refuse_folder_name(option: str, name: str | None, stem: str) -> None:
    """`-o .` ended in "internal error" and `-o out/` wrote a PDF called `out`: a name that
    can only be a folder is refused, with the file name to give instead."""
    if not name:
        return
    base = os.path.basename(name)
    if base in ("", ".", "..") or name.endswith(os.sep + ".") or name == os.sep:
        example = os.path.join(name, stem + (".pdf" if option == "-o" else ".tex"))
        raise FloatpageError(f"{name}: names a folder, and {option} writes one file; name the "
                             f"file, e.g. {example}")


def refuse_other_format(out: Path, project: str) -> None:
    suffix = out.suffix.lower()
    if suffix == ".toml":
        refuse_toml_output(out, project)
    if suffix not in NOT_PDF:
        return
    how = NOT_PDF[suffix]
    tip = (f"; for the .tex as well, add --tex {out.name}" if how == "--tex" else
           f"; for a {suffix[1:].upper()}, convert the PDF with `{how}`")
    raise FloatpageError(f"{out}: render writes a PDF; name it .pdf{tip}")


def cmd_check(args: argparse.Namespace) -> int:
    """Check each project named, all of them whatever one says: a pre-commit hook, or a
    Makefile's `floatpage check --strict $^`, passes every project file at once, and was
    refused with "unrecognized arguments", exit 2 (user-walk-13). A file that cannot be read
    is told as a single one is, and the others are still checked; the exit code is the
    worst of them."""
    if len(args.path) == 1:
        return check_one(args.path[0], args)
    status = EXIT_OK
    for number, path in enumerate(args.path):
        if number and not args.quiet:
            print()
        try:
            status = max(status, check_one(path, args, among_others=True))
        except FloatpageError as error:
            lines = [printable(line) for line in str(error).split("\n")]
            sys.stdout.flush()
            print("floatpage: " + "\n".join(lines), file=sys.stderr)
            status = max(status, EXIT_USER_ERROR)
    return status


def check_one(path: str, args: argparse.Namespace, *, among_others: bool = False) -> int:
    """`floatpage check` of one project: its report on stdout, 1 for a problem with the
    file, or with the layout under --strict. ``among_others``: under -q, the file's first
    line comes before anything else said of it, so each page's line has its file."""
    from floatpage.model import load_project

    project = load_project(path, allow_outside_files=args.allow_outside_files)
    from floatpage.model.page_report import (
        MAKE_ROOM, empty_page_notes, page_report, settle_may_help, settle_mends, tiny_items,
        what_settle_fixes,
    )
    from floatpage.model.layout import engine_for_page

    # -q (user-walk-12b: `check --strict -q` in a Makefile was exit 2, as the other commands
    # take -q): the figures of pages without problems and the notes are left out
    first_line = f"{printable(path)}: valid project, {len(project.pages)} page(s)"
    # under -q among other projects, the file's line waits for the first thing told of it
    waiting = [first_line] if args.quiet and among_others else []

    def tell(text: str) -> None:
        if waiting:
            print(waiting.pop())
        print(text)

    say = (lambda text: None) if args.quiet else tell
    say(first_line)
    issues = 0
    settle_lines: list[str] = []  # the lines that send the user to `settle`
    stuck: list[str] = []  # pages with problems no settle mends
    for page in project.pages:
        lines, problems = page_report(page, engine_for_page(page, project.physics),
                                      project.physics.gutter_mm)
        if settle_may_help(lines):
            with progress_line(args.quiet or not sys.stdout.isatty()) as show:
                show(f"page {printable(page.id)}: trying whether a settle mends it…")
                mends = settle_mends(page, project.physics, problems)
            if not mends:
                lines, problems = page_report(page, engine_for_page(page, project.physics),
                                              project.physics.gutter_mm, stuck=True)
        (tell if problems else say)("\n".join(lines))
        issues += problems
        if settle_may_help(lines):
            settle_lines += lines
        elif problems:
            stuck.append(page.id)
    from floatpage.typeset import text_fit_warnings
    from floatpage.typeset.render import (
        document_fits, faint_text_notes, picture_warnings, resolution_notes,
    )

    tiny = [warning for page in project.pages for warning in tiny_items(page)]
    fits = document_fits(project)  # each text fitted once, for the warnings and the notes
    for warning in tiny + text_fit_warnings(project, fits) + picture_warnings(project):
        tell(f"warning: {printable(warning)}")
        issues += 1
    # notes, not problems: --strict still passes
    for note in empty_page_notes(project) + resolution_notes(project) \
            + faint_text_notes(project, fits):
        say(f"note: {printable(note)}")
    for where, picture in pictures_outside(project):
        say(f"note: {where} uses {printable(picture)}, outside the project folder (allowed)")
    if issues and args.strict:
        tell(f"{printable(path)}: {issues} layout problem(s); " + "; ".join(
            ([f"run `floatpage settle {typed_path(path)}` to fix "
              f"{what_settle_fixes(settle_lines)}"] if settle_lines else [])
            + ([("no settle fixes them" if not settle_lines else "no settle fixes those on "
                 + ", ".join(f"page {printable(page_id)}" for page_id in stuck))
                + f": see the reasons above, or {MAKE_ROOM}"] if stuck else [])))
        return EXIT_USER_ERROR
    return EXIT_OK


def bleed_length(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of millimetres") from None
    if not 0.0 <= value <= 20.0:
        raise argparse.ArgumentTypeError("give a bleed between 0 and 20 mm (print shops ask 3)")
    return value


def seed_number(text: str) -> int:
    """``edit --seed``: a whole number the physics takes (its own range, physics.params); -1
    or 10**23 got as far as the editor and ended in "internal error", exit 70."""
    from floatpage.physics.params import out_of_range

    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    problem = out_of_range("seed", value)
    if problem:
        raise argparse.ArgumentTypeError(f"the seed {problem} (it is {value})")
    return value


def allow_outside_option(command: argparse.ArgumentParser) -> None:
    command.add_argument("--allow-outside-files", action="store_true",
                         help="let pictures lie outside the project's folder (as "
                              "`[files] allow_outside = true` does)")


def pictures_outside(project) -> list[tuple[str, str]]:
    """(where, path) of each picture outside the project's folder; only an allowing project has any."""
    from floatpage.model.picture_files import is_outside

    found = []
    for page in project.pages:
        named = [(f'item "{item.id}"', item.path) for item in page.items if item.kind == "picture"]
        if page.background is not None and page.background.picture:
            named.append((f'page "{page.id}" background', page.background.picture))
        found += [(where, path) for where, path in named
                  if is_outside(project.base_dir / path, project.base_dir)]
    return found


def jobs_option(command: argparse.ArgumentParser) -> None:
    command.add_argument("-j", "--jobs", type=job_count, default=None, metavar="N",
                         help="settle pages in N processes (default: one per core this "
                              "process may use; the result is the same for any N)")


def job_count(text: str) -> int:
    try:
        count = int(text)
    except ValueError:
        count = 0
    if count < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of processes (1 or more)")
    return count


def jobs_of(args: argparse.Namespace) -> int:
    from floatpage.model.page_pool import available_cores

    return args.jobs if args.jobs is not None else available_cores()


class ShowVersion(argparse.Action):
    """`--version`: the installed package's version, looked up only when asked (reading the
    package metadata costs every other command its start-up time)."""

    def __init__(self, option_strings, dest, help=None):
        super().__init__(option_strings, dest, nargs=0, default=argparse.SUPPRESS, help=help)

    def __call__(self, parser, namespace, values, option_string=None):
        from importlib.metadata import PackageNotFoundError, version

        try:
            found = version("floatpage")
        except PackageNotFoundError:  # run from a checkout that was never installed
            found = "(not installed)"
        print(f"floatpage {found}")
        parser.exit()


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="floatpage",
        description="Free-form pages whose items arrange themselves by physics, typeset by LaTeX.",
    )
    parser.add_argument("--version", action=ShowVersion,
                        help="show the installed version (for a bug report) and exit")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    new = commands.add_parser("new", help="start a project from a starter",
                              description="Create a new project file from a starter.")
    new.add_argument("kind", choices=STARTER_KINDS, help="what to start")
    new.add_argument("path", help="the .toml file to create (refuses to overwrite)")
    new.add_argument("--year", type=int, help="calendar year (default: next year)")
    new.add_argument("--photos", metavar="DIR", help="use the pictures in DIR")
    new.add_argument("--first-weekday", choices=WEEKDAYS, help="calendar: the first day of "
                     "each week (default: monday)")
    new.add_argument("--lang", default="en", choices=CALENDAR_LANGUAGES,
                     help="language of month and day names")
    new.add_argument("--orientation", choices=("portrait", "landscape"), default="portrait",
                     help="page orientation (default: portrait)")
    jobs_option(new)
    new.set_defaults(run=cmd_new)

    edit = commands.add_parser("edit", help="open the editor", description="Open the terminal editor.")
    edit.add_argument("path", help=PROJECT_PATH_HELP)
    edit.add_argument("--seed", type=seed_number, default=None,
                      help="seed the physics jitter for this session (default: the project's seed)")
    allow_outside_option(edit)
    edit.set_defaults(run=cmd_edit)

    settle = commands.add_parser("settle", help="run the physics until the layout settles",
                                 description="Run the physics headless until every page settles, "
                                             "then write the positions back.")
    settle.add_argument("path", help=PROJECT_PATH_HELP)
    settle.add_argument("--dry-run", action="store_true", help="report what settle would change; write nothing")
    settle.add_argument("-q", "--quiet", action="store_true", help="no progress output")
    jobs_option(settle)
    allow_outside_option(settle)
    settle.set_defaults(run=cmd_settle)

    render = commands.add_parser("render", help="typeset the project to PDF",
                                 description="Settle the layout and typeset it to PDF with LaTeX.")
    render.add_argument("path", help=PROJECT_PATH_HELP)
    render.add_argument("-o", "--output", metavar="OUT.pdf", help="default: the project's name with .pdf")
    render.add_argument("--tex", metavar="OUT.tex", help="also keep the standalone .tex")
    render.add_argument("--fragment", metavar="OUT.tex", help="also write a TikZ-only fragment for \\input")
    render.add_argument("--no-settle", action="store_true", help="render the positions as saved")
    render.add_argument("--print", action="store_true",
                        help="for a print shop: bleed, crop marks, TrimBox and BleedBox")
    render.add_argument("--bleed", type=bleed_length, default=None, metavar="MM",
                        help="bleed for --print, in mm (default 3)")
    render.add_argument("-q", "--quiet", action="store_true", help="no progress output")
    jobs_option(render)
    allow_outside_option(render)
    render.set_defaults(run=cmd_render, command_parser=render)

    check = commands.add_parser("check", help="validate and report layout quality",
                                description="Validate a project file and report overlaps, items off "
                                            "the page and text that would not fit.")
    check.add_argument("path", nargs="+",
                       help="the project's .toml file; name several to check each (a pre-commit "
                            "hook, `$^` in a Makefile): the exit code is the worst of them")
    check.add_argument("--strict", action="store_true", help="exit 1 when the layout has problems")
    check.add_argument("-q", "--quiet", action="store_true",
                       help="print only what needs attention: the pages with problems and the "
                            "warnings (nothing for a project without any)")
    allow_outside_option(check)
    check.set_defaults(run=cmd_check)

    from floatpage.cli.merge_command import add_merge_parser

    add_merge_parser(commands, allow_outside_option)
    return parser


class Stopped(KeyboardInterrupt):
    """SIGTERM or SIGHUP, unwinding as Ctrl+C does; ``signum`` gives the exit status."""

    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum


def stop_on_terminate(signum, frame) -> None:
    """SIGTERM (kill, CI's timeout) and SIGHUP (a closed terminal or SSH link) unwind like
    Ctrl+C, so temporary files and build folders are removed on the way out. The exit status
    is the shells' 128 + the signal's number (143, 129), as the editor's is: a job runner
    that reads it (a CI log, `wait` in a script) can tell a kill from a Ctrl+C (130). The
    editor installs its own handlers, which keep unsaved edits."""
    raise Stopped(signum)


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    if getattr(args, "bleed", None) is not None and not args.print:
        # --bleed alone made a plain PDF, no bleed at all: a file meant for the print shop
        # went out without it, and nothing said so.
        args.command_parser.error("argument --bleed: only shapes a --print sheet; add --print "
                                  "(crop marks, TrimBox and BleedBox), or leave --bleed out")
    import signal

    for stop in (signal.SIGTERM, signal.SIGHUP):
        if signal.getsignal(stop) is signal.SIG_DFL:
            signal.signal(stop, stop_on_terminate)
    try:
        os.getcwd()
    except FileNotFoundError:
        # The shell's folder was deleted (or moved) under it: every relative path, the lock
        # beside the project among them, would fail as an internal error.
        print("floatpage: the current folder no longer exists (it was deleted or moved while "
              "this shell was in it); cd to a folder that exists and run the command again",
              file=sys.stderr)
        return EXIT_USER_ERROR
    try:
        if args.run in (cmd_check, cmd_settle, cmd_render):
            for path in args.path if isinstance(args.path, list) else [args.path]:
                note_kept_edits(path)
        return args.run(args)
    except FloatpageError as error:
        # Line by line: a message may list several problems, each on its own line, and each
        # line is escaped so that nothing from a project file can start a line of its own.
        lines = [printable(line) for line in str(error).split("\n")]
        print("floatpage: " + "\n".join(lines), file=sys.stderr)
        return EXIT_USER_ERROR
    except KeyboardInterrupt as stop:
        from floatpage.cli.entry import interrupted_status

        print("floatpage: interrupted", file=sys.stderr)
        return interrupted_status(stop)
    except BrokenPipeError:
        return EXIT_OK
    except Exception as error:  # a bug of ours: keep the details, show a short message
        from floatpage.cli.entry import interrupted, interrupted_status

        stop = interrupted(error)
        if stop is not None:  # a Ctrl+C that Python wrapped (see entry.interrupted)
            print("floatpage: interrupted", file=sys.stderr)
            return interrupted_status(stop)
        log = write_crash_log()
        print(f"floatpage: internal error: {type(error).__name__}: {printable(str(error))}\n"
              f"  this is a bug in floatpage, not in your project; details are in {log}\n"
              "  please report it with that file and the project",
              file=sys.stderr)
        return EXIT_INTERNAL_ERROR


def write_crash_log() -> Path:
    import tempfile
    import traceback

    handle = tempfile.NamedTemporaryFile("w", prefix="floatpage-crash-", suffix=".log", delete=False)
    with handle:
        traceback.print_exc(file=handle)
    return Path(handle.name)


if __name__ == "__main__":
    sys.exit(main())
