"""GIRTD-sim from Python: render a trace, scene or model on one back end.

    import girtd
    r = girtd.render("traces/scenes/demo.json", backend="approx")
    r["image_sha256"], r["sustained_mpixels_per_s"], r.frame.shape  # (1024, 1024, 3)

`render` returns a Report: a dict with report.json's keys and values, plus
`.frame` (height x width x 3 uint8), `.z` (height x width uint16) and
`.frames` (every frame's picture with frames="all"). A Scene is built here
and rendered like a file. Bad input raises InputError, whose str() is the
line `girtd render` prints (FILE:LINE: what). docs/python.md has the rest.
"""

import json
import os
import subprocess
import sys
import tempfile

import operator

import numpy as np

from . import _girtd

__all__ = ["render", "backends", "merged_config", "Scene", "Report", "InputError"]

# The girtd executable of the build this module belongs to (build/python/girtd
# -> build/bin/girtd) and the driver: a render that needs an RTL variant runs
# as `tools/girtd render` on that executable, whose variant step builds it.
_EXECUTABLE = os.path.join(os.path.dirname(__file__), "..", "..", "bin", "girtd")
_DRIVER = os.path.join(_girtd.source_dir, "tools", "girtd")


class InputError(Exception):
    """Bad input: str(e) is `FILE:LINE: what`, as the CLI prints it."""

    def __init__(self, formatted, file, line, message):
        super().__init__(formatted)
        self.file = file
        self.line = line
        self.message = message


class Report(dict):
    """report.json as a dict, with the pictures as numpy arrays."""

    def __init__(self, report, frame, z, frames=()):
        super().__init__(report)
        self.frame = frame
        self.z = z
        self.frames = list(frames)


def backends():
    """The back ends in the registry: name, summary, timed, has_dda, records_waveforms, ..."""
    return json.loads(_girtd.backends())


def _layers(config):
    """`config`: None, a dict merged like a --config file, a path, or a list of those."""
    if config is None:
        return []
    if isinstance(config, (dict, str, os.PathLike)):
        config = [config]
    layers = []
    for i, c in enumerate(config):
        if isinstance(c, dict):
            layers.append({"patch": c, "origin": "config[%d]" % i})
        elif isinstance(c, (str, os.PathLike)):
            layers.append({"file": os.fspath(c)})
        else:
            raise TypeError("config: a dict, a path, or a list of them; got %r" % type(c).__name__)
    return layers


def _json(value, sort_keys=False):
    """JSON for the library: numpy arrays and scalars as lists and numbers;
    NaN and infinity refused here (JSON has no spelling for them)."""
    def plain(o):
        if isinstance(o, np.ndarray):
            return o.tolist()
        if isinstance(o, np.generic):
            return o.item()
        raise TypeError("%r is not a JSON value" % (o,))
    try:
        return json.dumps(value, allow_nan=False, default=plain, sort_keys=sort_keys)
    except ValueError:
        raise ValueError("a configuration or scene value is NaN or infinite") from None


def merged_config(config=None):
    """The configuration a render with `config` runs with (config/girtd.json merged with it)."""
    return json.loads(_girtd.merged_config(_json(_layers(config))))


