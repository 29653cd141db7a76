"""How fast `floatpage merge` makes personalised flyers, against a naive loop.

    .venv/bin/python benchmarks/merge.py                 # 1,000 records, local pool
    .venv/bin/python benchmarks/merge.py --dask          # also through a Dask LocalCluster
    .venv/bin/python benchmarks/merge.py --records 200 --naive 20
    .venv/bin/python benchmarks/merge.py --memory 1000 10000 100000   # the client's peak memory

The naive loop is what a user would script without merge: for each record, a filled
project file and one `floatpage render` (which settles it again), one process each.
Both run in the same session on the same machine, so their ratio is what to compare; half
the naive renders run before the merge and half after, so a load that drifts meanwhile
weighs on both.
Data: benchmarks/merge_data.py, names, products, prices, notes and picture proportions
from 1:3 to 3:1, with the sample template sample_projects/merge-offers/offer.toml.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from merge_data import draw_pictures, write_customers  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
FLOATPAGE = str(Path(sys.executable).with_name("floatpage"))
TEMPLATE = ROOT / "sample_projects" / "merge-offers" / "offer.toml"


def naive_files(folder: Path, data: Path, count: int) -> list[Path]:
    """A filled project file per record, as a script without merge would write them."""
    from floatpage.merge.records import DataFile
    from floatpage.merge.record_layout import fill_record
    from floatpage.merge.template import MergeTemplate
    from floatpage.model.save import dump_project

    template = MergeTemplate(folder / TEMPLATE.name)
    files = []
    for record, _ in zip(DataFile(data).records(), range(count)):
        project = fill_record(template, record.values)
        path = folder / f"naive-{record.number:05d}.toml"
        path.write_text(dump_project(project), encoding="utf-8")
        files.append(path)
    return files


def naive_renders(files: list[Path]) -> float:
    """Seconds for one `floatpage render` process per file, as a shell loop would run them."""
    started = time.perf_counter()
    for path in files:
        subprocess.run([FLOATPAGE, "render", str(path), "-q"], check=True,
                       stdout=subprocess.DEVNULL)
    return time.perf_counter() - started


def merge_run(folder: Path, data: Path, out: str, *extra: str) -> float:
    started = time.perf_counter()
    done = subprocess.run([FLOATPAGE, "merge", str(folder / TEMPLATE.name), str(data), "-o",
                           str(folder / out), "-q", "--name", "{id}", *extra],
                          capture_output=True, text=True)
    seconds = time.perf_counter() - started
    if done.returncode != 0:
        sys.exit(f"merge failed ({done.returncode}): {done.stderr}")
    return seconds


def peak_memory(folder: Path, records: int) -> tuple[float, float]:
    """Peak resident memory (MB) of the `floatpage merge` process itself, and seconds, for a
    data file of `records` rows that each fail at once (a missing picture): what grows with
    the data file is the client's part, reading, planning, reporting, not the typesetting."""
    data = folder / f"memory-{records}.csv"
    with data.open("w", encoding="utf-8") as handle:
        handle.write("id,first_name,surname,product,price,photo,note,valid_until\n")
        for number in range(records):
            handle.write(f"{number},Ana,Silva,Pears,€1,missing-{number}.png,,1 May\n")
    started = time.perf_counter()
    process = subprocess.Popen([FLOATPAGE, "merge", str(folder / TEMPLATE.name), str(data), "-o",
                                str(folder / f"memory-{records}"), "-q", "--name", "{id}"],
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    peak = 0
    while process.poll() is None:
        try:
            status = Path(f"/proc/{process.pid}/status").read_text()
            peak = max(peak, int(status.split("VmHWM:")[1].split()[0]))
        except (OSError, IndexError):
            pass
        time.sleep(0.05)
    return peak / 1024, time.perf_counter() - started


def load() -> str:
    """How busy the machine is: its ratios hold within one run, its seconds do not."""
    one, five, _ = os.getloadavg()
    return f"load {one:.1f} (5 min {five:.1f}) on {os.cpu_count()} cores"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--records", type=int, default=1000)
    parser.add_argument("--naive", type=int, default=50, help="naive renders to time")
    parser.add_argument("--dask", action="store_true", help="also time --dask local")
    parser.add_argument("--memory", type=int, nargs="+", metavar="RECORDS",
                        help="only measure the client's peak memory for these data sizes")
    args = parser.parse_args()
    folder = Path(tempfile.mkdtemp(prefix="floatpage-merge-bench-"))
    try:
        shutil.copy(TEMPLATE, folder / TEMPLATE.name)
        if args.memory:
            for records in args.memory:
                peak, seconds = peak_memory(folder, records)
                print(f"{records:>7} records: peak {peak:.0f} MB in the merge process "
                      f"({seconds:.0f} s, every record failing at once)")
            return
        pictures = draw_pictures(folder / "pictures", 24)
        data = folder / "customers.csv"
        write_customers(data, args.records, pictures)
        merge_run(folder, data, "warm-up", "--force")  # fonts and picture caches, as in use
        shutil.rmtree(folder / "warm-up")
        print(f"start: {load()}", flush=True)
        # Half the naive renders before the merge and half after: the machine's load drifts
        # (five other developers share it), and the ratio should not depend on when.
        files = naive_files(folder, data, args.naive)
        before = naive_renders(files[:len(files) // 2])
        local = merge_run(folder, data, "local")
        print(f"merge, local pool: {args.records} records in {local:.1f} s = "
              f"{args.records / local:.2f} records/s ({load()})", flush=True)
        after = naive_renders(files[len(files) // 2:])
        naive = before + after
        naive_rate = args.naive / naive
        print(f"naive loop: {args.naive} renders in {naive:.1f} s = {naive_rate:.2f} records/s "
              f"({before:.1f} s for the first half, before the merge; {load()})", flush=True)
        local_rate = args.records / local
        print(f"merge: {local_rate / naive_rate:.1f}x the naive loop", flush=True)
        again = merge_run(folder, data, "local")
        print(f"merge again, nothing changed: {again:.1f} s (every record skipped)")
        if args.dask:
            dask = merge_run(folder, data, "dask", "--dask", "local")
            print(f"merge, --dask local: {args.records} records in {dask:.1f} s = "
                  f"{args.records / dask:.2f} records/s, {dask / local:.2f}x the local pool's time "
                  f"({load()})", flush=True)
            same = all((folder / "dask" / p.name).read_bytes() == p.read_bytes()
                       for p in (folder / "local").glob("*.pdf"))
            print(f"dask PDFs byte-identical to the local pool's: {same}")
    finally:
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
