"""`cmake --install` of the python component puts a package that the system's python3 imports
and runs from the install prefix (Debian's dist-packages layout), without the build tree."""

import os
import pathlib
import subprocess
import sys

import pytest

from support import SOURCE_DIR


def test_the_installed_module_imports_and_renders(tmp_path):
    build = os.environ.get("TOYHOST_BUILD_DIR")
    if not build:
        pytest.skip("needs TOYHOST_BUILD_DIR (CTest sets it)")
    prefix = tmp_path / "prefix"
    done = subprocess.run(["cmake", "--install", build, "--component", "python", "--prefix", str(prefix)],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, check=False)
    assert done.returncode == 0, done.stdout
    version = f"python{sys.version_info.major}.{sys.version_info.minor}"
    package = prefix / "lib" / version / "dist-packages" / "toyhost"
    assert (package / "__init__.py").is_file(), sorted(str(p) for p in prefix.rglob("*"))
    assert list(package.glob("_toyhost*.so")), "the native module"
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(package.parent)
    script = ("import toyhost, sys\n"
              "assert toyhost.__file__.startswith(sys.argv[1]), toyhost.__file__\n"
              "with toyhost.Session(sys.argv[2], size=(8, 4)) as s:\n"
              "    s.step()\n"
              "    print(toyhost.__version__, s.frame().shape)\n")
    ran = subprocess.run([sys.executable, "-c", script, str(package), str(SOURCE_DIR / "shadertoys/bench-trivial")],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env, cwd=tmp_path,
                         check=False)
    assert ran.returncode == 0, ran.stdout
    assert "(4, 8, 4)" in ran.stdout
