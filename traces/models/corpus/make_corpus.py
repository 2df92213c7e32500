#!/usr/bin/env python3
"""Writes the real-world model corpus of traces/models/corpus/ and its
manifest corpus.tsv (deterministic, standard library only).

    python3 traces/models/corpus/make_corpus.py

Each feature file (negative indices, groups, continuations, n-gons, binary
PLY/STL, OFF colours, a missing .mtl, ...) has a TWIN: the same shape written
without the feature, which must give the same frame (README.md next to this
script; testbench/cli/test_model_corpus.sh checks it). The manifest also
gives each file's polygon count, taken from the face lists written here (not
by reading the files back), which the front end must report.

Coordinates are multiples of 1/256, so that every reader (OBJ, OFF, ASCII
PLY/STL text through assimp's fast_atof; binary float32) gets the same
floats bit for bit. Every face is wound counter-clockwise seen from outside.
"""
import math
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.dont_write_bytecode = True  # nothing written beside the models
import make_models  # noqa: E402  (the hand-made models' winding helpers)
from make_models import newell  # noqa: E402
Q = 256.0  # coordinates are multiples of 1/Q


def q(x):
    r = round(x * Q) / Q
    return 0.0 if r == 0 else r


def num(x):
    """Shortest exact decimal of a multiple of 1/Q (no exponent, no -0)."""
    s = repr(float(x))
    assert "e" not in s, s
    return s[:-2] if s.endswith(".0") else s


def check_outward(name, v, faces, outward):
    for f in faces:
        pts = [v[i] for i in f]
        c = [sum(p[k] for p in pts) / len(pts) for k in range(3)]
        n = newell(pts)
        o = outward(c)
        assert sum(n[k] * o[k] for k in range(3)) > 0, (name, f)


def orient(v, faces, outward):
    return [list(f) for f in make_models.orient(v, faces, outward)]


def fan(face):
    """The GIRTD triangulator's split of a convex polygon: a fan from corner 0."""
    return [[face[0], face[k], face[k + 1]] for k in range(1, len(face) - 1)]


# ----------------------------------------------------------------- shapes

