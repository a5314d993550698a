#!/usr/bin/env python3
"""Latch error against feed, notebook style: one touch of a Z plane per run,
on a machine that latches the skip position at the servo sample after the
signal (no high-speed skip input) and on one that latches it at the signal's
instant. The plane is moved by a fraction of a servo period's travel from run
to run, so each feed shows the whole spread.

Run from a build: PYTHONPATH=build/python python3 examples/python/feed_sweep.py
(writes feed_sweep.png; --quick for a few runs).
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import skipnc  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# %% The program: touch down at the feed in #101, keep the stored Z in #140.
PROGRAM = """%
G21 G90 G17 G54
G0 X0 Y0 Z10.
G31 Z-10. F#101
#140 = #5063
G0 Z10.
M30
%
"""

# %% Two machines: mill3 as it is (exact latch), and with a sampled latch.
AXIS = {"min": -500.0, "max": 500.0, "rapid": 30000.0, "max_feed": 20000.0,
        "accel": 2000.0, "kp": 30.0}
SAMPLED = {"name": "mill3-sampled", "dialect": "fanuc", "servo_period_ms": 1.0,
           "latch": {"mode": "sampled", "delay_ms": 0.0},
           "axis": [dict(AXIS, name=n) for n in "XYZ"]}
MACHINES = {"exact latch (mill3)": "mill3", "sampled latch, 1 ms": SAMPLED}


def plane(z):
    return {"trigger": [{"signal": "X0.4", "axis": "Z", "at": z, "direction": "decreasing"}]}


def latch_errors(machine, feeds, phases):
    """Stored Z minus the plane's Z, in micrometres: one row per feed."""
    out = np.zeros((len(feeds), len(phases)))
    for i, f in enumerate(feeds):
        for j, ph in enumerate(phases):
            # Move the plane by a fraction of one period's travel at this feed.
            z = -3.0 - ph * f / 60000.0
            r = skipnc.run(program_text=PROGRAM, machine=machine, scene=plane(z),
                           variables={101: f}, vars=["140"], trace=False)
            assert r.report["status"] == "completed", r.report["alarm"]
            out[i, j] = (r.report["variables"]["140"] - z) * 1000.0
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="feed_sweep.png")
    ap.add_argument("--quick", action="store_true", help="3 feeds, 3 phases")
    a = ap.parse_args()
    feeds = np.array([100.0, 1000.0, 3000.0]) if a.quick else np.geomspace(50.0, 5000.0, 12)
    phases = np.linspace(0.05, 0.95, 3 if a.quick else 10)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for label, machine in MACHINES.items():
        err = latch_errors(machine, feeds, phases)
        worst = np.abs(err).max(axis=1)
        ax.plot(feeds, worst, "o-", label=f"{label}: worst")
        ax.fill_between(feeds, err.min(axis=1), err.max(axis=1), alpha=0.2)
        print(f"{label:24s} worst |error| {worst.max():9.3f} um at F{feeds[worst.argmax()]:.0f}")
    # One servo period of travel: the bound of the sampled latch's error.
    ax.plot(feeds, feeds / 60.0, "k--", lw=1, label="one period of travel (F/60 um)")
    ax.set_xscale("log")
    ax.set_xlabel("skip feed F, mm/min")
    ax.set_ylabel("stored Z - plane Z, um")
    ax.set_title("G31 latch error against feed")
    ax.legend()
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
