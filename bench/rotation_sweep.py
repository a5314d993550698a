#!/usr/bin/env python3
"""The probing cycles against a part set up turned and moved (issue 33).

`skipnc sweep` moves parts but does not turn them, so this script writes one
scene per scenario: the plate of examples/probing_cycles/part.scene.toml (its
top, bore and pocket) in a frame turned by a uniform angle about the machine's
Z axis and moved by a uniform dx dy, and runs three of the library's cycles
against it with `skipnc run`:

- bore: O9811 Z S1 on the top and O9814 D40. S1 on the bore (as misplaced.nc):
  G54 X Y must be the turned bore's centre, Z the top;
- rectangle: O9812 X50.6 and O9812 Y40. in the pocket from its nominal centre
  (x0, y0): each touches along the machine's axes, so on a turned pocket it
  finds the midpoint of the chord through the start, on the line half-way
  between the faces: X = cx - tan(a) (y0 - cy), Y = cy + tan(a) (x0 - cx)
  (the true centre cx cy only at a = 0: turn the frame with the angle first),
  and the widths (W - 2 r) / cos(a) + 2 r (a ball of radius r stops r / cos(a)
  short of a face turned by a);
- angle: O9843 on the plate's -Y face: #139 = #144 = the angle; then the
  posts' `G68 X0 Y0 Z0 I0 J0 K1. R#144` turns the frame by it (R rounded to
  0.001 degree, its increment): a move of 100 along the program's X runs 100
  (cos r, sin r) in the work coordinates (#5041 #5042 before and after).

Every expected value is derived from the scenario's draw as above; the table
gives the worst error of each over all scenarios. Usage (from the source tree):
  bench/rotation_sweep.py [-n 40] [--seed 7] [--skipnc build/skipnc]
"""
import argparse
import json
import math
import random
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
G54 = (-80.0, 30.5, -229.5)  # examples/probing_cycles/cycles.machine.toml
BORE = (-80.123, 30.456)
POCKET = ((-40.25, -80.0, -249.87), (10.35, -40.0, -200.0))
TOP = -229.87
START = (65.05, -90.5)  # the pocket's nominal centre, G54 (the rectangle program)

SCENE = """spindle_tool = 20
[[frame]]
name = "setup"
origin = [{dx!r}, {dy!r}, 0.0]
rotation = {a!r}
[[box]]
part = "plate"
frame = "setup"
min = [-150.0, -100.0, -260.0]
max = [150.0, 100.0, -229.87]
[[bore]]
part = "plate"
frame = "setup"
center = [-80.123, 30.456]
radius = 20.0
[[pocket]]
part = "plate"
frame = "setup"
min = [-40.25, -80.0, -249.87]
max = [10.35, -40.0, -200.0]
[probe]
signal = "SKIP"
tool = 20
ball_radius = 1.0
length = 150.0
stylus_length = 50.0
body_radius = 20.0
pre_travel = 0.0
max_overtravel = 2.0
"""

PROGRAMS = {
    "bore": """%
O1 (BORE AND TOP, S1)
G21 G90 G17 G40 G49 G80 G54
#550=1.
G53 G0 Z0
G43 H20 G0 X20. Y-20.
G65 P9810 Z5. F3000.
G65 P9811 Z0 Q5. S1
G65 P9810 Z50.
G0 X0 Y0
G65 P9810 Z-10.
G65 P9814 D40. Q5. S1
G65 P9810 Z50.
M30
%
""",
    "rectangle": """%
O2 (POCKET X AND Y)
G21 G90 G17 G40 G49 G80 G54
#550=1.
G53 G0 Z0
G43 H20 G0 X65.05 Y-90.5
G65 P9810 Z-10. F3000.
G65 P9812 X50.6 Q5.
#101=#135
#102=#138
G65 P9812 Y40. Q5.
#103=#136
#104=#138
G65 P9810 Z50.
M30
%
""",
    "angle": """%
O3 (PLATE -Y FACE ANGLE)
G21 G90 G17 G40 G49 G80 G54
#550=1.
G53 G0 Z0
G43 H20 G0 X60. Y-140.5
G65 P9810 Z-10. F3000.
G65 P9843 Y-130.5 D20. Q5.
#101=#139
#102=#144
G65 P9810 Z50.
G68 X0 Y0 Z0 I0 J0 K1. R#144
G0 X0 Y-140.5
#103=#5041
#104=#5042
G0 X100.
#105=#5041
#106=#5042
G69
M30
%
""",
}
VARS = {"bore": ["5221", "5222", "5223"], "rectangle": ["101", "102", "103", "104"],
        "angle": ["101", "102", "103", "104", "105", "106"]}


