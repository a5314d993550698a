#!/usr/bin/env python3
"""CI output: `skipnc run --junit FILE` (with --expect, and with --repeat) and
`skipnc sweep --junit FILE` write a JUnit XML file that xmllint validates against
tests/ci/junit.xsd, with one test case per check (per scenario for a sweep), a failure
where a check failed, an error where a scenario could not start, and counts that add
up.

Usage: junit_test.py SKIPNC. Exit 77 (skipped) without xmllint (Debian libxml2-utils),
required when CI=true."""
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
GOLDEN = os.path.join(HERE, "..", "golden")
SWEEP = os.path.join(HERE, "..", "sweep")


def run(skipnc, args):
    return subprocess.run([skipnc] + args, capture_output=True, text=True).returncode


def validate(path):
    r = subprocess.run(["xmllint", "--noout", "--schema", os.path.join(HERE, "junit.xsd"), path],
                       capture_output=True, text=True)
    assert r.returncode == 0, f"{path} is not valid JUnit XML: {r.stderr}"
    return ET.parse(path).getroot()


def cases_of(root, kind="failure"):
    suites = root.findall("testsuite")
    assert len(suites) == 1
    suite = suites[0]
    cases = suite.findall("testcase")
    assert int(suite.get("tests")) == len(cases)
    for k in ("failure", "error"):
        n = len([c for c in cases if c.find(k) is not None])
        assert int(suite.get(k + "s")) == n, (k, n, suite.attrib)
    failed = [c for c in cases if c.find(kind) is not None]
    return cases, failed


def check_run(skipnc, tmp):
    where = os.path.join(GOLDEN, "where")
    out = os.path.join(tmp, "run.xml")
    rc = run(skipnc, ["run", os.path.join(where, "macro_files.nc"), "-I",
                      os.path.join(where, "macros"), "--scene",
                      os.path.join(where, "macro_files.scene.toml"), "-q",
                      "--expect", "#101=-3+-0.001", "--expect", "#101=-2.9+-0.05",
                      "--expect", "status=completed", "--junit", out])
    assert rc == 3, f"a failed expectation exits 3, got {rc}"
    cases, failed = cases_of(validate(out))
    assert [c.get("name") for c in cases] == ["#101=-3+-0.001", "#101=-2.9+-0.05",
                                              "status=completed"]
    assert [c.get("name") for c in failed] == ["#101=-2.9+-0.05"]
    msg = failed[0].find("failure").get("message")
    assert "#101 = -3" in msg, msg


def check_alarm_run(skipnc, tmp):
    probing = os.path.join(GOLDEN, "probing")
    out = os.path.join(tmp, "crash.xml")
    rc = run(skipnc, ["run", os.path.join(probing, "crash.nc"), "-m",
                      os.path.join(probing, "crash.machine.toml"), "--scene",
                      os.path.join(probing, "crash.scene.toml"), "-q", "--junit", out])
    assert rc == 1, rc
    cases, failed = cases_of(validate(out))
    assert len(cases) == 1 and len(failed) == 1
    assert "SN9061" in failed[0].find("failure").get("message")


def check_repeat(skipnc, tmp):
    where = os.path.join(GOLDEN, "where")
    out = os.path.join(tmp, "repeat.xml")
    rc = run(skipnc, ["run", os.path.join(where, "macro_files.nc"), "-I",
                      os.path.join(where, "macros"), "--scene",
                      os.path.join(where, "macro_files.scene.toml"), "-q", "--repeat", "3",
                      "--junit", out])
    assert rc == 0, rc
    cases, failed = cases_of(validate(out))
    assert len(cases) == 4 and not failed, [c.get("name") for c in cases]
    assert cases[0].get("name") == "nominal run"


def sweep_spec(tmp, name, program, tail):
    """A spec in tmp running tests/sweep's touch program (or a missing one)."""
    for f in ("touch.nc", "touch.scene.toml"):
        shutil.copy(os.path.join(SWEEP, f), tmp)
    spec = os.path.join(tmp, name + ".sweep.toml")
    with open(spec, "w") as f:
        f.write(f'program = "{program}"\nscene = "touch.scene.toml"\nseed = 7\nvars = ["140"]\n'
                + tail + '[[vary]]\nwhat = "part.Z"\nuniform = [-0.2, 0.2]\n'
                + '[[vary]]\nwhat = "#101"\nvalues = [200.0]\n')
    return spec


def check_sweep(skipnc, tmp):
    # A check that holds for some scenarios only: one case per scenario, the
    # failures exactly the rows the CSV table marks fail, each naming #140.
    spec = sweep_spec(tmp, "tight", "touch.nc",
                      'scenarios = 8\nexpect = ["#140=-3+-0.08", "status=completed"]\n')
    out = os.path.join(tmp, "sweep.xml")
    rc = run(skipnc, ["sweep", spec, "-q", "-j", "2", "--junit", out])
    assert rc == 1, f"a failed scenario exits 1, got {rc}"
    cases, failed = cases_of(validate(out))
    assert [c.get("name") for c in cases] == [f"scenario {i}" for i in range(8)]
    with open(os.path.join(tmp, "tight.sweep.csv")) as f:
        rows = list(csv.DictReader(f))
    want = [f"scenario {r['scenario']}" for r in rows if r["pass"] == "fail"]
    assert want and len(want) < 8, "the tolerance should split the scenarios"
    assert [c.get("name") for c in failed] == want
    for c in failed:
        msg = c.find("failure").get("message")
        assert "#140=-3+-0.08" in msg and "#140 = " in msg, msg
    out_text = cases[0].find("system-out").text
    assert "part.Z = " in out_text and "#140 = " in out_text, out_text

    # Every scenario could not start (a parameter bit drawn as 5): each case an
    # <error>, none a failure; exit 2.
    spec = sweep_spec(tmp, "broken", "touch.nc",
                      'scenarios = 3\n[[vary]]\nwhat = "param.6200#7"\nnormal = [5.0, 0.0]\n')
    out = os.path.join(tmp, "broken.xml")
    rc = run(skipnc, ["sweep", spec, "-q", "--junit", out])
    assert rc == 2, rc
    cases, errors = cases_of(validate(out), "error")
    assert len(cases) == 3 and len(errors) == 3
    assert all("could not start" in c.find("error").get("message") for c in errors)

    # Nothing could be loaded (the program is missing): exit 2, no file.
    spec = sweep_spec(tmp, "missing", "nowhere.nc", "scenarios = 3\n")
    out = os.path.join(tmp, "missing.xml")
    assert run(skipnc, ["sweep", spec, "-q", "--junit", out]) == 2
    assert not os.path.exists(out)


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    if shutil.which("xmllint") is None:
        print("xmllint not found (Debian: libxml2-utils)")
        return 1 if os.environ.get("CI") == "true" else 77
    with tempfile.TemporaryDirectory() as tmp:
        check_run(sys.argv[1], tmp)
        check_alarm_run(sys.argv[1], tmp)
        check_repeat(sys.argv[1], tmp)
        check_sweep(sys.argv[1], tmp)
    print("junit: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
