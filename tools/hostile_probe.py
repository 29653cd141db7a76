"""Hostile-input probe (fifteenth session, helper hostile-input): each case sets up files, runs
one `floatpage` command and flags a traceback, "internal error", an exit code other than 0/1
(3 for merge, 2 for a usage error), changed bytes of a file that must stay, inf/NaN in a saved
project, and files created where none may be.  About 700 cases in 25 minutes on 2 cores.

    .venv/bin/python tools/hostile_probe.py [FILTER]     # FILTER: part of a group's name

Run as root for the full-disk (tmpfs), read-only and immutable (chattr) cases; scratch files
go to $HOSTILE_WORK (default /tmp/hostile-input/work), results to results-FILTER.json beside it.
Every defect it found is a test now (tests/cli/test_hostile_input.py,
tests/merge/test_hostile_merge.py, the fuzz corpus); this is for finding the next ones."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

WT = Path(__file__).resolve().parents[1]
FP = str(WT / ".venv/bin/floatpage")
ROOT = Path(os.environ.get("HOSTILE_WORK", "/tmp/hostile-input/work"))
SAMPLES = WT / "sample_projects"
CASES = []


def case(fn):
    CASES.append(fn)
    return fn


def fresh(name: str) -> Path:
    d = ROOT / name
    if d.exists():
        subprocess.run(["chattr", "-R", "-i", str(d)], capture_output=True)
        shutil.rmtree(d)
    d.mkdir(parents=True)
    return d


def card(d: Path, name="card.toml") -> Path:
    src = SAMPLES / "greeting-card"
    shutil.copytree(src / "pictures", d / "pictures", dirs_exist_ok=True)
    p = d / name
    shutil.copy(src / "greeting-card.toml", p)
    return p


def offer(d: Path) -> tuple[Path, Path]:
    src = SAMPLES / "merge-offers"
    shutil.copytree(src / "pictures", d / "pictures", dirs_exist_ok=True)
    shutil.copy(src / "offer.toml", d / "offer.toml")
    shutil.copy(src / "customers.csv", d / "customers.csv")
    return d / "offer.toml", d / "customers.csv"


def perturb(p: Path) -> None:
    t = p.read_text()
    i = t.index('id = "front-picture"')
    j = t.index("x = ", i)
    k = t.index("\n", j)
    p.write_text(t[:j] + "x = 30.0" + t[k:])


def run(argv, cwd, timeout=240, stdin=subprocess.DEVNULL):
    env = {**os.environ, "FLOATPAGE_CACHE_DIR": str(ROOT / "cache")}
    t = time.time()
    try:
        p = subprocess.run([FP, *map(str, argv)], cwd=cwd, capture_output=True, timeout=timeout,
                           env=env, stdin=stdin)
        return p.returncode, p.stdout.decode(errors="replace"), p.stderr.decode(errors="replace"), time.time() - t
    except subprocess.TimeoutExpired as e:
        return "timeout", "", (e.stderr or b"").decode(errors="replace"), time.time() - t


def snapshot(paths):
    out = {}
    for p in paths:
        p = Path(p)
        try:
            st = os.lstat(p)
            out[str(p)] = (st.st_mode, p.read_bytes() if p.is_file() and not p.is_symlink() else os.readlink(p) if p.is_symlink() else None)
        except OSError:
            out[str(p)] = None
    return out


def outcome(name, argv, cwd, protect=(), forbid=(), expect=(0, 1), expect_text=(), timeout=240,
            nan_check=(), stdin=subprocess.DEVNULL):
    before = snapshot(protect)
    forbid_before = {str(f): os.path.lexists(f) for f in forbid}
    nan_before = {}
    for f in nan_check:
        try:
            t = Path(f).read_text(errors="replace").lower()
            nan_before[f] = bool(re.search(r"=\s*[-+]?(nan|inf)\b", t))
        except OSError:
            nan_before[f] = False
    rc, out, err, secs = run(argv, cwd, timeout, stdin)
    flags = []
    if rc == "timeout":
        flags.append("TIMEOUT")
    elif rc not in expect:
        if not (rc == 2 and "usage:" in err):
            flags.append(f"exit {rc}")
    if "Traceback" in err or "Traceback" in out:
        flags.append("traceback")
    if "internal error" in err:
        flags.append("internal error")
    after = snapshot(protect)
    for k in before:
        if before[k] != after[k]:
            flags.append(f"changed {k}")
    for f in forbid:
        if os.path.lexists(f) and not forbid_before[str(f)]:
            flags.append(f"created {f}")
    for f in nan_check:
        if f in nan_before and nan_before[f]:
            continue  # the input held inf or nan itself: refused, not written
        try:
            t = Path(f).read_text(errors="replace").lower()
            if "nan" in t.replace("nanum", "") and ("= nan" in t or "=nan" in t) or "= inf" in t:
                flags.append(f"nan/inf in {f}")
        except OSError:
            pass
    for t in expect_text:
        if t not in err + out:
            flags.append(f"missing text {t!r}")
    msg = (err.strip() or out.strip()).splitlines()
    short = " | ".join(msg[:3])[:400]
    r = {"case": name, "rc": rc, "secs": round(secs, 1), "flags": flags, "msg": short}
    mark = "FLAG" if r["flags"] else "ok  "
    print(f"{mark} {r['case'][:70]:70} rc={r['rc']} {r['secs']}s {';'.join(r['flags'])} :: {r['msg'][:250]}", flush=True)
    return r


# ---------------------------------------------------------------- project file as a path

@case
def project_is_fifo():
    d = fresh("fifo")
    os.mkfifo(d / "p.toml")
    return [outcome(f"project FIFO: {c}", [c, d / "p.toml"], d, timeout=30) for c in ("check", "settle", "render")]


@case
def project_is_dev_zero():
    d = fresh("devzero")
    return [outcome(f"project /dev/zero: {c}", [c, "/dev/zero"], d, timeout=30, forbid=[d / "zero.pdf"]) for c in ("check", "settle", "render")]


@case
def project_is_dir():
    d = fresh("pdir")
    (d / "x.toml").mkdir()
    return [outcome(f"project dir: {c}", [c, d / "x.toml"], d) for c in ("check", "settle", "render", "edit")]


@case
def project_symlink_settle():
    d = fresh("plink")
    p = card(d)
    (d / "link.toml").symlink_to("card.toml")
    r = outcome("project symlink: settle", ["settle", "link.toml"], d)
    if not (d / "link.toml").is_symlink():
        r["flags"].append("symlink replaced by file")
    return [r]


@case
def project_dangling_symlink():
    d = fresh("pdangle")
    (d / "link.toml").symlink_to("nowhere.toml")
    return [outcome(f"dangling symlink: {c}", [c, "link.toml"], d, forbid=[d / "nowhere.toml", d / "nowhere.pdf"]) for c in ("check", "settle", "render")]


@case
def project_symlink_loop():
    d = fresh("ploop")
    (d / "a.toml").symlink_to("b.toml")
    (d / "b.toml").symlink_to("a.toml")
    return [outcome(f"symlink loop: {c}", [c, "a.toml"], d) for c in ("check", "settle", "render")]


@case
def project_200mb():
    d = fresh("big")
    with open(d / "big.toml", "wb") as f:
        f.write(b"format = 1\n# " + b"x" * (200 << 20) + b"\n")
    return [outcome("200 MB project: check", ["check", "big.toml"], d, timeout=60)]


@case
def project_name_newline():
    d = fresh("pnl")
    p = card(d, "ca\nrd.toml")
    return [outcome("project name with newline: settle", ["settle", p], d),
            outcome("project name with newline: render", ["render", p], d)]


@case
def project_no_suffix():
    d = fresh("nosuffix")
    p = card(d, "card")
    return [outcome("project without .toml: render (default out)", ["render", "card"], d, protect=[p])]


@case
def project_dot_pdf_suffix():
    d = fresh("pdfsuffix")
    p = card(d, "card.pdf")
    return [outcome("project named card.pdf: render (default out = itself)", ["render", "card.pdf"], d, protect=[p])]


@case
def project_readonly_dir_settle():
    d = fresh("rodir")
    p = card(d)
    # move items so settle must write
    perturb(p)
    subprocess.run(["chattr", "+i", str(d)])
    try:
        r = outcome("settle in immutable folder", ["settle", p], d, protect=[p])
    finally:
        subprocess.run(["chattr", "-i", str(d)])
    return [r]


@case
def project_immutable_file():
    d = fresh("rofile")
    p = card(d)
    perturb(p)
    subprocess.run(["chattr", "+i", str(p)])
    try:
        r = outcome("settle of immutable file", ["settle", p], d, protect=[p])
    finally:
        subprocess.run(["chattr", "-i", str(p)])
    return [r]


@case
def full_disk():
    d = fresh("full")
    mnt = d / "mnt"
    mnt.mkdir()
    res = []
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=200k", "tmpfs", str(mnt)]).returncode:
        return [{"case": "full disk", "rc": "-", "secs": 0, "flags": ["could not mount"], "msg": ""}]
    try:
        p = card(d)
        # render onto a full disk: copy project in first, fill the rest
        shutil.copy(p, mnt / "card.toml")
        (mnt / "pictures").symlink_to(d / "pictures")
        with open(mnt / "fill", "wb") as f:
            try:
                f.write(b"x" * (400 << 10))
            except OSError:
                pass
        res.append(outcome("full disk: render -o on full fs", ["render", "--allow-outside-files", "card.toml", "-o", "card.pdf"], mnt,
                           protect=[mnt / "card.toml"], forbid=[mnt / "card.pdf"]))
        perturb(mnt / "card.toml")
        res.append(outcome("full disk: settle on full fs", ["settle", "--allow-outside-files", "card.toml"], mnt,
                           protect=[mnt / "card.toml"]))
        os.unlink(mnt / "fill")
        with open(mnt / "fill", "wb") as f:
            try:
                f.write(b"x" * ((200 << 10) - (mnt / "card.toml").stat().st_size - 12000))
            except OSError:
                pass
        res.append(outcome("nearly full disk: settle", ["settle", "--allow-outside-files", "card.toml"], mnt,
                           nan_check=[mnt / "card.toml"]))
        try:
            import tomllib
            tomllib.loads((mnt / "card.toml").read_text())
        except Exception as e:
            res[-1]["flags"].append(f"project unreadable after: {e}")
        # merge out to full fs
        o, c = offer(d)
        os.unlink(mnt / "fill")
        with open(mnt / "fill", "wb") as f:
            try:
                f.write(b"x" * (150 << 10))
            except OSError:
                pass
        res.append(outcome("full disk: merge -o on full fs", ["merge", o, c, "-o", mnt / "out", "-q"], d,
                           expect=(0, 1, 3)))
        res.append(outcome("full disk: new on full fs", ["new", "card", mnt / "new.toml"], d))
        if (mnt / "new.toml").exists():
            try:
                import tomllib
                tomllib.loads((mnt / "new.toml").read_text())
            except Exception as e:
                res[-1]["flags"].append(f"half-written new.toml: {e}")
    finally:
        subprocess.run(["umount", str(mnt)])
    return res


# ---------------------------------------------------------------- render outputs

@case
def render_outputs():
    d = fresh("outs")
    p = card(d)
    (d / "dev").symlink_to("/dev/null")
    (d / "folder.pdf").mkdir()
    (d / "link.pdf").symlink_to("target.pdf")
    os.mkfifo(d / "fifo.pdf")
    res = []
    for name, argv in {
        "-o project": ["-o", "card.toml"],
        "-o symlink to new": ["-o", "link.pdf"],
        "-o /dev/null": ["-o", "/dev/null"],
        "-o /dev/full": ["-o", "/dev/full"],
        "-o folder.pdf": ["-o", "folder.pdf"],
        "-o fifo.pdf": ["-o", "fifo.pdf"],
        "-o missing folder": ["-o", "nope/x.pdf"],
        "-o picture": ["-o", "pictures/" + sorted(os.listdir(d / "pictures"))[0]],
        "--tex project": ["--tex", "card.toml"],
        "--tex = -o": ["-o", "same.pdf", "--tex", "same.pdf"],
        "--tex /dev/stdout": ["--tex", "/dev/stdout"],
        "--fragment = --tex": ["--tex", "a.tex", "--fragment", "a.tex"],
        "-o empty": ["-o", ""],
        "-o dot": ["-o", "."],
        "-o slash-ended": ["-o", "out/"],
        "-o bak": ["-o", "card.toml.bak"],
        "-o lock": ["-o", ".card.toml.lock"],
        "-o cache dir pdf": ["-o", str(ROOT / "cache")],
        "-o spaces and newline": ["-o", "my out\nfile.pdf"],
        "-o with NUL-free but long name": ["-o", "x" * 300 + ".pdf"],
        "-o .PDF upper": ["-o", "OUT.PDF"],
        "-o .TOML other": ["-o", "other.TOML"],
    }.items():
        res.append(outcome(f"render {name}", ["render", "card.toml", "-q", *argv], d,
                           protect=[p, d / "dev", d / "link.pdf", d / "folder.pdf", d / "fifo.pdf"],
                           forbid=[d / "target.pdf"], timeout=120))
    return res


# ---------------------------------------------------------------- TOML extras not in the corpus

BASE = '''format = 1
title = "T"

[[pages]]
id = "p"
size = "A5"
'''


def item(i, extra="", kind="block", x=40.0, y=40.0, w=20.0, h=20.0):
    return f'\n[[pages.items]]\nid = "{i}"\nkind = "{kind}"\nx = {x}\ny = {y}\nw = {w}\nh = {h}\n{extra}\n'


TOMLS = {
    "region missing": BASE + item("a", 'region = "nowhere"'),
    "region zero size": BASE + '\n[[pages.regions]]\nid = "r"\nleft = 10.0\ntop = 10.0\nw = 0.0\nh = 10.0\n' + item("a", 'region = "r"'),
    "region off page": BASE + '\n[[pages.regions]]\nid = "r"\nleft = 1000.0\ntop = 1000.0\nw = 50.0\nh = 50.0\n' + item("a", 'region = "r"'),
    "region smaller than item": BASE + '\n[[pages.regions]]\nid = "r"\nleft = 10.0\ntop = 10.0\nw = 5.0\nh = 5.0\n' + item("a", 'region = "r"'),
    "region huge": BASE + '\n[[pages.regions]]\nid = "r"\nleft = -1e300\ntop = -1e300\nw = 1e308\nh = 1e308\n' + item("a", 'region = "r"'),
    "region duplicate id": BASE + '\n[[pages.regions]]\nid = "r"\nleft = 10.0\ntop = 10.0\nw = 50.0\nh = 50.0\n' * 2 + item("a", 'region = "r"'),
    "region id = item id": BASE + '\n[[pages.regions]]\nid = "a"\nleft = 10.0\ntop = 10.0\nw = 50.0\nh = 50.0\n' + item("a", 'region = "a"'),
    "region 5000": BASE + "".join(f'\n[[pages.regions]]\nid = "r{i}"\nleft = 10.0\ntop = 10.0\nw = 50.0\nh = 50.0\n' for i in range(5000)) + item("a", 'region = "r1"'),
    "regions on table": BASE + 'regions = {id = "r"}\n',
    "region from other page": BASE + '\n[[pages.regions]]\nid = "r"\nleft = 10.0\ntop = 10.0\nw = 50.0\nh = 50.0\n' + '\n[[pages]]\nid = "q"\n' + item("a", 'region = "r"'),
    "region negative w": BASE + '\n[[pages.regions]]\nid = "r"\nleft = 10.0\ntop = 10.0\nw = -50.0\nh = 50.0\n',
    "region extra key": BASE + '\n[[pages.regions]]\nid = "r"\nleft = 10.0\ntop = 10.0\nw = 50.0\nh = 50.0\ncolor = "#ff0000"\n',
    "group one item": BASE + item("a", 'group = "g"'),
    "group cyclic anchors": BASE + item("a", 'group = "g"\nanchor = {to = "b"}') + item("b", 'group = "g"\nanchor = {to = "a"}', x=70),
    "group anchored inside": BASE + item("a", 'group = "g"\nanchor = {to = "b", dx = 5.0}') + item("b", 'group = "g"', x=70),
    "group + region disagree": BASE + '\n[[pages.regions]]\nid = "r"\nleft = 0.0\ntop = 0.0\nw = 60.0\nh = 60.0\n[[pages.regions]]\nid = "s"\nleft = 80.0\ntop = 100.0\nw = 60.0\nh = 60.0\n' + item("a", 'group = "g"\nregion = "r"') + item("b", 'group = "g"\nregion = "s"', x=100, y=120),
    "group of hard anchored": BASE + item("a", 'group = "g"\nanchor = {x = 20.0, y = 20.0, hard = true}') + item("b", 'group = "g"\nanchor = {x = 120.0, y = 190.0, hard = true}', x=120, y=190),
    "group name = item id": BASE + item("a", 'group = "a"') + item("b", 'group = "a"', x=80),
    "group control chars": BASE + item("a", 'group = "g\\u001b[31m"') + item("b", 'group = "g\\u001b[31m"', x=80),
    "group huge (500 items)": BASE + "".join(item(f"i{k}", 'group = "g"', x=10 + k % 12 * 10, y=10 + k // 12 * 5, w=3, h=3) for k in range(500)),
    "group wrong type": BASE + item("a", "group = 3"),
    "anchor to item on other page": BASE + item("a") + '\n[[pages]]\nid = "q"\n' + item("b", 'anchor = {to = "a"}'),
    "anchor to decorative": BASE + item("a", "decorative = true") + item("b", 'anchor = {to = "a", dx = 30.0}', x=80),
    "anchor dx huge": BASE + item("a") + item("b", 'anchor = {to = "a", dx = 1e300}', x=80),
    "anchor gamma nan": BASE + item("a", "anchor = {x = 20.0, y = 20.0, gamma = nan}"),
    "anchor extra key": BASE + item("a", 'anchor = {x = 20.0, y = 20.0, color = "red"}'),
    "anchor is string": BASE + item("a", 'anchor = "b"') + item("b", x=80),
    "anchor is array": BASE + item("a", 'anchor = [1, 2]'),
    "page id duplicates item id": BASE.replace('id = "p"', 'id = "a"') + item("a"),
    "same item id on two pages": BASE + item("a") + '\n[[pages]]\nid = "q"\n' + item("a"),
    "text font name injection": BASE + item("a", 'text = "x"\nfont = "serif}\\\\input{/etc/passwd"', kind="text"),
    "colour name injection": BASE + item("a", 'color = "#ffffff}\\\\write18{id}"'),
    "title injection": BASE.replace('title = "T"', 'title = "\\\\immediate\\\\write18{touch /tmp/hostile-input/pwned-title}"') + item("a"),
    "title 100k": BASE.replace('title = "T"', 'title = "' + "T" * 100_000 + '"') + item("a"),
    "language injection": BASE.replace('title = "T"', 'title = "T"\nlanguage = "en}\\\\input{x}"'),
    "text ^^ notation": BASE + item("a", 'text = "^^5cinput^^7b/etc/passwd^^7d ^^M ^^@ ^^^^0041"', kind="text", w=80),
    "text catcode trick": BASE + item("a", 'text = "\\\\catcode`\\\\@=0 @input{/etc/passwd}"', kind="text", w=80),
    "text luacode": BASE + item("a", 'text = "\\\\begin{luacode}os.execute(\\"touch /tmp/hostile-input/pwned-lua\\")\\\\end{luacode}"', kind="text", w=80),
    "text \\csname": BASE + item("a", 'text = "\\\\csname input\\\\endcsname{/etc/passwd} \\\\def\\\\x{y}"', kind="text", w=80),
    "text 20000-char word": BASE + item("a", 'text = "' + "W" * 20000 + '"', kind="text", w=80, h=80),
    "text only combining": BASE + item("a", 'text = "' + "\u0301" * 3000 + '"', kind="text", w=80),
    "text RTL marks only": BASE + item("a", 'text = "\u200f\u200e\u202b\u202a\u2067\u2069"', kind="text", w=80),
    "text zero-width only": BASE + item("a", 'text = "\u200b\u200c\u200d\u2060\ufeff"', kind="text", w=80),
    "text BOM inside": BASE + item("a", 'text = "a\ufeffb"', kind="text", w=80),
    "text tab and FF": BASE + item("a", 'text = "a\\tb\\fc\\u000bd"', kind="text", w=80),
    "text private use": BASE + item("a", 'text = "\ue000\U000f0000\U00100000"', kind="text", w=80),
    "text line sep only": BASE + item("a", 'text = "\\u2028\\u2029\\u0085"', kind="text", w=80),
    "text tiny box": BASE + item("a", 'text = "Hello world"', kind="text", w=0.001, h=0.001),
    "text box 1e-300": BASE + item("a", 'text = "Hello"', kind="text", w=1e-300, h=1e-300),
    "picture tiny box": BASE + item("a", 'path = "pictures/x.png"', kind="picture", w=1e-300, h=1e-300),
    "id with slash and dots": BASE + item("../../x"),
    "id with quotes and braces": BASE + item('a\\"}{\\\\'),
    "page id injection": BASE.replace('id = "p"', 'id = "p}\\\\input{/etc/passwd}"') + item("a"),
    "calendar month injection-free, first_weekday int": BASE + item("a", "first_weekday = 3\nyear = 2027\nmonth = 1", kind="calendar", w=80, h=60),
    "calendar year 9999 dec": BASE + item("a", "year = 9999\nmonth = 12", kind="calendar", w=80, h=60),
    "calendar year 1 jan": BASE + item("a", "year = 1\nmonth = 1", kind="calendar", w=80, h=60),
    "calendar tiny": BASE + item("a", "year = 2027\nmonth = 2", kind="calendar", w=0.5, h=0.5),
    "background picture outside": BASE.replace('size = "A5"', 'size = "A5"\nbackground = {picture = "/etc/passwd"}'),
    "background colour injection": BASE.replace('size = "A5"', 'size = "A5"\nbackground = {color = "red}\\\\input{x}"}'),
    "background is string": BASE.replace('size = "A5"', 'size = "A5"\nbackground = "#ffffff"'),
    "background empty table": BASE.replace('size = "A5"', 'size = "A5"\nbackground = {}'),
    "background picture placeholder": BASE.replace('size = "A5"', 'size = "A5"\nbackground = {picture = "pictures/{x}.png"}'),
    "picture placeholder outside merge": BASE + item("a", 'path = "pictures/{photo}"', kind="picture"),
    "text with placeholder outside merge": BASE + item("a", 'text = "{{ 7*7 }} {% if %}"', kind="text", w=80),
    "size wrong type": BASE.replace('size = "A5"', "size = 5"),
    "size custom missing dims": BASE.replace('size = "A5"', 'size = "custom"'),
    "size A5 with dims": BASE.replace('size = "A5"', 'size = "A5"\nwidth_mm = 5000.0\nheight_mm = 5000.0') + item("a"),
    "orientation landscape 5000": BASE.replace('size = "A5"', 'size = "custom"\nwidth_mm = 5000.0\nheight_mm = 10.0\norientation = "landscape"') + item("a", x=20, y=5, w=5, h=5),
    "physics unknown key": BASE.replace("[[pages]]", "[physics]\nfoo = 1\n\n[[pages]]"),
    "physics gutter huge": BASE.replace("[[pages]]", "[physics]\ngutter_mm = 1e300\n\n[[pages]]") + item("a") + item("b", x=80),
    "physics margin huge": BASE.replace("[[pages]]", "[physics]\nmargin_mm = 1e300\n\n[[pages]]") + item("a") + item("b", x=80),
    "physics guides negative": BASE.replace("[[pages]]", "[physics]\nguides = -5.0\n\n[[pages]]") + item("a") + item("b", x=80),
    "physics steps huge": BASE.replace("[[pages]]", "[physics]\nsteps_per_frame = 9223372036854775807\n\n[[pages]]") + item("a"),
    "physics as array": BASE.replace("[[pages]]", "physics = [1]\n\n[[pages]]"),
    "files table array": "[[files]]\nallow_outside = true\n" + BASE,
    "format float": BASE.replace("format = 1", "format = 1.0"),
    "format huge": BASE.replace("format = 1", "format = 99999999999999999999") if False else BASE.replace("format = 1", "format = 9223372036854775807"),
    "format negative": BASE.replace("format = 1", "format = -1"),
    "CRLF everywhere": (BASE + item("a") + item("b", x=90)).replace("\n", "\r\n"),
    "CR only": (BASE + item("a")).replace("\n", "\r"),
    "mixed CRLF": (BASE + item("a") + item("b", x=90)).replace("\n", "\r\n", 5),
    "BOM + CRLF": "\ufeff" + (BASE + item("a") + item("b", x=90)).replace("\n", "\r\n"),
    "two BOMs": "\ufeff\ufeff" + BASE + item("a"),
    "NUL in comment": BASE + "# a \x00 b\n" + item("a"),
    "lone surrogate bytes": None,
    "overlong utf8": None,
    "latin-1 text": None,
    "key with unicode homoglyph": BASE + item("a", "wіdth = 3"),  # cyrillic i
    "id RTL override": BASE + item("a\u202eb"),
    "id 10000 chars": BASE + item("a" * 10000),
    "id NUL escape": BASE + item("a\\u0000b"),
    "kind missing": BASE + '\n[[pages.items]]\nid = "a"\nx = 1.0\ny = 1.0\nw = 1.0\nh = 1.0\n',
    "item x as int big": BASE + item("a", x=10**30),
    "item w int max": BASE + '\n[[pages.items]]\nid = "a"\nkind = "block"\nx = 1\ny = 1\nw = 9223372036854775807\nh = 1\n',
    "items 10001": BASE + "".join(item(f"i{k}", x=1 + k % 140, y=1 + k // 140 * 2, w=0.5, h=0.5) for k in range(10001)),
    "pages 5000 empty": "format = 1\n" + "".join(f'\n[[pages]]\nid = "p{i}"\nsize = "A7"\n' for i in range(5000)),
    "z nested": BASE + item("a", "z = {a = 1}"),
    "drop_if_empty string": BASE + item("a", 'drop_if_empty = "yes"', kind="text"),
    "align bad": BASE + item("a", 'text = "x"\nalign = "justify}"', kind="text"),
    "lock_aspect int": BASE + item("a", 'path = "x.png"\nlock_aspect = 1', kind="picture"),
    "bleed on text": BASE + item("a", 'text = "x"\nbleed = true', kind="text"),
    "datetime title": BASE.replace('title = "T"', "title = 1979-05-27T07:32:00Z"),
    "time value": BASE + item("a", "z = 07:32:00"),
    "dotted pages.items key": 'format = 1\npages.items = 3\n',
    "array of tables then table": 'format = 1\n[[pages]]\nid = "p"\n[pages]\nid = "q"\n',
    "integer keys": 'format = 1\n1 = 2\n' + BASE.replace("format = 1\n", ""),
    "quoted empty key": 'format = 1\n"" = 2\n' + BASE.replace("format = 1\n", ""),
}


def odd_bytes():
    base = (BASE + item("a", 'text = "XX"', kind="text")).encode()
    return {
        "lone surrogate bytes": base.replace(b"XX", b"\xed\xa0\x80"),
        "overlong utf8": base.replace(b"XX", b"\xc0\xaf"),
        "latin-1 text": base.replace(b"XX", "café".encode("latin-1")),
    }


@case
def toml_cases():
    d = fresh("toml")
    pics = d / "pictures"
    pics.mkdir()
    shutil.copy(next((SAMPLES / "greeting-card/pictures").iterdir()), pics / "x.png")
    res = []
    ob = odd_bytes()
    for name, text in TOMLS.items():
        f = d / (name.replace(" ", "_").replace("/", "_") + ".toml")
        data = ob[name] if text is None else text.encode()
        f.write_bytes(data)
        for cmd in ("check", "settle", "render"):
            before = f.read_bytes()
            r = outcome(f"toml {name}: {cmd}", [cmd, "-q" if cmd != "check" else "--strict", f] if cmd != "check" else [cmd, f], d,
                        nan_check=[f], timeout=180)
            res.append(r)
            if cmd == "settle":
                f.write_bytes(before)
    for leak in ("pwned-title", "pwned-lua"):
        if Path("/tmp/hostile-input", leak).exists():
            res.append({"case": f"injection {leak}", "rc": "-", "secs": 0, "flags": ["SHELL ESCAPE RAN"], "msg": ""})
    return res


# ---------------------------------------------------------------- pictures

@case
def picture_cases():
    from PIL import Image
    d = fresh("pics")
    pics = d / "pictures"
    pics.mkdir()
    Image.new("CMYK", (200, 100), (0, 100, 0, 0)).save(pics / "cmyk.jpg")
    Image.new("I;16", (200, 100), 30000).save(pics / "deep16.png")
    Image.new("LA", (200, 100), (100, 50)).save(pics / "la.png")
    Image.new("P", (200, 100), 3).save(pics / "palette.png", transparency=3)
    Image.new("RGBA", (200, 100), (1, 2, 3, 0)).save(pics / "transparent.png")
    Image.new("1", (200, 100), 1).save(pics / "bilevel.png")
    Image.new("F", (20, 10), 1.5).save(pics / "float.tiff")
    Image.new("RGB", (200, 100), "red").save(pics / "prog.jpg", progressive=True)
    Image.new("RGB", (200, 100), "red").save(pics / "x.webp")
    Image.new("RGB", (200, 100), "red").save(pics / "x.bmp")
    Image.new("RGB", (200, 100), "red").save(pics / "x.ico")
    Image.new("RGB", (200, 100), "red").save(pics / "x.tga")
    # rotated via EXIF
    im = Image.new("RGB", (200, 100), "red")
    exif = im.getexif()
    exif[0x0112] = 6
    im.save(pics / "rotated.jpg", exif=exif)
    (pics / "x.svg").write_text('<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10"><rect width="10" height="10"/></svg>')
    (pics / "svg-bomb.svg").write_text('<?xml version="1.0"?><!DOCTYPE lolz [<!ENTITY lol "lol">]><svg xmlns="http://www.w3.org/2000/svg">&lol;</svg>')
    (pics / "evil.pdf").write_bytes(b"%PDF-1.4\n1 0 obj<</Type/Catalog/Pages 2 0 R/OpenAction<</S/JavaScript/JS(app.alert(1))>>>>endobj\n"
                                   b"2 0 obj<</Type/Pages/Kids[3 0 R]/Count 1>>endobj\n3 0 obj<</Type/Page/Parent 2 0 R/MediaBox[0 0 1e30 1e30]>>endobj\n"
                                   b"trailer<</Root 1 0 R>>\n%%EOF\n")
    (pics / "zero-media.pdf").write_bytes(b"%PDF-1.4\n1 0 obj<</Type/Catalog/Pages 2 0 R>>endobj\n"
                                          b"2 0 obj<</Type/Pages/Kids[3 0 R]/Count 1>>endobj\n3 0 obj<</Type/Page/Parent 2 0 R/MediaBox[0 0 0 0]>>endobj\n"
                                          b"trailer<</Root 1 0 R>>\n%%EOF\n")
    # multi-page pdf
    Image.new("RGB", (100, 50), "green").save(pics / "two.pdf", save_all=True, append_images=[Image.new("RGB", (50, 100), "blue")])
    (pics / "eps.eps").write_text("%!PS-Adobe-3.0 EPSF-3.0\n%%BoundingBox: 0 0 10 10\n(%pipe%id) (w) file\n")
    (pics / "link.png").symlink_to("/dev/zero")
    (pics / "loop.png").symlink_to("loop.png")
    os.mkfifo(pics / "fifo.png")
    (pics / "name with spaces & $ { } % #.png").write_bytes((pics / "transparent.png").read_bytes())
    (pics / "quote\".png").write_bytes((pics / "transparent.png").read_bytes())
    (pics / "back\\slash.png").write_bytes((pics / "transparent.png").read_bytes())
    (pics / "unicode-ñ-漢.png").write_bytes((pics / "transparent.png").read_bytes())
    (pics / "caps.PNG").write_bytes((pics / "transparent.png").read_bytes())
    (pics / "noext").write_bytes((pics / "transparent.png").read_bytes())
    (pics / "png-named.jpg").write_bytes((pics / "transparent.png").read_bytes())
    (pics / "jpg-named.png").write_bytes((pics / "cmyk.jpg").read_bytes())
    (pics / ".hidden.png").write_bytes((pics / "transparent.png").read_bytes())
    (pics / "x.toml").write_text("format = 1\n")
    os.symlink(d / "pictures", pics / "dirlink")
    (d.parent / "outside.png").write_bytes((pics / "transparent.png").read_bytes())
    (pics / "escape.png").symlink_to(d.parent / "outside.png")
    # PNG with huge iCCP / text chunk
    import zlib, struct
    raw = (pics / "transparent.png").read_bytes()

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    (pics / "ztxt-bomb.png").write_bytes(raw[:33] + chunk(b"zTXt", b"k\x00\x00" + zlib.compress(b"\x00" * (50 << 20))) + raw[33:])
    (pics / "bad-crc.png").write_bytes(raw[:30] + b"\x00\x00\x00\x00" + raw[34:])
    (pics / "png-many-idat-huge-decl.png").write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 9000, 9000, 16, 6, 0, 0, 0)) + chunk(b"IDAT", zlib.compress(b"\x00" * 100000)) + chunk(b"IEND", b""))
    # GIF bomb: huge logical screen
    (pics / "gif-bomb.gif").write_bytes(b"GIF89a" + struct.pack("<HH", 65535, 65535) + b"\x00\x00\x00" + b";")
    # JPEG claiming 65500x65500
    jpg = bytearray((pics / "prog.jpg").read_bytes())
    i = jpg.find(b"\xff\xc2")
    if i > 0:
        jpg[i + 5:i + 9] = struct.pack(">HH", 65500, 65500)
    (pics / "jpeg-bomb.jpg").write_bytes(bytes(jpg))
    names = sorted(os.listdir(pics))
    res = []
    for n in names + ["/dev/zero", "/dev/urandom", "/proc/self/environ", "../outside.png", "pictures/../pictures/cmyk.jpg", "dirlink/cmyk.jpg", "pictures//cmyk.jpg", "~/x.png", "file:///etc/passwd", "http://example.com/x.png", "C:\\x.png", "pictures/nonexistent.png\x00.png"]:
        path = n if n.startswith(("/", "..", "pictures", "~", "file:", "http", "C:", "dirlink")) else f"pictures/{n}"
        if n == "dirlink/cmyk.jpg":
            path = "pictures/dirlink/cmyk.jpg"
        esc = path.replace("\\", "\\\\").replace('"', '\\"').replace("\x00", "\\u0000")
        f = d / "p.toml"
        f.write_text(BASE + item("a", f'path = "{esc}"', kind="picture", w=60, h=40) + item("b", f'text = "t"', kind="text", x=90, y=150))
        for cmd in ("check", "render"):
            res.append(outcome(f"picture {path!r}: {cmd}", [cmd, f] + (["-q", "--no-settle"] if cmd == "render" else []), d,
                               timeout=120, protect=[pics / "link.png"]))
        f.write_text(BASE.replace('size = "A5"', f'size = "A5"\nbackground = {{picture = "{esc}"}}') + item("b", 'text = "t"', kind="text"))
        res.append(outcome(f"background {path!r}: render", ["render", f, "-q", "--no-settle"], d, timeout=120))
    return res


# ---------------------------------------------------------------- merge

@case
def merge_cases():
    d = fresh("merge")
    o, c = offer(d)
    header = c.read_text().splitlines()[0]
    row = c.read_text().splitlines()[1]
    cols = header.split(",")
    res = []

    def data(name, text, suffix=".csv", raw=None):
        f = d / f"{name}{suffix}"
        if raw is not None:
            f.write_bytes(raw)
        else:
            f.write_text(text)
        return f

    def run_merge(label, datafile, extra=(), expect=(0, 1, 3), template=o, timeout=300, **kw):
        out = d / ("out-" + label.replace(" ", "_").replace("/", "_")[:40])
        r = outcome(f"merge {label}", ["merge", template, datafile, "-o", out, "-q", "--workers", "1", *extra], d,
                    expect=expect, timeout=timeout, protect=[o, c] + kw.pop("protect", []), **kw)
        rep = out / "report.csv"
        if rep.exists():
            t = rep.read_text(errors="replace")
            for line in t.splitlines()[1:]:
                for cell in line.split(","):
                    if cell[:1] in ("=", "+", "-", "@") and not cell[:2].lstrip("-").isdigit():
                        r["flags"].append(f"formula cell in report.csv: {cell[:40]!r}")
                        break
            r["report"] = t[:300]
        return r

    def rowwith(**vals):
        v = dict(zip(cols, next(iter(__import__("csv").reader([row])))))
        v.update(vals)
        import csv, io
        s = io.StringIO()
        w = csv.writer(s)
        w.writerow(cols)
        w.writerow([v[k] for k in cols])
        return s.getvalue()

    res.append(run_merge("missing column", data("missing", "id,first_name\n1,A\n")))
    res.append(run_merge("extra columns", data("extra", header + ",x,y\n" + row + ",1,2\n")))
    res.append(run_merge("short row", data("short", header + "\n1001,Priya\n")))
    res.append(run_merge("NUL in value", data("nul", None, raw=(header + "\n" + row.replace("Priya", "Pr\x00iya") + "\n").encode())))
    res.append(run_merge("NUL in header", data("nulh", None, raw=(header.replace("id", "i\x00d", 1) + "\n" + row + "\n").encode())))
    res.append(run_merge("formula injection", data("formula", rowwith(first_name="=HYPERLINK(\"http://evil\",\"x\")", product="@SUM(1+1)*cmd|' /C calc'!A0", photo="=1+1.png"))))
    res.append(run_merge("formula in id for report", data("formula2", rowwith(id="=cmd|' /C calc'!A0", photo="missing.png"))))
    res.append(run_merge("jinja in value", data("jinja", rowwith(first_name="{{ 7*7 }}", product="{% for x in y %}{{x}}{% endfor %}", note="{first_name}"))))
    res.append(run_merge("format attr in value", data("fmtattr", rowwith(first_name="{0.__class__}", product="{id.__class__.__mro__}"))))
    res.append(run_merge("latex in value", data("latexv", rowwith(first_name="\\immediate\\write18{touch /tmp/hostile-input/pwned-merge}", product="\\input{/etc/passwd}^^5c", note="}}}}{{{{ %#&$_"))))
    res.append(run_merge("photo path traversal", data("trav", rowwith(photo="../../../../etc/passwd"))))
    res.append(run_merge("photo /dev/zero", data("devz", rowwith(photo="../../../../../../dev/zero"))))
    res.append(run_merge("photo absolute via ..", data("abs", rowwith(photo="/etc/hostname"))))
    res.append(run_merge("photo empty", data("pempty", rowwith(photo=""))))
    res.append(run_merge("photo folder", data("pdir", rowwith(photo="."))))
    res.append(run_merge("photo newline", data("pnl", rowwith(photo="bottle.png\nfoo"))))
    res.append(run_merge("huge value", data("huge", rowwith(product="x" * 2_000_000))))
    res.append(run_merge("value 100k word", data("word", rowwith(product="W" * 100_000))))
    res.append(run_merge("RTL/bidi in value", data("bidi", rowwith(first_name="\u202eevil\u202c", surname="\u200fשלום")))),
    res.append(run_merge("emoji value", data("emoji", rowwith(first_name="👨‍👩‍👧 \U0001F9D1\u200d\U0001F52C"))))
    res.append(run_merge("CRLF + BOM", data("crlf", None, raw=("\ufeff" + header + "\r\n" + row + "\r\n").encode())))
    res.append(run_merge("latin-1 csv", data("latin", None, raw=(header + "\n" + row.replace("Priya", "Café") + "\n").encode("latin-1", errors="replace"))))
    res.append(run_merge("utf-16 csv", data("u16", None, raw=(header + "\n" + row + "\n").encode("utf-16"))))
    res.append(run_merge("empty csv", data("empty", "")))
    res.append(run_merge("header only", data("honly", header + "\n")))
    res.append(run_merge("binary garbage csv", data("garb", None, raw=bytes(range(256)) * 20)))
    res.append(run_merge("quote never closes", data("quote", header + "\n" + row.replace("Priya", '"Priya') + "\n")))
    res.append(run_merge("header with spaces/dup", data("dup", header + ",id\n" + row + ",2\n")))
    res.append(run_merge("column name with braces", data("bcol", header.replace("note", "{note}") + "\n" + row + "\n")))
    res.append(run_merge("jsonl ok", data("ok", json.dumps(dict(zip(cols, next(iter(__import__('csv').reader([row])))))) + "\n", ".jsonl")))
    jl = dict(zip(cols, next(iter(__import__('csv').reader([row])))))
    res.append(run_merge("jsonl NaN", data("nan", json.dumps({**jl, "price": float("nan")}) + "\n", ".jsonl")))
    res.append(run_merge("jsonl Infinity/huge int", data("inf", json.dumps({**jl, "price": float("inf"), "id": 10**400}) + "\n", ".jsonl")))
    res.append(run_merge("jsonl huge int id", data("bigint", json.dumps(jl).replace('"1001"', "9" * 5000) + "\n", ".jsonl")))
    res.append(run_merge("jsonl duplicate keys", data("dupk", '{"id": "1", "id": "2", ' + json.dumps(jl)[1:].replace('"id": "1001", ', '') + "\n", ".jsonl")))
    res.append(run_merge("jsonl deep", data("deep", "[" * 100000 + "]" * 100000 + "\n", ".jsonl")))
    res.append(run_merge("jsonl nested values", data("nest", json.dumps({**jl, "first_name": {"a": 1}}) + "\n", ".jsonl")))
    res.append(run_merge("jsonl lone surrogate", data("surr", json.dumps(jl).replace("Priya", "\\ud800") + "\n", ".jsonl")))
    res.append(run_merge("jsonl NUL escape", data("nule", json.dumps(jl).replace("Priya", "\\u0000") + "\n", ".jsonl")))
    res.append(run_merge("jsonl key order differs", data("order", json.dumps(jl) + "\n" + json.dumps(dict(reversed(list(jl.items())))) + "\n" + json.dumps({"x": 1}) + "\n", ".jsonl")))
    res.append(run_merge("jsonl non-string keys (number)", data("numk", '{"1": 2}\n', ".jsonl")))
    res.append(run_merge(".json refused", data("arr", "[]", ".json")))
    res.append(run_merge("data is template", o))
    res.append(run_merge("data is /dev/zero", "/dev/zero"))
    res.append(run_merge("data is dir", d))
    res.append(run_merge("data is fifo", (lambda p: (os.mkfifo(p), p)[1])(d / "fifo.csv"), timeout=30))
    res.append(run_merge("data missing", d / "nope.csv"))
    # --name patterns
    ok = data("ok2", header + "\n" + row + "\n")
    for label, pat in {"name ../": "../{id}", "name absolute": "/tmp/hostile-input/abs-{id}", "name with slash col": "{surname}",
                       "name empty": "", "name report": "report", "name combined": "combined", "name newline": "a\n{id}",
                       "name NUL-like": "a\\0", "name dot": ".", "name dotdot": "..", "name unknown col": "{nope}",
                       "name jinja": "{{id}}", "name lone brace": "{id", "name 300 chars": "x" * 300 + "{id}",
                       "name with .toml": "{id}.toml", "name spaces": "  {id}  ", "name to template": "offer"}.items():
        extra = ["--name", pat]
        if label == "name to template":
            res.append(run_merge(label, ok, extra=extra + ["--toml"], protect=[o]))
        else:
            res.append(run_merge(label, ok, extra=extra, forbid=[d.parent / "1001.pdf", Path("/tmp/hostile-input/abs-1001.pdf")]))
    slash = data("slash", rowwith(surname="../../../hostile-escape"))
    res.append(run_merge("surname traversal in --name", slash, extra=["--name", "{surname}"], forbid=[ROOT / "hostile-escape.pdf", d.parent / "hostile-escape.pdf"]))
    res.append(run_merge("surname with slash", data("slash2", rowwith(surname="a/b")), extra=["--name", "{surname}"]))
    res.append(run_merge("surname NUL", data("slash3", None, raw=rowwith(surname="a\x00b").encode()), extra=["--name", "{surname}"]))
    res.append(run_merge("surname empty", data("slash4", rowwith(surname="")), extra=["--name", "{surname}"]))
    res.append(run_merge("surname dots", data("slash5", rowwith(surname="..")), extra=["--name", "{surname}"]))
    res.append(run_merge("surname 1000 chars", data("slash6", rowwith(surname="s" * 1000)), extra=["--name", "{surname}"]))
    res.append(run_merge("surname reserved CON", data("slash7", rowwith(surname="CON")), extra=["--name", "{surname}"]))
    two = data("two", header + "\n" + row + "\n" + row + "\n")
    res.append(run_merge("two records same name", two, extra=["--name", "{id}"]))
    # output dir oddities
    (d / "afile").write_text("x")
    res.append(run_merge("outdir is file", ok, protect=[d / "afile"]))
    (d / "outlink").symlink_to("/dev")
    r = outcome("merge outdir symlink to /dev", ["merge", o, ok, "-o", d / "outlink", "-q"], d, expect=(0, 1, 3), forbid=[Path("/dev/report.csv"), Path("/dev/record-00001.pdf")])
    res.append(r)
    res.append(outcome("merge outdir = template folder", ["merge", o, ok, "-o", d, "-q", "--toml", "--name", "offer"], d, expect=(0, 1, 3), protect=[o, ok]))
    res.append(outcome("merge outdir /dev/null", ["merge", o, ok, "-o", "/dev/null", "-q"], d, expect=(0, 1, 3)))
    (d / "outrep").mkdir()
    (d / "outrep" / "report.csv").symlink_to(d / "afile")
    res.append(outcome("merge report.csv is symlink", ["merge", o, ok, "-o", d / "outrep", "-q"], d, expect=(0, 1, 3), protect=[d / "afile", d / "outrep" / "report.csv"]))
    (d / "outpdf").mkdir()
    (d / "outpdf" / "record-00001.pdf").symlink_to(d / "afile")
    res.append(outcome("merge record pdf is symlink", ["merge", o, ok, "-o", d / "outpdf", "-q"], d, expect=(0, 1, 3), protect=[d / "afile", d / "outpdf" / "record-00001.pdf"]))
    (d / "outcomb").mkdir()
    (d / "outcomb" / "combined.pdf").mkdir()
    res.append(outcome("merge combined.pdf is dir", ["merge", o, ok, "-o", d / "outcomb", "-q", "--combined"], d, expect=(0, 1, 3)))
    # template oddities
    t2 = d / "t-jinja.toml"
    t2.write_text(o.read_text().replace('text = "{product}"', 'text = "{{ product }} {%if%} {product.__class__} {product!r} {product:>10}"'))
    res.append(run_merge("template jinja-ish", ok, template=t2))
    t3 = d / "t-lone.toml"
    t3.write_text(o.read_text().replace('text = "{product}"', 'text = "{product"'))
    res.append(run_merge("template lone brace", ok, template=t3))
    t4 = d / "t-colour.toml"
    t4.write_text(o.read_text().replace('color = "#2f2a24"', 'color = "{colour}"', 1))
    res.append(run_merge("template placeholder in colour", ok, template=t4))
    t5 = d / "t-id.toml"
    t5.write_text(o.read_text().replace('id = "product"', 'id = "{product}"'))
    res.append(run_merge("template placeholder in id", ok, template=t5))
    t6 = d / "t-nofields.toml"
    shutil.copy(SAMPLES / "greeting-card/greeting-card.toml", t6)
    res.append(run_merge("template without placeholders", ok, template=t6))
    # 10,000 records, all failing fast (missing picture) -> timing + report
    import csv, io
    s = io.StringIO()
    w = csv.writer(s)
    w.writerow(cols)
    base = next(iter(csv.reader([row])))
    for k in range(10000):
        v = list(base)
        v[0] = str(k)
        v[cols.index("photo")] = "missing.png"
        w.writerow(v)
    big = data("tenk", s.getvalue())
    res.append(run_merge("10000 records all failing", big, timeout=400))
    if Path("/tmp/hostile-input/pwned-merge").exists():
        res.append({"case": "merge shell escape", "rc": "-", "secs": 0, "flags": ["SHELL ESCAPE RAN"], "msg": ""})
    return res


# ---------------------------------------------------------------- new

@case
def new_cases():
    d = fresh("new")
    (d / "exists.toml").write_text("keep me")
    (d / "adir").mkdir()
    (d / "link.toml").symlink_to("target.toml")
    (d / "photos-file").write_text("x")
    (d / "emptyphotos").mkdir()
    (d / "badphotos").mkdir()
    (d / "badphotos" / "a.png").write_bytes(b"not a png")
    (d / "badphotos" / "b.jpg").write_bytes(b"")
    os.symlink("/dev/zero", d / "badphotos" / "c.png")
    os.mkfifo(d / "badphotos" / "d.png")
    from PIL import Image
    import struct, zlib

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    (d / "badphotos" / "bomb.png").write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 100000, 100000, 8, 2, 0, 0, 0)) + chunk(b"IEND", b""))
    Image.new("RGB", (30, 20), "red").save(d / "badphotos" / "ok.png")
    (d / "loopphotos").mkdir()
    os.symlink(d / "loopphotos", d / "loopphotos" / "self")
    res = []
    for label, argv, prot in [
        ("new over existing", ["card", "exists.toml"], [d / "exists.toml"]),
        ("new onto dir", ["card", "adir"], []),
        ("new onto dangling symlink", ["card", "link.toml"], [d / "link.toml"]),
        ("new to /dev/null", ["card", "/dev/null"], []),
        ("new in missing folder", ["card", "no/such/x.toml"], []),
        ("new without .toml", ["card", "plain"], []),
        ("new .pdf name", ["card", "x.pdf"], []),
        ("new year 0", ["calendar", "y0.toml", "--year", "0"], []),
        ("new year -5", ["calendar", "yneg.toml", "--year", "-5"], []),
        ("new year 10000", ["calendar", "ybig.toml", "--year", "10000"], []),
        ("new year 10**30", ["calendar", "yhuge.toml", "--year", "1" + "0" * 30], []),
        ("new album photos missing", ["album", "a1.toml", "--photos", "nope"], []),
        ("new album photos file", ["album", "a2.toml", "--photos", "photos-file"], []),
        ("new album photos empty", ["album", "a3.toml", "--photos", "emptyphotos"], []),
        ("new album bad photos", ["album", "a4.toml", "--photos", "badphotos"], []),
        ("new album photo loop", ["album", "a5.toml", "--photos", "loopphotos"], []),
        ("new album photos=/dev", ["album", "a6.toml", "--photos", "/dev"], []),
        ("new name with newline", ["card", "a\nb.toml"], []),
        ("new empty path", ["card", ""], []),
        ("new name .toml only", ["card", ".toml"], []),
    ]:
        res.append(outcome(label, ["new", *argv], d, protect=prot, forbid=[d / "target.toml"], timeout=120))
    return res


# ---------------------------------------------------------------- edit without a tty, CLI misc

@case
def misc_cases():
    d = fresh("misc")
    p = card(d)
    res = []
    res.append(outcome("edit in pipe", ["edit", p], d))
    res.append(outcome("render -j 0", ["render", p, "-j", "0"], d))
    res.append(outcome("render -j 100000", ["render", "-q", p, "-j", "100000", "-o", "j.pdf"], d, timeout=200))
    res.append(outcome("settle -j 99999999999999999999", ["settle", p, "-j", "99999999999999999999"], d, timeout=200))
    res.append(outcome("render --bleed nan", ["render", p, "--print", "--bleed", "nan"], d))
    res.append(outcome("render --bleed -0", ["render", "-q", p, "--print", "--bleed", "-0", "-o", "b.pdf"], d))
    res.append(outcome("render --bleed 1e-320", ["render", "-q", p, "--print", "--bleed", "1e-320", "-o", "b2.pdf"], d))
    res.append(outcome("edit --seed nan", ["edit", p, "--seed", "nan"], d))
    res.append(outcome("merge --chunk-size 10**20", ["merge", p, d / "x.csv", "-o", d / "o", "--chunk-size", "1" + "0" * 20], d))
    res.append(outcome("merge --dask bogus", ["merge", p, d / "x.csv", "-o", d / "o", "--dask", "tcp://256.0.0.1:1"], d, timeout=60))
    (d / "x.csv").write_text("a\n1\n")
    res.append(outcome("merge --dask bogus with data", ["merge", p, d / "x.csv", "-o", d / "o", "--dask", "tcp://256.0.0.1:1"], d, timeout=90, expect=(0, 1, 3)))
    res.append(outcome("merge --dask garbage scheme", ["merge", p, d / "x.csv", "-o", d / "o2", "--dask", "ftp://x"], d, timeout=90, expect=(0, 1, 3)))
    return res


# ---------------------------------------------------------------- found while fixing (second pass)

@case
def extra_cases():
    import csv as _csv
    d = fresh("extra")
    res = []
    p = card(d)
    shutil.copy(p, d / "other.toml")
    res.append(outcome("render -o another project .toml", ["render", "card.toml", "-q", "-o", "other.toml"], d,
                       protect=[d / "other.toml"]))
    for name in ("..", "/", "./", "sub/"):
        res.append(outcome(f"render -o {name!r}", ["render", "card.toml", "-q", "-o", name], d, protect=[p]))
    res.append(outcome("render --tex 'x/'", ["render", "card.toml", "-q", "--tex", "x/"], d, protect=[p]))
    # lock litter
    res.append(outcome("settle missing project (lock litter)", ["settle", "nope.toml"], d, forbid=[d / ".nope.toml.lock"]))
    res.append(outcome("settle /dev/zero (lock litter in /dev)", ["settle", "/dev/zero"], d, forbid=[Path("/dev/.zero.lock")]))
    # .bak that is a symlink to a precious file
    (d / "precious.txt").write_text("precious")
    (d / "card.toml.bak").symlink_to("precious.txt")
    perturb(p)
    res.append(outcome("settle with .bak a symlink to a precious file", ["settle", "card.toml"], d, protect=[d / "precious.txt"]))
    # immutable output
    (d / "imm.pdf").write_bytes(b"%PDF-old")
    subprocess.run(["chattr", "+i", str(d / "imm.pdf")])
    try:
        res.append(outcome("render -o immutable file", ["render", "card.toml", "-q", "-o", "imm.pdf"], d, protect=[d / "imm.pdf"]))
    finally:
        subprocess.run(["chattr", "-i", str(d / "imm.pdf")])
    # PDFs
    from PIL import Image
    import pikepdf, io, re as _re
    buf = io.BytesIO(); Image.new("RGB", (100, 50), "green").save(buf, "PDF"); good = buf.getvalue()
    def boxed(key, box):
        with pikepdf.open(io.BytesIO(good)) as pdf:
            pdf.pages[0][key] = pikepdf.Array(box); out = io.BytesIO(); pdf.save(out); return out.getvalue()
    m = _re.search(rb"startxref\s+(\d+)", good)
    pdfs = {"wide.pdf": boxed("/MediaBox", [0, 0, 28346, 100]), "speck.pdf": boxed("/CropBox", [0, 0, 0.01, 0.01]),
            "brokenxref.pdf": good[:m.start()] + b"startxref\n" + str(int(m.group(1)) + 7).encode() + b"\n%%EOF\n"}
    for name, data in pdfs.items():
        (d / "pictures" / name).write_bytes(data)
    Image.new("RGB", (300, 200), "red").save(d / "pictures" / "photo {1}.png")
    for name in list(pdfs) + ["photo {1}.png"]:
        f = d / "pic.toml"
        f.write_text(BASE + item("a", f'path = "pictures/{name}"', kind="picture", w=60, h=40))
        for cmd in ("check", "render"):
            res.append(outcome(f"picture {name}: {cmd}", [cmd, "pic.toml"] + (["-q", "--no-settle"] if cmd == "render" else []), d))
    f = d / "bg.toml"
    f.write_text(BASE.replace('size = "A5"', 'size = "A5"\nbackground = {picture = "pictures/{x}.png"}'))
    res.append(outcome("background placeholder outside merge: render", ["render", "-q", "bg.toml"], d))
    (d / "cr.toml").write_text((BASE + item("a")).replace("\n", "\r"))
    res.append(outcome("CR-only line ends: check", ["check", "cr.toml"], d, expect_text=["bare carriage return"]))
    # non-UTF-8 photo name
    (d / "photos").mkdir()
    Image.new("RGB", (400, 300), "red").save(os.fsdecode(os.fsencode(d / "photos") + b"/caf\xe9.png"))
    res.append(outcome("new album, photo name not UTF-8", ["new", "album", "al.toml", "--photos", "photos"], d))
    # merge: formula names, state dir link, JSON oddities, dask address
    o, c = offer(d / "m")
    rows = list(_csv.reader(open(c)))
    with open(d / "m" / "f.csv", "w", newline="") as h:
        w = _csv.writer(h); w.writerow(rows[0])
        for v in ['=HYPERLINK("http://evil.example","x")', "+1+1", "@SUM(A1)", "-2+3"]:
            r = list(rows[1]); r[0] = v; w.writerow(r)
    r = outcome("merge --name {id} with formula ids", ["merge", o, d / "m" / "f.csv", "-o", d / "m" / "of", "-q", "--name", "{id}"], d / "m", expect=(0, 3))
    for line in (d / "m" / "of" / "report.csv").read_text().splitlines()[1:]:
        cell = next(_csv.reader([line]))[2]
        if cell[:1] in "=+@-":
            r["flags"].append(f"formula cell {cell!r}")
    res.append(r)
    (d / "m" / "os").mkdir(); (d / "elsewhere").mkdir()
    (d / "m" / "os" / ".floatpage-merge").symlink_to(d / "elsewhere")
    r = outcome("merge state folder is a symlink", ["merge", o, c, "-o", d / "m" / "os", "-q"], d / "m", expect=(0, 1, 3))
    if list((d / "elsewhere").iterdir()):
        r["flags"].append("wrote through the state link")
    res.append(r)
    first = dict(zip(rows[0], rows[1]))
    lines = [json.dumps(first), json.dumps({k: v for k, v in first.items() if k != "first_name"}),
             json.dumps(first).replace(first["first_name"], "\\ud800"), "[1, 2]", json.dumps(first).replace('"1001"', "9" * 5000)]
    (d / "m" / "odd.jsonl").write_text("\n".join(lines) + "\n")
    res.append(outcome("merge jsonl: key left out, lone surrogate, no object, 5000-digit int", ["merge", o, d / "m" / "odd.jsonl", "-o", d / "m" / "oj", "-q", "--name", "{id}"], d / "m", expect=(0, 3)))
    for addr in ("ftp://x", "host", "tcp://h:port"):
        res.append(outcome(f"merge --dask {addr}", ["merge", o, c, "-o", d / "m" / "od", "-q", "--dask", addr], d / "m", timeout=90))
    return res


# ---------------------------------------------------------------- sixteenth session (hostile-2)

def leftovers(folder: Path) -> list[str]:
    """Temporaries and half-written files a run must not leave: *.floatpage-tmp*, *.part, build
    folders, empty PDFs."""
    found = []
    for path in Path(folder).rglob("*"):
        name = path.name
        if "floatpage-tmp" in name or name.endswith((".part", ".tmp")) or \
                (path.is_file() and path.suffix == ".pdf" and path.stat().st_size == 0):
            found.append(str(path.relative_to(folder)))
    return found


def whole_pdf(path: Path) -> bool:
    """Whether a PDF opens and ends (a killed writer leaves a cut one)."""
    try:
        import pikepdf

        with pikepdf.open(path) as pdf:
            return len(pdf.pages) > 0
    except Exception:
        return False


S16_TOMLS = {
    "bidi override in text": BASE + item("a", 'text = "price \u202e0.99$\u202c ok \u2066x\u2069"', kind="text", w=80),
    "bidi isolate unclosed in id": BASE + item("a\u2067b"),
    "C1 CSI in id": BASE + item("a\\u009b31mred"),
    "ESC sequence in text": BASE + item("a", 'text = "\\u001b]0;pwned\\u0007 \\u001b[2J"', kind="text", w=80),
    "ESC in title": BASE.replace('title = "T"', 'title = "\\u001b[31mT"') + item("a"),
    "NUL in text escape": BASE + item("a", 'text = "a\\u0000b"', kind="text", w=80),
    "NUL in picture path": BASE + item("a", 'path = "pictures/x.png\\u0000"', kind="picture"),
    "surrogate escape in text": BASE + item("a", 'text = "\\ud800"', kind="text", w=80),
    "surrogate pair escapes": BASE + item("a", 'text = "\\ud83d\\ude00"', kind="text", w=80),
    "10 MB text": BASE + item("a", 'text = "' + "lorem ipsum " * 870_000 + '"', kind="text", w=120, h=150),
    "10 MB id": BASE + item("i" * 10_000_000),
    "10 MB title": BASE.replace('title = "T"', 'title = "' + "T" * 10_000_000 + '"') + item("a"),
    "1 MB font name": BASE + item("a", 'text = "x"\nfont = "' + "f" * 1_000_000 + '"', kind="text"),
    "x = 5e-324": BASE + item("a", x=5e-324, y=5e-324),
    "w = 5e-324": BASE + item("a", w=5e-324, h=20.0),
    "x = -0.0": BASE + item("a", x=-0.0),
    "w = 1.7976931348623157e308": BASE + item("a", w=1.7976931348623157e308),
    "x = -1.7976931348623157e308": BASE + item("a", x=-1.7976931348623157e308),
    "x = inf": BASE + item("a", x="inf"),
    "x = -nan": BASE + item("a", x="-nan"),
    "size_pt 1e-300": BASE + item("a", 'text = "x"\nsize_pt = 1e-300', kind="text"),
    "size_pt 1e300": BASE + item("a", 'text = "x"\nsize_pt = 1e300', kind="text"),
    "size_pt 5e-324": BASE + item("a", 'text = "x"\nsize_pt = 5e-324', kind="text"),
    "opacity 1e-320": BASE + item("a", "opacity = 1e-320"),
    "z = 2**63-1": BASE + item("a", "z = 9223372036854775807") + item("b", "z = -9223372036854775808", x=80),
    "custom page 1e-300": BASE.replace('size = "A5"', 'size = "custom"\nwidth_mm = 1e-300\nheight_mm = 1e-300') + item("a", x=0, y=0, w=1e-300, h=1e-300),
    "custom page 5 m": BASE.replace('size = "A5"', 'size = "custom"\nwidth_mm = 5000.0\nheight_mm = 5000.0') + item("a", x=2500, y=2500, w=4000, h=4000),
    "gutter 5e-324": BASE.replace("[[pages]]", "[physics]\ngutter_mm = 5e-324\n\n[[pages]]") + item("a") + item("b", x=80),
    "margin -0.0": BASE.replace("[[pages]]", "[physics]\nmargin_mm = -0.0\n\n[[pages]]") + item("a") + item("b", x=80),
    "anchor dx 5e-324": BASE + item("a") + item("b", 'anchor = {to = "a", dx = 5e-324, dy = -0.0}', x=80),
    "nesting 500 arrays in z": BASE + item("a", "z = " + "[" * 500 + "]" * 500),
    "nesting 300 inline tables": BASE + item("a", "anchor = " + "{a = " * 300 + "1" + "}" * 300),
    "nesting 5000 arrays": BASE + item("a", "z = " + "[" * 5000 + "]" * 5000),
    "duplicate key in item": BASE + item("a", "x = 3.0"),
    "duplicate table [physics]": "[physics]\ngutter_mm = 3.0\n[physics]\ngutter_mm = 4.0\n" + BASE,
    "duplicate item ids on one page": BASE + item("a") + item("a", x=80),
    "duplicate page ids": BASE + item("a") + '\n[[pages]]\nid = "p"\nsize = "A5"\n' + item("b"),
    "anchor to duplicated id": BASE + item("a") + item("a", x=80) + item("b", 'anchor = {to = "a", dx = 5.0}', x=120),
    "duplicate region and group ids": BASE + '\n[[pages.regions]]\nid = "g"\nleft = 0.0\ntop = 0.0\nw = 80.0\nh = 80.0\n' + item("a", 'group = "g"\nregion = "g"') + item("b", 'group = "g"\nregion = "g"', x=60),
    "id differs by NFC/NFD": BASE + item("caf\u00e9") + item("cafe\u0301", x=80),
    "id differs by case": BASE + item("A") + item("a", x=80),
    "id whitespace only": BASE + item(" \\t "),
    "id empty": BASE + item(""),
    "text only NUL": BASE + item("a", 'text = "\\u0000\\u0000"', kind="text"),
    "text U+FFFE/U+FFFF": BASE + item("a", 'text = "\\uFFFE\\uFFFF\\U0010FFFF"', kind="text", w=80),
    "text 50k lines": BASE + item("a", 'text = "' + "a\\n" * 50_000 + '"', kind="text", w=80, h=100),
    "text 5000 zalgo marks on one letter": BASE + item("a", 'text = "a' + "\u0300\u0301\u0302\u0303" * 1250 + '"', kind="text", w=80),
    "text tag characters (emoji flags)": BASE + item("a", 'text = "\U0001F3F4\U000E0067\U000E0062\U000E0065\U000E006E\U000E0067\U000E007F"', kind="text", w=80),
    "role 1 MB": BASE + item("a", 'text = "x"\nrole = "' + "r" * 1_000_000 + '"', kind="text"),
    "colour short hex": BASE + item("a", 'color = "#fff"'),
    "colour 8-digit hex": BASE + item("a", 'color = "#ff000080"'),
    "colour named": BASE + item("a", 'color = "red"'),
    "colour with NUL": BASE + item("a", 'color = "#ff0000\\u0000"'),
}


def s16_pictures(pics: Path) -> dict[str, str]:
    """Pictures the fifteenth probe did not try; name -> file name in pics."""
    import io
    import struct
    import zlib

    from PIL import Image
    import numpy as np

    made = {}
    rng = np.random.default_rng(3)
    photo = Image.fromarray(rng.integers(0, 256, (300, 400, 3), dtype=np.uint8))

    def save(name, data):
        (pics / name).write_bytes(data)
        made[name] = name

    def encoded(img, fmt, **kw):
        buf = io.BytesIO()
        img.save(buf, fmt, **kw)
        return buf.getvalue()

    png, jpg = encoded(photo, "PNG"), encoded(photo, "JPEG", quality=90)
    save("trunc-half.png", png[: len(png) // 2])
    save("trunc-noiend.png", png[:-12])
    save("trunc-header.png", png[:40])
    save("trunc-half.jpg", jpg[: len(jpg) // 2])
    save("trunc-noeoi.jpg", jpg[:-2])
    save("trunc-sos.jpg", jpg[: jpg.find(b"\xff\xda") + 20])
    frames = [Image.new("RGB", (120, 80), c) for c in ("red", "green", "blue")]
    save("animated.gif", encoded(frames[0], "GIF", save_all=True, append_images=frames[1:], loop=0, duration=100))
    save("animated.png", encoded(frames[0], "PNG", save_all=True, append_images=frames[1:], duration=100))
    save("animated.webp", encoded(frames[0], "WEBP", save_all=True, append_images=frames[1:], duration=100))
    save("multipage.tiff", encoded(frames[0], "TIFF", save_all=True, append_images=frames[1:]))
    cmyk = photo.convert("CMYK")
    save("cmyk-adobe.jpg", encoded(cmyk, "JPEG", quality=90))
    save("cmyk.tiff", encoded(cmyk, "TIFF"))
    rgb16 = np.zeros((80, 120, 3), dtype=">u2")
    rgb16[..., 0] = 65535

    def png16(array):
        h, w = array.shape[:2]
        raw = b"".join(b"\x00" + row.tobytes() for row in array.reshape(h, -1))
        def chunk(kind, data):
            return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
        return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 16, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
    save("rgb16.png", png16(rgb16))
    save("gray16.png", encoded(Image.fromarray(np.full((80, 120), 40000, dtype=np.uint16)), "PNG"))
    save("one-by-100000.png", encoded(Image.new("L", (1, 100_000), 128), "PNG"))
    save("100000-by-1.jpg", encoded(Image.new("RGB", (60_000, 1), "red"), "JPEG"))
    save("one-pixel.png", encoded(Image.new("RGB", (1, 1), "red"), "PNG"))
    save("huge-9999x9999.png", encoded(Image.new("1", (9999, 9999), 1), "PNG"))
    save("over-100mpx.png", encoded(Image.new("1", (10_001, 10_001), 1), "PNG"))

    def pdf(mediabox=b"0 0 200 100", extra=b"", count=b"1"):
        return (b"%PDF-1.4\n1 0 obj<</Type/Catalog/Pages 2 0 R>>endobj\n"
                b"2 0 obj<</Type/Pages/Kids[3 0 R]/Count " + count + b">>endobj\n"
                b"3 0 obj<</Type/Page/Parent 2 0 R/MediaBox[" + mediabox + b"]" + extra + b">>endobj\n"
                b"trailer<</Root 1 0 R>>\n%%EOF\n")
    save("pdf-15000pt.pdf", pdf(b"0 0 15000 15000"))
    save("pdf-negative-box.pdf", pdf(b"100 100 0 0"))
    save("pdf-rotated-90.pdf", pdf(extra=b"/Rotate 90"))
    save("pdf-rotate-45.pdf", pdf(extra=b"/Rotate 45"))
    save("pdf-no-pages.pdf", pdf(count=b"0").replace(b"/Kids[3 0 R]", b"/Kids[]"))
    good = encoded(Image.new("RGB", (100, 50), "green"), "PDF")
    save("pdf-truncated.pdf", good[: len(good) // 2])
    save("pdf-no-eof.pdf", good[: good.rfind(b"%%EOF")])
    save("pdf-mediabox-nan.pdf", pdf(b"0 0 nan 100"))
    save("pdf-text-only-header.pdf", b"%PDF-1.7\n")
    try:
        import pikepdf

        with pikepdf.open(io.BytesIO(good)) as src:
            buf = io.BytesIO()
            src.save(buf, encryption=pikepdf.Encryption(owner="o", user="u"))
            save("pdf-encrypted.pdf", buf.getvalue())
    except Exception:
        pass
    return made


S16_MERGE_HEADER = "id,first_name,surname,product,price,photo,note,valid_until"
S16_ROW = "1001,Priya,Doe,Earl Grey,€2.40 a kilo,bottle.png,,31 May"


@case
def sixteenth_toml():
    d = fresh("s16toml")
    pics = d / "pictures"
    pics.mkdir()
    shutil.copy(next((SAMPLES / "greeting-card/pictures").iterdir()), pics / "x.png")
    res = []
    for name, text in S16_TOMLS.items():
        f = d / (f"t{len(res):03d}.toml")
        f.write_bytes(text.encode("utf-8", errors="surrogatepass"))
        for cmd in ("check", "settle", "render"):
            before = f.read_bytes()
            argv = [cmd, f] if cmd == "check" else [cmd, "-q", f]
            r = outcome(f"s16 toml {name}: {cmd}", argv, d, nan_check=[f], timeout=180)
            res.append(r)
            if cmd == "settle":
                f.write_bytes(before)
    return res


@case
def sixteenth_pictures():
    d = fresh("s16pics")
    pics = d / "pictures"
    pics.mkdir()
    res = []
    for name in s16_pictures(pics):
        f = d / "p.toml"
        f.write_text(BASE + item("a", f'path = "pictures/{name}"', kind="picture", w=60, h=40)
                     + item("b", 'text = "t"', kind="text", x=90, y=150))
        for cmd in ("check", "render"):
            out = d / "p.pdf"
            out.unlink(missing_ok=True)
            r = outcome(f"s16 picture {name}: {cmd}", [cmd, f] + (["-q", "--no-settle", "-o", out] if cmd == "render" else []),
                        d, timeout=180)
            if cmd == "render" and r["rc"] != 0 and out.exists():
                r["flags"].append("failed render left a PDF")
            if cmd == "render" and r["rc"] == 0 and not whole_pdf(out):
                r["flags"].append("render said ok, PDF not whole")
            res.append(r)
        f.write_text(BASE.replace('size = "A5"', f'size = "A5"\nbackground = {{picture = "pictures/{name}"}}')
                     + item("b", 'text = "t"', kind="text"))
        res.append(outcome(f"s16 background {name}: render", ["render", f, "-q", "--no-settle", "-o", d / "bg.pdf"], d, timeout=180))
    # the same pictures as photos for `new album`
    res.append(outcome("s16 new album from the odd pictures", ["new", "album", d / "al" / "al.toml", "--photos", pics],
                       d, timeout=180))
    r = outcome("s16 check the album made from them", ["check", d / "al" / "al.toml"], d, timeout=180)
    res.append(r)
    return res


@case
def sixteenth_merge_data():
    import csv as _csv

    d = fresh("s16merge")
    o, c = offer(d)
    res = []
    rows = list(_csv.reader(open(c, encoding="utf-8")))
    header, first = rows[0], rows[1]

    def merge(label, data, extra=(), expect=(0, 1, 3), timeout=300, check_report=True):
        out = d / ("out-" + str(len(res)))
        r = outcome(f"s16 merge {label}", ["merge", o, data, "-o", out, "-q", "--workers", "1", *extra], d,
                    expect=expect, timeout=timeout, protect=[o, c])
        left = leftovers(out) if out.exists() else []
        if left:
            r["flags"].append(f"left {left[:3]}")
        for pdf in out.glob("*.pdf") if out.exists() else []:
            if not whole_pdf(pdf):
                r["flags"].append(f"cut PDF {pdf.name}")
                break
        report = out / "report.csv"
        if check_report and report.exists():
            for line in list(_csv.reader(open(report, encoding="utf-8", newline="")))[1:]:
                if any(cell and cell[0] in "=+@-\t\r" and cell != "-" for cell in line):
                    r["flags"].append(f"formula cell in report {line}")
                    break
        res.append(r)
        return r

    def write(name, raw: bytes) -> Path:
        f = d / name
        f.write_bytes(raw)
        return f

    lines = [",".join(header), S16_ROW, S16_ROW.replace("1001", "1002")]
    merge("csv BOM + mixed newlines", write("mixed.csv", ("\ufeff" + lines[0] + "\r\n" + lines[1] + "\n" + lines[2] + "\r").encode()))
    merge("csv CR only", write("cr.csv", ("\r".join(lines) + "\r").encode()))
    merge("csv BOM twice", write("bom2.csv", ("\ufeff\ufeff" + "\n".join(lines) + "\n").encode()))
    merge("csv UTF-16 BOM", write("u16bom.csv", ("\n".join(lines) + "\n").encode("utf-16-le").join([b"\xff\xfe", b""])))
    merge("csv UTF-8 BOM header has spaces", write("spaces.csv", ("\ufeff" + " , ".join(header) + "\n" + S16_ROW + "\n").encode()))
    merge("jsonl with BOM", write("bom.jsonl", ("\ufeff" + json.dumps(dict(zip(header, first))) + "\n").encode()))
    merge("jsonl CRLF + blank lines", write("crlf.jsonl", ("\r\n" + json.dumps(dict(zip(header, first))) + "\r\n\r\n").encode()))
    merge("jsonl BOM on line 2", write("bom2.jsonl", (json.dumps(dict(zip(header, first))) + "\n\ufeff" + json.dumps(dict(zip(header, first))).replace("1001", "1002") + "\n").encode()))
    merge("jsonl U+2028 inside value", write("ls.jsonl", (json.dumps(dict(zip(header, first)), ensure_ascii=False).replace("Priya", "Pri\u2028ya") + "\n").encode()))
    inj = ["=1+1", "+cmd|' /C calc'!A0", "-2+3", "@SUM(A1)", "\t=1", "\r=1", "=HYPERLINK(\"x\")"]
    f = d / "inj.csv"
    with open(f, "w", newline="", encoding="utf-8") as h:
        w = _csv.writer(h)
        w.writerow(header)
        for k, v in enumerate(inj):
            row = list(first)
            row[0] = v
            row[5] = v + ".png"  # missing photo: report names it
            w.writerow(row)
    merge("formula injection in ids and photos", f, extra=["--name", "rec-{first_name}-" + "{surname}"])
    merge("formula injection as --name", f, extra=["--name", "{id}"])
    big = d / "big.csv"
    with open(big, "w", newline="", encoding="utf-8") as h:
        w = _csv.writer(h)
        w.writerow(header)
        for k in range(100_000):
            row = list(first)
            row[0] = str(k)
            row[5] = "missing.png"
            w.writerow(row)
    merge("100k rows, all failing (missing photo)", big, timeout=900)
    noc = d / "noc.csv"
    noc.write_text(",".join(h for h in header if h != "photo") + "\n" + ",".join(v for h, v in zip(header, first) if h != "photo") + "\n")
    merge("missing column photo", noc, expect=(1,))
    part = d / "part.jsonl"
    part.write_text(json.dumps(dict(zip(header, first))) + "\n" + json.dumps({k: v for k, v in zip(header, first) if k != "product"}) + "\n")
    merge("jsonl record missing a column", part)
    return res


@case
def sixteenth_cli():
    d = fresh("s16cli")
    p = card(d)
    res = []
    os.mkfifo(d / "pipe.tex")
    (d / "out").mkdir()
    for label, argv, prot in [
        ("render -o a folder", ["render", "-q", p, "-o", d / "out"], [p]),
        ("render --tex to a FIFO", ["render", "-q", p, "--tex", d / "pipe.tex", "-o", d / "x.pdf"], [p]),
        ("render -o the project itself, --print", ["render", "-q", p, "--print", "-o", p], [p]),
        ("render --print --fragment", ["render", "-q", p, "--print", "--fragment", d / "f.tex", "-o", d / "f.pdf"], [p]),
        ("render --print --bleed 20", ["render", "-q", p, "--print", "--bleed", "20", "-o", d / "b20.pdf"], [p]),
        ("render --print --bleed 20.0001", ["render", "-q", p, "--print", "--bleed", "20.0001", "-o", d / "b21.pdf"], [p]),
        ("render --bleed without --print", ["render", "-q", p, "--bleed", "3", "-o", d / "nb.pdf"], [p]),
        ("render -o /dev/stdout", ["render", "-q", p, "-o", "/dev/stdout"], [p]),
        ("render -o to /proc", ["render", "-q", p, "-o", "/proc/x.pdf"], [p]),
        ("render -o a .bak of the project", ["render", "-q", p, "-o", str(p) + ".bak"], [p]),
        ("check -o", ["check", p, "-o", d / "c.pdf"], [p]),
        ("settle --print", ["settle", p, "--print"], []),
        ("render --no-settle --print -j 2", ["render", "-q", p, "--no-settle", "--print", "-j", "2", "-o", d / "j.pdf"], [p]),
    ]:
        res.append(outcome(f"s16 {label}", argv, d, protect=prot, timeout=180))
    for kind in ("blank", "calendar", "card", "album", "flyer"):
        t = d / kind / f"{kind}.toml"
        res.append(outcome(f"s16 new {kind}", ["new", kind, t], d, timeout=180))
        out = d / kind / f"{kind}-print.pdf"
        r = outcome(f"s16 render --print {kind}", ["render", "-q", t, "--print", "-o", out], d, timeout=400, protect=[t])
        if r["rc"] == 0:
            try:
                import pikepdf

                with pikepdf.open(out) as pdf:
                    for number, page in enumerate(pdf.pages, 1):
                        if "/TrimBox" not in page.obj or "/BleedBox" not in page.obj:
                            r["flags"].append(f"page {number} lacks TrimBox/BleedBox")
                            break
            except Exception as error:
                r["flags"].append(f"PDF unreadable: {error}")
        res.append(r)
    return res


def interrupt(label, argv, cwd, after_s, sig, protect=(), watch=None, when_exists=None):
    """Start a command, send ``sig`` after ``after_s`` seconds (or as soon as ``when_exists``
    appears), then look for what it left.  SIGINT is reset to its default in the child: a
    probe started in the background (`cmd &`) hands its children SIGINT ignored, as shells do,
    and Python then keeps ignoring it."""
    import signal as _signal

    env = {**os.environ, "FLOATPAGE_CACHE_DIR": str(ROOT / "cache")}
    before = snapshot(protect)
    start = time.time()
    proc = subprocess.Popen([FP, *map(str, argv)], cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            stdin=subprocess.DEVNULL, env=env,
                            preexec_fn=lambda: _signal.signal(_signal.SIGINT, _signal.SIG_DFL))
    if when_exists is not None:
        while not os.path.lexists(when_exists) and proc.poll() is None and time.time() - start < 30:
            time.sleep(0.002)
    else:
        time.sleep(after_s)
    proc.send_signal(getattr(_signal, sig))
    try:
        out, err = proc.communicate(timeout=120)
    except subprocess.TimeoutExpired:
        proc.kill()
        out, err = proc.communicate()
        err += b"\n(TIMEOUT after the signal)"
    err = err.decode(errors="replace")
    flags = []
    if "Traceback" in err or "internal error" in err:
        flags.append("traceback/internal error")
    if proc.returncode not in (0, 1, 3, 130, -2, -15, 143):
        flags.append(f"exit {proc.returncode}")
    if "TIMEOUT" in err:
        flags.append("did not stop")
    after = snapshot(protect)
    for k in before:
        if before[k] != after[k]:
            flags.append(f"changed {k}")
    if watch is not None and Path(watch).exists():
        left = leftovers(watch)
        if left:
            flags.append(f"left {left[:3]}")
        for pdf in Path(watch).rglob("*.pdf"):
            if not whole_pdf(pdf):
                flags.append(f"cut PDF {pdf.name}")
                break
    r = {"case": label, "rc": proc.returncode, "secs": round(time.time() - start, 1), "flags": flags,
         "msg": " | ".join(err.strip().splitlines()[:2])[:300]}
    print(f"{'FLAG' if flags else 'ok  '} {label[:70]:70} rc={proc.returncode} {r['secs']}s {';'.join(flags)} :: {r['msg'][:200]}", flush=True)
    return r


@case
def sixteenth_interrupts():
    d = fresh("s16int")
    res = []
    cal = d / "cal" / "calendar.toml"
    cal.parent.mkdir()
    shutil.copytree(SAMPLES / "calendar-2027", cal.parent, dirs_exist_ok=True)
    cal = cal.parent / "calendar-2027.toml"
    perturb_cal = cal.read_text()
    for sig in ("SIGINT", "SIGTERM"):
        for after in (0.8, 2.5, 6.0):
            out = d / "cal" / f"r-{sig}-{after}.pdf"
            r = interrupt(f"s16 {sig} render calendar after {after}s", ["render", "-q", cal, "-o", out], d, after, sig,
                          protect=[cal], watch=d / "cal")
            if out.exists() and not whole_pdf(out):
                r["flags"].append("half-written PDF at -o")
            res.append(r)
        r = interrupt(f"s16 {sig} settle calendar after 1.0s", ["settle", "-q", cal], d, 1.0, sig, watch=d / "cal")
        try:
            from floatpage.model import load_project
            load_project(cal)
        except Exception as error:
            r["flags"].append(f"project unreadable after: {error}")
        cal.write_text(perturb_cal)
        res.append(r)
    o, c = offer(d / "m")
    for sig in ("SIGINT", "SIGTERM"):
        for after in (1.5, 5.0, 12.0):
            out = d / "m" / f"out-{sig}-{after}"
            r = interrupt(f"s16 {sig} merge after {after}s", ["merge", o, c, "-o", out, "-q", "--workers", "2", "--combined"],
                          d / "m", after, sig, protect=[o, c], watch=out)
            res.append(r)
            # a second run must finish what the first left, and agree with itself
            res.append(outcome(f"s16 merge again after {sig} at {after}s", ["merge", o, c, "-o", out, "-q", "--workers", "2", "--combined"],
                               d / "m", expect=(0, 3), timeout=600, protect=[o, c]))
    album_photos = d / "photos"
    album_photos.mkdir()
    from PIL import Image
    for k in range(30):
        Image.new("RGB", (300 + k, 200), (k * 8, 90, 60)).save(album_photos / f"p{k:02d}.png")
    for sig in ("SIGINT", "SIGTERM"):
        target = d / f"new-{sig}" / "album.toml"
        r = interrupt(f"s16 {sig} new album once its pictures/ appears", ["new", "album", target, "--photos", album_photos], d,
                      0.0, sig, when_exists=target.parent / "pictures" / "p29.png")
        if r["rc"] != 0 and target.parent.exists() and any(target.parent.iterdir()):
            r["flags"].append(f"interrupted new left {sorted(p.name for p in target.parent.iterdir())[:4]}")
        res.append(r)
    return res


def main():
    ROOT.mkdir(parents=True, exist_ok=True)
    flt = sys.argv[1] if len(sys.argv) > 1 else ""
    results = []
    for fn in CASES:
        if flt and flt not in fn.__name__:
            continue
        t = time.time()
        got = fn()
        for r in got:
            results.append(r)
        print(f"# {fn.__name__}: {time.time() - t:.0f}s", flush=True)
    out = ROOT.parent / f"results-{flt or 'all'}.json"
    out.write_text(json.dumps(results, indent=1))
    print(f"{sum(1 for r in results if r['flags'])} flagged of {len(results)}")


if __name__ == "__main__":
    main()
