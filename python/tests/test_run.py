"""skipnc.run: a program with machine, scene, parameters and variables given
as files or Python values; the report as a dict, the trace as NumPy arrays.
Expected values come from the exact latch rule (the stored Z is the plane's
machine Z minus the work offset) and from the program's own arithmetic."""
import csv
import json
import os
import subprocess

import numpy as np
import pytest

import skipnc

SRC = os.environ["SKIPNC_SOURCE_DIR"]
CLI = os.environ["SKIPNC_BINARY"]
PROBING = os.path.join(SRC, "examples", "probing")
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


def test_the_trace_has_the_columns_of_the_cli_trace(tmp_path):
    # A probe in the spindle (probe and tip columns), work coordinates and
    # the scene's signals: every kind of column.
    args = dict(machine=os.path.join(PROBING, "mill3_probe.machine.toml"),
                scene=os.path.join(PROBING, "fixture.scene.toml"))
    prog = os.path.join(PROBING, "bore_centre.nc")
    out = tmp_path / "t.csv"
    subprocess.run([CLI, "run", prog, "-m", args["machine"], "-s", args["scene"],
                    "--trace", str(out), "-q"], check=True)
    with open(out, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    t = skipnc.run(prog, **args).trace
    assert list(t) == header
    assert "probe_deflection" in header and "Z_tip" in header and "X_work" in header
    assert len(t["time_s"]) == len(body)
    for j, name in enumerate(header):
        if name == "file":
            assert list(t[name]) == [r[j] for r in body]
        else:
            # The CSV rounds to 6 decimals.
            cli = np.array([float(r[j]) for r in body])
            assert np.allclose(t[name], cli, rtol=0, atol=6e-7), name


def test_strict_makes_a_warning_an_alarm():
    prog = "G21 G90 G17 G54\nG05.1 Q1\nG0 X10. Y0 Z5.\n"
    r = skipnc.run(program_text=prog)
    assert r.exit_code == 0 and r.report["warnings"]
    r = skipnc.run(program_text=prog, strict=True)
    assert r.exit_code == 1
    assert r.report["status"] == "alarm"
    assert r.report["alarm"]["code"].endswith("9076")


def test_expectations_as_the_cli_checks_them():
    scene = os.path.join(SWEEP, "touch.scene.toml")
    ok = skipnc.run(TOUCH, scene=scene, variables={101: 200.0}, vars=["140"],
                    expect=["#140=-3+-0.001", "status=completed"])
    assert ok.exit_code == 0 and ok.failed == []
    bad = skipnc.run(TOUCH, scene=scene, variables={101: 200.0}, expect="#140=-2.9+-0.001")
    assert bad.exit_code == 3
    (why,) = bad.failed
    assert why.startswith("expectation failed: #140=-2.9+-0.001: #140 = -3")
    # An expected alarm holds: exit status 0 (no feed: the alarm on line 5).
    alarm = skipnc.run(TOUCH, scene=scene, expect=["status=alarm"])
    assert alarm.report["status"] == "alarm" and alarm.exit_code == 0
    # The alarm by the dialect's code or by its key, as --expect takes it, and
    # the report's checks as the CLI's --report gives them.
    for name in ("PS0011", "skip_no_feed"):
        coded = skipnc.run(TOUCH, scene=scene, expect=["alarm=" + name])
        assert coded.exit_code == 0 and coded.failed == []
        (check,) = coded.report["expectations"]
        assert check["expect"] == "alarm=" + name and check["pass"] is True
        assert check["value"] == "PS0011"
    wrong = skipnc.run(TOUCH, scene=scene, expect=["alarm=PS0003"])
    assert wrong.exit_code == 3 and wrong.report["expectations"][0]["pass"] is False
    with pytest.raises(skipnc.StartError, match="no alarm of the fanuc dialect"):
        skipnc.run(TOUCH, scene=scene, expect=["alarm=PS9999"])
    with pytest.raises(skipnc.StartError, match="--expect '#140~3'"):
        skipnc.run(TOUCH, scene=scene, expect=["#140~3"])


def test_repeat_gives_the_cli_repeat_report(tmp_path):
    prog = os.path.join(PROBING, "bore_centre.nc")
    machine = os.path.join(PROBING, "mill3_probe.machine.toml")
    scene = os.path.join(PROBING, "fixture_real.scene.toml")
    out = tmp_path / "rep.json"
    subprocess.run([CLI, "run", prog, "-m", machine, "-s", scene, "--var", "130", "--repeat",
                    "5", "--seed", "3", "--report", str(out), "-q"], check=True)
    r = skipnc.run(prog, machine=machine, scene=scene, vars=["130"], repeat=5, seed=3)
    assert r.report == json.loads(out.read_text())
    assert r.report["format"] == "skipnc-repeat/1" and r.report["runs"] == 5
    (x,) = [v for v in r.report["values"] if v["name"] == "#130"]
    assert x["count"] == 5 and 0.0 < x["std"] < 0.01
    assert r.trace is None and r.exit_code == 0


def test_plot_writes_the_pictures(tmp_path):
    svg, html = tmp_path / "p.svg", tmp_path / "p.html"
    r = skipnc.run(TOUCH, scene=PLANE, variables={101: 600.0}, plot=[svg, html])
    assert r.exit_code == 0
    assert "<svg" in svg.read_text()[:200]
    assert "<html" in html.read_text()[:500].lower()
    with pytest.raises(skipnc.StartError, match="must end in .svg or .html"):
        skipnc.run(TOUCH, scene=PLANE, variables={101: 600.0}, plot=tmp_path / "p.png")


def test_an_error_in_a_dict_names_its_key_not_a_file():
    bad = {"trigger": [PLANE["trigger"][0], {"signal": "X0.4", "axis": "Q", "at": 1.0}]}
    with pytest.raises(skipnc.StartError) as e:
        skipnc.run(TOUCH, scene=bad)
    assert str(e.value).startswith("scene (dict), key trigger[1].axis: error:")
    with pytest.raises(skipnc.StartError) as e:
        skipnc.run(TOUCH, machine={"extends": "mill3", "servo_period_ms": -1.0})
    assert str(e.value).startswith("machine (dict), key servo_period_ms: error:")
    with pytest.raises(TypeError, match=r"scene \(dict\), key trigger\[0\].at"):
        skipnc.run(TOUCH, scene={"trigger": [{"signal": "X0.4", "axis": "Z", "at": {1, 2}}]})


PROBE_MACHINE = {"extends": "mill3_probe.machine.toml", "name": "probe-dict"}
H20 = "G21 G90 G54\n#1 = #11020\nM30\n"


def test_relative_paths_in_a_dict_follow_base_dir_or_the_working_directory(monkeypatch, tmp_path):
    # extends: the probe machine's H20 length (150 mm) comes with it.
    r = skipnc.run(program_text=H20, machine=PROBE_MACHINE, base_dir=PROBING, vars=["1"])
    assert r.report["variables"]["1"] == 150.0
    monkeypatch.chdir(PROBING)
    r = skipnc.run(program_text=H20, machine=PROBE_MACHINE, vars=["1"])
    assert r.report["variables"]["1"] == 150.0
    monkeypatch.chdir(tmp_path)
    with pytest.raises(skipnc.StartError) as e:
        skipnc.run(program_text=H20, machine=PROBE_MACHINE)
    assert str(e.value).startswith("machine (dict), key extends: error:")
    assert str(tmp_path / "mill3_probe.machine.toml") in str(e.value)
    # A mesh's file, in a scene dict.
    mesh = {"mesh": [{"file": "block.stl"}]}
    r = skipnc.run(program_text="M30\n", scene=mesh, base_dir=os.path.join(SRC, "examples", "stl"))
    assert r.exit_code == 0
    with pytest.raises(skipnc.StartError, match=r"^scene \(dict\), key mesh\[0\]\.file: "):
        skipnc.run(program_text="M30\n", scene=mesh)