def house():
    """A house: box walls (no top), floor, a hip roof (pyramid) and a chimney
    poking through it. Returns vertices, faces and the face groups."""
    v = []
    for y in (0.0, 1.25):
        for x, z in ((-1, -0.75), (1, -0.75), (1, 0.75), (-1, 0.75)):
            v.append((x, y, z))
    v.append((0.0, 2.0, 0.0))  # 8: roof apex
    for y in (1.0, 2.25):
        for x, z in ((0.375, -0.375), (0.625, -0.375), (0.625, -0.125), (0.375, -0.125)):
            v.append((x, y, z))
    v = [tuple(q(c) for c in p) for p in v]
    walls = [[0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    floor = [[0, 3, 2, 1]]
    roof = [[4, 5, 8], [5, 6, 8], [6, 7, 8], [7, 4, 8]]
    chimney_sides = [[9, 10, 14, 13], [10, 11, 15, 14], [11, 12, 16, 15], [12, 9, 13, 16]]
    chimney_top = [[13, 14, 15, 16]]

    def outward_house(c):
        if 0.3 < c[0] < 0.7 and -0.4 < c[2] < -0.1 and c[1] > 1.0:  # chimney
            return (c[0] - 0.5, c[1] - 1.6, c[2] + 0.25)
        return (c[0], c[1] - 0.9, c[2])
    groups = [("house", "walls", walls + floor), ("house", "roof", roof),
              ("chimney", "chimney_sides", chimney_sides), ("chimney", "chimney_top", chimney_top)]
    groups = [(o, g, orient(v, fs, outward_house)) for o, g, fs in groups]
    faces = [f for _, _, fs in groups for f in fs]
    check_outward("house", v, faces, outward_house)
    return v, faces, groups


def gem():
    """A faceted gem: octagonal table (one 8-gon), 8 crown quads, 8 girdle
    quads, 8 pavilion triangles down to the culet; tilted 12 deg about x."""
    v = []
    def ring(r, y, phase):
        return [(r * math.cos(phase + k * math.pi / 4), y, r * math.sin(phase + k * math.pi / 4)) for k in range(8)]
    v += ring(0.55, 0.45, math.pi / 8)           # 0..7 table
    v += ring(1.0, 0.1, math.pi / 8)             # 8..15 girdle top
    v += ring(1.0, -0.1, math.pi / 8)            # 16..23 girdle bottom
    v.append((0.0, -0.95, 0.0))                  # 24 culet
    tilt = math.radians(12)
    v = [(x, y * math.cos(tilt) - z * math.sin(tilt), y * math.sin(tilt) + z * math.cos(tilt)) for x, y, z in v]
    v = [tuple(q(16 * c) for c in p) for p in v]  # 16 x: faces planar to 1e-3 after rounding
    faces = [list(range(8))]
    faces += [[k, (k + 1) % 8, 8 + (k + 1) % 8, 8 + k] for k in range(8)]
    faces += [[8 + k, 8 + (k + 1) % 8, 16 + (k + 1) % 8, 16 + k] for k in range(8)]
    faces += [[16 + k, 16 + (k + 1) % 8, 24] for k in range(8)]
    faces = orient(v, faces, lambda c: c)
    check_outward("gem", v, faces, lambda c: c)
    return v, faces


def prisms():
    """Four prisms side by side with 5-, 6-, 7- and 8-gon caps (convex,
    regular) and quad sides. The caps lie in y = const planes (exact normals)."""
    v, faces = [], []
    spots = [(5, -1.25, 1.1, 0.7), (6, 1.25, 1.1, 1.0), (7, -1.25, -1.1, 1.5), (8, 1.25, -1.1, 2.0)]
    for n, cx, cz, h in spots:
        base = len(v)
        for y in (0.0, h):
            for k in range(n):
                a = 0.3 + 2 * math.pi * k / n
                v.append((q(cx + math.cos(a)), q(y), q(cz + math.sin(a))))
        bottom = list(range(base, base + n))
        top = list(range(base + n, base + 2 * n))
        fs = [list(reversed(bottom)), top]
        fs += [[bottom[k], bottom[(k + 1) % n], top[(k + 1) % n], top[k]] for k in range(n)]
        centre = (cx, h / 2, cz)
        out = lambda c, centre=centre: tuple(c[i] - centre[i] for i in range(3))
        fs = orient(v, fs, out)
        check_outward("prism", v, fs, out)
        faces += fs
    return v, faces


def uv_sphere(nlat=6, nlon=10, r=16.0):
    """A low-poly UV sphere: 2 x nlon cap triangles, (nlat - 2) x nlon quads."""
    v = [(0.0, r, 0.0)]
    for i in range(1, nlat):
        th = math.pi * i / nlat
        for j in range(nlon):
            ph = 2 * math.pi * j / nlon + 0.2
            v.append((q(r * math.sin(th) * math.cos(ph)), q(r * math.cos(th)), q(r * math.sin(th) * math.sin(ph))))
    v.append((0.0, -r, 0.0))
    ring = lambda i, j: 1 + (i - 1) * nlon + j % nlon
    faces = []
    for j in range(nlon):
        faces.append([0, ring(1, j), ring(1, j + 1)])
    for i in range(1, nlat - 1):
        for j in range(nlon):
            faces.append([ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)])
    for j in range(nlon):
        faces.append([len(v) - 1, ring(nlat - 1, j + 1), ring(nlat - 1, j)])
    faces = orient(v, faces, lambda c: c)
    check_outward("sphere", v, faces, lambda c: c)
    return v, faces


def icosahedron():
    """An icosahedron stretched 1.4 x along y (20 triangles)."""
    p = (1 + math.sqrt(5)) / 2
    raw = [(-1, p, 0), (1, p, 0), (-1, -p, 0), (1, -p, 0), (0, -1, p), (0, 1, p), (0, -1, -p), (0, 1, -p),
           (p, 0, -1), (p, 0, 1), (-p, 0, -1), (-p, 0, 1)]
    s = 1 / math.sqrt(1 + p * p)
    v = [(q(x * s), q(1.4 * y * s), q(z * s)) for x, y, z in raw]
    faces = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2],
             [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5],
             [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1]]
    faces = orient(v, faces, lambda c: c)
    check_outward("icosahedron", v, faces, lambda c: c)
    return v, faces


