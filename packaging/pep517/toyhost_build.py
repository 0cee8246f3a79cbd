"""The PEP 517 backend of `pip install .`: builds the Python module with the project's CMake build
and packs what the build assembled in BUILD/python/toyhost (the native _toyhost, the package's .py
files, its types) into a wheel. In-tree and without requirements, so pip needs nothing from the
network. `-C build-dir=DIR` builds in DIR (an existing build folder is reused when it was configured
for this interpreter, refused otherwise), else in build-pip/INTERPRETER/ beside this file's checkout
(one folder per interpreter and ABI, e.g. build-pip/cpython-311-x86_64-linux-gnu: a second Python
never reuses the first one's module); `-C cmake-args="..."` adds configure arguments. The build's
progress goes to the terminal when there is one (pip shows a backend's output only with -v)."""

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


def _interpreter():
    """This interpreter and ABI as its extension modules' suffix names them:
    cpython-311-x86_64-linux-gnu."""
    return sysconfig.get_config_var("EXT_SUFFIX").strip(".").removesuffix(".so").removesuffix(".pyd")


def build_folder(config_settings):
    """Where the module is built: -C build-dir, else build-pip/INTERPRETER/ in the checkout."""
    given = (config_settings or {}).get("build-dir")
    return pathlib.Path(given or ROOT / "build-pip" / _interpreter()).resolve()


def configured_python(build):
    """The interpreter an existing build folder was configured for (its CMakeCache), or None."""
    cache = build / "CMakeCache.txt"
    if not cache.exists():
        return None
    found = re.search(r"^_?Python3_EXECUTABLE:\w+=(.*)$", cache.read_text(errors="replace"), re.M)
    return found.group(1).strip() if found else None


def _console():
    """The terminal, for the build's progress (pip captures the backend's own output), or None."""
    try:
        return open("/dev/tty", "w")  # noqa: SIM115 (closed by the caller)
    except OSError:
        return None


def _build(config_settings):
    settings = config_settings or {}
    build = build_folder(settings)
    configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                 f"-DPython3_EXECUTABLE={sys.executable}", "-DTOYHOST_BUILD_TESTS=OFF"]
    configured = configured_python(build)
    if configured and os.path.realpath(configured) != os.path.realpath(sys.executable):
        raise RuntimeError(f"{build} was configured for {configured}, not for this interpreter ({sys.executable}): "
                           "give another -C build-dir (or none: build-pip/ has one folder per interpreter)")
    console = _console()
    try:
        if console:
            print(f"toyhost: building the Python module in {build} (a first build takes minutes)", file=console,
                  flush=True)
        if configured is None:
            subprocess.run(configure + shlex.split(settings.get("cmake-args", "")), check=True, stdout=console)
        jobs = str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(build), "--target", "toyhost_python", "-j", jobs], check=True,
                       stdout=console)
    finally:
        if console:
            console.close()
    package = build / "python" / "toyhost"
    module = package / ("_toyhost" + sysconfig.get_config_var("EXT_SUFFIX"))
    if not module.exists():
        raise RuntimeError(f"{module}: no native module for this interpreter after the build "
                           "(is pybind11-dev installed, and python3-dev for this Python?)")
    return package


def numpy_requirement(build):
    """The numpy the module supports: pybind11 before 2.12 knows numpy 1's C API only (read from
    the pybind11 the build found: its CMake package's version file)."""
    cache = build / "CMakeCache.txt"
    folder = re.search(r"^pybind11_DIR:\w+=(.*)$", cache.read_text(errors="replace"), re.M) if cache.exists() else None
    version_file = pathlib.Path(folder.group(1).strip()) / "pybind11ConfigVersion.cmake" if folder else None
    found = re.search(r'PACKAGE_VERSION "([0-9]+)\.([0-9]+)', version_file.read_text()) \
        if version_file and version_file.exists() else None
    if found and (int(found.group(1)), int(found.group(2))) < (2, 12):
        return "numpy<2"
    return "numpy"


def _tag():
    interpreter = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{interpreter}-{interpreter}-{platform}"


def _metadata(version, numpy="numpy"):
    return (f"Metadata-Version: 2.1\nName: toyhost\nVersion: {version}\n"
            "Summary: Run Shadertoy shaders unmodified, headless, with frames as numpy arrays\n"
            f"Requires-Python: >=3.9\nRequires-Dist: {numpy}\n")


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


def get_requires_for_build_wheel(config_settings=None):
    return []


# No prepare_metadata_for_build_wheel: the numpy requirement depends on the pybind11 the build
# finds, so pip reads the metadata from the built wheel.


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    version = _version()
    package = _build(config_settings)
    name = f"toyhost-{version}-{_tag()}.whl"
    info = f"toyhost-{version}.dist-info"
    module = "_toyhost" + sysconfig.get_config_var("EXT_SUFFIX")  # this interpreter's, no other
    files = [(f"toyhost/{p.name}", p.read_bytes()) for p in sorted(package.iterdir())
             if p.is_file() and (p.suffix in (".py", ".pyi") or p.name in ("py.typed", module))]
    files.append((f"{info}/METADATA", _metadata(version, numpy_requirement(package.parents[1])).encode()))
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
