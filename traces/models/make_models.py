#!/usr/bin/env python3
"""Writes the small test models of traces/models/ (deterministic, stdlib only).

    python3 traces/models/make_models.py

Every face is wound counter-clockwise seen from outside (outward normal by
the right-hand rule); the script checks it against an 'outward' direction.
"""
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def newell(pts):
    n = [0.0, 0.0, 0.0]
    for i, a in enumerate(pts):
        b = pts[(i + 1) % len(pts)]
        n[0] += (a[1] - b[1]) * (a[2] + b[2])
        n[1] += (a[2] - b[2]) * (a[0] + b[0])
        n[2] += (a[0] - b[0]) * (a[1] + b[1])
    return n


def orient(verts, faces, outward):
    out = []
    for f in faces:
        pts = [verts[i] for i in f]
        c = [sum(p[k] for p in pts) / len(pts) for k in range(3)]
        n = newell(pts)
        o = outward(c)
        out.append(f if sum(n[k] * o[k] for k in range(3)) >= 0 else list(reversed(f)))
    return out


def cube():
    v = [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    idx = {p: i for i, p in enumerate(v)}
    faces = []
    for axis in range(3):
        for s in (-1, 1):
            corners = []
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0, 0, 0]
                p[axis] = s
                p[(axis + 1) % 3] = a
                p[(axis + 2) % 3] = b
                corners.append(idx[tuple(p)])
            faces.append(corners)
    return v, orient(v, faces, lambda c: c)


def uv_sphere(nlat=12, nlon=24):
    v = [(0.0, 1.0, 0.0)]
    for i in range(1, nlat):
        th = math.pi * i / nlat
        for j in range(nlon):
            ph = 2 * math.pi * j / nlon
            v.append((round(math.sin(th) * math.cos(ph), 6), round(math.cos(th), 6), round(math.sin(th) * math.sin(ph), 6)))
    v.append((0.0, -1.0, 0.0))
    ring = lambda i, j: 1 + (i - 1) * nlon + j % nlon
    faces = []
    for j in range(nlon):
        faces.append([0, ring(1, j), ring(1, j + 1)])
        faces.append([len(v) - 1, ring(nlat - 1, j + 1), ring(nlat - 1, j)])
    for i in range(1, nlat - 1):
        for j in range(nlon):
            faces.append([ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)])
    return v, orient(v, faces, lambda c: c)


def torus(R=1.0, r=0.4, nu=24, nv=12):
    v = []
    for i in range(nu):
        u = 2 * math.pi * i / nu
        for j in range(nv):
            w = 2 * math.pi * j / nv
            v.append((round((R + r * math.cos(w)) * math.cos(u), 6), round(r * math.sin(w), 6),
                      round((R + r * math.cos(w)) * math.sin(u), 6)))
    at = lambda i, j: (i % nu) * nv + j % nv
    faces = [[at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)] for i in range(nu) for j in range(nv)]

    def outward(c):
        u = math.atan2(c[2], c[0])
        return (c[0] - R * math.cos(u), c[1], c[2] - R * math.sin(u))
    return v, orient(v, faces, outward)


def write_obj(name, v, faces, comment):
    with open(os.path.join(HERE, name), "w") as f:
        f.write("# %s\n" % comment)
        for p in v:
            f.write("v %g %g %g\n" % p)
        for fc in faces:
            f.write("f %s\n" % " ".join(str(i + 1) for i in fc))


def write_ply(name, v, faces, comment):
    with open(os.path.join(HERE, name), "w") as f:
        f.write("ply\nformat ascii 1.0\ncomment %s\n" % comment)
        f.write("element vertex %d\nproperty float x\nproperty float y\nproperty float z\n" % len(v))
        f.write("element face %d\nproperty list uchar int vertex_indices\nend_header\n" % len(faces))
        for p in v:
            f.write("%g %g %g\n" % p)
        for fc in faces:
            f.write("%d %s\n" % (len(fc), " ".join(map(str, fc))))


def write_off(name, v, faces, comment):
    with open(os.path.join(HERE, name), "w") as f:
        f.write("OFF\n# %s\n%d %d 0\n" % (comment, len(v), len(faces)))
        for p in v:
            f.write("%g %g %g\n" % p)
        for fc in faces:
            f.write("%d %s\n" % (len(fc), " ".join(map(str, fc))))


def write_stl(name, v, faces, comment):
    """Binary STL: polygons fanned (STL holds triangles only)."""
    tris = [(fc[0], fc[k], fc[k + 1]) for fc in faces for k in range(1, len(fc) - 1)]
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(comment.encode()[:80].ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            pts = [v[i] for i in t]
            n = newell(pts)
            ln = math.sqrt(sum(c * c for c in n)) or 1.0
            f.write(struct.pack("<3f", *(c / ln for c in n)))
            for p in pts:
                f.write(struct.pack("<3f", *p))
            f.write(struct.pack("<H", 0))


def star(points=5, r_out=1.0, r_in=0.45):
    """A flat star: 2 x points vertices, `points` concave ones, in the z = 0 plane, facing +z."""
    v = []
    for k in range(2 * points):
        a = math.pi / 2 + math.pi * k / points
        r = r_out if k % 2 == 0 else r_in
        v.append((round(r * math.cos(a), 6), round(r * math.sin(a), 6), 0.0))
    return v, [list(range(2 * points))]


def main():
    v, f = cube()
    write_obj("cube.obj", v, f, "cube, side 2, centred on the origin: 8 vertices, 6 quads")
    write_off("cube.off", v, f, "cube, side 2, centred on the origin: 8 vertices, 6 quads")
    v, f = uv_sphere()
    write_ply("sphere.ply", v, f, "unit UV sphere, 12 x 24: 24 + 24 triangle caps, 240 quads")
    write_stl("sphere.stl", v, f, "unit UV sphere 12 x 24, quads fanned into triangles (binary STL)")
    v, f = torus()
    write_off("torus.off", v, f, "torus R 1 r 0.4, 24 x 12 quads")
    write_obj("torus.obj", v, f, "torus R 1 r 0.4, 24 x 12 quads")
    v, f = star()
    write_obj("star.obj", v, f, "a flat five-pointed star: one 10-gon with 5 concave vertices, facing +z")
    write_obj("nonplanar_quad.obj", [(-1, -1, 0), (1, -1, 0.5), (1, 1, 0), (-1, 1, 0.5)], [[0, 1, 2, 3]],
              "one twisted quad: corners alternate z = 0 and z = 0.5 (non-planar)")
    write_obj("floor.obj", [(-20, 0, -20), (-20, 0, 20), (20, 0, 20), (20, 0, -20)], [[0, 1, 2, 3]],
              "a 40 x 40 floor quad in y = 0, facing +y")
    write_obj("lshape.obj", [(0, 0, 0), (2, 0, 0), (2, 1, 0), (1, 1, 0), (1, 2, 0), (0, 2, 0)],
              [[0, 1, 2, 3, 4, 5]], "an L-shaped hexagon with one concave vertex, facing +z")


if __name__ == "__main__":
    main()