def render(input, backend="golden", config=None, repeat=1, frames="last", level=None, prune=True, aa=None,
           sample_timing=None, dump=None, progress=False, print_warnings=True, camera=None):
    """Renders `input` (a path, or a Scene) on `backend`; returns a Report.

    The options are `girtd render`'s: frames "last" or "all" (Report.frames),
    level for a trace without a header, prune=False for --no-prune, aa for
    --aa, sample_timing, dump "LEVEL=FILE", camera for --camera (a model
    file's camera by name). The report's "warnings" are
    printed on sys.stderr after the render (a notebook shows them) unless
    print_warnings=False.
    """
    if frames not in ("last", "all"):
        raise ValueError("frames: 'last' or 'all'")
    request = {"backend": backend, "config": _layers(config), "repeat": int(repeat),
               "keep_all_frames": frames == "all", "prune": bool(prune), "progress": bool(progress),
               "print_warnings": False}  # printed here, through sys.stderr
    if isinstance(input, Scene):
        request["input"] = input.name
        request["scene"] = input.document()
    else:
        request["input"] = os.fspath(input)
    for key, value in (("level", level), ("aa", aa), ("sample_timing", sample_timing), ("dump", dump),
                       ("camera", camera)):
        if value is not None:
            request[key] = value
    if _needs_rtl_variant(backend, request["config"]):
        report = _render_with_executable(request)
    else:
        out = _girtd.render(_json(request))
        report = Report(json.loads(out["report"]), out["frame"], out["z"], out["frames"])
    if print_warnings:
        sys.stderr.writelines("warning: %s\n" % w for w in report["warnings"])
    return report


def _needs_rtl_variant(backend, layers):
    entry = next((b for b in backends() if b["name"] == backend), None)
    return entry is not None and entry["runs_rtl"] and _girtd.needs_rtl_variant(_json(layers))


def _render_with_executable(request):
    """A render whose configuration needs an RTL elaborated for other widths or
    depths: the driver builds that variant once (its variant step) and
    `girtd render` runs in it."""
    with tempfile.TemporaryDirectory(prefix="girtd_") as tmp:
        args = [_DRIVER, "render", request["input"], "--backend", request["backend"], "--out",
                os.path.join(tmp, "out"), "--quiet", "--z-png", "--repeat", str(request["repeat"]),
                "--frames", "all" if request["keep_all_frames"] else "last"]
        if "scene" in request:
            scene_file = os.path.join(tmp, "scene.json")
            with open(scene_file, "w") as f:
                json.dump(request["scene"], f)
            args[2] = scene_file
        for i, layer in enumerate(request["config"]):
            path = layer.get("file")
            if path is None:
                path = os.path.join(tmp, "config_%d.json" % i)
                with open(path, "w") as f:
                    json.dump(layer["patch"], f)
            args += ["--config", path]
        for key, flag in (("level", "--level"), ("aa", "--aa"), ("sample_timing", "--sample-timing"),
                          ("dump", "--dump"), ("camera", "--camera")):
            if key in request:
                args += [flag, str(request[key])]
        if not request["prune"]:
            args.append("--no-prune")
        env = dict(os.environ, GIRTD_BINARY=os.path.abspath(_EXECUTABLE))
        done = subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, env=env)
        if done.returncode == 2:  # bad input: the CLI's one line
            line = (done.stderr.strip().splitlines() or ["girtd render: exit 2 without a message"])[-1]
            file, _, rest = line.partition(":")
            number, _, message = rest.partition(": ")
            raise InputError(line, file, int(number) if number.isdigit() else 0,
                             message if number.isdigit() else rest.strip())
        if done.returncode != 0:
            raise RuntimeError("girtd render failed (exit %d):\n%s" % (done.returncode, done.stderr))
        out = os.path.join(tmp, "out")
        with open(os.path.join(out, "report.json")) as f:
            report = json.load(f)
        frames = sorted((n for n in os.listdir(out) if n.startswith("frame_")), key=lambda n: int(n[6:-4]))
        return Report(report, _girtd.read_png_rgb(os.path.join(out, "frame.png")),
                      _girtd.read_png_gray16(os.path.join(out, "z.png")),
                      [_girtd.read_png_rgb(os.path.join(out, n)) for n in frames])


def _vec3(v, what):
    a = np.asarray(v, dtype=float).reshape(-1)
    if a.shape != (3,):
        raise ValueError("%s: three numbers, got %r" % (what, v))
    return a.tolist()


