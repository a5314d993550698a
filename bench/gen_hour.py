#!/usr/bin/env python3
"""Generate about one hour of 3-axis machining (the simulation benchmark).

Random lines at F1200-3000 over a 400 mm square, Z between -5 and 0, until the
nominal machining time (length / feed) reaches SECONDS (default 3600).

Usage: gen_hour.py OUT [SECONDS]
"""
import random
import sys


def main():
    seconds = float(sys.argv[2]) if len(sys.argv) > 2 else 3600.0
    rnd = random.Random(1)
    out = ["G21 G90 G17 G54", "G0 X0 Y0 Z5."]
    t = 0.0
    x = y = 0.0
    while t < seconds:
        f = rnd.choice([1200, 2000, 3000])
        nx, ny = rnd.uniform(-200, 200), rnd.uniform(-200, 200)
        out.append(f"G1 X{nx:.3f} Y{ny:.3f} Z{rnd.uniform(-5, 0):.3f} F{f}.")
        t += (((nx - x) ** 2 + (ny - y) ** 2) ** 0.5) / (f / 60.0)
        x, y = nx, ny
    out.append("M30")
    open(sys.argv[1], "w").write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