def soccer_ball(r=8.0):
    """A truncated icosahedron (12 pentagons, 20 hexagons): neighbouring
    faces 37-42 deg apart, so under the 60 deg crease it is one smooth
    surface and its vertex normals average the n-gons' normals."""
    p = (1 + math.sqrt(5)) / 2
    def even_perms(t):
        return [(t[0], t[1], t[2]), (t[1], t[2], t[0]), (t[2], t[0], t[1])]
    pts = set()
    for base in ((0, 1, 3 * p), (1, 2 + p, 2 * p), (p, 2, 2 * p + 1)):
        for sx in (1, -1):
            for sy in (1, -1):
                for sz in (1, -1):
                    t = (sx * base[0], sy * base[1], sz * base[2])
                    for e in even_perms(t):
                        pts.add(tuple(0.0 if c == 0 else c for c in e))
    raw = sorted(pts)
    scale = r / math.sqrt(1 + 9 * p * p)
    v = [tuple(q(c * scale) for c in pt) for pt in raw]
    # Face directions: the icosahedron's 12 vertices (pentagons) and its 20
    # faces (hexagons); a face is the set of vertices farthest along one.
    ico = []
    for a, b in ((1, p), (-1, p), (1, -p), (-1, -p)):
        ico += [(0, a, b), (a, b, 0), (b, 0, a)]
    dirs = list(ico)
    for i in range(12):
        for j in range(i + 1, 12):
            for k in range(j + 1, 12):
                if all(abs(sum((u[m] - w[m]) ** 2 for m in range(3)) - 4) < 1e-9
                       for u, w in ((ico[i], ico[j]), (ico[j], ico[k]), (ico[i], ico[k]))):
                    dirs.append(tuple(ico[i][m] + ico[j][m] + ico[k][m] for m in range(3)))
    assert len(dirs) == 32
    faces = []
    for d in sorted(dirs):
        dots = [sum(pt[m] * d[m] for m in range(3)) for pt in raw]
        top = max(dots)
        f = [i for i, x in enumerate(dots) if x > top - 1e-6]
        assert len(f) in (5, 6), len(f)
        # around d: angle in a plane perpendicular to d
        ln = math.sqrt(sum(c * c for c in d))
        n = [c / ln for c in d]
        a = [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0]
        e1 = [a[1] * n[2] - a[2] * n[1], a[2] * n[0] - a[0] * n[2], a[0] * n[1] - a[1] * n[0]]
        e2 = [n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]]
        f.sort(key=lambda i: math.atan2(sum(raw[i][m] * e2[m] for m in range(3)), sum(raw[i][m] * e1[m] for m in range(3))))
        faces.append(f)
    faces = orient(v, faces, lambda c: c)
    check_outward("soccer ball", v, faces, lambda c: c)
    return v, faces


# ---------------------------------------------------------------- writers

def put(name, data):
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


POLYGONS = {}  # model file -> the polygons (faces of 3+ corners) written to it


def put_model(name, data, faces):
    """Writes a model file that holds exactly the polygons `faces` (lines and
    points besides them are not polygons) and records their count."""
    assert name not in POLYGONS, name
    assert faces and all(len(fc) >= 3 for fc in faces), name
    POLYGONS[name] = len(faces)
    put(name, data)


def vline(p):
    return "v %s\n" % " ".join(num(c) for c in p)


def obj_text(comment, v, faces, head=""):
    s = "# %s\n%s" % (comment, head)
    s += "".join(vline(p) for p in v)
    s += "".join("f %s\n" % " ".join(str(i + 1) for i in fc) for fc in faces)
    return s


def off_text(keyword, comment, v, faces, vertex_extra=lambda k: "", face_extra=lambda k: ""):
    """OFF (or COFF): faces of at most 9 corners (assimp's OFF reader drops
    a longer face, so GIRTD refuses it: sim/io/model_precheck.cpp)."""
    assert all(len(fc) <= 9 for fc in faces), comment
    s = "%s\n# %s\n%d %d 0\n" % (keyword, comment, len(v), len(faces))
    for k, p in enumerate(v):
        s += " ".join(num(c) for c in p) + vertex_extra(k) + "\n"
    for k, fc in enumerate(faces):
        s += "%d %s%s\n" % (len(fc), " ".join(map(str, fc)), face_extra(k))
    return s


