#!/usr/bin/env bash
# Probing a part whose STL holds overlapping triangles (issue 31): a 400 x
# 400 x 50 mm plate whose top face is given COPIES times over (coincident
# triangles, as an exporter that writes a face once per body does), plus FAN
# large triangles that all lie in the top face and overlap one another (a fan
# turned about the face's centre). The same 100-touch program as
# bench/stl_probe.sh. Prints the triangles in the file, the simulated time,
# the touches, and the processor time of the run (user + system, GNU time).
#
# Usage: bench/stl_overlap.sh [SKIPNC] [COPIES] [FAN]
#   (default build/skipnc, 20000, 20000; writes only to a temp folder)
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-$PWD/build/skipnc}
copies=${2:-20000}
fan=${3:-20000}
work=$(mktemp -d "${TMPDIR:-/tmp}/skipnc-overlap.XXXXXX")
trap 'rm -rf "$work"' EXIT

python3 - "$work" "$copies" "$fan" <<'PY'
import math, os, sys
out, copies, fan = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
X0, Y0, X1, Y1, ZB, ZT = -200.0, -200.0, 200.0, 200.0, -250.0, -200.0
c = [(X0, Y0), (X1, Y0), (X1, Y1), (X0, Y1)]
top = [((X0, Y0, ZT), (X1, Y0, ZT), (X1, Y1, ZT)), ((X0, Y0, ZT), (X1, Y1, ZT), (X0, Y1, ZT))]
bottom = [((X0, Y0, ZB), (X1, Y1, ZB), (X1, Y0, ZB)), ((X0, Y0, ZB), (X0, Y1, ZB), (X1, Y1, ZB))]
sides = []
for k in range(4):
    (x0, y0), (x1, y1) = c[k], c[(k + 1) % 4]
    sides += [((x0, y0, ZT), (x0, y0, ZB), (x1, y1, ZB)), ((x0, y0, ZT), (x1, y1, ZB), (x1, y1, ZT))]
tris = top * copies + bottom + sides
# Overlapping triangles inside the top face, counter-clockwise seen from +Z:
# each spans most of the face, turned a little from the last.
for i in range(fan):
    a = 2 * math.pi * i / fan
    p = [(150 * math.cos(a + k * 2 * math.pi / 3), 150 * math.sin(a + k * 2 * math.pi / 3), ZT) for k in range(3)]
    tris.append(tuple(p))
sys.dont_write_bytecode = True
sys.path.insert(0, 'examples/stl')
from make_block import write
write(os.path.join(out, 'plate.stl'), tris, 'skipnc bench overlapping plate')
print('plate.stl: %d triangles (%d copies of the top face, %d overlapping), %.1f MB' % (
    len(tris), copies, fan, os.path.getsize(os.path.join(out, 'plate.stl')) / 1e6))
lines = ['G21 G90 G17 G40 G54', 'G43 H20 G0 Z-150.']
for i in range(10):
    for j in range(10):
        lines += ['G0 X%.3f Y%.3f' % (-180 + 40 * i + 0.37 * j, -180 + 40 * j + 0.21 * i),
                  'G31 Z-220. F300.', 'G0 Z-150.']
lines += ['M30']
open(os.path.join(out, 'grid.nc'), 'w').write('\n'.join(lines) + '\n')
probe = '\n[probe]\nsignal = "SKIP"\ntool = 20\nball_radius = 1.0\nlength = 150.0\nmax_overtravel = 2.0\n'
open(os.path.join(out, 'stl.toml'), 'w').write('spindle_tool = 20\n[[mesh]]\nfile = "plate.stl"\n' + probe)
PY
cat > "$work/m.toml" <<'EOF2'
extends = "mill3"
[tool_offsets]
20 = { length = 150.0 }
EOF2
/usr/bin/time -f '%U %S %M' -o "$work/time.txt" \
  "$bin" run "$work/grid.nc" -m "$work/m.toml" -s "$work/stl.toml" --report "$work/r.json" -q || true
python3 - "$work/r.json" "$work/time.txt" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
u, s, rss = open(sys.argv[2]).read().split()[-3:]
touched = sum(x['triggered'] for x in r['skips'])
z = sorted({round(x['machine_position']['Z'], 4) for x in r['skips'] if x['triggered']})
print('status %s, simulated %.3f s, %d skips (%d touched, latched Z %s), processor %.2f s, peak %d MB'
      % (r['status'], r['final']['time'], len(r['skips']), touched, z[:3], float(u) + float(s), int(rss) // 1024))
PY
