#!/usr/bin/env python3
"""Writes a generated triangle mesh as an OBJ (deterministic, standard library only).

    python3 tools/make_mesh.py sphere --triangles 1000000 -o sphere.obj
    python3 tools/make_mesh.py sphere --rings 300 -o sphere_179k.obj

`sphere` is a unit UV sphere of R rings and R segments: 2R pole triangles
plus 2R(R-2) from the quads, so --triangles N picks the R that comes
closest to N. Every face is wound counter-clockwise seen from outside.
Nothing is stored in the repo: `girtd bench --scale` and the tests write
what they need.
"""
import argparse
import math
import sys


def sphere_triangles(rings):
    return 2 * rings + 2 * rings * (rings - 2)


def rings_for(triangles):
    # 2R^2 - 2R = N  ->  R = (1 + sqrt(1 + 2N)) / 2
    r = max(3, round((1 + math.sqrt(1 + 2 * triangles)) / 2))
    return r


def write_sphere(out, rings):
    nlat = nlon = rings
    out.write("# unit UV sphere, %d x %d: %d triangles (tools/make_mesh.py)\n"
              % (nlat, nlon, sphere_triangles(rings)))
    lines = ["v 0 1 0"]
    for i in range(1, nlat):
        th = math.pi * i / nlat
        st, ct = math.sin(th), math.cos(th)
        for j in range(nlon):
            ph = 2 * math.pi * j / nlon
            lines.append("v %.7f %.7f %.7f" % (st * math.cos(ph), ct, st * math.sin(ph)))
    south = 1 + (nlat - 1) * nlon + 1  # 1-based index of the south pole
    lines.append("v 0 -1 0")
    out.write("\n".join(lines))
    out.write("\n")

    def ring(i, j):  # 1-based OBJ index of ring i (1..nlat-1), segment j
        return 2 + (i - 1) * nlon + j % nlon

    faces = []
    for j in range(nlon):
        # Seen from outside (+y above, phi turning from +x towards +z) these are
        # counter-clockwise: the outward normal is the right-hand rule's.
        faces.append("f 1 %d %d" % (ring(1, j + 1), ring(1, j)))
        faces.append("f %d %d %d" % (south, ring(nlat - 1, j), ring(nlat - 1, j + 1)))
    for i in range(1, nlat - 1):
        for j in range(nlon):
            a, b = ring(i, j), ring(i + 1, j)
            c, d = ring(i + 1, j + 1), ring(i, j + 1)
            faces.append("f %d %d %d" % (a, d, c))
            faces.append("f %d %d %d" % (a, c, b))
        if len(faces) > 200000:
            out.write("\n".join(faces))
            out.write("\n")
            faces = []
    if faces:
        out.write("\n".join(faces))
        out.write("\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("kind", choices=["sphere"])
    size = ap.add_mutually_exclusive_group(required=True)
    size.add_argument("--triangles", type=int, help="about this many triangles")
    size.add_argument("--rings", type=int, help="the sphere's rings (and segments)")
    ap.add_argument("-o", "--output", required=True)
    a = ap.parse_args()
    rings = a.rings if a.rings else rings_for(a.triangles)
    if rings < 3 or rings > 100000:
        sys.exit("make_mesh.py: rings must be 3..100000, got %d" % rings)
    with open(a.output, "w") as f:
        write_sphere(f, rings)
    print("%s: %d triangles" % (a.output, sphere_triangles(rings)))


if __name__ == "__main__":
    main()
