#!/usr/bin/env python3
"""Writes the seed corpora of the fuzzers (fuzz/corpus/<target>/): small valid and
nearly valid files of each format, and fixed pseudo-random bytes for the harnesses
that build their input from bytes. The .vtp seeds are written by blayer itself
(blayer normals), so the path of the blayer executable is the only argument.
Usage: fuzz/make_seed_corpora.py build/app/blayer"""
import os
import random
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TETRA_P = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRA_T = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]
CUBE_P = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
CUBE_Q = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]


def put(target, name, data):
    d = os.path.join(HERE, "corpus", target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def stl_ascii(points, tris, name="t"):
    s = "solid %s\n" % name
    for t in tris:
        s += "facet normal 0 0 0\n outer loop\n"
        for v in t:
            s += "  vertex %g %g %g\n" % points[v]
        s += " endloop\nendfacet\n"
    return s + "endsolid %s\n" % name


def cube_tris():
    return [t for a, b, c, d in CUBE_Q for t in ((a, b, c), (a, c, d))]


def stl_records(points, tris):
    out = b""
    for t in tris:
        out += struct.pack("<3f", 0, 0, 0)
        for v in t:
            out += struct.pack("<3f", *points[v])
        out += b"\0\0"
    return out


def main():
    blayer = sys.argv[1]
    put("read_stl_ascii", "tetra.stl", stl_ascii(TETRA_P, TETRA_T))
    put("read_stl_ascii", "cube.stl", stl_ascii(CUBE_P, cube_tris(), "cube"))
    put("read_stl_ascii", "two_solids.stl", stl_ascii(TETRA_P, TETRA_T[:2], "a") + stl_ascii(TETRA_P, TETRA_T[2:], "b"))
    put("read_stl_binary", "tetra.records", stl_records(TETRA_P, TETRA_T))
    put("read_stl_binary", "cube.records", stl_records(CUBE_P, cube_tris()))

    obj_v = "".join("v %g %g %g\n" % p for p in CUBE_P)
    put("read_obj", "tetra.obj", "".join("v %g %g %g\n" % p for p in TETRA_P) +
        "".join("f %d %d %d\n" % tuple(v + 1 for v in t) for t in TETRA_T))
    put("read_obj", "cube_quads.obj", "# cube\no cube\n" + obj_v + "vt 0 0\nvn 0 0 1\ng sides\n" +
        "".join("f %d/1/1 %d/1/1 %d//1 %d\n" % tuple(v + 1 for v in q) for q in CUBE_Q))
    put("read_obj", "relative.obj", obj_v + "".join("f %d %d \\\n %d %d\n" % tuple(v - 8 for v in q) for q in CUBE_Q))

    off_t = "".join("3 %d %d %d\n" % t for t in TETRA_T)
    put("read_off", "tetra.off", "OFF\n4 4 0\n" + "".join("%g %g %g\n" % p for p in TETRA_P) + off_t)
    put("read_off", "cube_quads.off", "OFF 8 6 12\n# a cube\n" + "".join("%g %g %g\n" % p for p in CUBE_P) +
        "".join("4 %d %d %d %d\n" % q for q in CUBE_Q))
    put("read_off", "coloured.off", "COFF\n4 4 0\n" + "".join("%g %g %g 255 0 0 255\n" % p for p in TETRA_P) + off_t)
    put("read_off", "normals.off", "NOFF\n4 4 0\n" + "".join("%g %g %g 0 0 1\n" % p for p in TETRA_P) + off_t)

    ply_head = ("ply\nformat ascii 1.0\ncomment seed\nelement vertex 4\nproperty float x\nproperty float y\n"
                "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n")
    put("read_ply_ascii", "tetra.ply", ply_head + "".join("%g %g %g\n" % p for p in TETRA_P) + off_t)
    put("read_ply_ascii", "extras.ply",
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
        "property uchar red\nelement face 4\nproperty list uchar uint vertex_index\nproperty float quality\n"
        "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n" +
        "".join("%g %g %g 7\n" % p for p in TETRA_P) + "".join("3 %d %d %d 0.5\n" % t for t in TETRA_T) + "0 1\n")
    # Binary PLY: 7 header-choosing bytes (little-endian, 4 vertices, 4 faces, float
    # coordinates, uchar counts, int indices), then the body.
    body = b"".join(struct.pack("<3f", *p) for p in TETRA_P) + b"".join(struct.pack("<B3i", 3, *t) for t in TETRA_T)
    put("read_ply_binary", "tetra_le", bytes([0, 4, 0, 4, 0, 6, 0x14]) + body)
    body_be = b"".join(struct.pack(">3d", *p) for p in TETRA_P) + b"".join(struct.pack(">B3I", 3, *t) for t in TETRA_T)
    put("read_ply_binary", "tetra_be_double", bytes([1, 4, 0, 4, 0, 7, 0x15]) + body_be)

    vtk_pts = "POINTS 4 double\n" + "".join("%g %g %g\n" % p for p in TETRA_P)
    put("read_vtk_legacy", "tetra_v3.vtk", "# vtk DataFile Version 3.0\ntetra\nASCII\nDATASET POLYDATA\n" + vtk_pts +
        "POLYGONS 4 16\n" + off_t + "CELL_DATA 4\nSCALARS id int 1\nLOOKUP_TABLE default\n0 1 2 3\n")
    put("read_vtk_legacy", "tetra_v5.vtk", "# vtk DataFile Version 5.1\ntetra\nASCII\nDATASET POLYDATA\n" + vtk_pts +
        "METADATA\nINFORMATION 0\n\nLINES 2 2\nOFFSETS vtktypeint64\n0 2\nCONNECTIVITY vtktypeint64\n0 1\n"
        "POLYGONS 5 12\nOFFSETS vtktypeint64\n0 3 6 9 12\nCONNECTIVITY vtktypeint64\n" +
        " ".join("%d %d %d" % t for t in TETRA_T) + "\n")
    bin_pts = b"".join(struct.pack(">3f", *p) for p in TETRA_P)
    bin_polys = b"".join(struct.pack(">4i", 3, *t) for t in TETRA_T)
    put("read_vtk_legacy", "tetra_binary.vtk", b"# vtk DataFile Version 3.0\ntetra\nBINARY\nDATASET POLYDATA\n"
        b"FIELD FieldData 1\nTIME 1 1 double\n" + struct.pack(">d", 0.5) + b"\nPOINTS 4 float\n" + bin_pts +
        b"\nPOLYGONS 4 16\n" + bin_polys + b"\n")

    with tempfile.TemporaryDirectory() as tmp:
        off = os.path.join(tmp, "t.off")
        with open(off, "w") as f:
            f.write("OFF\n4 4 0\n" + "".join("%g %g %g\n" % p for p in TETRA_P) + off_t)
        vtp = os.path.join(tmp, "n.vtp")
        subprocess.run([blayer, "normals", off, "-o", vtp], check=True, stdout=subprocess.DEVNULL)
        with open(vtp, "rb") as f:
            put("read_vtp", "tetra_normals.vtp", f.read())

    put("read_vtp", "tetra_ascii.vtp",
        '<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n'
        '<PolyData><Piece NumberOfPoints="4" NumberOfVerts="0" NumberOfLines="0" NumberOfStrips="0" '
        'NumberOfPolys="4">\n<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">'
        '0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>\n<Polys>'
        '<DataArray type="Int32" Name="connectivity" format="ascii">0 2 1 0 1 3 1 2 3 0 3 2</DataArray>'
        '<DataArray type="Int32" Name="offsets" format="ascii">3 6 9 12</DataArray></Polys>\n'
        '</Piece></PolyData></VTKFile>\n')

    # The appended layouts (raw and base64, 32-bit headers) through VTK's own writer,
    # when Python's VTK is there (scripts/install-deps.sh --extras).
    try:
        import vtk
    except ImportError:
        vtk = None
    if vtk is not None:
        points = vtk.vtkPoints()
        for p in TETRA_P:
            points.InsertNextPoint(*p)
        polys = vtk.vtkCellArray()
        for t in TETRA_T:
            polys.InsertNextCell(3, t)
        poly = vtk.vtkPolyData()
        poly.SetPoints(points)
        poly.SetPolys(polys)
        for name, encode in (("tetra_appended_raw.vtp", False), ("tetra_appended_base64.vtp", True)):
            writer = vtk.vtkXMLPolyDataWriter()
            writer.SetInputData(poly)
            writer.WriteToOutputStringOn()
            writer.SetDataModeToAppended()
            writer.SetEncodeAppendedData(encode)
            writer.SetHeaderTypeToUInt32()
            writer.SetCompressorTypeToZLib()
            writer.Write()
            put("read_vtp", name, writer.GetOutputStdString() if hasattr(writer, "GetOutputStdString")
                else writer.GetOutputString())

    rng = random.Random(20261201)
    for target in ("prepare_surface", "normals_fan", "extrude_check"):
        for i in range(4):
            put(target, "random%d" % i, bytes(rng.randrange(256) for _ in range(64 * (i + 1))))


if __name__ == "__main__":
    main()
