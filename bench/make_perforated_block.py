#!/usr/bin/env python3
"""A perforated block (10 x 5 x 1, 10 x 5 through holes of radius 0.3) tessellated as CAD
exports are: Gmsh's OpenCASCADE kernel meshes the solid with no size limit inside the
faces, so the planar faces are triangulated between their boundary points only (long thin
triangles, points of valence up to 80) and each hole's wall is a band of chords between
its two rims of 96 points. Every point lies on a sharp edge. With the defaults: 11,567
points, 23,330 triangles. Needs gmsh (scripts/install-deps.sh installs it).
Usage: make_perforated_block.py OUT.off [points per hole rim, default 96]"""
import os, subprocess, sys, tempfile

GEO = """SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 10, 5, 1};
k = 0;
For i In {0:9}
  For j In {0:4}
    k += 1;
    Cylinder(100 + k) = {0.5 + i, 0.5 + j, -1, 0, 0, 3, 0.3};
  EndFor
EndFor
BooleanDifference{ Volume{1}; Delete; }{ Volume{101:150}; Delete; }
cs[] = Curve{:};
For c In {0:#cs[]-1}
  bb[] = BoundingBox Curve{cs[c]};
  dx = bb[3] - bb[0]; dy = bb[4] - bb[1];
  If (dx > 0.5 && dx < 0.7 && dy > 0.5 && dy < 0.7)
    Transfinite Curve{cs[c]} = %(rim)d;
  ElseIf (dx > 9)
    Transfinite Curve{cs[c]} = 41;
  ElseIf (dy > 4)
    Transfinite Curve{cs[c]} = 21;
  Else
    Transfinite Curve{cs[c]} = 2;
  EndIf
EndFor
Mesh.MeshSizeMax = 100;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.Algorithm = 6;
"""


def stl_to_off(stl, off):
    index, points, triangles, corners = {}, [], [], []
    for line in open(stl):
        words = line.split()
        if words and words[0] == "vertex":
            key = tuple(words[1:4])  # Gmsh writes a shared point with the same digits
            if key not in index:
                index[key] = len(points)
                points.append(key)
            corners.append(index[key])
            if len(corners) == 3:
                triangles.append(corners)
                corners = []
    with open(off, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(triangles)))
        for p in points:
            f.write(" ".join(p) + "\n")
        for t in triangles:
            f.write("3 %d %d %d\n" % tuple(t))
    return len(points), len(triangles)


def main():
    out = sys.argv[1]
    rim = int(sys.argv[2]) if len(sys.argv) > 2 else 96
    with tempfile.TemporaryDirectory() as work:
        geo, stl = os.path.join(work, "block.geo"), os.path.join(work, "block.stl")
        with open(geo, "w") as f:
            f.write(GEO % {"rim": rim + 1})
        subprocess.run(["gmsh", geo, "-2", "-format", "stl", "-o", stl], check=True, stdout=subprocess.DEVNULL)
        n_points, n_triangles = stl_to_off(stl, out)
    print("%s: %d points, %d triangles" % (out, n_points, n_triangles))


main()
