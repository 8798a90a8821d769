"""`cmake --install` puts the package into the Python site directory of the prefix, where the
interpreter imports it from outside the build tree."""
import os
import pathlib
import subprocess
import sys

import pytest


def test_installed_package_imports(tmp_path):
    build, cmake = os.environ.get("TRAVEL_BUILD_DIR"), os.environ.get("TRAVEL_CMAKE", "cmake")
    if not build:
        pytest.skip("TRAVEL_BUILD_DIR not set (run through ctest)")
    prefix = tmp_path / "prefix"
    subprocess.run([cmake, "--install", build, "--prefix", str(prefix)], check=True,
                   capture_output=True)
    site = os.environ["TRAVEL_PYTHON_INSTALL_DIR"]
    package = prefix / site / "travel"
    assert (package / "__init__.py").is_file() and (package / "_travel.pyi").is_file()
    assert list(package.glob("_travel*.so"))
    # A preset only the scratch prefix has: the module finds the share directory of the prefix it
    # is installed in, not only the configured CMAKE_INSTALL_PREFIX or the source tree.
    presets = prefix / "share" / "travel" / "presets"
    (presets / "installed_only.yaml").write_text((presets / "vlp16.yaml").read_text())
    code = ("import travel; p = travel.Params.from_preset('installed_only'); "
            "print(travel.__file__, p.num_rings)")
    env = dict(os.environ, PYTHONPATH=str(prefix / site))
    env.pop("TRAVEL_SHARE_DIR", None)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          cwd=tmp_path, env=env)
    assert done.returncode == 0, done.stderr
    installed, rings = done.stdout.split()
    assert pathlib.Path(installed).is_relative_to(prefix) and rings == "16"
