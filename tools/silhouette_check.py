#!/usr/bin/env python3
"""Where does culling back faces change a frame? Only at silhouettes.

Usage: silhouette_check.py TRIANGLES.trace UNCULLED.png CULLED.png [--margin PX] [--picture OUT.png]

TRIANGLES.trace is the unculled run's `render --dump triangle=FILE`, of a
one-frame input (the PNGs are the last frame). A
silhouette edge is an edge two triangles share (the same two screen corners,
as written) whose windings on the screen differ: one faces the camera, the
other away. Every pixel that differs between the two frames must lie within
MARGIN (default Q + 1 of the trace's q, the AA fringe and a pixel) of a
silhouette edge. Prints
`N pixels differ, N within MARGIN px of M silhouette edges, N elsewhere` and
exits 1 when any differs elsewhere. --picture writes the unculled frame with
the differing pixels in magenta and the rest darkened.
Independent of the simulator: it reads only the dump and the two PNGs.
"""
import argparse
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from png_crop import read_rgb, write_rgb  # noqa: E402


def read_triangles(path):
    tris, q = [], 1.0
    for line in open(path):
        f = line.split()
        if not f:
            continue
        if f[0] == "frame":
            sys.exit(f"{path}: more than one frame: the check compares one frame")
        if f[0] == "q":
            q = float(f[1])
        elif f[0] == "tri":
            v = [(f[1 + 7 * i], f[2 + 7 * i]) for i in range(3)]  # as written: shared corners are equal strings
            tris.append(v)
    return tris, q


def signed_area(v):
    (x0, y0), (x1, y1), (x2, y2) = [(float(x), float(y)) for x, y in v]
    return (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)


def silhouette_edges(tris):
    facing = {}
    for v in tris:
        s = signed_area(v)
        if s == 0:
            continue
        for i in range(3):
            key = tuple(sorted((v[i], v[(i + 1) % 3])))
            facing.setdefault(key, set()).add(s > 0)
    return [[(float(x), float(y)) for x, y in k] for k, sides in facing.items() if len(sides) == 2]


def near_mask(edges, margin, width, height):
    near = bytearray(width * height)
    for (ax, ay), (bx, by) in edges:
        dx, dy = bx - ax, by - ay
        ll = dx * dx + dy * dy
        for y in range(max(0, math.floor(min(ay, by) - margin)), min(height - 1, math.ceil(max(ay, by) + margin)) + 1):
            for x in range(max(0, math.floor(min(ax, bx) - margin)), min(width - 1, math.ceil(max(ax, bx) + margin)) + 1):
                t = 0.0 if ll == 0 else max(0.0, min(1.0, ((x - ax) * dx + (y - ay) * dy) / ll))
                if math.hypot(x - ax - t * dx, y - ay - t * dy) <= margin:
                    near[y * width + x] = 1
    return near


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("triangles")
    ap.add_argument("unculled")
    ap.add_argument("culled")
    ap.add_argument("--margin", type=float)
    ap.add_argument("--picture")
    a = ap.parse_args()
    tris, q = read_triangles(a.triangles)
    margin = a.margin if a.margin is not None else q + 1
    w, h, before = read_rgb(a.unculled)
    w2, h2, after = read_rgb(a.culled)
    if (w, h) != (w2, h2):
        sys.exit("the two frames differ in size")
    edges = silhouette_edges(tris)
    near = near_mask(edges, margin, w, h)
    differ = inside = 0
    out = []
    for y in range(h):
        rb, ra = before[y], after[y]
        row = bytearray(len(rb))
        for x in range(w):
            p = rb[3 * x:3 * x + 3]
            if p != ra[3 * x:3 * x + 3]:
                differ += 1
                inside += near[y * w + x]
                row[3 * x:3 * x + 3] = bytes((255, 0, 255))
            else:
                row[3 * x:3 * x + 3] = bytes(c // 3 for c in p)
        out.append(row)
    print(f"{differ} pixels differ, {inside} within {margin:g} px of {len(edges)} silhouette edges, "
          f"{differ - inside} elsewhere")
    if a.picture:
        write_rgb(a.picture, w, h, out)
    return 0 if differ == inside else 1


if __name__ == "__main__":
    sys.exit(main())
