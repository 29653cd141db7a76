"""`floatpage merge` end to end: real LuaLaTeX, real PDFs read back, a real process pool."""

from __future__ import annotations

import csv
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pdfplumber
import pikepdf

from floatpage.model import load_project
from merge_helpers import COLUMNS, rows, session_members, write_csv

FLOATPAGE = str(Path(sys.executable).with_name("floatpage"))


def merge(folder: Path, data: Path, out: str = "out", *extra: str,
          env: dict[str, str] | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([FLOATPAGE, "merge", str(folder / "offer.toml"), str(data), "-o",
                           str(folder / out), "--name", "{id}-{surname}", *extra],
                          capture_output=True, text=True, timeout=600,
                          env=None if env is None else {**os.environ, **env})


def report(folder: Path, out: str = "out") -> list[dict]:
    with (folder / out / "report.csv").open(encoding="utf-8") as handle:
        return list(csv.DictReader(handle))


def text_of(pdf: Path) -> str:
    with pdfplumber.open(pdf) as document:
        return "\n".join(page.extract_text() or "" for page in document.pages)


def test_each_record_gets_its_own_pdf_and_a_failing_record_is_isolated(merge_folder):
    good = rows(3)
    missing = ["2001", "Joe", "Doe", "Candle", "$5", "no-such-picture.png", "", "3 June"]
    too_long = ["2002", "Max", "Long", "word " * 3000, "$1", "pears.png", "", "3 June"]
    long_name = ["2003", "Ann " * 400, "Lee", "Tea", "$1", "pears.png", "", "3 June"]
    data = write_csv(merge_folder / "customers.csv", good + [missing, too_long, long_name])
    done = merge(merge_folder, data)
    assert done.returncode == 3, done.stderr
    assert "3 record(s) failed" in done.stderr
    rows_found = report(merge_folder)
    assert [row["status"] for row in rows_found] == ["made"] * 3 + ["failed"] * 3
    assert [row["line"] for row in rows_found] == ["2", "3", "4", "5", "6", "7"]
    assert "no-such-picture.png" in rows_found[3]["reason"] and "not found" in rows_found[3]["reason"]
    assert "item \"product\"" in rows_found[4]["reason"]
    assert "shorten the text" in rows_found[4]["reason"]
    # Each failure names the data column to fix, also where the item has another name.
    assert rows_found[3]["reason"].endswith('[data column "photo"]')
    assert rows_found[4]["reason"].endswith('[data column "product"]')
    assert 'item "greeting"' in rows_found[5]["reason"]
    assert rows_found[5]["reason"].endswith('[data column "first_name"]')
    made = sorted(p.name for p in (merge_folder / "out").glob("*.pdf"))
    assert made == ["1001-Silva.pdf", "1002-Müller.pdf", "1003-Okonkwo-Fitzgerald.pdf"]
    text = text_of(merge_folder / "out" / "1002-Müller.pdf")
    assert "Product number 1" in text and "Person1" in text and "€1.50" in text


def png_with_an_unknown_critical_chunk(whole: bytes) -> bytes:
    """The PNG with a chunk of a made-up critical kind after its header: Pillow reads and
    verifies it (it skips what it does not know), LuaTeX's libpng stops at it."""
    import struct
    import zlib

    chunk = b"QQQQ" + b"made up"
    return whole[:33] + struct.pack(">I", 7) + chunk + struct.pack(">I", zlib.crc32(chunk)) \
        + whole[33:]


def test_a_record_that_breaks_the_engine_run_fails_alone(merge_folder):
    """A picture that reads well to Pillow, header and pixels, passes the layout and fails in
    LuaLaTeX: the chunk's run is split until that record runs alone.  (A PNG cut short served
    here until render learnt to print what such a file has.)"""
    whole = (merge_folder / "pictures" / "pears.png").read_bytes()
    (merge_folder / "pictures" / "cut.png").write_bytes(png_with_an_unknown_critical_chunk(whole))
    records = rows(5)
    records[2][5] = "cut.png"
    data = write_csv(merge_folder / "customers.csv", records)
    done = merge(merge_folder, data, "out", "--chunk-size", "5", "--workers", "1")
    assert done.returncode == 3, done.stderr
    statuses = [(row["status"], row["reason"]) for row in report(merge_folder)]
    assert [status for status, _ in statuses] == ["made", "made", "failed", "made", "made"]
    assert statuses[2][1].startswith("LuaLaTeX could not typeset it: ")
    assert "readpng" in statuses[2][1] and "pictures/cut.png" in statuses[2][1]
    assert "full log" not in statuses[2][1]  # the build folder, and its log, are gone
    assert len(list((merge_folder / "out").glob("*.pdf"))) == 4


def test_the_pdfs_do_not_depend_on_chunk_size_or_workers(merge_folder):
    data = write_csv(merge_folder / "customers.csv", rows(5))
    assert merge(merge_folder, data, "one", "--chunk-size", "1", "--workers", "1").returncode == 0
    assert merge(merge_folder, data, "many", "--chunk-size", "3", "--workers", "2").returncode == 0
    one = {p.name: p.read_bytes() for p in (merge_folder / "one").glob("*.pdf")}
    many = {p.name: p.read_bytes() for p in (merge_folder / "many").glob("*.pdf")}
    assert len(one) == 5 and one == many


def test_records_that_share_lines_in_one_run_keep_the_bytes_they_get_alone(merge_folder):
    """Records setting the same lines in a face share its font subset in a run (also a face
    with a fallback font, here Arabic through HarfBuzz): each PDF must still hold only its
    own glyphs, so one engine run per record makes the same bytes as one run for all."""
    base = rows(1)[0]
    shared = [[str(3001 + n), first, "Haddad", product, "€2", "pears.png", note, "1 May"]
              for n, (first, product, note) in enumerate([
                  ("فاطمة", "Peonies", "Picked this morning."), ("فاطمة", "Peonies", ""),
                  ("Ana", "Peonies", "Picked this morning."), ("Ana", "Tulips", "")])]
    data = write_csv(merge_folder / "customers.csv", [base] + shared)
    alone = merge(merge_folder, data, "alone", "--chunk-size", "1", "--workers", "1")
    together = merge(merge_folder, data, "together", "--chunk-size", "5", "--workers", "1")
    assert alone.returncode == 0 and together.returncode == 0, alone.stderr + together.stderr
    first = {p.name: p.read_bytes() for p in (merge_folder / "alone").glob("*.pdf")}
    second = {p.name: p.read_bytes() for p in (merge_folder / "together").glob("*.pdf")}
    assert len(first) == 5 and first == second
    arabic = text_of(merge_folder / "together" / "3001-Haddad.pdf")
    assert "فاطمة" in arabic or "فاطمة"[::-1] in arabic  # pdfplumber reads it left to right


def test_a_second_run_skips_what_has_not_changed(merge_folder):
    data = write_csv(merge_folder / "customers.csv", rows(4))
    assert merge(merge_folder, data).returncode == 0
    again = merge(merge_folder, data)
    assert "0 made, 4 unchanged" in again.stdout
    assert [row["status"] for row in report(merge_folder)] == ["unchanged"] * 4
    changed = rows(4)
    changed[1][3] = "Another product"
    write_csv(data, changed)
    (merge_folder / "pictures" / "bread.png").write_bytes(
        (merge_folder / "pictures" / "pears.png").read_bytes())  # record 4 uses bread.png
    third = merge(merge_folder, data)
    assert [row["status"] for row in report(merge_folder)] == ["unchanged", "made", "unchanged",
                                                               "made"]
    assert "Another product" in text_of(merge_folder / "out" / "1002-Müller.pdf")
    assert "4 made" in merge(merge_folder, data, "out", "--force").stdout, third.stdout


def test_a_pdf_cut_short_is_made_again_and_a_killed_runs_temporaries_go(merge_folder):
    """A power cut can leave a PDF whose key was written but whose bytes never reached the
    disk: a resumed run keeps only PDFs that end whole. Temporaries a killed run left are
    removed when the next run starts."""
    data = write_csv(merge_folder / "customers.csv", rows(2))
    assert merge(merge_folder, data).returncode == 0
    out = merge_folder / "out"
    whole = (out / "1001-Silva.pdf").read_bytes()
    (out / "1001-Silva.pdf").write_bytes(whole[:len(whole) // 2])
    leftover = out / ".1002-Müller.pdf.999999.0badcafe.floatpage-tmp"
    leftover.write_bytes(b"half a PDF")
    os.utime(leftover, (time.time() - 3600, time.time() - 3600))
    again = merge(merge_folder, data)
    assert "1 made, 1 unchanged" in again.stdout, again.stdout + again.stderr
    assert (out / "1001-Silva.pdf").read_bytes() == whole
    assert not leftover.exists()


def test_an_output_hard_linked_elsewhere_is_replaced_not_written_through(merge_folder):
    data = write_csv(merge_folder / "customers.csv", rows(1))
    (merge_folder / "out").mkdir()
    precious = merge_folder / "precious.pdf"
    precious.write_bytes(b"%PDF-1.7 the user's own file")
    os.link(precious, merge_folder / "out" / "1001-Silva.pdf")
    assert merge(merge_folder, data).returncode == 0
    assert precious.read_bytes() == b"%PDF-1.7 the user's own file"
    assert (merge_folder / "out" / "1001-Silva.pdf").read_bytes().startswith(b"%PDF")


def test_columns_the_template_needs_are_checked_before_any_work(merge_folder):
    columns = [c for c in COLUMNS if c != "price"] + ["unused"]
    data = write_csv(merge_folder / "customers.csv", [["1"] * len(columns)], columns)
    done = merge(merge_folder, data)
    assert done.returncode == 1
    assert 'item "price" on page "offer" asks for "{price}"' in done.stderr
    assert "has no column 'price'" in done.stderr and "Traceback" not in done.stderr
    assert not (merge_folder / "out").exists()


def test_picture_paths_from_the_data_never_read_devices_pipes_or_outside(merge_folder):
    """A path column may name /dev/zero (reading it never ends), a pipe (opening it waits
    forever) or a file outside the template's folder: each record fails alone, at once, and
    nothing outside the folder is read, also when pictures are shipped to the workers."""
    template = merge_folder / "offer.toml"
    template.write_text(template.read_text(encoding="utf-8").replace(
        'path = "pictures/{photo}"', 'path = "{photo}"'), encoding="utf-8")
    os.mkfifo(merge_folder / "pipe.png")
    secret = merge_folder.parent / "secret.png"
    secret.write_bytes((merge_folder / "pictures" / "pears.png").read_bytes())
    paths = ["/dev/zero", "pipe.png", "../secret.png", "/etc/passwd", "pictures/pears.png"]
    records = rows(len(paths))
    for record, path in zip(records, paths):
        record[5] = path
    data = write_csv(merge_folder / "customers.csv", records)
    for out, extra in (("shared", []), ("ship", ["--pictures", "ship"])):
        done = merge(merge_folder, data, out, *extra)
        assert done.returncode == 3, done.stderr
        reasons = [row["reason"] for row in report(merge_folder, out)]
        assert "outside" in reasons[0] and "outside" in reasons[2] and "outside" in reasons[3]
        assert "not a regular file" in reasons[1] and reasons[4] == ""


def test_user_text_is_set_as_text_never_run_as_latex(merge_folder):
    hostile = ["7", r"\input{/etc/passwd}", "x", r"\directlua{os.exit(1)} $x$ 100% #1 ~ ^ _ &",
               "{price}", "pears.png", r"}\end{document}", "1 June"]
    data = write_csv(merge_folder / "customers.csv", [hostile])
    done = merge(merge_folder, data, "out", "--name", "{first_name}")
    assert done.returncode == 0, done.stderr
    (pdf,) = (merge_folder / "out").glob("*.pdf")
    text = " ".join(text_of(pdf).split())
    for value in (hostile[1], hostile[3], hostile[4], hostile[6]):
        assert value in text
    assert "/" not in pdf.name and pdf.name.endswith(".pdf")


def test_the_samples_empty_price_or_product_leaves_no_dangling_words(merge_folder):
    """A record with no price printed "only" and nothing after it, and one with no product an
    empty box where the product goes: the sample template dropped only an empty note
    (user-walk-2, a 50-row CSV with empty fields)."""
    records = rows(2)
    records[0][4] = ""   # price
    records[1][3] = " "  # product
    data = write_csv(merge_folder / "customers.csv", records)
    done = merge(merge_folder, data)
    assert done.returncode == 0, done.stderr
    no_price = " ".join(text_of(merge_folder / "out" / "1001-Silva.pdf").split())
    assert "Product number 0" in no_price and "only" not in no_price
    no_product = " ".join(text_of(merge_folder / "out" / "1002-Müller.pdf").split())
    assert "only €1.50" in no_product and "Product number" not in no_product


def test_an_empty_picture_column_is_named_as_empty_not_as_a_folder(merge_folder):
    """`path = "pictures/{photo}"` with an empty photo is "pictures/", and the record failed
    with 'picture "pictures/" is a folder' (user-walk-2, a CSV with empty fields)."""
    records = rows(1)
    records[0][5] = ""
    done = merge(merge_folder, write_csv(merge_folder / "customers.csv", records))
    assert done.returncode == 3, done.stderr
    [row] = report(merge_folder)
    assert "the picture's column is empty" in row["reason"], row["reason"]
    assert "folder" not in row["reason"] and "drop_if_empty" in row["reason"]


def test_names_are_made_safe_and_unique(merge_folder):
    data = write_csv(merge_folder / "customers.csv", rows(2))
    done = merge(merge_folder, data, "out", "--name", "../{valid_until}/x")
    assert done.returncode == 0, done.stderr
    assert sorted(p.name for p in (merge_folder / "out").glob("*.pdf")) == [
        "31 May-x-2.pdf", "31 May-x.pdf"]


def test_combined_pdf_and_record_projects_that_open(merge_folder):
    data = write_csv(merge_folder / "customers.csv", rows(3))
    done = merge(merge_folder, data, "out", "--combined", "--toml")
    assert done.returncode == 0, done.stderr
    with pikepdf.open(merge_folder / "out" / "combined.pdf") as combined:
        assert len(combined.pages) == 3
    project = load_project(merge_folder / "out" / "1002-Müller.toml")
    assert project.pages[0].item("product").text == "Product number 1"
    assert [item.id for item in project.pages[0].items if item.id == "note"] == ["note"]
    empty_note = load_project(merge_folder / "out" / "1001-Silva.toml")
    assert "note" not in empty_note.pages[0].item_ids()  # drop_if_empty
    check = subprocess.run([FLOATPAGE, "check", "--strict",
                            str(merge_folder / "out" / "1001-Silva.toml")],
                           capture_output=True, text=True)
    assert check.returncode == 0, check.stdout


def test_pictures_keep_their_proportions(merge_folder):
    data = write_csv(merge_folder / "customers.csv", rows(3))
    assert merge(merge_folder, data, "out", "--toml").returncode == 0
    for name, aspect in (("1001-Silva", 600 / 400), ("1002-Müller", 400 / 600),
                         ("1003-Okonkwo-Fitzgerald", 1.0)):
        photo = load_project(merge_folder / "out" / f"{name}.toml").pages[0].item("photo")
        assert abs(photo.w / photo.h - aspect) < 0.01
        assert photo.w * photo.h <= 90 * 60 * 1.01


def test_an_output_never_replaces_an_input(merge_folder):
    data = write_csv(merge_folder / "customers.csv", rows(1))
    done = subprocess.run([FLOATPAGE, "merge", str(merge_folder / "offer.toml"), str(data),
                           "-o", str(merge_folder), "--name", "offer", "--toml"],
                          capture_output=True, text=True)
    assert done.returncode == 3
    assert "is one of the merge's inputs" in report(merge_folder, ".")[0]["reason"]
    assert "{first_name}" in (merge_folder / "offer.toml").read_text(encoding="utf-8")


def test_json_lines_work_like_csv(merge_folder):
    import json

    lines = [dict(zip(COLUMNS, row)) for row in rows(2)]
    data = merge_folder / "customers.jsonl"
    data.write_text("".join(json.dumps(line) + "\n" for line in lines), encoding="utf-8")
    assert merge(merge_folder, data).returncode == 0
    assert len(list((merge_folder / "out").glob("*.pdf"))) == 2


def test_ctrl_c_leaves_no_partial_pdf(merge_folder):
    # enough records that a loaded machine cannot finish them all before the signal lands
    data = write_csv(merge_folder / "customers.csv", rows(80))
    out = merge_folder / "out"
    builds = merge_folder / "tmp"  # its own, so other runs' engines on this machine don't count
    builds.mkdir()
    # Ctrl+C as a terminal sends it: to a process that has not been told to ignore it (a
    # process started with SIGINT ignored, as by `nohup` or an earlier test, keeps ignoring it)
    process = subprocess.Popen([FLOATPAGE, "merge", str(merge_folder / "offer.toml"), str(data),
                                "-o", str(out), "--chunk-size", "2", "--workers", "2"],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               env={**os.environ, "TMPDIR": str(builds)},
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and len(list(out.glob("*.pdf"))) < 2:
        time.sleep(0.05)
    process.send_signal(signal.SIGINT)
    _, stderr = process.communicate(timeout=60)
    assert process.returncode == 130, stderr
    pdfs = list(out.glob("*.pdf"))
    assert 2 <= len(pdfs) < 80
    for pdf in pdfs:
        with pikepdf.open(pdf) as document:
            assert len(document.pages) == 1
    leftovers = [p.name for p in out.iterdir() if p.name.startswith(".") and
                 p.name != ".floatpage-merge"]
    assert leftovers == []
    assert (out / "report.csv").is_file()
    time.sleep(1.0)
    assert engines_in_build_folders(builds) == []


def test_a_merge_killed_outright_leaves_no_process_behind(merge_folder):
    """user-walk-12b: `kill -9` of a merge (a CI job's timeout) left its workers, the fork
    server and the resource tracker waiting for good, minutes later: the workers hold their
    own task queue's ends, so nothing told them the command was gone."""
    data = write_csv(merge_folder / "customers.csv", rows(80))
    out = merge_folder / "out"
    process = subprocess.Popen([FLOATPAGE, "merge", str(merge_folder / "offer.toml"), str(data),
                                "-o", str(out), "--chunk-size", "2", "--workers", "2"],
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                               start_new_session=True)
    try:
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline and len(list(out.glob("*.pdf"))) < 2:
            assert process.poll() is None
            time.sleep(0.05)
        assert len(session_members(process.pid)) >= 4  # command, tracker, server, workers
        process.kill()
        process.wait(timeout=10)
        deadline = time.monotonic() + 30
        while session_members(process.pid) and time.monotonic() < deadline:
            time.sleep(0.1)
        assert session_members(process.pid) == []
    finally:  # a failure leaves nothing running either
        for pid in session_members(process.pid):
            os.kill(pid, signal.SIGKILL)


def test_a_second_merge_into_the_same_folder_is_refused_while_the_first_runs(merge_folder):
    """user-walk-12b: two merges into one folder at once (`make -j2`, a CI job retried)
    shared `.floatpage-merge/report.partial`: the second typeset every record, then stopped
    at "report.csv: could not write it (No such file or directory)"."""
    first_data = write_csv(merge_folder / "first.csv", rows(40))
    second_data = write_csv(merge_folder / "second.csv", rows(3))
    out = merge_folder / "out"
    # one record per engine run: the first is still at work long after the second has asked
    first = subprocess.Popen([FLOATPAGE, "merge", str(merge_folder / "offer.toml"),
                              str(first_data), "-o", str(out), "--chunk-size", "1", "--workers",
                              "1", "-q"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True,
                             preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline and not list(out.glob("*.pdf")):
            assert first.poll() is None, first.communicate()
            time.sleep(0.05)
        second = merge(merge_folder, second_data)
        assert first.poll() is None, "the first merge ended before the second asked"
    finally:
        first.send_signal(signal.SIGINT)  # enough shown: the first need not finish its 40
        first.communicate(timeout=60)
    assert second.returncode == 1, second.stdout + second.stderr
    assert second.stderr.startswith(f"floatpage: {out}: another merge is writing there (PID "
                                    f"{first.pid} (floatpage merge)); wait for it to finish"), \
        second.stderr
    assert first.returncode == 130
    assert report(merge_folder)[0]["name"] == "record-00001"  # the first's own report


def test_pdfs_of_records_the_data_no_longer_names_are_told_and_pruned(merge_folder):
    """user-walk-12b: with --name "{id}-{surname}", a surname corrected in the data made
    `1001-Silva-Costa.pdf` and left `1001-Silva.pdf` beside it without a word: `lpr out/*.pdf`
    printed both. A run says so; --prune removes the files merge made for them, no other."""
    table = rows(3)
    data = write_csv(merge_folder / "customers.csv", table)
    assert merge(merge_folder, data).returncode == 0
    out = merge_folder / "out"
    (out / "cover.pdf").write_bytes(b"%PDF-1.4 the user's own")
    table[0][2] = "Silva-Costa"
    write_csv(data, table)
    again = merge(merge_folder, data)
    assert again.returncode == 0, again.stderr
    assert (f"note: {out} holds 1 PDF(s) an earlier run made for records this data no longer "
            f"names (1001-Silva.pdf); they are not in report.csv or combined.pdf") in again.stderr
    assert (out / "1001-Silva.pdf").is_file()
    pruned = merge(merge_folder, data, "out", "--prune")
    assert pruned.returncode == 0, pruned.stderr
    assert "removed 1 record(s) this data no longer names: 1001-Silva.pdf" in pruned.stdout
    assert sorted(p.name for p in out.glob("*.pdf")) == [
        "1001-Silva-Costa.pdf", "1002-Müller.pdf", "1003-Okonkwo-Fitzgerald.pdf", "cover.pdf"]
    assert not (out / ".floatpage-merge" / "1001-Silva.key").exists()
    assert "no longer names" not in merge(merge_folder, data).stderr


def test_a_name_changed_only_in_case_leaves_no_pdf_unnamed(merge_folder):
    """A surname corrected from "müller" to "Müller" made `1002-Müller.pdf` and left
    `1002-müller.pdf` beside it without a word: names are compared case-blind (for a disk that
    is), and this one is not. Made or failed, the old PDF is told, and --prune removes it."""
    table = rows(3)
    table[1][2] = "müller"
    data = write_csv(merge_folder / "customers.csv", table)
    assert merge(merge_folder, data).returncode == 0
    out = merge_folder / "out"
    table[1][2] = "Müller"
    write_csv(data, table)
    again = merge(merge_folder, data)
    assert again.returncode == 0, again.stderr
    assert (f"note: {out} holds 1 PDF(s) an earlier run made for records this data no longer "
            f"names (1002-müller.pdf)") in again.stderr
    table[1][5] = "no-such-picture.png"  # and failed: still told, never taken for this one's
    table[1][2] = "MÜLLER"
    write_csv(data, table)
    failed = merge(merge_folder, data)
    assert failed.returncode == 3, failed.stderr
    assert "(1002-Müller.pdf, 1002-müller.pdf)" in failed.stderr, failed.stderr
    pruned = merge(merge_folder, data, "out", "--prune")
    assert "1002-Müller.pdf, 1002-müller.pdf" in pruned.stdout, pruned.stdout
    assert sorted(p.name for p in out.glob("*.pdf")) == [
        "1001-Silva.pdf", "1003-Okonkwo-Fitzgerald.pdf"]


def test_a_record_renamed_for_a_name_another_had_is_told(merge_folder):
    """user-walk-12b: a customer number that repeats in the data (one customer exported
    twice) gave `1001-Silva.pdf` and `1001-Silva-2.pdf` without a word."""
    table = rows(3)
    table[2][0], table[2][2] = table[0][0], table[0][2]
    data = write_csv(merge_folder / "customers.csv", table)
    done = merge(merge_folder, data)
    assert done.returncode == 0, done.stderr
    assert (f"warning: record 3 (line 4 of {data}) is named 1001-Silva-2: --name "
            "'{id}-{surname}' gave it 1001-Silva, the name of record 1 (line 2); if they are "
            "one record twice, take one out of the data") in done.stderr
    assert [row["name"] for row in report(merge_folder)] == [
        "1001-Silva", "1002-Müller", "1001-Silva-2"]


def engines_in_build_folders(parent: Path) -> list[int]:
    """Processes (LuaLaTeX) still working in a floatpage build folder under `parent`."""
    found = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                cwd = os.readlink(entry / "cwd")
                if cwd.startswith(str(parent) + os.sep) and "floatpage-build" in cwd:
                    found.append(int(entry.name))
            except OSError:
                pass
    return found


def test_a_pipe_gets_plain_progress_lines_and_the_end_once(merge_folder):
    """Also: a column no placeholder uses is noted before any work."""
    data = write_csv(merge_folder / "customers.csv", [row + ["gold"] for row in rows(3)],
                     COLUMNS + ["loyalty"])
    done = subprocess.run([FLOATPAGE, "merge", str(merge_folder / "offer.toml"), str(data),
                           "-o", str(merge_folder / "out")], capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stderr
    said = done.stderr.splitlines()
    notes = [n for n, line in enumerate(said) if line.startswith("note: column 'loyalty' of ")]
    lines = [line for line in said if line.startswith("merge: ")]
    assert notes and notes[0] < said.index(lines[0]) and "no placeholder" in said[notes[0]]
    assert lines and lines[-1].startswith("merge: 3/3 records, 0 failed, ")
    assert "records/s, ETA 0 s" in lines[-1] and len(lines) == len(set(lines))
    assert "\x1b" not in done.stderr  # no terminal codes in a pipe


def test_a_terminal_gets_a_progress_bar_with_rate_and_eta(merge_folder):
    import pty

    data = write_csv(merge_folder / "customers.csv", rows(3))
    controller, terminal = pty.openpty()
    process = subprocess.Popen([FLOATPAGE, "merge", str(merge_folder / "offer.toml"), str(data),
                                "-o", str(merge_folder / "out")],
                               stdin=terminal, stdout=terminal, stderr=terminal,
                               env={**os.environ, "COLUMNS": "120", "TERM": "xterm"})
    os.close(terminal)
    seen = b""
    while True:
        try:
            chunk = os.read(controller, 4096)
        except OSError:  # the process closed its side
            break
        if not chunk:
            break
        seen += chunk
    process.wait(timeout=300)
    os.close(controller)
    text = seen.decode("utf-8", "replace")
    assert process.returncode == 0, text
    assert "records/s" in text and "ETA" in text and "merging" in text
    assert "merge: " not in text  # the plain lines are for pipes


def test_swapped_template_and_data_are_named_as_swapped(merge_folder):
    """`floatpage merge customers.csv offer.toml` used to answer with a TOML syntax error
    about the CSV file's first line; it now says the two are the wrong way round."""
    data = write_csv(merge_folder / "customers.csv", rows(2))
    done = subprocess.run([FLOATPAGE, "merge", str(data), str(merge_folder / "offer.toml"),
                           "-o", str(merge_folder / "out")], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 1
    assert "TOML syntax error" not in done.stderr
    assert "customers.csv" in done.stderr and "the wrong way round" in done.stderr
    assert "floatpage merge TEMPLATE.toml DATA" in done.stderr
    assert not (merge_folder / "out").exists()


def test_a_json_or_toml_data_file_is_refused_with_what_to_give_instead(merge_folder):
    """A .json array (or any .json/.toml file) was read as CSV: its first line became the
    column names, e.g. '[{"id":1}]'. It is refused, naming the formats read."""
    (merge_folder / "records.json").write_text('[{"id": 1001, "first_name": "Ann"}]\n')
    done = merge(merge_folder, merge_folder / "records.json")
    assert done.returncode == 1
    assert "the columns are" not in done.stderr
    assert "records.json" in done.stderr and ".jsonl" in done.stderr and ".csv" in done.stderr
    assert "one JSON object per line" in done.stderr
    assert not (merge_folder / "out").exists()


def test_an_empty_column_around_other_words_is_named_with_its_record_and_line(merge_folder):
    """A first name left empty printed "A little something for" and nothing after it, and an
    empty date "Valid until · customer no. 1003", without a word (user-walk-10).  The records
    are still made, as a mail merge makes them, but the run warns of each: the record, its
    line in the data, the column, the item and what it prints, and how to leave the item out;
    report.csv says it beside "made".  A column that is a whole text (the note, empty in
    every other row) prints nothing and is not named."""
    records = rows(3)
    records[1][1] = ""   # first_name
    records[2][7] = " "  # valid_until
    data = write_csv(merge_folder / "customers.csv", records)
    done = merge(merge_folder, data)
    assert done.returncode == 0, done.stderr
    warnings = [line for line in done.stderr.splitlines() if line.startswith("warning:")]
    assert len(warnings) == 2, done.stderr
    assert warnings[0].startswith(f"warning: record 2 (line 3 of {data}): ")
    assert 'column "first_name" is empty: item "greeting" on page "offer" prints ' \
        '"A little something for"' in warnings[0]
    assert "drop_if_empty = true" in warnings[0]
    assert warnings[1].startswith(f"warning: record 3 (line 4 of {data}): ")
    assert 'column "valid_until" is empty' in warnings[1] and '"Valid until · customer no. ' \
        '1003' in warnings[1]
    first, second, third = report(merge_folder)
    assert first["status"] == "made" and "empty" not in first["reason"]
    assert second["status"] == "made" and 'column "first_name" is empty' in second["reason"]
    assert third["status"] == "made" and 'column "valid_until" is empty' in third["reason"]
    printed = " ".join(text_of(merge_folder / "out" / "1002-Müller.pdf").split())
    assert "A little something for" in printed and "Person1" not in printed
    again = merge(merge_folder, data)  # nothing changed: every record skipped
    assert again.returncode == 0 and "3 unchanged" in again.stdout, again.stdout
    # the report still says it (it said nothing once the record was skipped as unchanged)
    assert [row["reason"] for row in report(merge_folder)] == [
        first["reason"], second["reason"], third["reason"]]
    assert [row["status"] for row in report(merge_folder)] == ["unchanged"] * 3


def test_a_second_run_warns_again_of_the_empty_columns_on_the_terminal(merge_folder):
    """A second run of the same merge skipped every record as unchanged and said nothing on
    the terminal of the records it had made with "A little something for" and no name: only
    report.csv said it (user-walk-12a).  A user re-running the merge still sees the same
    warnings, each with its record and line; a record made again with the value filled no
    longer warns."""
    records = rows(3)
    records[1][1] = ""   # first_name
    data = write_csv(merge_folder / "customers.csv", records)
    first = merge(merge_folder, data)
    assert first.returncode == 0, first.stderr
    told = [line for line in first.stderr.splitlines() if line.startswith("warning:")]
    assert len(told) == 1 and told[0].startswith(f"warning: record 2 (line 3 of {data}): ")
    again = merge(merge_folder, data)
    assert again.returncode == 0 and "3 unchanged" in again.stdout, again.stdout
    assert [line for line in again.stderr.splitlines() if line.startswith("warning:")] == told
    records[1][1] = "Ana"
    filled = merge(merge_folder, write_csv(merge_folder / "customers.csv", records))
    assert filled.returncode == 0 and "1 made, 2 unchanged" in filled.stdout, filled.stdout
    assert "warning:" not in filled.stderr, filled.stderr
    assert all("empty" not in row["reason"] for row in report(merge_folder))


def test_a_column_empty_in_many_records_is_one_warning_in_record_order(merge_folder):
    """Twelve rows without a first name printed ten warnings alike, in the order the workers
    finished (records 4, 5, 6, 1, 2, 3, ...).  The first record is told in full, then the
    numbers of the others; report.csv names each."""
    records = rows(12)
    for record in records:
        record[1] = ""
    done = merge(merge_folder, write_csv(merge_folder / "customers.csv", records), "out",
                 "--chunk-size", "3")
    assert done.returncode == 0, done.stderr
    warnings = [line for line in done.stderr.splitlines() if line.startswith("warning:")]
    assert len(warnings) == 2, done.stderr
    assert warnings[0].startswith("warning: record 1 (line 2 of ")
    assert 'column "first_name" is empty: item "greeting"' in warnings[0]
    assert warnings[1].startswith("warning: the same in 11 more record(s): 2, 3, 4, 5, 6, 7, "
                                  "8, 9, 10, 11 and 1 more; ")
    assert all('column "first_name" is empty' in row["reason"] for row in report(merge_folder))


def test_a_record_that_now_fails_loses_the_pdf_an_earlier_run_made_from_other_data(
        merge_folder):
    """The folder kept 1002-Müller.pdf, with the old product, beside a report.csv that said
    the record failed, and `lpr out/*.pdf` would have printed it. Both ways a record fails
    are covered: in the layout (a picture not found) and in the engine's run (a word too
    long to break). A record that fails on the data it was made from keeps its PDF."""
    first = rows(3)
    assert merge(merge_folder, write_csv(merge_folder / "customers.csv", first)).returncode == 0
    out = merge_folder / "out"
    assert sorted(p.name for p in out.glob("*.pdf")) == [
        "1001-Silva.pdf", "1002-Müller.pdf", "1003-Okonkwo-Fitzgerald.pdf"]
    changed = [list(row) for row in first]
    changed[1][5] = "no-such-picture.png"
    changed[2][3] = "word " * 3000
    done = merge(merge_folder, write_csv(merge_folder / "customers.csv", changed))
    assert done.returncode == 3, done.stderr
    assert sorted(p.name for p in out.glob("*.pdf")) == ["1001-Silva.pdf"]
    assert ("2 of them had a PDF an earlier run made from other data or another template "
            "(1002-Müller.pdf, 1003-Okonkwo-Fitzgerald.pdf); it was removed") in done.stderr
    reasons = [row["reason"] for row in report(merge_folder)]
    assert reasons[0] == "" and all(
        "made by an earlier run from other data (or another template or --toml), was removed"
        in reason for reason in reasons[1:])
    # Nothing left that a later run takes for "made": mended, both come back.
    assert merge(merge_folder, write_csv(merge_folder / "customers.csv", first)).returncode == 0
    assert [row["status"] for row in report(merge_folder)] == ["unchanged", "made", "made"]


def test_a_forced_run_that_fails_keeps_the_pdfs_made_from_the_same_data(merge_folder):
    """The data and pictures are those the PDFs were made from; the engine fails for a reason
    of this machine's (a memory limit far too low), and the PDFs are still right."""
    data = write_csv(merge_folder / "customers.csv", rows(2))
    assert merge(merge_folder, data).returncode == 0
    pdf = merge_folder / "out" / "1002-Müller.pdf"
    made = pdf.read_bytes()
    done = merge(merge_folder, data, "out", "--force", env={"FLOATPAGE_ENGINE_MEMORY_MB": "40"})
    assert done.returncode == 3, done.stderr
    assert [row["status"] for row in report(merge_folder)] == ["failed", "failed"]
    assert "had a PDF an earlier run made" not in done.stderr
    assert pdf.read_bytes() == made


def test_a_merge_runs_under_a_tmpdir_too_long_for_a_unix_socket(merge_folder):
    """multiprocessing's fork server listens on a socket under $TMPDIR, whose path may hold
    107 bytes: under a CI job's long TMPDIR (here a test's own folder, under pytest-xdist)
    merge ended in "internal error: OSError: AF_UNIX path too long"."""
    long = merge_folder / ("t" * 60) / ("u" * 60)
    long.mkdir(parents=True)
    data = write_csv(merge_folder / "customers.csv", rows(4))
    done = subprocess.run([FLOATPAGE, "merge", str(merge_folder / "offer.toml"), str(data), "-o",
                           str(merge_folder / "out"), "--workers", "2", "--chunk-size", "1"],
                          capture_output=True, text=True, timeout=600,
                          env={**os.environ, "TMPDIR": str(long)})
    assert done.returncode == 0, done.stderr
    assert len(list((merge_folder / "out").glob("*.pdf"))) == 4


def test_a_tex_installation_that_cannot_start_stops_the_merge_once(merge_folder):
    """LuaLaTeX that ends before its log (here it finds no texmf.cnf, so no format) is no
    record's fault: each record was reported failed, after its chunk had been halved down to
    it, with the engine's words cut short. The merge now stops, saying what to try, once."""
    data = write_csv(merge_folder / "customers.csv", rows(6))
    done = subprocess.run([FLOATPAGE, "merge", str(merge_folder / "offer.toml"), str(data), "-o",
                           str(merge_folder / "out"), "--workers", "2", "--chunk-size", "3"],
                          capture_output=True, text=True, timeout=600,
                          env={**os.environ, "TEXMFCNF": str(merge_folder / "no-texmf-cnf")})
    assert done.returncode == 1, done.stderr
    assert done.stderr.count("could not start LuaLaTeX") == 1, done.stderr
    assert "fmtutil-sys --byfmt lualatex" in done.stderr and "Traceback" not in done.stderr
    assert list((merge_folder / "out").glob("*.pdf")) == []