def house_files(v, faces, groups):
    put_model("house.obj", obj_text("house: walls, floor, hip roof, chimney; one object, no groups, no materials", v, faces),
              faces)
    put_model("house.off", off_text("OFF", "house (as house.obj), plain OFF", v, faces), faces)
    # o / g: the objects' vertices written where the object starts (global,
    # positive indices, as exporters write them).
    s = "# house: the same shape as house.obj in two objects (o) of two groups (g) each\n"
    chimney_first = 9
    for o, g, fs in groups:
        if g == "walls":
            s += "o house\n" + "".join(vline(p) for p in v[:chimney_first])
        if g == "chimney_sides":
            s += "o chimney\n" + "".join(vline(p) for p in v[chimney_first:])
        s += "g %s\ns 1\n" % g + "".join("f %s\n" % " ".join(str(i + 1) for i in fc) for fc in fs)
    put_model("house_groups.obj", s, [fc for _, _, fs in groups for fc in fs])
    # Line and point elements besides the faces (wire edges, markers): skipped.
    put_model("house_lines.obj", obj_text("house (as house.obj) with l and p elements, which are not drawn", v, faces)
              + "l 1 2 3 4 1\nl 5 9\np 9\np 1 2\n", faces)

    def with_materials(mtllib, comment, chimney_material="brick", obj="o house\n"):
        s = "# %s\nmtllib %s\n%s" % (comment, mtllib, obj) + "".join(vline(p) for p in v)
        material = {"walls": "plaster", "roof": "tiles", "chimney_sides": chimney_material, "chimney_top": "soot"}
        for _, g, fs in groups:
            s += "usemtl %s\ns off\n" % material[g] + "".join("f %s\n" % " ".join(str(i + 1) for i in fc) for fc in fs)
        return s
    put("house.mtl", "# materials of house_mtl.obj\n"
        "newmtl plaster\nKa 0.2 0.2 0.2\nKd 0.9 0.85 0.7\nKs 0 0 0\nillum 1\n\n"
        "newmtl tiles\nKa 0.2 0.1 0.1\nKd 0.7 0.2 0.1\nKs 0.3 0.3 0.3\nNs 20\nillum 2\n\n"
        "newmtl brick\nKd 0.6 0.3 0.2\nillum 1\n\n"
        "newmtl soot\nKd 0.1 0.1 0.1\nd 1\nillum 1\n")
    # As Blender writes it: mtllib, o, the vertices, usemtl before each group of faces.
    put_model("house_mtl.obj", with_materials("house.mtl", "house with materials from house.mtl (four usemtl)"), faces)
    # usemtl before any o or g (hand-written files, older exporters): assimp
    # 5.2.5 logs "No object detected to attach a new mesh instance" at Err
    # severity, then reads every face; nothing is wrong with the file.
    put_model("house_mtl_noobj.obj", with_materials("house.mtl", "house with materials from house.mtl, no o or g line",
                                                    obj=""), faces)
    # The same bytes but for the library's name: a file that does not exist
    # (nor house_nomtl.mtl, the name assimp's own fallback would try).
    put_model("house_nomtl.obj", with_materials("house_lost.mtl", "house with materials from house.mtl (four usemtl)"),
              faces)
    put_model("house_badmtl.obj", with_materials("house.mtl", "house: the chimney's usemtl names a material house.mtl lacks",
                                                 chimney_material="granite"), faces)


