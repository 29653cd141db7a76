"""Where chunks run: a local process pool, or a Dask distributed cluster.

Both take an iterator of tasks and yield each chunk's results as it completes, with at
most a few chunks in flight per worker, so memory stays flat however long the data file.
Dask's own machinery does the scheduling: `Client.submit` with retries, and `as_completed`;
a task of a worker that dies is run again on another by the scheduler.
"""

from __future__ import annotations

import multiprocessing
import os
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from typing import Iterator

from floatpage.merge.chunk_job import ChunkTask, RecordResult, run_chunk
from floatpage.model.errors import FloatpageError
from floatpage.model.lifeline import end_with
from floatpage.model.socket_folder import fit_socket_folder
from floatpage.model.page_pool import stop_pool

IN_FLIGHT_PER_WORKER = 2


def cores() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:
        return os.cpu_count() or 1


def local_results(tasks: Iterator[ChunkTask], workers: int) -> Iterator[list[RecordResult]]:
    # forkserver: workers start from a clean process, not a fork of one holding threads.
    fit_socket_folder()
    context = multiprocessing.get_context("forkserver")
    # A command killed outright (kill -9, a CI timeout) takes its workers with it.
    executor = ProcessPoolExecutor(workers, mp_context=context, initializer=end_with,
                                   initargs=(os.getpid(),))
    pending: set = set()
    try:
        for task in tasks:
            pending.add(executor.submit(run_chunk, task))
            while len(pending) >= workers * IN_FLIGHT_PER_WORKER:
                done, pending = wait(pending, return_when=FIRST_COMPLETED)
                for future in done:
                    yield future.result()
        while pending:
            done, pending = wait(pending, return_when=FIRST_COMPLETED)
            for future in done:
                yield future.result()
    finally:
        # Interrupted (Ctrl+C): stop the workers now, rather than finishing their chunks;
        # their LuaLaTeX dies with them (PR_SET_PDEATHSIG).
        if pending:
            stop_pool(executor)
        else:
            executor.shutdown()


def dask_client(address: str, workers: int):
    try:
        from distributed import Client, LocalCluster
    except ImportError:
        raise FloatpageError("--dask needs Dask's distributed package: pip install "
                             "'floatpage[cluster]'") from None
    if address == "local":
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        return Client(cluster), cluster
    try:
        return Client(address, timeout="20s"), None
    except (OSError, TimeoutError) as error:
        raise FloatpageError(f"--dask {address}: no Dask scheduler answered ({error}); start "
                             "one with `dask scheduler`, or use --dask local") from None
    except ValueError as error:  # `ftp://x`, `host` without a port: was an internal error
        raise FloatpageError(f"--dask {address}: not a scheduler's address ({error}); give "
                             "tcp://HOST:PORT (a `dask scheduler` prints it, port 8786 by "
                             "default), or --dask local") from None


def dask_results(tasks: Iterator[ChunkTask], address: str, workers: int, retries: int = 3
                 ) -> Iterator[list[RecordResult]]:
    from distributed import as_completed

    client, cluster = dask_client(address, workers)
    try:
        width = max(1, sum(client.nthreads().values())) * IN_FLIGHT_PER_WORKER
        queue = iter(tasks)
        # range first: zip stops on it without pulling (and losing) one more task from queue
        first = [client.submit(run_chunk, task, retries=retries, pure=False)
                 for _, task in zip(range(width), queue)]
        flow = as_completed(first)
        for future in flow:
            yield future.result()
            future.release()
            following = next(queue, None)
            if following is not None:
                flow.add(client.submit(run_chunk, following, retries=retries, pure=False))
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
