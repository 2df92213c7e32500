"""girtd.render against `girtd render`: the same report, picture and Z plane."""
import hashlib
import json
import os

import numpy as np
import pytest

import girtd
from conftest import ROOT, cli_render

DEMO = os.path.join(ROOT, "traces", "scenes", "demo.json")


def without_wall(report):
    return {k: v for k, v in report.items() if k != "wall_s"}


@pytest.mark.parametrize("backend", ["approx", "rtl", "golden"])
def test_report_and_picture_match_the_cli(tmp_path, backend):
    rc, err, out = cli_render(tmp_path, DEMO, "--backend", backend, "--z-png")
    assert rc == 0, err
    with open(out / "report.json") as f:
        expected = json.load(f)
    r = girtd.render(DEMO, backend=backend)
    assert r["image_sha256"] == expected["image_sha256"]
    assert without_wall(r) == without_wall(expected)
    assert r.frame.shape == (1024, 1024, 3) and r.frame.dtype == np.uint8
    # The array is the picture the report hashed (the SHA-256 of its RGB bytes).
    assert hashlib.sha256(r.frame.tobytes()).hexdigest() == r["image_sha256"]
    z = girtd._girtd.read_png_gray16(str(out / "z.png"))
    assert r.z.shape == (1024, 1024) and np.array_equal(r.z, z)


def test_a_timed_back_end_renders_many_times_in_one_process():
    # SystemC elaborates once per process: the module renders approx in a child each time.
    def rate(depth):
        return girtd.render(DEMO, backend="approx", repeat=3,
                            config={"fifo": {"dda_had_depth": depth}})["sustained_mpixels_per_s"]

    shallow, deep, again = rate(1), rate(16), rate(16)
    assert shallow < deep == again  # a one-entry FIFO stalls the DDA more than sixteen


def test_config_dict_merges_like_a_config_file(tmp_path):
    patch = {"dda": {"clock_ns": 50}}
    path = tmp_path / "slow_dda.json"
    path.write_text(json.dumps(patch))
    rc, err, out = cli_render(tmp_path, DEMO, "--backend", "approx", "--config", path)
    assert rc == 0, err
    with open(out / "report.json") as f:
        expected = json.load(f)
    from_dict = girtd.render(DEMO, backend="approx", config=patch)
    from_path = girtd.render(DEMO, backend="approx", config=str(path))
    for r in (from_dict, from_path):
        assert r["modeled_time_s"] == expected["modeled_time_s"]
        assert r["config"]["dda"]["clock_ns"] == 50
    assert girtd.merged_config(patch)["dda"]["clock_ns"] == 50


def test_frames_all_gives_every_frame():
    r = girtd.render(os.path.join(ROOT, "traces", "scenes", "animation.json"), frames="all")
    assert len(r.frames) == r["frames"] and r["frames"] > 1
    assert np.array_equal(r.frames[-1], r.frame)


def test_backends_read_the_registry():
    by_name = {b["name"]: b for b in girtd.backends()}
    assert set(by_name) == {"reference", "golden", "approx", "rtl"}
    assert [n for n, b in by_name.items() if b["timed"]] == ["approx", "rtl"]
    assert by_name["rtl"]["records_waveforms"] and not by_name["golden"]["records_waveforms"]
    assert not by_name["reference"]["has_dda"] and by_name["golden"]["has_dda"]


def test_warnings_go_through_sys_stderr(capsys):
    # Through Python's own stream (a notebook shows it), each once, as the report lists them.
    r = girtd.render(os.path.join(ROOT, "traces", "scenes", "near_clip.json"))
    assert r["warnings"] and any("clamped" in w for w in r["warnings"])
    assert capsys.readouterr().err == "".join("warning: %s\n" % w for w in r["warnings"])
    girtd.render(os.path.join(ROOT, "traces", "scenes", "near_clip.json"), print_warnings=False)
    assert capsys.readouterr().err == ""


def test_a_model_files_camera_by_name():
    # traces/models/file_scenes/two_materials.gltf: camera "far" at (0, 0, 10),
    # vertical field of view 0.8 rad: 512 x 2.365 / 10 = 121.1 px per unit,
    # the red quad's centre (X -1.1) at x 379, the blue one's at 645.
    gltf = os.path.join(ROOT, "traces", "models", "file_scenes", "two_materials.gltf")
    far = girtd.render(gltf, camera="far", print_warnings=False)
    red, blue, gap = far.frame[512, 379], far.frame[512, 645], far.frame[512, 512]
    assert red[0] >= 250 and red[1] < 70
    assert blue[2] >= 250 and blue[0] < 70
    assert not gap.any()
    with pytest.raises(girtd.InputError) as caught:
        girtd.render(gltf, camera="nope")
    assert caught.value.file == "--camera" and '"front", "far"' in caught.value.message
