"""A sweep distributed with Dask (python3-distributed).

In a script, start the cluster under `if __name__ == "__main__":`. Dask's
worker processes start by importing the script again; without the guard each
of them would start a cluster of its own, and the script hangs:

    from dask.distributed import Client, LocalCluster
    import skipnc.dask_sweep as ds

    if __name__ == "__main__":
        with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, \\
                Client(cluster) as client:
            sweep, table = ds.run(client, "feeds.sweep.toml", chunk=500)

The scenarios are cut into chunks, each chunk runs on a worker through the
Python module, and the chunks' tables come back as one table, the same as
`skipnc sweep` writes for the same spec and seed (a scenario's values depend
only on the seed and its index). docs/python.md shows a run on several
machines.
"""
import functools
import os

from . import Sweep, concat


@functools.lru_cache(maxsize=8)
def _plan(spec, scenarios, seed):
    # One load per worker process and spec: the machine, scene and program
    # are read once, not once per chunk.
    return Sweep(spec, scenarios, seed)


def _run_chunk(spec, scenarios, seed, begin, end, threads):
    return _plan(spec, scenarios, seed).run(begin, end, threads)


def run(client, spec, *, scenarios=None, seed=None, chunk=256, threads=1, csv=None,
        json_path=None):
    """Runs every scenario of `spec` on the client's workers, `chunk`
    scenarios per task, each task on `threads` threads. The spec and the
    files it names must be readable at the same path on every worker (a
    shared folder). Returns (Sweep, table): the table a dict of NumPy arrays
    keyed by column name (Sweep.columns), in scenario order; writes the CSV
    and JSON tables of `skipnc sweep` when paths are given."""
    spec = os.path.abspath(os.fspath(spec))
    local = Sweep(spec, scenarios, seed)
    n = local.count
    bounds = [(b, min(b + chunk, n)) for b in range(0, n, chunk)]
    futures = [client.submit(_run_chunk, spec, scenarios, local.seed, b, e, threads,
                             pure=False) for b, e in bounds]
    table = concat(client.gather(futures)) if futures else local.run(0, 0)
    if csv:
        with open(csv, "w", encoding="utf-8") as f:
            f.write(local.csv(table))
    if json_path:
        with open(json_path, "w", encoding="utf-8") as f:
            f.write(local.json(table))
    return local, table
