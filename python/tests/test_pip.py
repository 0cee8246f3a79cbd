"""`pip install .` from the checkout, as a Python user installs a package: the in-tree backend
(pyproject.toml, packaging/pep517) builds the module with the project's CMake build, offline
(--no-build-isolation --no-index), into a fresh venv made with --system-site-packages (Debian's
numpy); `import toyhost` from another folder then renders the ocean. `pip wheel .` makes the wheel
it installs. The build folder is the suite's own (already built: the backend reuses it)."""

import os
import pathlib
import subprocess
import sys
import sysconfig
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
    # Only this interpreter's module, and the numpy the bindings support (Debian's pybind11 2.10
    # knows numpy 1's C API only).
    modules = [n for n in names if n.startswith("toyhost/_toyhost") and n.endswith(".so")]
    assert modules == ["toyhost/_toyhost" + sysconfig.get_config_var("EXT_SUFFIX")], modules
    [metadata] = [n for n in names if n.endswith(".dist-info/METADATA")]
    requires = [line for line in zipfile.ZipFile(wheel).read(metadata).decode().splitlines()
                if line.startswith("Requires-Dist:")]
    assert requires in (["Requires-Dist: numpy<2"], ["Requires-Dist: numpy"]), requires
    assert requires == ["Requires-Dist: " + backend().numpy_requirement(pathlib.Path(build_dir()))], requires


def backend():
    sys.path.insert(0, str(SOURCE_DIR / "packaging" / "pep517"))
    try:
        import toyhost_build
    finally:
        sys.path.pop(0)
    return toyhost_build


def test_one_build_folder_per_interpreter_and_no_other_interpreters_folder(tmp_path):
    """pip per interpreter (issue 45): the default folder names the interpreter and ABI, so a
    second Python never reuses the first one's module; a folder given with -C build-dir that was
    configured for another interpreter is refused before anything is built."""
    b = backend()
    default = b.build_folder({})
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    assert default.parent == (SOURCE_DIR / "build-pip").resolve()
    assert default.name == suffix.strip(".").removesuffix(".so"), (default.name, suffix)
    assert b.build_folder({"build-dir": str(tmp_path)}) == tmp_path.resolve()
    other = tmp_path / "other"
    other.mkdir()
    (other / "CMakeCache.txt").write_text("_Python3_EXECUTABLE:INTERNAL=/opt/python3.99/bin/python3.99\n")
    assert b.configured_python(other) == "/opt/python3.99/bin/python3.99"
    with pytest.raises(RuntimeError, match="configured for /opt/python3.99/bin/python3.99, not for this interpreter"):
        b._build({"build-dir": str(other)})
    assert b.configured_python(tmp_path / "fresh") is None
