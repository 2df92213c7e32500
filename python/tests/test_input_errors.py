"""Bad input raises girtd.InputError carrying the CLI's one line."""
import pytest

import girtd
from conftest import cli_render


def test_a_bad_model_line_is_the_cli_line(tmp_path):
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n")  # vertex 7 does not exist
    rc, err, _ = cli_render(tmp_path, bad)
    assert rc == 2
    with pytest.raises(girtd.InputError) as caught:
        girtd.render(str(bad))
    e = caught.value
    assert str(e) == err.strip().splitlines()[-1]
    assert e.file == str(bad) and e.line == 4
    assert str(e) == "%s:%d: %s" % (e.file, e.line, e.message)


def test_a_missing_file(tmp_path):
    with pytest.raises(girtd.InputError) as caught:
        girtd.render(str(tmp_path / "none.json"), backend="approx")  # raised by the child process too
    assert caught.value.message == "no such file"


def test_an_option_the_back_end_refuses():
    with pytest.raises(girtd.InputError) as caught:
        girtd.render("traces/scenes/demo.json", backend="golden", sample_timing=0.5)
    assert caught.value.file == "--sample-timing"


def test_a_bad_config_key_names_its_origin():
    with pytest.raises(girtd.InputError) as caught:
        girtd.render("traces/scenes/demo.json", config={"dda": {"clock": 30}})
    assert caught.value.file == "config[0]" and "clock" in caught.value.message


def test_a_polygon_index_out_of_range():
    s = girtd.Scene()
    s.add_mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 3]])
    with pytest.raises(girtd.InputError) as caught:
        girtd.render(s)
    assert caught.value.file == "<scene>" and '"models/0/mesh/polygons/0/2"' in caught.value.message


def test_an_error_in_a_scene_built_in_python_names_its_key():
    # A document has no lines: the message says which key, even where the
    # scene file's message leaves it to the line number.
    s = girtd.Scene(lights=dict(ambient=0.2, directional=[dict(intensity=0.5)]))  # no "toward"
    s.add_mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    with pytest.raises(girtd.InputError) as caught:
        girtd.render(s)
    assert caught.value.line == 0 and '"lights/directional/0"' in caught.value.message, str(caught.value)
