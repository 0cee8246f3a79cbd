"""What the toyhost pytest suite shares: where things are (from CTest's environment, with
fallbacks for a plain `pytest` run from a build), running the CLI, reading its PNG files, and
writing small shadertoys into a temporary folder."""

import os
import pathlib
import struct
import subprocess
import zlib

import numpy
import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("TOYHOST_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
TOYHOST_BIN = pathlib.Path(os.environ.get("TOYHOST_BIN", SOURCE_DIR / "build" / "tools" / "toyhost"))
SHARED_DIR = SOURCE_DIR.parent / "shared"
# Fixed inputs make frames repeatable (iDate).
DATE = "2026-01-01T00:00:00"


def require_shared(relative):
    """Skips (as the C++ suite's TOYHOST_REQUIRE_SHARED) when ../shared/RELATIVE is absent."""
    if not (SHARED_DIR / relative).exists():
        pytest.skip(f"needs ../shared/{relative} beside the repository")


def egl_device_platform_absence():
    """Why this machine's EGL has no device platform, or None when it has one, asked of libEGL
    directly (tests/support/EglDevicePlatform.h, the same rule): absent means libEGL resolves no
    eglQueryDevicesEXT or eglGetPlatformDisplayEXT, or lists no device. Anything else (a failing
    query, a device that does not start) is there but broken, which a test must report, not skip."""
    import ctypes

    try:
        egl = ctypes.CDLL("libEGL.so.1")
    except OSError:
        return "no libEGL.so.1"
    egl.eglGetProcAddress.restype = ctypes.c_void_p
    egl.eglGetProcAddress.argtypes = [ctypes.c_char_p]
    query = egl.eglGetProcAddress(b"eglQueryDevicesEXT")
    if not query or not egl.eglGetProcAddress(b"eglGetPlatformDisplayEXT"):
        return "libEGL has no eglQueryDevicesEXT or eglGetPlatformDisplayEXT (no EGL_EXT_platform_device)"
    query_devices = ctypes.CFUNCTYPE(ctypes.c_uint, ctypes.c_int32, ctypes.c_void_p,
                                     ctypes.POINTER(ctypes.c_int32))(query)
    count = ctypes.c_int32(0)
    if query_devices(0, None, ctypes.byref(count)) and count.value == 0:
        return "EGL lists no device"
    return None


def run_cli(*args):
    """Runs the toyhost CLI; returns (exit code, stdout + stderr text)."""
    done = subprocess.run([str(TOYHOST_BIN), *map(str, args)], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, check=False)
    return done.returncode, done.stdout


def read_png(path):
    """An 8-bit RGB or RGBA, non-interlaced PNG as a (height, width, 4) uint8 array, top row first
    (as PNG stores rows). Enough for toyhost's own files; anything else raises."""
    data = pathlib.Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path}: not a PNG"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
    width, height, depth, colour, _, _, interlace = header
    assert depth == 8 and colour in (2, 6) and interlace == 0, f"{path}: unsupported PNG form {header}"
    channels = 4 if colour == 6 else 3
    raw = zlib.decompress(idat)
    stride = width * channels
    rows = numpy.zeros((height, stride), dtype=numpy.int32)
    previous = numpy.zeros(stride, dtype=numpy.int32)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = numpy.frombuffer(raw, dtype=numpy.uint8, count=stride, offset=y * (stride + 1) + 1).astype(numpy.int32)
        out = numpy.zeros(stride, dtype=numpy.int32)
        if kind == 0:
            out = line
        elif kind == 2:
            out = (line + previous) & 255
        else:  # Sub, Average, Paeth depend on the pixel to the left: one byte at a time
            for i in range(stride):
                left = out[i - channels] if i >= channels else 0
                up = previous[i]
                corner = previous[i - channels] if i >= channels else 0
                if kind == 1:
                    predictor = left
                elif kind == 3:
                    predictor = (left + up) // 2
                elif kind == 4:
                    p = left + up - corner
                    pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                    predictor = left if pa <= pb and pa <= pc else (up if pb <= pc else corner)
                else:
                    raise AssertionError(f"{path}: bad filter type {kind}")
                out[i] = (line[i] + predictor) & 255
        rows[y] = out
        previous = out
    pixels = rows.astype(numpy.uint8).reshape(height, width, channels)
    if channels == 3:
        pixels = numpy.concatenate([pixels, numpy.full((height, width, 1), 255, numpy.uint8)], axis=2)
    return pixels


def write_shadertoy(folder, passes, common=None):
    """A folder with manifest.json and one file per pass: `passes` maps a pass name ("Image",
    "Buffer A") to its code, or to (code, channels) with channels as the manifest writes them."""
    import json

    folder = pathlib.Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    manifest = {"name": folder.name, "passes": {}}
    if common is not None:
        (folder / "common.glsl").write_text(common)
        manifest["common"] = "common.glsl"
    for name, code in passes.items():
        channels = None
        if isinstance(code, tuple):
            code, channels = code
        file = name.lower().replace(" ", "_") + ".glsl"
        (folder / file).write_text(code)
        manifest["passes"][name] = {"source": file}
        if channels:
            manifest["passes"][name]["channels"] = channels
    (folder / "manifest.json").write_text(json.dumps(manifest, indent=2))
    return folder
