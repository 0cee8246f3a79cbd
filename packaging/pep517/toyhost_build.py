"""The PEP 517 backend of `pip install .`: builds the Python module with the project's CMake build
and packs what the build assembled in BUILD/python/toyhost (the native _toyhost, the package's .py
files, its types) into a wheel. In-tree and without requirements, so pip needs nothing from the
network. `-C build-dir=DIR` builds in DIR (an existing build folder is reused), else in
build-pip/ beside this file's checkout; `-C cmake-args="..."` adds configure arguments."""

import base64
import hashlib
import os
import pathlib
import re
import shlex
import subprocess
import sys
import sysconfig
import zipfile

ROOT = pathlib.Path(__file__).resolve().parents[2]


def _version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(\s*toyhost\s+VERSION\s+([0-9.]+)", text).group(1)


def _build(config_settings):
    settings = config_settings or {}
    build = pathlib.Path(settings.get("build-dir") or ROOT / "build-pip").resolve()
    configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                 f"-DPython3_EXECUTABLE={sys.executable}", "-DTOYHOST_BUILD_TESTS=OFF"]
    if not (build / "CMakeCache.txt").exists():
        subprocess.run(configure + shlex.split(settings.get("cmake-args", "")), check=True)
    jobs = str(os.cpu_count() or 1)
    subprocess.run(["cmake", "--build", str(build), "--target", "toyhost_python", "-j", jobs], check=True)
    package = build / "python" / "toyhost"
    if not any(package.glob("_toyhost*.so")):
        raise RuntimeError(f"{package}: no native module _toyhost after the build (is pybind11-dev installed?)")
    return package


def _tag():
    interpreter = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{interpreter}-{interpreter}-{platform}"


def _metadata(version):
    return (f"Metadata-Version: 2.1\nName: toyhost\nVersion: {version}\n"
            "Summary: Run Shadertoy shaders unmodified, headless, with frames as numpy arrays\n"
            "Requires-Python: >=3.9\nRequires-Dist: numpy\n")


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


def get_requires_for_build_wheel(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    version = _version()
    info = pathlib.Path(metadata_directory) / f"toyhost-{version}.dist-info"
    info.mkdir(parents=True, exist_ok=True)
    (info / "METADATA").write_text(_metadata(version))
    return info.name


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    version = _version()
    package = _build(config_settings)
    name = f"toyhost-{version}-{_tag()}.whl"
    info = f"toyhost-{version}.dist-info"
    files = [(f"toyhost/{p.name}", p.read_bytes()) for p in sorted(package.iterdir())
             if p.is_file() and (p.suffix in (".py", ".pyi", ".so") or p.name == "py.typed")]
    files.append((f"{info}/METADATA", _metadata(version).encode()))
    files.append((f"{info}/WHEEL", (f"Wheel-Version: 1.0\nGenerator: toyhost_build\nRoot-Is-Purelib: false\n"
                                    f"Tag: {_tag()}\n").encode()))
    record = [_record_line(n, d) for n, d in files] + [f"{info}/RECORD,,"]
    files.append((f"{info}/RECORD", ("\n".join(record) + "\n").encode()))
    path = pathlib.Path(wheel_directory) / name
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as wheel:
        for member, data in files:
            entry = zipfile.ZipInfo(member, date_time=(2026, 1, 1, 0, 0, 0))
            entry.external_attr = (0o755 if member.endswith(".so") else 0o644) << 16
            entry.compress_type = zipfile.ZIP_DEFLATED
            wheel.writestr(entry, data)
    return name
