#!/usr/bin/python3
"""Converts an OFF surface (optionally .gz) to ASCII STL, for tools that read only STL."""
import gzip
import sys


def main(src, dst):
    opener = gzip.open if src.endswith(".gz") else open
    with opener(src, "rt") as f:
        words = []
        for line in f:
            line = line.split("#", 1)[0]
            words.extend(line.split())
    assert words[0] == "OFF", "not an OFF file"
    nv, nf = int(words[1]), int(words[2])
    pos = 4
    pts = []
    for _ in range(nv):
        pts.append(words[pos:pos + 3])
        pos += 3
    with open(dst, "w") as o:
        o.write("solid s\n")
        for _ in range(nf):
            n = int(words[pos])
            ids = [int(w) for w in words[pos + 1:pos + 1 + n]]
            pos += 1 + n
            for k in range(1, n - 1):
                o.write("facet normal 0 0 0\nouter loop\n")
                for i in (ids[0], ids[k], ids[k + 1]):
                    o.write("vertex %s %s %s\n" % tuple(pts[i]))
                o.write("endloop\nendfacet\n")
        o.write("endsolid s\n")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
