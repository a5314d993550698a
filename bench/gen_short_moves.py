#!/usr/bin/env python3
"""Generate a long program of short moves for the simulation benchmarks.

Lines of 0.2 to 3 mm in X and Y (now and then a small Z step) at F600-3000,
wandering inside a 200 mm square, until the sum of the nominal move times
(length / feed) reaches SECONDS; the simulated time is somewhat longer
(acceleration, corners). Deterministic for a given SEED.

Usage: gen_short_moves.py SECONDS [SEED] > short.nc
"""
import math
import random
import sys


def main():
    seconds = float(sys.argv[1]) if len(sys.argv) > 1 else 9000.0
    rnd = random.Random(int(sys.argv[2]) if len(sys.argv) > 2 else 1)
    out = ["G21 G90 G17 G54", "G0 X0 Y0 Z2.", "G1 Z-1. F600."]
    x = y = 0.0
    z = -1.0
    t = 0.0
    heading = 0.0
    while t < seconds:
        f = rnd.choice([600, 1200, 2000, 3000])
        length = rnd.uniform(0.2, 3.0)
        heading += rnd.uniform(-1.2, 1.2)
        nx, ny = x + length * math.cos(heading), y + length * math.sin(heading)
        if abs(nx) > 100 or abs(ny) > 100:
            heading += math.pi
            nx, ny = x + length * math.cos(heading), y + length * math.sin(heading)
        words = f"G1 X{nx:.3f} Y{ny:.3f}"
        if rnd.random() < 0.05:
            z = -rnd.uniform(0.5, 2.0)
            words += f" Z{z:.3f}"
        out.append(f"{words} F{f}.")
        t += length / (f / 60.0)
        x, y = nx, ny
    out.append("G0 Z2.")
    out.append("M30")
    sys.stdout.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