def gem_files(v, faces):
    put_model("gem.obj", obj_text("faceted gem: 8-gon table, 8 crown quads, 8 girdle quads, 8 pavilion triangles", v, faces),
              faces)
    # Negative indices, as streaming exporters write them: each ring's
    # vertices, then the faces that can be drawn so far, indices counted back
    # from the last vertex read (reaching back across earlier blocks).
    s = "# faceted gem (as gem.obj) with negative (relative) indices only\n"
    blocks = [(0, 8), (8, 16), (16, 24), (24, 25)]
    done = set()
    for lo, hi in blocks:
        s += "".join(vline(p) for p in v[lo:hi])
        for k, fc in enumerate(faces):
            if k not in done and max(fc) < hi:
                done.add(k)
                s += "f %s\n" % " ".join(str(i - hi) for i in fc)
    assert len(done) == len(faces)
    put_model("gem_negidx.obj", s, faces)
    # Negative indices on v/vt/vn corners (per-face normals and texture
    # coordinates written before each face, as some exporters do).
    s = "# faceted gem (as gem.obj): v/vt/vn corners, all three indices negative\n" + "".join(vline(p) for p in v)
    for fc in faces:
        n = newell([v[i] for i in fc])
        ln = math.sqrt(sum(c * c for c in n))
        s += "vn %s\n" % " ".join("%.4f" % (c / ln) for c in n)
        for k in range(len(fc)):
            s += "vt %s %s\n" % (num(q(0.5 + 0.5 * math.cos(2 * math.pi * k / len(fc)))),
                                 num(q(0.5 + 0.5 * math.sin(2 * math.pi * k / len(fc)))))
        s += "f %s\n" % " ".join("%d/%d/-1" % (i - len(v), k - len(fc)) for k, i in enumerate(fc))
    put_model("gem_negidx_vtn.obj", s, faces)
    # Line continuations: the 8-gon table's face line over three lines, a
    # vertex over two, a pavilion face over two (a space before each '\').
    s = "# faceted gem (as gem.obj) with backslash line continuations\n"
    for k, p in enumerate(v):
        c = [num(x) for x in p]
        s += ("v %s \\\n  %s %s\n" % tuple(c)) if k in (3, 24) else vline(p)
    for k, fc in enumerate(faces):
        idx = [str(i + 1) for i in fc]
        if len(fc) == 8:
            s += "f %s \\\n  %s \\\n  %s\n" % (" ".join(idx[:3]), " ".join(idx[3:6]), " ".join(idx[6:]))
        elif k == len(faces) - 1:
            s += "f %s \\\n%s\n" % (" ".join(idx[:2]), idx[2])
        else:
            s += "f %s\n" % " ".join(idx)
    put_model("gem_cont.obj", s, faces)
    # Windows line ends (CR LF), the continuations included.
    put_model("gem_crlf.obj", s.replace("# faceted gem (as gem.obj) with backslash line continuations",
                                        "# faceted gem (as gem.obj) with CR LF line ends and backslash continuations")
              .replace("\n", "\r\n"), faces)
    put_model("gem.off", off_text("OFF", "faceted gem (as gem.obj), plain OFF", v, faces), faces)
    put_model("gem_fcolor.off", off_text("OFF", "faceted gem (as gem.obj), an RGB colour (0..255) after each face", v, faces,
                                         face_extra=lambda k: " %d %d %d" % (40 + 7 * k, 200 - 5 * k, 90 + 3 * k)), faces)
    put_model("gem_coff.off", off_text("COFF", "faceted gem (as gem.obj), COFF: RGBA (0..1) after each vertex", v, faces,
                                       vertex_extra=lambda k: " %.3f %.3f %.3f 1" % (k / 24, 1 - k / 24, 0.5)), faces)


def ply_header(fmt, nv, nf, vertex_props, face_prop, comment):
    return ("ply\nformat %s 1.0\ncomment %s\nelement vertex %d\n%selement face %d\n%send_header\n"
            % (fmt, comment, nv, vertex_props, nf, face_prop)).encode()


XYZ = "property float x\nproperty float y\nproperty float z\n"


def prism_files(v, faces):
    put_model("prisms.obj", obj_text("four prisms: convex 5-, 6-, 7- and 8-gon caps, quad sides", v, faces), faces)
    tris = []
    for fc in faces:
        tris += fan(fc) if len(fc) > 4 else [fc]
    put_model("prisms_tri.obj", obj_text("the prisms of prisms.obj, each cap n-gon split as the GIRTD triangulator does "
                                         "(fan from its first corner); quads kept", v, tris), tris)
    # The n-gons through a reader that is not OBJ's: binary little-endian
    # PLY, positions only, the same polygons in the same order.
    data = ply_header("binary_little_endian", len(v), len(faces), XYZ, "property list uchar int vertex_indices\n",
                      "four prisms (as prisms.obj), binary little-endian")
    for p in v:
        data += struct.pack("<3f", *p)
    for fc in faces:
        data += struct.pack("<B%di" % len(fc), len(fc), *fc)
    put_model("prisms.ply", data, faces)


