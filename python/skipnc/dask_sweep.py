"""A sweep distributed with Dask (python3-distributed): the scenarios are cut
into chunks, each chunk runs on a worker through the Python module, and the
rows come back to be written as one table, the same as `skipnc sweep` writes
for the same spec and seed (a scenario's values depend only on the seed and
its index). docs/python.md shows a run on several machines.

    from dask.distributed import Client, LocalCluster
    import skipnc.dask_sweep as ds
    with Client(LocalCluster(n_workers=2, threads_per_worker=1)) as client:
        sweep, rows = ds.run(client, "feeds.sweep.toml", chunk=500)
"""
import functools
import os

from . import Sweep


@functools.lru_cache(maxsize=8)
def _plan(spec, scenarios, seed):
    # One load per worker process and spec: the machine, scene and program
    # are read once, not once per chunk.
    return Sweep(spec, scenarios, seed)


def _run_chunk(spec, scenarios, seed, begin, end, threads):
    return _plan(spec, scenarios, seed).run(begin, end, threads)


def run(client, spec, *, scenarios=None, seed=None, chunk=256, threads=1, csv=None,
        json_path=None):
    """Runs every scenario of `spec` on the client's workers, `chunk` scenarios
    per task, each task on `threads` threads. The spec and the files it names
    must be readable at the same path on every worker (a shared folder).
    Returns (Sweep, rows) with the rows in scenario order."""
    spec = os.path.abspath(os.fspath(spec))
    local = Sweep(spec, scenarios, seed)
    n = local.count
    bounds = [(b, min(b + chunk, n)) for b in range(0, n, chunk)]
    futures = [client.submit(_run_chunk, spec, scenarios, local.seed, b, e, threads,
                             pure=False) for b, e in bounds]
    rows = [row for part in client.gather(futures) for row in part]
    if csv:
        with open(csv, "w", encoding="utf-8") as f:
            f.write(local.csv(rows))
    if json_path:
        with open(json_path, "w", encoding="utf-8") as f:
            f.write(local.json(rows))
    return local, rows