def turned(p, a_deg, dx, dy):
    c, s = math.cos(math.radians(a_deg)), math.sin(math.radians(a_deg))
    return (c * p[0] - s * p[1] + dx, s * p[0] + c * p[1] + dy)


def expected(cycle, a, dx, dy):
    c = math.cos(math.radians(a))
    if cycle == "bore":
        x, y = turned(BORE, a, dx, dy)
        return [x, y, TOP]
    if cycle == "rectangle":
        cx = (POCKET[0][0] + POCKET[1][0]) / 2
        cy = (POCKET[0][1] + POCKET[1][1]) / 2
        x, y = turned((cx, cy), a, dx, dy)
        x, y = x - G54[0], y - G54[1]
        t = math.tan(math.radians(a))
        w = POCKET[1][0] - POCKET[0][0]
        h = POCKET[1][1] - POCKET[0][1]
        return [x - t * (START[1] - y), (w - 2) / c + 2, y + t * (START[0] - x), (h - 2) / c + 2]
    # G68's R is rounded to its increment, 0.001 degree, like any word.
    r = math.copysign(math.floor(abs(a) * 1000 + 0.5) / 1000, a)
    return [a, a, 100 * math.cos(math.radians(r)), 100 * math.sin(math.radians(r))]


def run(skipnc, work, cycle, scene):
    prog = work / f"{cycle}.nc"
    prog.write_text(PROGRAMS[cycle])
    args = [skipnc, "run", str(prog), "-q", "--report", "-", "-s", str(scene), "-m",
            str(ROOT / "examples/probing_cycles/cycles.machine.toml"), "-I",
            str(ROOT / "macros/probing")]
    for v in VARS[cycle]:
        args += ["--var", v]
    r = subprocess.run(args, capture_output=True, text=True, check=False)
    rep = json.loads(r.stdout)
    if rep["status"] != "completed":
        sys.exit(f"{cycle}: {rep.get('alarm')}")
    got = [rep["variables"][v] for v in VARS[cycle]]
    if cycle == "angle":  # the move under G68, as a vector
        return got[:2] + [got[4] - got[2], got[5] - got[3]]
    return got


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("-n", type=int, default=40)
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--skipnc", default=str(ROOT / "build/skipnc"))
    opt = ap.parse_args()
    rng = random.Random(opt.seed)
    worst = {k: 0.0 for k in PROGRAMS}
    t0 = time.monotonic()
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        for _ in range(opt.n):
            a, dx, dy = rng.uniform(-2, 2), rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)
            scene = work / "turned.scene.toml"
            scene.write_text(SCENE.format(a=a, dx=dx, dy=dy))
            for cycle in PROGRAMS:
                got = run(opt.skipnc, work, cycle, scene)
                err = max(abs(g - e) for g, e in zip(got, expected(cycle, a, dx, dy)))
                worst[cycle] = max(worst[cycle], err)
    secs = time.monotonic() - t0
    print(f"{opt.n} scenarios, angle -2..2 deg, dx dy -0.5..0.5 mm, seed {opt.seed}: "
          f"{secs:.1f} s")
    print("| cycle | checked | worst error |")
    print("| --- | --- | --- |")
    print(f"| bore (O9811 Z, O9814 S1) | G54 X Y Z | {worst['bore']:.2e} mm |")
    print(f"| rectangle (O9812 X, Y) | chord midpoints, widths | {worst['rectangle']:.2e} mm |")
    print(f"| angle (O9843 Y, then G68 R#144) | #139, #144 (deg), the move under G68 (mm) "
          f"| {worst['angle']:.2e} |")
    return 0 if max(worst.values()) < 1e-6 else 1


if __name__ == "__main__":
    sys.exit(main())
