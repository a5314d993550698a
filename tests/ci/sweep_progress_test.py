#!/usr/bin/env python3
"""A long sweep shows a progress line (scenarios done, rate, time left) on standard
error when it is a terminal, and never when standard error is a pipe or a file (CI
logs); Ctrl-C (SIGINT) on the terminal leaves the scenarios not taken as not_run,
none of them failed.

Usage: sweep_progress_test.py SKIPNC."""
import json
import os
import pty
import re
import signal
import subprocess
import sys
import tempfile
import time

PROGRESS = re.compile(rb"\r  (\d+)/100000 scenarios, (\d+)/s, (\d+) s left")


def make_spec(tmp):
    with open(os.path.join(tmp, "p.nc"), "w") as f:
        # A move, not a dwell: a dwell's still periods are skipped in one
        # step, and the sweep must last longer than the test's 2.5 s.
        f.write("G91 G01 X30. F1000.\nM30\n")
    spec = os.path.join(tmp, "s.sweep.toml")
    with open(spec, "w") as f:
        f.write('program = "p.nc"\nscenarios = 100000\nworkers = 1\n')
    return spec


def read_until(fd, pattern, seconds):
    got = b""
    end = time.monotonic() + seconds
    while time.monotonic() < end and not pattern.search(got):
        try:
            chunk = os.read(fd, 4096)
        except OSError:
            break
        if not chunk:
            break
        got += chunk
    return got


def on_terminal(skipnc, tmp):
    spec = make_spec(tmp)
    leader, follower = pty.openpty()
    p = subprocess.Popen([skipnc, "sweep", spec], stdin=subprocess.DEVNULL,
                         stdout=subprocess.DEVNULL, stderr=follower)
    os.close(follower)
    got = read_until(leader, PROGRESS, 30.0)
    m = PROGRESS.search(got)
    assert m, f"no progress line on the terminal: {got!r}"
    assert int(m.group(1)) > 0 and int(m.group(2)) > 0 and int(m.group(3)) > 0, m.group(0)
    p.send_signal(signal.SIGINT)
    rc = p.wait(60)
    os.close(leader)
    assert rc == 1, f"a sweep stopped by Ctrl-C exits 1, got {rc}"
    with open(os.path.join(tmp, "s.sweep.json")) as f:
        summary = json.load(f)["summary"]
    assert summary["not_run"] > 0 and summary["passed"] > 0, summary
    assert summary["failed"] == summary["statuses"].get("interrupted", 0), summary
    assert summary["errors"] == 0, summary


def in_a_pipe(skipnc, tmp):
    spec = make_spec(tmp)
    p = subprocess.Popen([skipnc, "sweep", spec], stdin=subprocess.DEVNULL,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    time.sleep(2.5)  # the terminal's line comes after one second
    p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=60)
    assert p.returncode == 1, p.returncode
    assert b"scenarios, " not in err and b"\r" not in err, f"progress in a pipe: {err!r}"
    assert b"not run (stopped)" in out, out


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    with tempfile.TemporaryDirectory() as tmp:
        on_terminal(sys.argv[1], tmp)
    with tempfile.TemporaryDirectory() as tmp:
        in_a_pipe(sys.argv[1], tmp)
    print("sweep progress: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