def sphere_files(v, faces):
    put_model("sphere.obj", obj_text("low-poly UV sphere r 16: 10 + 10 cap triangles, 40 quads", v, faces), faces)
    # v/vt/vn corners: a normal and a texture coordinate per vertex.
    s = "# low-poly UV sphere (as sphere.obj) with v/vt/vn corners\n" + "".join(vline(p) for p in v)
    for x, y, z in v:
        ln = math.sqrt(x * x + y * y + z * z)
        s += "vn %.4f %.4f %.4f\n" % (x / ln, y / ln, z / ln)
    for x, y, z in v:
        s += "vt %.4f %.4f\n" % (0.5 + math.atan2(z, x) / (2 * math.pi), 0.5 + y / 32)
    s += "".join("f %s\n" % " ".join("%d/%d/%d" % (i + 1, i + 1, i + 1) for i in fc) for fc in faces)
    put_model("sphere_vtn.obj", s, faces)
    s = "# low-poly UV sphere (as sphere.obj) with v//vn corners (normals, no texture coordinates)\n"
    s += "".join(vline(p) for p in v)
    for x, y, z in v:
        ln = math.sqrt(x * x + y * y + z * z)
        s += "vn %.4f %.4f %.4f\n" % (x / ln, y / ln, z / ln)
    s += "".join("f %s\n" % " ".join("%d//%d" % (i + 1, i + 1) for i in fc) for fc in faces)
    put_model("sphere_vn.obj", s, faces)
    s = "# low-poly UV sphere (as sphere.obj) with v/vt corners (texture coordinates, no normals)\n"
    s += "".join(vline(p) for p in v)
    for x, y, z in v:
        s += "vt %.4f %.4f\n" % (0.5 + math.atan2(z, x) / (2 * math.pi), 0.5 + y / 32)
    s += "".join("f %s\n" % " ".join("%d/%d" % (i + 1, i + 1) for i in fc) for fc in faces)
    put_model("sphere_vt.obj", s, faces)

    head = ply_header("ascii", len(v), len(faces), XYZ, "property list uchar int vertex_indices\n",
                      "low-poly UV sphere (as sphere.obj), ASCII")
    body = "".join("%s\n" % " ".join(num(c) for c in p) for p in v)
    body += "".join("%d %s\n" % (len(fc), " ".join(map(str, fc))) for fc in faces)
    put_model("sphere.ply", head + body.encode(), faces)
    # Binary, both byte orders, with what scanners and exporters add: vertex
    # normals (float) and colours (uchar); the big-endian one names its list
    # vertex_index (the older spelling) with a uint count and uint indices.
    props = XYZ + "property float nx\nproperty float ny\nproperty float nz\n" \
        "property uchar red\nproperty uchar green\nproperty uchar blue\n"
    for order, fmt, name, face_prop, count_fmt, index_fmt in (
            ("<", "binary_little_endian", "sphere_le.ply", "property list uchar int vertex_indices\n", "B", "i"),
            (">", "binary_big_endian", "sphere_be.ply", "property list uint uint vertex_index\n", "I", "I")):
        data = ply_header(fmt, len(v), len(faces), props, face_prop,
                          "low-poly UV sphere (as sphere.obj), %s, normals and colours" % fmt)
        for k, (x, y, z) in enumerate(v):
            ln = math.sqrt(x * x + y * y + z * z)
            data += struct.pack(order + "6f3B", x, y, z, x / ln, y / ln, z / ln, (37 * k) % 256, (91 * k) % 256, 128)
        for fc in faces:
            data += struct.pack(order + count_fmt + index_fmt * len(fc), len(fc), *fc)
        put_model(name, data, faces)


