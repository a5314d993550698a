#!/usr/bin/env python3
"""Writes block.stl: a block 80 x 80 x 30 mm with a 2 mm x 45 degree chamfer
on its top edges and a 24 mm through bore at its centre, and boss.stl: a
boss 16 mm across and 10 mm tall standing on the block's top face. Part
coordinates: the block from (0, 0, -30) to (80, 80, 0), the bore's axis at
(40, 40), the boss's at (64, 64). Closed meshes, triangles counter-clockwise seen from outside
(checked here: every edge is used once in each direction, and the volume is
positive). Binary STL, little-endian.

    python3 make_block.py            # writes block.stl and boss.stl here
    python3 make_block.py --sides 200000 --out DIR   # the same part, finer
                                     # (bench/stl_probe.sh: about 1.6M triangles)

The bore and the boss are polygons of SIDES sides with their corners on the
circle (block_cycle.nc says what that does to the measured values).
"""
import math
import os
import struct
import sys

L, W, H = 80.0, 80.0, 30.0       # block (square: its corners and the chamfer's
CH = 2.0                         # are on the same diagonals seen from the bore)
BORE = (40.0, 40.0, 12.0)        # x, y, radius
BOSS = (64.0, 64.0, 8.0, 10.0)   # x, y, radius, height
SIDES = 128  # --sides


def ring_angles():
    return [2.0 * math.pi * i / SIDES for i in range(SIDES)]


def ray_to_rect(cx, cy, a, x0, y0, x1, y1):
    """Where the ray from (cx, cy) at angle a leaves the rectangle."""
    dx, dy = math.cos(a), math.sin(a)
    ts = []
    if dx > 1e-12:
        ts.append((x1 - cx) / dx)
    if dx < -1e-12:
        ts.append((x0 - cx) / dx)
    if dy > 1e-12:
        ts.append((y1 - cy) / dy)
    if dy < -1e-12:
        ts.append((y0 - cy) / dy)
    t = min(ts)
    return (cx + t * dx, cy + t * dy)


def outer_ring(cx, cy, x0, y0, x1, y1, angles):
    """The rectangle's boundary seen from (cx, cy): the ray point at each
    angle, and the corners between them, in angular order. Returns the points
    and, for each angle, the index of its ray point."""
    corners = [(x1, y1), (x0, y1), (x0, y0), (x1, y0)]
    corner_angles = sorted(((math.atan2(y - cy, x - cx)) % (2 * math.pi), (x, y)) for x, y in corners)
    pts, at = [], []
    k = 0
    for i, a in enumerate(angles):
        while k < 4 and corner_angles[k][0] < a + 1e-12:
            if corner_angles[k][0] < a - 1e-12:  # else the ray's point is the corner
                pts.append(corner_angles[k][1])
            k += 1
        at.append(len(pts))
        pts.append(ray_to_rect(cx, cy, a, x0, y0, x1, y1))
    while k < 4:
        pts.append(corner_angles[k][1])
        k += 1
    return pts, at


