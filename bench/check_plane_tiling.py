#!/usr/bin/env python3
"""Does a half model's hybrid mesh tile its symmetry plane? (issue of symmetry planes)

Usage: check_plane_tiling.py HYBRID.vtu HALF_WALL.off[.gz] AXIS   (AXIS: x, y or z; plane AXIS = 0)

Finds the mesh's boundary faces (faces of one cell only), keeps those whose every point
has coordinate AXIS exactly 0, and compares their area plus the area the wall's cut
encloses (its boundary loops, from the OFF file) with the box face on the plane (the
mesh's extent in the two other axes). Also counts boundary faces within 1e-6 x the
diagonal of the plane but not on it. Needs python3-vtk9 and numpy
(scripts/install-deps.sh --extras).
"""
import gzip
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

# Local faces of each VTK cell type, as corner indices.
FACES = {
    10: [(0, 1, 2), (0, 1, 3), (1, 2, 3), (0, 2, 3)],
    14: [(0, 1, 2, 3), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)],
    13: [(0, 1, 2), (3, 4, 5), (0, 1, 4, 3), (1, 2, 5, 4), (2, 0, 3, 5)],
    12: [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)],
}


def read_mesh(path):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    g = r.GetOutput()
    pts = vtk_to_numpy(g.GetPoints().GetData()).astype(float)
    types = vtk_to_numpy(g.GetCellTypesArray())
    conn = vtk_to_numpy(g.GetCells().GetConnectivityArray())
    off = vtk_to_numpy(g.GetCells().GetOffsetsArray())
    return pts, types, conn, off


def boundary_faces(types, conn, off):
    """Boundary faces as arrays of node ids, one array per face size (3, 4)."""
    faces = {3: [], 4: []}
    for t, local in FACES.items():
        cells = np.where(types == t)[0]
        if len(cells) == 0:
            continue
        start = off[cells]
        for f in local:
            faces[len(f)].append(np.stack([conn[start + k] for k in f], axis=1))
    out = {}
    for n, parts in faces.items():
        if not parts:
            out[n] = np.zeros((0, n), dtype=np.int64)
            continue
        allf = np.concatenate(parts)
        _, inverse, counts = np.unique(np.sort(allf, axis=1), axis=0, return_inverse=True, return_counts=True)
        out[n] = allf[counts[inverse.ravel()] == 1]
    return out


def polygon_area(pts, faces, axis):
    """Sum of the areas of planar faces (fan triangulation, |normal| along axis)."""
    u, v = [k for k in range(3) if k != axis]
    area = 0.0
    for i in range(1, faces.shape[1] - 1):
        a, b, c = pts[faces[:, 0]], pts[faces[:, i]], pts[faces[:, i + 1]]
        area += np.abs((b[:, u] - a[:, u]) * (c[:, v] - a[:, v]) - (b[:, v] - a[:, v]) * (c[:, u] - a[:, u])).sum() / 2
    return area


def smallest_angles(pts, tris):
    """Each triangle's smallest angle, degrees."""
    p = pts[tris]
    best = np.full(len(tris), 180.0)
    for k in range(3):
        a = p[:, (k + 1) % 3] - p[:, k]
        b = p[:, (k + 2) % 3] - p[:, k]
        cos = (a * b).sum(axis=1) / np.linalg.norm(a, axis=1) / np.linalg.norm(b, axis=1)
        best = np.minimum(best, np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))))
    return best


def cut_area(off_path, axis):
    """Area enclosed by the wall's boundary loops (signed sum over its open edges)."""
    opener = gzip.open if off_path.endswith(".gz") else open
    with opener(off_path, "rt") as f:
        words = [w for line in f for w in line.split("#")[0].split()]
    nv, nf = int(words[1]), int(words[2])
    pts = np.array(words[4:4 + 3 * nv], dtype=float).reshape(nv, 3)
    edges = {}
    i = 4 + 3 * nv
    for _ in range(nf):
        n = int(words[i])
        ids = [int(w) for w in words[i + 1:i + 1 + n]]
        i += 1 + n
        for a, b in zip(ids, ids[1:] + ids[:1]):
            key = (min(a, b), max(a, b))
            if key in edges:
                del edges[key]
            else:
                edges[key] = (a, b)
    u, v = [k for k in range(3) if k != axis]
    s = sum(pts[a, u] * pts[b, v] - pts[b, u] * pts[a, v] for a, b in edges.values())
    return abs(s) / 2, len(edges)


def main(mesh_path, off_path, axis_name):
    axis = "xyz".index(axis_name)
    pts, types, conn, off = read_mesh(mesh_path)
    faces = boundary_faces(types, conn, off)
    diag = np.linalg.norm(pts.max(axis=0) - pts.min(axis=0))
    on_area, n_on, n_near = 0.0, {}, 0
    for n, f in faces.items():
        coord = pts[f][:, :, axis]
        on = (coord == 0.0).all(axis=1)
        near = (np.abs(coord) <= 1e-6 * diag).all(axis=1) & ~on
        n_on[n] = int(on.sum())
        n_near += int(near.sum())
        on_area += polygon_area(pts, f[on], axis)
        if n == 3:
            angles = smallest_angles(pts, f[on])
    u, v = [k for k in range(3) if k != axis]
    box = (pts[:, u].max() - pts[:, u].min()) * (pts[:, v].max() - pts[:, v].min())
    cut, n_cut_edges = cut_area(off_path, axis)
    print("plane %s = 0: %d triangles and %d quads on it, area %.12g" % (axis_name, n_on[3], n_on[4], on_area))
    print("wall's cut: %d edges enclosing %.12g; box face %.12g" % (n_cut_edges, cut, box))
    print("relative difference (faces + cut - box) / box: %.3g" % ((on_area + cut - box) / box))
    if len(angles):
        print("triangles on the plane: smallest angle %.3g degrees, %d below 20.7" % (angles.min(), (angles < 20.7).sum()))
    print("boundary faces within 1e-6 x diagonal of the plane but off it: %d" % n_near)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
