"""Where the tests find the repository and the build (CTest passes GIRTD_BUILD)."""
import os
import subprocess

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BUILD = os.environ.get("GIRTD_BUILD", os.path.join(ROOT, "build"))
GIRTD = os.path.join(BUILD, "bin", "girtd")


def cli_render(tmp_path, *args):
    """`girtd render ARGS --out DIR --quiet`: (exit code, stderr, DIR)."""
    out = tmp_path / "cli"
    done = subprocess.run([GIRTD, "render", *map(str, args), "--out", str(out), "--quiet"],
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, cwd=ROOT,
                          env=dict(os.environ, SYSTEMC_DISABLE_COPYRIGHT_MESSAGE="1"))
    return done.returncode, done.stderr, out


@pytest.fixture
def repo():
    return ROOT