def block():
    cx, cy, r = BORE
    angles = ring_angles()
    circle = [(cx + r * math.cos(a), cy + r * math.sin(a)) for a in angles]
    full, at_full = outer_ring(cx, cy, 0.0, 0.0, L, W, angles)
    inset, at_inset = outer_ring(cx, cy, CH, CH, L - CH, W - CH, angles)
    assert at_full == at_inset and len(full) == len(inset)
    tris = []

    def annulus(z, up):
        # Between the bore's circle and the outer ring, sector by sector.
        ring = inset if up else full
        n = len(angles)
        for i in range(n):
            j = (i + 1) % n
            a, b = at_inset[i], at_inset[j] if j else len(ring) + at_inset[0]
            poly = [ring[k % len(ring)] for k in range(a, b + 1)]  # outer, in order
            c0, c1 = circle[i], circle[j]
            # Fan from the circle: (c0, outer...) then (c0, outer_last, c1).
            for k in range(len(poly) - 1):
                t = (c0, poly[k], poly[k + 1])
                tris.append(tuple((x, y, z) for x, y in (t if up else t[::-1])))
            t = (c0, poly[-1], c1)
            tris.append(tuple((x, y, z) for x, y in (t if up else t[::-1])))

    annulus(0.0, True)
    annulus(-H, False)
    # The chamfer (inset ring at z 0 to the full ring at z -CH) and the walls
    # (full ring from z -CH down to -H): quads between matching points.
    m = len(full)
    for k in range(m):
        p0, p1 = inset[k], inset[(k + 1) % m]
        q0, q1 = full[k], full[(k + 1) % m]
        a0, a1 = (p0[0], p0[1], 0.0), (p1[0], p1[1], 0.0)
        b0, b1 = (q0[0], q0[1], -CH), (q1[0], q1[1], -CH)
        tris += [(a0, b0, b1), (a0, b1, a1)]
        c0, c1 = (q0[0], q0[1], -H), (q1[0], q1[1], -H)
        tris += [(b0, c0, c1), (b0, c1, b1)]
    # The bore's wall, facing the axis.
    n = len(circle)
    for i in range(n):
        u0, u1 = circle[i], circle[(i + 1) % n]
        t0, t1 = (u0[0], u0[1], 0.0), (u1[0], u1[1], 0.0)
        d0, d1 = (u0[0], u0[1], -H), (u1[0], u1[1], -H)
        tris += [(t0, t1, d1), (t0, d1, d0)]
    return tris


def boss():
    cx, cy, r, h = BOSS
    pts = [(cx + r * math.cos(a), cy + r * math.sin(a)) for a in ring_angles()]
    tris = []
    n = len(pts)
    for i in range(n):
        p, q = pts[i], pts[(i + 1) % n]
        tris.append(((cx, cy, h), (p[0], p[1], h), (q[0], q[1], h)))
        tris.append(((cx, cy, 0.0), (q[0], q[1], 0.0), (p[0], p[1], 0.0)))
        tris += [((p[0], p[1], 0.0), (q[0], q[1], 0.0), (q[0], q[1], h)),
                 ((p[0], p[1], 0.0), (q[0], q[1], h), (p[0], p[1], h))]
    return tris


def check(tris, name):
    edges = {}
    vol = 0.0
    for a, b, c in tris:
        for e in ((a, b), (b, c), (c, a)):
            edges[e] = edges.get(e, 0) + 1
        vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0
    bad = [e for e, k in edges.items() if k != 1 or edges.get((e[1], e[0]), 0) != 1]
    if bad or vol <= 0:
        sys.exit('%s: not closed and outward (%d bad edges, volume %g)' % (name, len(bad), vol))
    return vol


def write(path, tris, name):
    with open(path, 'wb') as f:
        f.write(name.encode().ljust(80, b' '))
        f.write(struct.pack('<I', len(tris)))
        for t in tris:
            f.write(struct.pack('<3f', 0.0, 0.0, 0.0))
            for v in t:
                f.write(struct.pack('<3f', *v))
            f.write(b'\0\0')


def main():
    global SIDES
    here = os.path.dirname(os.path.abspath(__file__))
    args = sys.argv[1:]
    while args:
        if args[0] == '--sides' and len(args) > 1 and int(args[1]) % 8 == 0 and int(args[1]) >= 8:
            SIDES = int(args[1])
        elif args[0] == '--out' and len(args) > 1:
            here = args[1]
        else:
            sys.exit(__doc__)
        args = args[2:]
    for name, tris in (('block', block()), ('boss', boss())):
        vol = check(tris, name)
        write(os.path.join(here, name + '.stl'), tris, 'skipnc example: ' + name)
        print('%s.stl: %d triangles, %.3f cm3' % (name, len(tris), vol / 1000.0))


if __name__ == '__main__':
    main()
