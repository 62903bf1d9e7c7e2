# SPDX-License-Identifier: MIT
# `cmake --install` puts the module where Debian's interpreter finds it under the prefix.
import os
import subprocess
import sys

import pytest


def test_cmake_install_gives_an_importable_module(tmp_path):
    build = os.environ.get("SWARMPATH_BUILD_DIR")
    if not build:
        pytest.skip("SWARMPATH_BUILD_DIR is set by ctest")
    subprocess.run(["cmake", "--install", build, "--prefix", str(tmp_path), "--component", "python"], check=True,
                   capture_output=True)
    found = [r for r, _, files in os.walk(tmp_path) for f in files if f.startswith("swarmpath.") and f.endswith(".so")]
    assert len(found) == 1
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    site = "lib/python%d.%d/dist-packages" % sys.version_info[:2]
    if os.path.isdir(tmp_path / site):
        assert found[0] == str(tmp_path / site)
    env["PYTHONPATH"] = found[0]
    out = subprocess.run([sys.executable, "-c", "import swarmpath; print(swarmpath.__file__, swarmpath.Params()['v_max'])"],
                         env=env, capture_output=True, text=True, check=True)
    assert out.stdout.startswith(found[0]) and out.stdout.split()[1] == "20.0"
