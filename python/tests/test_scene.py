"""A scene built in Python: drawn as the lighting formula says, the same on
golden and rtl, and the same as the scene file it stands for."""
import json
import os

import numpy as np
import pytest

import girtd
from conftest import ROOT, cli_render

SQUARE = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]  # counter-clockwise seen from +z


def facing_square(colour):
    s = girtd.Scene(camera=dict(eye=[0, 0, 5], target=[0, 0, 0], up=[0, 1, 0], fov_deg=40),
                    lights=dict(ambient=1.0, directional=[]), background=[0, 0, 0])
    s.add_mesh(np.array(SQUARE, dtype=float), [[0, 1, 2, 3]], material=dict(colour=colour))
    return s


def test_ambient_light_alone_gives_the_material_colour():
    # With no directional light, colour = R Id (docs/design.md §3): Id = 1 gives R.
    r = girtd.render(facing_square([200, 100, 50]))
    centre = r.frame[512, 512].astype(int)
    assert np.all(np.abs(centre - [200, 100, 50]) <= 1), centre
    assert r.frame[0, 0].tolist() == [0, 0, 0]  # the background around it
    # The square at 5 units with a 40 degree field of view: 1 / tan(20 deg) / 5 of the half screen.
    half = 512 / np.tan(np.radians(20)) / 5
    row = np.nonzero(r.frame[512, :, 0] > 100)[0]
    assert abs((row[-1] - row[0] + 1) / 2 - half) <= 2


def two_models():
    s = girtd.Scene(camera=dict(eye=[0, 2, 6], target=[0, 0, 0], fov_deg=40),
                    lights=dict(ambient=0.2, directional=[dict(toward=[0.4, 1, 0.7], intensity=0.7)]),
                    background=[16, 24, 48])
    s.add_model(os.path.join(ROOT, "traces", "models", "torus.obj"), material=dict(colour=[235, 120, 30], n=40))
    s.add_mesh(np.array(SQUARE) * 1.5, [[0, 1, 2, 3]], translate=[0, 0, 1.2],
               material=dict(colour=[200, 230, 255], t_min=0.3, t_max=0.7))
    return s


def test_golden_and_rtl_draw_it_alike():
    s = two_models()
    golden, rtl = girtd.render(s, backend="golden"), girtd.render(s, backend="rtl")
    assert golden["image_sha256"] == rtl["image_sha256"]
    assert np.array_equal(golden.z, rtl.z)
    assert golden["pixels_generated"] == rtl["pixels_generated"]


def test_it_is_the_scene_file_it_stands_for(tmp_path):
    s = two_models()
    scene_file = tmp_path / "scene.json"
    scene_file.write_text(json.dumps(s.document()))
    rc, err, out = cli_render(tmp_path, scene_file, "--backend", "golden")
    assert rc == 0, err
    with open(out / "report.json") as f:
        assert json.load(f)["image_sha256"] == girtd.render(s)["image_sha256"]


def cube_scene():
    return girtd.Scene(camera=dict(eye=[3, 2.5, 4], target=[0, 0, 0], fov_deg=40),
                       lights=dict(ambient=0.2, directional=[dict(toward=[0.4, 1, 0.7], intensity=0.7)]))


def test_a_mesh_with_a_vertex_per_corner_is_the_model_file_it_copies():
    # traces/models/cube.off's faces, each with its own four corners (as
    # trimesh or an STL export gives them): with crease_deg 180 the file's
    # cube is shaded smooth across its edges, and so must this one be.
    off = open(os.path.join(ROOT, "traces", "models", "cube.off")).read().split("\n")
    rows = [l.split() for l in off if l and not l.startswith(("#", "OFF"))]
    corners = [list(map(float, r)) for r in rows[1:9]]
    faces = [list(map(int, r[1:])) for r in rows[9:15]]
    vertices = np.array([corners[i] for f in faces for i in f])
    per_corner = [[4 * k + j for j in range(4)] for k in range(len(faces))]
    from_file, inline = cube_scene(), cube_scene()
    from_file.add_model(os.path.join(ROOT, "traces", "models", "cube.off"), crease_deg=180)
    inline.add_mesh(vertices, per_corner, crease_deg=180)
    assert girtd.render(inline)["image_sha256"] == girtd.render(from_file)["image_sha256"]
    faceted = cube_scene()
    faceted.add_model(os.path.join(ROOT, "traces", "models", "cube.off"), crease_deg=0)
    assert girtd.render(faceted)["image_sha256"] != girtd.render(from_file)["image_sha256"]


def test_an_unknown_back_end_is_bad_input():
    with pytest.raises(girtd.InputError) as caught:
        girtd.render(facing_square([1, 2, 3]), backend="nonesuch")
    assert caught.value.file == "--backend" and "known: reference, golden" in caught.value.message


def test_numpy_values_are_taken_and_non_finite_ones_refused():
    s = girtd.Scene(camera=dict(eye=np.array([0.0, 0.0, 5.0]), target=[0, 0, 0], fov_deg=np.float32(40)),
                    lights=dict(ambient=np.float64(1.0), directional=[]), background=[0, 0, 0])
    s.add_mesh(np.array(SQUARE, dtype=float), np.array([[0, 1, 2, 3]]), material=dict(colour=np.array([200, 100, 50])))
    assert girtd.render(s)["image_sha256"] == girtd.render(facing_square([200, 100, 50]))["image_sha256"]
    for bad in (np.nan, np.inf):
        with pytest.raises(ValueError, match="NaN or infinite"):
            facing_square([1, 2, 3]).add_mesh(np.array([[0, 0, bad], [1, 0, 0], [0, 1, 0]]), [[0, 1, 2]])
    with pytest.raises(TypeError):  # a fractional vertex index is not truncated
        facing_square([1, 2, 3]).add_mesh(np.array(SQUARE, dtype=float), [[0, 1, 2.5]])
