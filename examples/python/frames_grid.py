#!/usr/bin/env python3
"""Notebook-style example: render a shadertoy's frames into numpy arrays, look at them as data,
and save a contact sheet. Each `# %%` block is one notebook cell (Jupyter, VS Code and Spyder run
them one by one); as a script it runs top to bottom.

    PYTHONPATH=build/python python3 examples/python/frames_grid.py shadertoys/ripple-pool \
        --size 320x180 --frames 120 --every 20 --out out/ripple-grid.png

The mouse is dragged across the canvas while it renders, so interactive shaders show it."""

# %% Set-up: what to render (command-line arguments when run as a script)
import argparse
import pathlib
import struct
import sys
import zlib

import numpy

import toyhost

parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
parser.add_argument("shadertoy", nargs="?", default="shadertoys/ripple-pool",
                    help="folder, manifest or export (default: shadertoys/ripple-pool)")
parser.add_argument("--size", default="320x180", help="canvas WxH (default 320x180)")
parser.add_argument("--frames", type=int, default=120)
parser.add_argument("--every", type=int, default=20, help="keep every Nth frame for the sheet")
parser.add_argument("--fps", type=float, default=60)
parser.add_argument("--columns", type=int, default=4)
parser.add_argument("--out", default="frames-grid.png", help="the contact sheet (PNG)")
args = parser.parse_args(sys.argv[1:] if "ipykernel" not in sys.modules else [])
width, height = (int(v) for v in args.size.split("x"))

# %% Load: a problem raises a toyhost.Error naming its file, pass and line
try:
    shadertoy = toyhost.load(args.shadertoy)
except toyhost.Error as error:
    sys.exit(f"cannot load {args.shadertoy}:\n{error}")
print(f"{shadertoy.name}: passes {', '.join(shadertoy.passes)} (toyhost {toyhost.__version__})")

# %% Render: frames as (height, width, 4) uint8 arrays, top row first; the mouse drags across
kept = []
means = []
with toyhost.Session(shadertoy, size=(width, height), fps=args.fps, date="2026-01-01T00:00:00") as session:
    for n in range(args.frames):
        x = (n + 0.5) / args.frames * width
        session.step(mouse=(x, height * 0.5))
        frame = session.frame()
        means.append(frame[..., :3].mean(axis=(0, 1)))
        if n % args.every == 0 or n == args.frames - 1:
            kept.append((n, frame))
    notices = session.notices
for notice in notices:
    print(f"notice: {notice}")

# %% Look at the numbers: mean colour per frame and how much each kept frame changed
means = numpy.array(means)
print(f"{len(kept)} frames kept of {args.frames}; mean RGB over the run: "
      + " ".join(f"{v:.1f}" for v in means.mean(axis=0)))
previous = None
for n, frame in kept:
    changed = "" if previous is None else f", {(frame != previous).any(axis=2).mean() * 100:5.1f}% of pixels changed"
    print(f"frame {n:4d}: mean RGB {' '.join(f'{v:6.1f}' for v in means[n])}{changed}")
    previous = frame

# %% The contact sheet: kept frames in a grid, 2-pixel gaps, saved as PNG (numpy + zlib only)
columns = min(args.columns, len(kept))
rows = (len(kept) + columns - 1) // columns
gap = 2
sheet = numpy.zeros((rows * (height + gap) - gap, columns * (width + gap) - gap, 4), numpy.uint8)
sheet[..., 3] = 255
for i, (_, frame) in enumerate(kept):
    top, left = (i // columns) * (height + gap), (i % columns) * (width + gap)
    sheet[top:top + height, left:left + width] = frame


def write_png(path, rgba):
    """An RGBA8 image (top row first) as a PNG file."""
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    h, w, _ = rgba.shape
    raw = b"".join(b"\x00" + rgba[y].tobytes() for y in range(h))
    data = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))
    pathlib.Path(path).write_bytes(data)


out = pathlib.Path(args.out)
out.parent.mkdir(parents=True, exist_ok=True)
write_png(out, sheet)
print(f"wrote {out} ({sheet.shape[1]}x{sheet.shape[0]}, {len(kept)} frames)")
