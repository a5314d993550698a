"""Sweeps through the module: tables of named columns, the same table as
`skipnc sweep` whatever the number of workers or the chunks, and on a Dask
local cluster."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

import skipnc

SRC = os.environ["SKIPNC_SOURCE_DIR"]
SPEC = os.path.join(SRC, "tests", "sweep", "touch.sweep.toml")


def test_the_table_is_named_columns_that_follow_the_exact_latch_rule():
    s, t = skipnc.sweep(SPEC, workers=2)
    assert s.count == 40
    assert s.columns == ["scenario", "probe_seed", "status", "alarm", "alarm_text", "part.Z",
                         "G54.Z", "#101", "#140", "#140=-3+-0.2", "status=completed", "pass",
                         "time_s"]
    assert list(t) == s.columns
    assert all(isinstance(a, np.ndarray) and len(a) == 40 for a in t.values())
    assert t["scenario"].tolist() == list(range(40))
    assert (t["status"] == "completed").all()
    # With the exact latch the stored Z is the plane's machine Z minus G54 Z.
    assert np.allclose(t["#140"], -3.0 + t["part.Z"] - t["G54.Z"], atol=1e-9)
    assert (t["pass"] == (np.abs(t["part.Z"] - t["G54.Z"]) <= 0.2)).all()
    assert t["pass"].dtype == bool and t["#140=-3+-0.2"].dtype == bool


def test_chunks_and_workers_give_the_cli_table(tmp_path):
    s = skipnc.Sweep(SPEC)
    t = skipnc.concat([s.run(0, 13, 1), s.run(13, 40, 2)])
    csv, js = tmp_path / "cli.csv", tmp_path / "cli.json"
    subprocess.run([os.environ["SKIPNC_BINARY"], "sweep", SPEC, "--csv", str(csv),
                    "--json", str(js), "-j", "1", "-q"], check=False)
    assert s.csv(t) == csv.read_text()
    assert s.json(t) == js.read_text()
    assert json.loads(s.json(t))["summary"]["statuses"] == {"completed": 40}


def test_a_table_of_another_sweep_is_refused():
    s = skipnc.Sweep(SPEC)
    t = s.run(0, 1)
    del t["G54.Z"]
    with pytest.raises(ValueError, match="no column 'G54.Z'"):
        s.csv(t)


def test_dask_local_cluster_gives_the_same_table(tmp_path):
    distributed = pytest.importorskip("distributed")
    from skipnc import dask_sweep
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        s, t = dask_sweep.run(client, SPEC, chunk=7, json_path=tmp_path / "d.json")
    local = skipnc.Sweep(SPEC)
    assert s.csv(t) == local.csv(local.run(0, local.count, 2))
    assert json.loads((tmp_path / "d.json").read_text())["scenarios"] == 40


def test_the_dask_example_runs_as_a_script(tmp_path):
    # Pasted into a script as it is written (the __main__ guard), it ends.
    pytest.importorskip("distributed")
    out = tmp_path / "t.csv"
    p = subprocess.run([sys.executable, os.path.join(SRC, "examples", "python", "dask_sweep.py"),
                        SPEC, "--csv", str(out)], capture_output=True, text=True, timeout=240)
    assert p.returncode == 0, p.stderr
    assert out.read_text().count("\n") == 41
