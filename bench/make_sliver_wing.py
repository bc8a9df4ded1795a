#!/usr/bin/env python3
"""A NACA 0012 wing segment (chord 1, span 1) tessellated as CAD STL exports are: every
side triangle spans the whole span, and the end caps are strips between the upper and
lower surfaces with no interior point. With 2000 points per side (7,996 points, 15,988
triangles) the trailing-edge triangles are 1.6e6 times as long as they are wide. The
same surface as tests/common/analytic_surfaces.h sliver_wing_segment.
Usage: make_sliver_wing.py OUT.off [points per side, default 2000]"""
import math, sys

def naca0012(x):
    return 0.6 * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1036 * x**4)

def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 2000
    xs = [0.5 * (1 - math.cos(math.pi * i / (n - 1))) for i in range(n)]
    # section loop: upper LE -> TE, then lower TE -> LE (LE and TE shared)
    loop = [(x, naca0012(x)) for x in xs] + [(x, -naca0012(x)) for x in reversed(xs[1:-1])]
    m = len(loop)
    pts = [(x, y, z) for z in (0.0, 1.0) for (x, y) in loop]
    tris = []
    for i in range(m):                      # sides: one quad across the span, two triangles
        a, b = i, (i + 1) % m
        tris.append((a, m + b, b))
        tris.append((a, m + a, m + b))
    upper = list(range(n))                  # cap strip between upper and lower points
    lower = [0] + [m - k for k in range(1, n - 1)] + [n - 1]
    for i in range(n - 1):
        u0, u1, l0, l1 = upper[i], upper[i + 1], lower[i], lower[i + 1]
        cap = [(u0, u1, l1)] + ([] if i == 0 else [(u0, l1, l0)])
        if i == n - 2:                      # the trailing edge closes the strip
            cap = [(u0, u1, l0)]
        for (a, b, c) in cap:
            tris.append((a, b, c))          # root cap faces -z
            tris.append((m + a, m + c, m + b))
    with open(out, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(pts), len(tris)))
        for p in pts: f.write("%.17g %.17g %.17g\n" % p)
        for t in tris: f.write("3 %d %d %d\n" % t)

main()
