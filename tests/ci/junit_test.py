#!/usr/bin/env python3
"""CI output: `skipnc run --junit FILE` (with --expect, and with --repeat) writes a
JUnit XML file that xmllint validates against tests/ci/junit.xsd, with one test case
per check, a failure where a check failed, and counts that add up.

Usage: junit_test.py SKIPNC. Exit 77 (skipped) without xmllint (Debian libxml2-utils),
required when CI=true."""
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
GOLDEN = os.path.join(HERE, "..", "golden")


def run(skipnc, args):
    return subprocess.run([skipnc] + args, capture_output=True, text=True).returncode


def validate(path):
    r = subprocess.run(["xmllint", "--noout", "--schema", os.path.join(HERE, "junit.xsd"), path],
                       capture_output=True, text=True)
    assert r.returncode == 0, f"{path} is not valid JUnit XML: {r.stderr}"
    return ET.parse(path).getroot()


def cases_of(root):
    suites = root.findall("testsuite")
    assert len(suites) == 1
    suite = suites[0]
    cases = suite.findall("testcase")
    assert int(suite.get("tests")) == len(cases)
    failed = [c for c in cases if c.find("failure") is not None]
    assert int(suite.get("failures")) == len(failed)
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
    print("junit: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
