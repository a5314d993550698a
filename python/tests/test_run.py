"""skipnc.run: a program with machine, scene, parameters and variables given
as files or Python values; the report as a dict, the trace as NumPy arrays.
Expected values come from the exact latch rule (the stored Z is the plane's
machine Z minus the work offset) and from the program's own arithmetic."""
import os

import numpy as np
import pytest

import skipnc

SRC = os.environ["SKIPNC_SOURCE_DIR"]
SWEEP = os.path.join(SRC, "tests", "sweep")
TOUCH = os.path.join(SWEEP, "touch.nc")
PLANE = {"trigger": [{"signal": "X0.4", "axis": "Z", "at": -3.0, "direction": "decreasing"}]}


def test_files_give_the_report_as_a_dict():
    r = skipnc.run(TOUCH, scene=os.path.join(SWEEP, "touch.scene.toml"),
                   variables={101: 200.0}, vars=["140", "#101"])
    assert r.exit_code == 0
    assert r.report["format"] == "skipnc-report/1"
    assert r.report["status"] == "completed"
    assert r.report["variables"]["140"] == pytest.approx(-3.0, abs=1e-9)
    assert r.report["variables"]["101"] == 200.0
    (skip,) = r.report["skips"]
    assert skip["triggered"] and skip["signal"] == "X0.4"
    assert skip["line"] == 5


def test_python_values_for_scene_machine_params_and_variables(tmp_path):
    axis = {"min": -500.0, "max": 500.0, "rapid": 30000.0, "max_feed": 20000.0,
            "accel": 2000.0, "kp": 30.0}
    machine = {"name": "mill3_g54", "dialect": "fanuc", "servo_period_ms": 1.0,
               "axis": [dict(axis, name=n) for n in "XYZ"],
               "work_offsets": {"G54": {"Z": -1.25}}}
    r = skipnc.run(program_text=open(TOUCH).read(), scene=PLANE, machine=machine,
                   params={"6200#7": 0}, variables={101: 100.0}, vars=["140"])
    # Plane at machine Z-3, G54 Z = -1.25: #5063 = -3 - (-1.25).
    assert r.report["variables"]["140"] == pytest.approx(-1.75, abs=1e-9)


def test_a_variable_file(tmp_path):
    f = tmp_path / "vars.txt"
    f.write_text("; feed and a flag\n#101 = 400\n#500 = 7\n")
    r = skipnc.run(TOUCH, scene=PLANE, variables=f, vars=["101", "500"])
    assert r.report["variables"] == {"101": 400.0, "500": 7.0}


def test_the_trace_is_numpy_columns():
    r = skipnc.run(TOUCH, scene=PLANE, variables={101: 600.0})
    t = r.trace
    assert isinstance(t["time_s"], np.ndarray)
    n = len(t["time_s"])
    assert n > 100
    for name in ("line", "feed_mm_min", "X_cmd", "Z_act", "Z_ferr", "Z_torque", "X0.4"):
        assert t[name].shape == (n,), name
    # 1 ms servo period (mill3).
    assert np.allclose(np.diff(t["time_s"]), 0.001)
    # The probe input is on exactly while the axis is below the plane.
    on = t["X0.4"] > 0.5
    assert on.any()
    assert np.all(t["Z_act"][on] < -3.0 + 1e-9)
    # ferr is commanded minus actual, as the CSV trace.
    assert np.allclose(t["Z_ferr"], t["Z_cmd"] - t["Z_act"])
    # The skip block runs at the programmed feed, 600 mm/min.
    assert t["feed_mm_min"][t["line"] == 5].max() == pytest.approx(600.0)


def test_no_trace_when_not_asked():
    r = skipnc.run(TOUCH, scene=PLANE, variables={101: 600.0}, trace=False)
    assert r.trace is None


def test_an_alarm_is_a_report_not_an_exception():
    # No feed at all (#101 vacant): the dialect's no-feed alarm on line 5.
    r = skipnc.run(TOUCH, scene=PLANE)
    assert r.exit_code == 1
    assert r.report["status"] == "alarm"
    assert r.report["alarm"]["line"] == 5


def test_a_bad_scene_raises_with_file_line_and_column(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[[trigger]]\nsignal = \"X0.4\"\naxis = \"Q\"\nat = 1.0\n")
    with pytest.raises(skipnc.StartError, match=r"bad\.toml:3:"):
        skipnc.run(TOUCH, scene=bad)
    with pytest.raises(skipnc.StartError, match="cannot be set before a run"):
        skipnc.run(TOUCH, variables={5063: 1.0})
    with pytest.raises(ValueError):
        skipnc.run()


def test_the_feed_sweep_example_plots_the_latch_error(tmp_path):
    import subprocess
    import sys
    pytest.importorskip("matplotlib")
    out = tmp_path / "f.png"
    p = subprocess.run([sys.executable, os.path.join(SRC, "examples", "python", "feed_sweep.py"),
                        "--quick", "--out", str(out)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    exact, sampled = [float(line.split("|error|")[1].split()[0])
                      for line in p.stdout.splitlines() if "|error|" in line]
    # Exact latch: the plane itself. Sampled: the axis runs on to the next
    # sample, at most one period of travel: F3000 -> 50 um.
    assert exact < 1e-3
    assert 0.0 < sampled <= 50.0 + 1e-6
