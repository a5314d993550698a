"""Sweeps through the module: the same table as `skipnc sweep`, whatever the
number of workers or the chunks, and on a Dask local cluster."""
import json
import os
import subprocess

import pytest

import skipnc

SRC = os.environ["SKIPNC_SOURCE_DIR"]
SPEC = os.path.join(SRC, "tests", "sweep", "touch.sweep.toml")


def test_rows_follow_the_exact_latch_rule():
    s, rows = skipnc.sweep(SPEC, workers=2)
    assert s.count == 40 and len(rows) == 40
    assert s.vary == ["part.Z", "G54.Z", "#101"]
    for r in rows:
        part, g54, _feed = r["chosen"]
        assert r["status"] == "completed"
        assert r["values"][0] == pytest.approx(-3.0 + part - g54, abs=1e-9)
        assert r["pass"] == (abs(part - g54) <= 0.2)


def test_chunks_and_workers_give_the_cli_table(tmp_path):
    s = skipnc.Sweep(SPEC)
    rows = s.run(0, 13, 1) + s.run(13, 40, 2)
    csv, js = tmp_path / "cli.csv", tmp_path / "cli.json"
    subprocess.run([os.environ["SKIPNC_BINARY"], "sweep", SPEC, "--csv", str(csv),
                    "--json", str(js), "-j", "1", "-q"], check=False)
    assert s.csv(rows) == csv.read_text()
    assert s.json(rows) == js.read_text()
    assert json.loads(s.json(rows))["summary"]["statuses"] == {"completed": 40}


def test_a_row_of_another_sweep_is_refused():
    s = skipnc.Sweep(SPEC)
    rows = s.run(0, 1)
    rows[0]["chosen"] = rows[0]["chosen"][:1]
    with pytest.raises(ValueError):
        s.csv(rows)


def test_dask_local_cluster_gives_the_same_table(tmp_path):
    distributed = pytest.importorskip("distributed")
    from skipnc import dask_sweep
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        s, rows = dask_sweep.run(client, SPEC, chunk=7, json_path=tmp_path / "d.json")
    local = skipnc.Sweep(SPEC)
    assert s.csv(rows) == local.csv(local.run(0, local.count, 2))
    assert json.loads((tmp_path / "d.json").read_text())["scenarios"] == 40