def stl_binary(header, v, faces):
    assert len(header) <= 80
    data = header.ljust(80, b" ") + struct.pack("<I", len(faces))
    for fc in faces:
        pts = [v[i] for i in fc]
        n = newell(pts)
        ln = math.sqrt(sum(c * c for c in n))
        data += struct.pack("<3f", *(c / ln for c in n))
        for p in pts:
            data += struct.pack("<3f", *p)
        data += struct.pack("<H", 0)
    return data


def icosa_files(v, faces):
    put_model("icosa.obj", obj_text("icosahedron stretched 1.4 x along y: 20 triangles", v, faces), faces)
    s = "solid icosa\n"
    for fc in faces:
        pts = [v[i] for i in fc]
        n = newell(pts)
        ln = math.sqrt(sum(c * c for c in n))
        s += "  facet normal %.6e %.6e %.6e\n    outer loop\n" % tuple(c / ln for c in n)
        s += "".join("      vertex %s\n" % " ".join(num(c) for c in p) for p in pts)
        s += "    endloop\n  endfacet\n"
    s += "endsolid icosa\n"
    put_model("icosa_ascii.stl", s, faces)
    put_model("icosa_bin.stl", stl_binary(b"icosahedron stretched 1.4 x along y (binary STL)", v, faces), faces)
    # Binary STL whose 80-byte header starts with "solid", as some CAD
    # exporters write it: only the size (84 + 50 n bytes) tells it is binary.
    put_model("icosa_solidhdr.stl", stl_binary(b"solid icosa, binary STL from an exporter that starts its header so",
                                               v, faces), faces)


# --------------------------------------------------------------- manifest

# Frames no twin can give, blessed on purpose: the golden image_sha256 of
# build/bin/girtd on the file, checked by eye (frame.png) before pasting it
# here. Re-bless after a change that is meant to alter the picture (README.md).
BLESSED = {
    # The n-gons of a smooth surface: fanned into triangles, a polygon would
    # count in a corner's vertex normal once per triangle there (up to 3 times
    # for a pentagon, 4 for a hexagon), so no n-gon-free twin shades the same
    # (the triangles' positions are the same, the colours not).
    "ball.obj": "60917a1ead7f12ff7b66a75694ebfd2b630b4ea0bd2dd112f8422b4efff3157b",
}