class Scene:
    """A scene built in Python, rendered like a scene file (traces/FORMAT.md
    "Scene files"): the same keys, the same defaults, the same errors.

        s = girtd.Scene(camera=dict(eye=[0, 2, 6], target=[0, 0, 0], fov_deg=40),
                        lights=dict(ambient=0.2, directional=[dict(toward=[0.4, 1, 0.7], intensity=0.7)]),
                        background=[16, 24, 48])
        s.add_mesh(vertices, [[0, 1, 2, 3], ...], material=dict(colour=[235, 120, 30], n=40))
        s.add_model("traces/models/torus.obj", translate=[1, 0, 0])
        girtd.render(s, backend="rtl")

    camera: "auto" (framed on the models), {eye, target, up, fov_deg} or
    {centre, angles_deg, fov_deg}; lights: {ambient, directional: [{toward,
    intensity}]}; a material: {colour, cre, n, t_min, t_max}.
    """

    def __init__(self, camera="auto", lights=None, background=None, window=None, q=None, cull_back_faces=None,
                 focal_distance=None, name="<scene>"):
        self.name = name
        self._doc = {"girtd_scene": 1, "camera": camera}
        for key, value in (("lights", lights), ("background", background), ("window", window), ("q", q),
                           ("cull_back_faces", cull_back_faces), ("focal_distance", focal_distance)):
            if value is not None:
                self._doc[key] = value
        self._materials = {}
        self._models = []

    def _material(self, material):
        if material is None:
            return None
        key = _json(material, sort_keys=True)
        if key not in self._materials:
            self._materials[key] = ("material%d" % len(self._materials), material)
        return self._materials[key][0]

    def _add(self, model, material, name, placement):
        model["name"] = name if name is not None else "model%d" % len(self._models)
        m = self._material(material)
        if m is not None:
            model["material"] = m
        for key, value in placement.items():
            if value is not None:
                model[key] = value if key == "scale" and np.isscalar(value) else _vec3(value, key)
        self._models.append(model)
        return model["name"]

    def add_mesh(self, vertices, polygons, material=None, normals=None, name=None, crease_deg=None, scale=None,
                 rotate_deg=None, translate=None):
        """vertices: (N, 3) floats; polygons: lists of vertex indices, counter-clockwise
        seen from the front (polygons stay polygons: the GIRTD triangulator splits them).
        Returns the model's name."""
        if normals is not None:
            raise NotImplementedError("add_mesh: given normals are not taken: GIRTD's front end computes each "
                                      "vertex normal from the polygons around it (crease_deg groups them)")
        v = np.asarray(vertices, dtype=float)
        if v.ndim != 2 or v.shape[1] != 3:
            raise ValueError("add_mesh: vertices must be an (N, 3) array, got shape %r" % (v.shape,))
        if not np.all(np.isfinite(v)):
            raise ValueError("add_mesh: a vertex coordinate is NaN or infinite")
        # operator.index: an index 1.7 is an error, not vertex 1.
        mesh = {"vertices": v.tolist(), "polygons": [[operator.index(i) for i in p] for p in polygons]}
        model = {"mesh": mesh}
        if crease_deg is not None:
            model["crease_deg"] = crease_deg
        return self._add(model, material, name, dict(scale=scale, rotate_deg=rotate_deg, translate=translate))

    def add_model(self, path, material=None, name=None, crease_deg=None, scale=None, rotate_deg=None,
                  translate=None):
        """A model file (any format assimp reads) placed in the scene. Returns the model's name."""
        model = {"file": os.path.abspath(os.fspath(path))}
        if crease_deg is not None:
            model["crease_deg"] = crease_deg
        return self._add(model, material, name, dict(scale=scale, rotate_deg=rotate_deg, translate=translate))

    def document(self):
        """The scene as a scene file's JSON document (plain Python values: json.dump writes it)."""
        doc = dict(self._doc)
        if self._materials:
            doc["materials"] = {name: m for name, m in self._materials.values()}
        doc["models"] = list(self._models)
        return json.loads(_json(doc))
