"""`pip install .` from the checkout, as a Python user installs a package: the in-tree backend
(pyproject.toml, packaging/pep517) builds the module with the project's CMake build, offline
(--no-build-isolation --no-index), into a fresh venv made with --system-site-packages (Debian's
numpy); `import toyhost` from another folder then renders the ocean. `pip wheel .` makes the wheel
it installs. The build folder is the suite's own (already built: the backend reuses it)."""

import os
import pathlib
import subprocess
import sys
import zipfile

import pytest

from support import DATE, SOURCE_DIR, require_shared


def build_dir():
    build = os.environ.get("TOYHOST_BUILD_DIR")
    assert build, "TOYHOST_BUILD_DIR is set by CTest (the build this suite runs in)"
    return build


def test_pip_install_into_a_venv_then_import_elsewhere_renders_the_ocean(tmp_path):
    require_shared("shadertoys/MdXyzX/image.glsl")
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True)
    python = venv / "bin" / "python"
    done = subprocess.run([str(python), "-m", "pip", "install", "--no-build-isolation", "--no-index",
                           "--config-settings", f"build-dir={build_dir()}", str(SOURCE_DIR)],
                          capture_output=True, text=True, cwd=tmp_path, check=False)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    script = ("import toyhost\n"
              "print(toyhost.__file__)\n"
              f"with toyhost.Session({str(SOURCE_DIR / 'shadertoys/ocean')!r}, size=(48, 27), date={DATE!r}) as s:\n"
              "    s.step()\n"
              "    print(float(s.frame()[..., :3].mean()))\n")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}  # the venv's module, not the build's
    ran = subprocess.run([str(python), "-c", script], capture_output=True, text=True, cwd=elsewhere, env=env,
                         check=False)
    assert ran.returncode == 0, ran.stderr[-2000:]
    where, mean = ran.stdout.split()
    assert pathlib.Path(where).is_relative_to(venv), where
    assert 20 < float(mean) < 250, "the ocean is neither black nor white"


def test_pip_wheel_holds_the_module_and_its_types(tmp_path):
    done = subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-build-isolation", "--no-index", "--no-deps",
                           "--config-settings", f"build-dir={build_dir()}", "-w", str(tmp_path), str(SOURCE_DIR)],
                          capture_output=True, text=True, cwd=tmp_path, check=False)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    [wheel] = list(tmp_path.glob("toyhost-*.whl"))
    names = zipfile.ZipFile(wheel).namelist()
    for expected in ("toyhost/__init__.py", "toyhost/py.typed", "toyhost/_toyhost.pyi"):
        assert expected in names, names
    assert any(n.startswith("toyhost/_toyhost.cpython-") and n.endswith(".so") for n in names), names
    assert any(n.endswith(".dist-info/RECORD") for n in names)