# file, twin ('-' for none; 'shape:NAME' when only the shape is NAME's, the colours not), expect (ok | warning), what it exercises,
# stored image_sha256 ('-' unless no twin can give the same frame); main()
# adds the polygon count the writer recorded (POLYGONS).
MANIFEST = [
    ("house.obj", "-", "ok", "reference: house (walls, floor, hip roof, chimney), one object, positive indices", "-"),
    ("house_groups.obj", "house.obj", "ok", "o and g: two objects of two groups, each object's vertices before its faces", "-"),
    ("house_lines.obj", "house.obj", "ok", "l and p elements besides the faces (not drawn)", "-"),
    ("house_mtl.obj", "shape:house.obj", "ok", "mtllib house.mtl (present) and usemtl of its materials (drawn in their colours)", "-"),
    ("house_mtl_noobj.obj", "house_mtl.obj", "ok",
     "usemtl before any o or g (assimp 5.2.5 logs 'No object detected to attach a new mesh instance' at Err: no warning)", "-"),
    ("house_nomtl.obj", "house.obj", "warning",
     "the same bytes as house_mtl.obj but its mtllib names a file that does not exist (house_lost.mtl): "
     "the default material", "-"),
    ("house_badmtl.obj", "shape:house_mtl.obj", "warning", "usemtl of a material house.mtl lacks: warning, the default material there", "-"),
    ("house.off", "house.obj", "ok", "plain OFF (the house as house.obj, read by a reader that is not OBJ's)", "-"),
    ("gem.obj", "-", "ok", "reference: faceted gem (8-gon table, crown and girdle quads, pavilion triangles)", "-"),
    ("gem_negidx.obj", "gem.obj", "ok", "negative (relative) indices, vertices in blocks, faces reaching back across blocks", "-"),
    ("gem_negidx_vtn.obj", "gem.obj", "ok", "negative indices in v/vt/vn corners (vn, vt written before each face)", "-"),
    ("gem_cont.obj", "gem.obj", "ok", "backslash line continuations in v and f lines (the 8-gon over three lines)", "-"),
    ("gem_crlf.obj", "gem.obj", "ok", "CR LF line ends (Windows), backslash continuations included", "-"),
    ("gem.off", "gem.obj", "ok", "plain OFF (the gem as gem.obj: same polygons, same order)", "-"),
    ("gem_fcolor.off", "gem.off", "ok", "OFF with an RGB colour (0..255) after each face (assimp 5.2.5 does not read it)", "-"),
    ("gem_coff.off", "shape:gem.off", "ok", "COFF: RGBA (0..1) after each vertex (drawn as corner colours)", "-"),
    ("prisms.obj", "prisms_tri.obj", "ok", "convex 5-, 6-, 7-, 8-gon caps and quad sides (polygons kept for the GIRTD triangulator)", "-"),
    ("prisms_tri.obj", "-", "ok", "reference: the prisms with each n-gon cap written as the triangulator's fan", "-"),
    ("prisms.ply", "prisms.obj", "ok", "binary little-endian PLY with the prisms' 5- to 8-gons (as prisms.obj: a reader that is not OBJ's)", "-"),
    ("sphere.obj", "-", "ok", "reference: low-poly UV sphere, smooth shading (cap triangles, quads)", "-"),
    ("sphere_vtn.obj", "sphere.obj", "ok", "v/vt/vn corners (file normals and texture coordinates ignored)", "-"),
    ("sphere_vn.obj", "sphere.obj", "ok", "v//vn corners", "-"),
    ("sphere_vt.obj", "sphere.obj", "ok", "v/vt corners", "-"),
    ("sphere.ply", "sphere.obj", "ok", "ASCII PLY (float x y z, uchar/int face list)", "-"),
    ("sphere_le.ply", "shape:sphere.ply", "ok", "binary little-endian PLY with vertex normals and colours (normals ignored, colours drawn)", "-"),
    ("sphere_be.ply", "sphere_le.ply", "ok", "binary big-endian PLY with vertex normals and colours, uint vertex_index list", "-"),
    ("icosa.obj", "-", "ok", "reference: stretched icosahedron, 20 triangles", "-"),
    ("icosa_ascii.stl", "icosa.obj", "ok", "ASCII STL", "-"),
    ("icosa_bin.stl", "icosa_ascii.stl", "ok", "binary STL", "-"),
    ("icosa_solidhdr.stl", "icosa_bin.stl", "ok", "binary STL whose header starts with 'solid' (told apart by its size)", "-"),
    ("ball.obj", "-", "ok", "no twin (stored sha): pentagons and hexagons on one smooth surface (a truncated icosahedron); "
     "fanned, they would weigh more in the vertex normals", BLESSED["ball.obj"]),
]


def main():
    v, faces, groups = house()
    house_files(v, faces, groups)
    gem_files(*gem())
    prism_files(*prisms())
    sphere_files(*uv_sphere())
    icosa_files(*icosahedron())
    v, f = soccer_ball()
    put_model("ball.obj", obj_text("truncated icosahedron (soccer ball): 12 pentagons, 20 hexagons, one smooth surface",
                                   v, f), f)
    rows = ["# file\ttwin\texpect\twhat it exercises\tstored_image_sha256\tpolygons\n"]
    for row in MANIFEST:
        assert os.path.exists(os.path.join(HERE, row[0])), row[0]
        twin = row[1].removeprefix("shape:")
        assert twin == "-" or os.path.exists(os.path.join(HERE, twin)), twin
        rows.append("\t".join(row + (str(POLYGONS[row[0]]),)) + "\n")
    assert sorted(POLYGONS) == sorted(row[0] for row in MANIFEST), set(POLYGONS) ^ {row[0] for row in MANIFEST}
    assert not os.path.exists(os.path.join(HERE, "house_nomtl.mtl"))
    assert not os.path.exists(os.path.join(HERE, "house_lost.mtl"))
    put("corpus.tsv", "".join(rows))


if __name__ == "__main__":
    main()
