#!/usr/bin/env bash
# Probing against a million-triangle STL part (issue 17): the same 100-touch
# program run against a plate given as an analytic box and as an STL plate
# whose top face is a fine grid of triangles (1,002,001 triangles, ~48 MB).
# Prints, for each, the simulated time, the wall time of the run less that of
# loading the scene (an `M30` run with the same scene), and the real-time
# factor (simulated seconds per wall second). Median of N runs (default 5).
#
# Usage: bench/stl_probe.sh [N]     (needs build/skipnc; writes only to a temp folder)
set -euo pipefail
cd "$(dirname "$0")/.."
bin=$PWD/build/skipnc
reps=${1:-5}
work=$(mktemp -d "${TMPDIR:-/tmp}/skipnc-stl.XXXXXX")
trap 'rm -rf "$work"' EXIT

python3 - "$work" <<'PY'
import os, sys
out = sys.argv[1]
N = 707                    # grid cells per side: 2 N^2 triangles on the top face
X0, Y0, X1, Y1, ZB, ZT = -200.0, -200.0, 200.0, 200.0, -250.0, -200.0
xs = [X0 + (X1 - X0) * i / N for i in range(N + 1)]
ys = [Y0 + (Y1 - Y0) * j / N for j in range(N + 1)]
tris = []
for i in range(N):
    for j in range(N):
        a, b = (xs[i], ys[j], ZT), (xs[i + 1], ys[j], ZT)
        c, d = (xs[i + 1], ys[j + 1], ZT), (xs[i], ys[j + 1], ZT)
        tris += [(a, b, c), (a, c, d)]
# The boundary of the top face, counter-clockwise seen from +Z.
ring = [(x, Y0) for x in xs] + [(X1, y) for y in ys[1:]] + \
       [(x, Y1) for x in reversed(xs[:-1])] + [(X0, y) for y in reversed(ys[1:-1])]
m = len(ring)
for k in range(m):
    (x0, y0), (x1, y1) = ring[k], ring[(k + 1) % m]
    tris += [((x0, y0, ZT), (x0, y0, ZB), (x1, y1, ZB)), ((x0, y0, ZT), (x1, y1, ZB), (x1, y1, ZT))]
    tris.append(((0.0, 0.0, ZB), (x1, y1, ZB), (x0, y0, ZB)))  # bottom: a fan from its centre
sys.dont_write_bytecode = True  # leave the source tree as it is
sys.path.insert(0, 'examples/stl')
from make_block import write  # the binary STL writer of the example part
write(os.path.join(out, 'plate.stl'), tris, 'skipnc bench plate')
print('plate.stl: %d triangles, %.1f MB' % (len(tris), os.path.getsize(os.path.join(out, 'plate.stl')) / 1e6))
# 100 touches on a 10 x 10 grid of points of the top face.
lines = ['G21 G90 G17 G40 G54', 'G43 H20 G0 Z-150.']
for i in range(10):
    for j in range(10):
        lines += ['G0 X%.3f Y%.3f' % (-180 + 40 * i + 0.37 * j, -180 + 40 * j + 0.21 * i),
                  'G31 Z-220. F300.', 'G0 Z-150.']
lines += ['M30']
open(os.path.join(out, 'grid.nc'), 'w').write('\n'.join(lines) + '\n')
open(os.path.join(out, 'end.nc'), 'w').write('M30\n')
probe = '\n[probe]\nsignal = "SKIP"\ntool = 20\nball_radius = 1.0\nlength = 150.0\nmax_overtravel = 2.0\n'
open(os.path.join(out, 'stl.toml'), 'w').write('spindle_tool = 20\n[[mesh]]\nfile = "plate.stl"\n' + probe)
open(os.path.join(out, 'box.toml'), 'w').write(
    'spindle_tool = 20\n[[box]]\nmin = [-200.0, -200.0, -250.0]\nmax = [200.0, 200.0, -200.0]\n' + probe)
PY

cat > "$work/m.toml" <<'EOF2'
extends = "mill3"
[tool_offsets]
20 = { length = 150.0 }
EOF2

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
wall() {  # wall seconds of one run
  python3 -c 'import subprocess, sys, time
t = time.perf_counter()
subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
print(time.perf_counter() - t)' "$@"
}
for scene in box stl; do
  sim=$("$bin" run "$work/grid.nc" -m "$work/m.toml" -s "$work/$scene.toml" --report - -q |
        python3 -c 'import json,sys; r=json.load(sys.stdin); print(r["final"]["time"], len(r["skips"]), sum(s["triggered"] for s in r["skips"]))')
  set -- $sim
  run=$(for _ in $(seq "$reps"); do wall "$bin" run "$work/grid.nc" -m "$work/m.toml" -s "$work/$scene.toml" -q; done | median)
  load=$(for _ in $(seq "$reps"); do wall "$bin" run "$work/end.nc" -m "$work/m.toml" -s "$work/$scene.toml" -q; done | median)
  printf '%-4s simulated %.3f s, %d skips (%d touched); run %.3f s wall, of which loading %.3f s; real-time factor %.0fx (without loading)\n' \
    "$scene" "$1" "$2" "$3" "$run" "$load" "$(python3 -c "print($1 / ($run - $load))")"
done
