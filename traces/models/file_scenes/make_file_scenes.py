#!/usr/bin/env python3
"""Writes the model files that carry their own scene: a camera, lights,
materials, vertex colours, a texture (traces/models/README.md "Scenes in
model files"). Deterministic, standard library only: commit what it writes.

    python3 traces/models/file_scenes/make_file_scenes.py
"""
import base64
import json
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def write(name, data):
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(os.path.join(HERE, name), mode) as f:
        f.write(data)


def gltf_two_materials():
    """Two quads in the plane z = 0 facing +z: red at x -2..-0.2, blue at
    x 0.2..2, y -1..1. Cameras "front" at (0, 0, 5) and "far" at (0, 0, 10),
    both looking down -z with a vertical field of view of 0.8 rad ("far"
    with an aspect ratio of 2); a point light (KHR_lights_punctual) at
    (0, 0, 10); metalness 0, roughness 1 (red) and 0.5 (blue)."""
    quads = [(-2.0, -0.2), (0.2, 2.0)]
    positions = b""
    for x0, x1 in quads:
        for x, y in ((x0, -1), (x1, -1), (x1, 1), (x0, 1)):
            positions += struct.pack("<3f", x, y, 0.0)
    indices = struct.pack("<6H", 0, 1, 2, 0, 2, 3)
    buffer = positions + indices
    accessors, views = [], []
    for q in range(2):
        views.append({"buffer": 0, "byteOffset": 48 * q, "byteLength": 48, "target": 34962})
        x0, x1 = quads[q]
        accessors.append({"bufferView": q, "componentType": 5126, "count": 4, "type": "VEC3",
                          "min": [x0, -1, 0], "max": [x1, 1, 0]})
    views.append({"buffer": 0, "byteOffset": 96, "byteLength": 12, "target": 34963})
    accessors.append({"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"})
    perspective = {"aspectRatio": 1.0, "yfov": 0.8, "znear": 0.1, "zfar": 100}
    wide = dict(perspective, aspectRatio=2.0)
    doc = {
        "asset": {"version": "2.0", "generator": "girtd make_file_scenes.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"name": "lamp", "type": "point", "color": [1, 1, 1], "intensity": 80}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 3, 4]}],
        "nodes": [
            {"name": "red_quad", "mesh": 0},
            {"name": "blue_quad", "mesh": 1},
            {"name": "front", "camera": 0, "translation": [0, 0, 5]},
            {"name": "far", "camera": 1, "translation": [0, 0, 10]},
            {"name": "lamp", "translation": [0, 0, 10], "extensions": {"KHR_lights_punctual": {"light": 0}}},
        ],
        "cameras": [{"name": "front", "type": "perspective", "perspective": perspective},
                    {"name": "far", "type": "perspective", "perspective": wide}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": q}, "indices": 2, "material": q}]} for q in range(2)],
        "materials": [
            {"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 1], "metallicFactor": 0,
                                                     "roughnessFactor": 1}},
            {"name": "blue", "pbrMetallicRoughness": {"baseColorFactor": [0, 0, 1, 1], "metallicFactor": 0,
                                                      "roughnessFactor": 0.5}},
        ],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(buffer),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(buffer).decode()}],
    }
    write("two_materials.gltf", json.dumps(doc, indent=1) + "\n")


def ply_vertex_colours():
    """A square -1..1 in z = 0 facing +z, its corners red, green, blue, white."""
    rows = ["-1 -1 0 255 0 0", "1 -1 0 0 255 0", "1 1 0 0 0 255", "-1 1 0 255 255 255"]
    write("vertex_colours.ply", "\n".join(
        ["ply", "format ascii 1.0", "element vertex 4", "property float x", "property float y",
         "property float z", "property uchar red", "property uchar green", "property uchar blue",
         "element face 1", "property list uchar int vertex_indices", "end_header"] + rows + ["4 0 1 2 3", ""]))


def png(width, height, rows):
    """An 8-bit RGB PNG; rows: lists of (r, g, b), top row first."""
    raw = b"".join(b"\0" + bytes(c for px in row for c in px) for row in rows)

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def obj_textured():
    """Two squares side by side facing +z; the left one maps the left half of
    a 2 x 1 texture (red), the right one its right half (blue); Kd is white."""
    write("half_red_half_blue.png", png(2, 1, [[(255, 0, 0), (0, 0, 255)]]))
    write("textured.mtl", "newmtl halves\nKd 1 1 1\nmap_Kd half_red_half_blue.png\n")
    write("textured.obj", "\n".join([
        "mtllib textured.mtl",
        "v -2 -1 0", "v -0.2 -1 0", "v -0.2 1 0", "v -2 1 0",
        "v 0.2 -1 0", "v 2 -1 0", "v 2 1 0", "v 0.2 1 0",
        "vt 0.05 0.1", "vt 0.45 0.1", "vt 0.45 0.9", "vt 0.05 0.9",
        "vt 0.55 0.1", "vt 0.95 0.1", "vt 0.95 0.9", "vt 0.55 0.9",
        "usemtl halves",
        "f 1/1 2/2 3/3 4/4", "f 5/5 6/6 7/7 8/8", ""]))


def obj_broken_library():
    """A square whose material library is 3 bytes: assimp 5.2.5 fails on it."""
    write("broken.mtl", "Kd\n")
    write("broken_library.obj", "mtllib broken.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nusemtl x\nf 1 2 3 4\n")


if __name__ == "__main__":
    gltf_two_materials()
    ply_vertex_colours()
    obj_textured()
    obj_broken_library()
