#!/usr/bin/python3
"""Writes the full model of a half model: the half and its mirror image about the
symmetry plane `axis = 0` (x, y or z), joined along the open boundary. The boundary's
points are snapped onto the plane first (files often hold them a rounding away), so
that each is shared by both halves. Faces of the mirror are reversed, to keep the
orientation. Usage: mirror_half_model.py HALF.off[.gz] AXIS FULL.off"""
import gzip
import sys


def read_off(path):
    with (gzip.open(path, "rt") if path.endswith(".gz") else open(path)) as f:
        words = []
        for line in f:
            words.extend(line.split("#", 1)[0].split())
    assert words[0] == "OFF", "not an OFF file"
    nv, nf = int(words[1]), int(words[2])
    pos = 4
    pts = [[float(w) for w in words[pos + 3 * i:pos + 3 * i + 3]] for i in range(nv)]
    pos += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(words[pos])
        faces.append([int(w) for w in words[pos + 1:pos + 1 + n]])
        pos += 1 + n
    return pts, faces


def main(src, axis_name, dst):
    axis = "xyz".index(axis_name)
    pts, faces = read_off(src)
    count = {}
    for f in faces:
        for a, b in zip(f, f[1:] + f[:1]):
            key = (min(a, b), max(a, b))
            count[key] = count.get(key, 0) + 1
    on_plane = set()
    for (a, b), n in count.items():
        if n == 1:
            on_plane.update((a, b))
    # Snapped only when a rounding away: any other open edge (a hole, a base off the
    # plane) would make a wrong full model.
    lo = [min(p[k] for p in pts) for k in range(3)]
    hi = [max(p[k] for p in pts) for k in range(3)]
    tol = 1e-9 * sum((h - l) ** 2 for l, h in zip(lo, hi)) ** 0.5
    off = [v for v in on_plane if abs(pts[v][axis]) > tol]
    if off:
        sys.exit("%s: %d points of open edges lie off the plane %s = 0 (e.g. point %d at %s = %g), "
                 "so the model is not a half model open at that plane" % (src, len(off), axis_name, off[0],
                                                                         axis_name, pts[off[0]][axis]))
    for v in on_plane:
        pts[v][axis] = 0.0
    mirror = {}
    out_pts = [list(p) for p in pts]
    for v, p in enumerate(pts):
        if v in on_plane:
            mirror[v] = v
        else:
            q = list(p)
            q[axis] = -q[axis]
            mirror[v] = len(out_pts)
            out_pts.append(q)
    out_faces = [list(f) for f in faces] + [[mirror[v] for v in reversed(f)] for f in faces]
    with open(dst, "w") as o:
        o.write("OFF\n%d %d 0\n" % (len(out_pts), len(out_faces)))
        for p in out_pts:
            o.write("%.17g %.17g %.17g\n" % tuple(p))
        for f in out_faces:
            o.write("%d %s\n" % (len(f), " ".join(map(str, f))))
    print("%s: %d points on the plane %s = 0; full model %d points, %d faces"
          % (dst, len(on_plane), axis_name, len(out_pts), len(out_faces)))


if __name__ == "__main__":
    main(*sys.argv[1:4])
