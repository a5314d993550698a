#!/usr/bin/env python3
"""A sweep on a Dask cluster of local worker processes (python3-distributed).

Keep the `if __name__ == "__main__":` guard when you copy this: Dask's worker
processes import the script again, and without the guard each would start a
cluster of its own and the script would hang.

Run from a build: PYTHONPATH=build/python python3 examples/python/dask_sweep.py \\
    tests/sweep/touch.sweep.toml --csv touch.csv
"""
import argparse

from dask.distributed import Client, LocalCluster

import skipnc.dask_sweep as ds


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("spec", help="sweep spec (docs/cli.md)")
    ap.add_argument("--workers", type=int, default=2, help="worker processes")
    ap.add_argument("--chunk", type=int, default=256, help="scenarios per task")
    ap.add_argument("--csv", help="write the table skipnc sweep writes here")
    a = ap.parse_args()
    with LocalCluster(n_workers=a.workers, threads_per_worker=1,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        sweep, table = ds.run(client, a.spec, chunk=a.chunk, csv=a.csv)
    print(sweep.summary(table))


if __name__ == "__main__":
    main()
