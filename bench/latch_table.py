#!/usr/bin/env python3
"""Latch accuracy table: G31 Z-10 from Z0 against a trigger plane at Z-3, on the
mill3_lowgain servo (kp 30/s, no feedforward) and on an ideal servo, in skipnc's exact,
sampled (1 ms) and sampled-with-delay (1 ms + 1 ms) modes, over F10..F10000.
LinuxCNC's figures (G38.2, 1 ms servo thread, ideal servo loop: the peer kit's
`fb` variant, results-2026-11-22.txt) are printed beside them.

Usage: bench/latch_table.py [path/to/skipnc]
"""
import json
import os
import subprocess
import sys
import tempfile

SKIPNC = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "build", "skipnc")
FEEDS = [10, 50, 100, 200, 1000, 2000, 5000, 10000]
# LinuxCNC 2.9.0 (Debian linuxcnc-uspace), peer kit "fb" variant: err_um, overtravel_um.
LCNC = {50: (-1.107, 4.2), 100: (-2.834, 11.7), 200: (-4.781, 33.3), 1000: (-19.830, 600.0)}
MODES = [("exact", 'mode = "exact"', []), ("sampled", 'mode = "sampled"', []),
         ("sampled+1ms", 'mode = "sampled"\ndelay_ms = 1.0', []),
         ("exact,SKF=1", 'mode = "exact"', ["-p", "6200#7=1"])]
# The move starts 0.4 um above Z0 so that the plane is crossed inside a servo
# period (from exactly Z0, -3.0 falls on a sample at many feeds and the sampled
# modes would look exact by luck).
START_Z = 0.0004

AXES = "\n".join(f'[[axis]]\nname = "{a}"\nkp = {{kp}}\n' for a in "XYZ")


def run(tmp, feed, latch, extra, kp):
    machine = os.path.join(tmp, "m.toml")
    with open(machine, "w") as f:
        f.write(f'name = "bench"\ndialect = "fanuc"\n[latch]\n{latch}\n' + AXES.replace("{kp}", str(kp)))
    prog = os.path.join(tmp, "p.nc")
    with open(prog, "w") as f:
        f.write(f"G21 G90 G54\nG0 Z{START_Z}\nG31 Z-10. F{feed}.\nM30\n")
    scene = os.path.join(tmp, "s.toml")
    with open(scene, "w") as f:
        f.write('[[trigger]]\nsignal = "X0.4"\naxis = "Z"\nat = -3.0\ndirection = "decreasing"\n')
    rep = os.path.join(tmp, "r.json")
    subprocess.run([SKIPNC, "run", prog, "-m", machine, "--scene", scene, "--report", rep, "-q"] + extra, check=True)
    r = json.load(open(rep))
    s = r["skips"][0]
    return (s["position"]["Z"] + 3.0) * 1000.0, (-3.0 - s["end_position"]["Z"]) * 1000.0


def main():
    with tempfile.TemporaryDirectory() as tmp:
        for kp, title in ((0, "ideal servo (actual = command), like the LinuxCNC peer set-up"),
                          (30, "mill3_lowgain servo: kp 30/s, no feedforward")):
            print(f"\n{title}: latch error / over-travel in um (SKF = 0: immediate stop; SKF = 1: deceleration)")
            head = f"{'F mm/min':>9}"
            for name, _, _ in MODES:
                head += f" {name + ' err':>16} {'over':>9}"
            head += f" {'LinuxCNC err':>13} {'over':>8}"
            print(head)
            for feed in FEEDS:
                row = f"{feed:>9}"
                for _, latch, extra in MODES:
                    err, over = run(tmp, feed, latch, extra, kp)
                    row += f" {err:>16.4f} {over:>9.2f}"
                if feed in LCNC:
                    row += f" {LCNC[feed][0]:>13.3f} {LCNC[feed][1]:>8.1f}"
                print(row)


if __name__ == "__main__":
    main()
