"""The Dask path on a real distributed.LocalCluster with two worker processes."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

from distributed import Client, LocalCluster

from floatpage.merge.run import Merge, MergeOptions
from merge_helpers import rows, write_csv

FLOATPAGE = str(Path(sys.executable).with_name("floatpage"))
RECORDS = 12


def pdfs(folder: Path) -> dict[str, bytes]:
    return {path.name: path.read_bytes() for path in folder.glob("*.pdf")}


def kill_a_worker_once_work_is_done(cluster: LocalCluster, out: Path, killed: list) -> None:
    """SIGKILL one worker process as soon as the first record is written, mid-run."""
    deadline = time.monotonic() + 300
    while time.monotonic() < deadline and not list(out.glob("*.pdf")):
        time.sleep(0.02)
    with Client(cluster) as client:
        pids = client.run(os.getpid)
    victim = sorted(pids.values())[0]
    killed.append((victim, len(list(out.glob("*.pdf")))))
    os.kill(victim, signal.SIGKILL)


def test_a_cluster_makes_the_local_pools_bytes_and_survives_a_killed_worker(merge_folder):
    data = write_csv(merge_folder / "customers.csv", rows(RECORDS))
    local = subprocess.run([FLOATPAGE, "merge", str(merge_folder / "offer.toml"), str(data),
                            "-o", str(merge_folder / "local"), "--chunk-size", "3", "-q"],
                           capture_output=True, text=True, timeout=600)
    assert local.returncode == 0, local.stderr
    out = merge_folder / "dask"
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster:
        killed: list = []
        killer = threading.Thread(target=kill_a_worker_once_work_is_done,
                                  args=(cluster, out, killed))
        killer.start()
        summary = Merge(MergeOptions(merge_folder / "offer.toml", data, out, chunk_size=2,
                                     dask=cluster.scheduler_address)).run()
        killer.join()
    assert killed and killed[0][1] < RECORDS, "the worker was killed after the run, not in it"
    assert (summary.made, summary.failed) == (RECORDS, 0)
    report = (out / "report.csv").read_text(encoding="utf-8").splitlines()
    assert len(report) == RECORDS + 1  # every record once, however often its chunk ran
    assert [line.split(",")[0] for line in report[1:]] == [str(n) for n in range(1, RECORDS + 1)]
    assert pdfs(out) == pdfs(merge_folder / "local")


def test_dask_local_starts_its_own_cluster_with_the_same_bytes(merge_folder):
    data = write_csv(merge_folder / "customers.csv", rows(4))
    for out, extra in (("local", []), ("dask", ["--dask", "local", "--pictures", "ship"])):
        done = subprocess.run([FLOATPAGE, "merge", str(merge_folder / "offer.toml"), str(data),
                               "-o", str(merge_folder / out), "-q", "--workers", "2", *extra],
                              capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, done.stderr
    assert len(pdfs(merge_folder / "dask")) == 4
    assert pdfs(merge_folder / "dask") == pdfs(merge_folder / "local")
