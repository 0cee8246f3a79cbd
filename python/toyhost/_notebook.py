"""Frames in notebooks: PNG files made in Python (zlib, no imaging library needed) for Jupyter's
rich display, and animations as animated PNGs (APNG, which every current browser plays in an
<img>) or as a strip of stills. Nothing here imports IPython: Jupyter calls _repr_png_ and
_repr_html_ on the objects by itself."""

import base64
import struct
import zlib

import numpy


def _chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)


def _rows(frame):
    """The PNG scanlines of an (h, w, 4) uint8 frame, top row first, each with filter byte 0."""
    frame = numpy.ascontiguousarray(frame, dtype=numpy.uint8)
    h, w = frame.shape[:2]
    lines = numpy.zeros((h, 1 + w * 4), numpy.uint8)
    lines[:, 1:] = frame.reshape(h, w * 4)
    return zlib.compress(lines.tobytes(), 6)


def _header(frame):
    h, w = frame.shape[:2]
    return b"\x89PNG\r\n\x1a\n" + _chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0))


def png_bytes(frame):
    """A PNG file (RGBA, 8 bits) of an (h, w, 4) uint8 frame, top row first."""
    return _header(frame) + _chunk(b"IDAT", _rows(frame)) + _chunk(b"IEND", b"")


def apng_bytes(frames, fps):
    """An animated PNG of equally sized frames shown 1/fps s each, looping; its default image (what
    a viewer without APNG shows) is the first frame."""
    frames = list(frames)
    # The delay as a fraction num/den of a second, both 16-bit.
    den = 1000
    num = max(1, min(65535, round(den / fps)))
    out = [_header(frames[0]), _chunk(b"acTL", struct.pack(">II", len(frames), 0))]
    sequence = 0
    h, w = frames[0].shape[:2]
    for n, frame in enumerate(frames):
        out.append(_chunk(b"fcTL", struct.pack(">IIIIIHHBB", sequence, w, h, 0, 0, num, den, 0, 0)))
        sequence += 1
        data = _rows(frame)
        if n == 0:
            out.append(_chunk(b"IDAT", data))
        else:
            out.append(_chunk(b"fdAT", struct.pack(">I", sequence) + data))
            sequence += 1
    out.append(_chunk(b"IEND", b""))
    return b"".join(out)


def data_uri(png):
    return "data:image/png;base64," + base64.b64encode(png).decode("ascii")


class Animation:
    """What Session.show() returns: Jupyter shows it as an animated image (or a strip of stills);
    ``frames`` holds the (iframe, array) pairs, ``png`` the file's bytes (save it with
    ``open("take.png", "wb").write(animation.png)``)."""

    def __init__(self, frames, fps, strip=False, scale=1):
        self.frames = list(frames)
        if not self.frames:
            raise ValueError("no frames to show")
        self.fps = fps
        self.strip = strip
        self.scale = scale
        arrays = [image for _, image in self.frames]
        self.png = png_bytes(numpy.concatenate(arrays, axis=1)) if strip else apng_bytes(arrays, fps)

    def _repr_html_(self):
        h, w = self.frames[0][1].shape[:2]
        width = w * (len(self.frames) if self.strip else 1) * self.scale
        what = "strip" if self.strip else "animation"
        title = f"{len(self.frames)} frames ({what}, iFrame {self.frames[0][0]}..{self.frames[-1][0]})"
        return (f'<img src="{data_uri(self.png)}" width="{width}" title="{title}" '
                f'style="image-rendering: pixelated" alt="toyhost {what}"/>')

    def _repr_png_(self):
        return png_bytes(self.frames[0][1])

    def __repr__(self):
        return f"<toyhost.Animation {len(self.frames)} frames at {self.fps:g} fps>"
