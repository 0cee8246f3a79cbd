"""examples/python/frames_grid.py runs as documented: it prints its statistics and writes a
contact sheet whose tiles are the frames a session renders."""

import os
import subprocess
import sys

import numpy

import toyhost
from support import SOURCE_DIR, read_png


def test_the_notebook_example_writes_its_contact_sheet(tmp_path):
    out = tmp_path / "sheet.png"
    done = subprocess.run(
        [sys.executable, str(SOURCE_DIR / "examples/python/frames_grid.py"), str(SOURCE_DIR / "shadertoys/ripple-pool"),
         "--size", "40x24", "--frames", "9", "--every", "4", "--columns", "2", "--out", str(out)],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=dict(os.environ), check=False)
    assert done.returncode == 0, done.stdout
    assert "3 frames kept of 9" in done.stdout, done.stdout
    assert f"wrote {out}" in done.stdout
    sheet = read_png(out)
    assert sheet.shape == (2 * 24 + 2, 2 * 40 + 2, 4), "frames 0, 4 and 8 in two columns"
    # The last tile (bottom left) is frame 8 with the mouse dragged as the example drags it.
    with toyhost.Session(SOURCE_DIR / "shadertoys/ripple-pool", size=(40, 24), date="2026-01-01T00:00:00") as s:
        for n in range(9):
            s.step(mouse=((n + 0.5) / 9 * 40, 12))
        assert numpy.array_equal(sheet[26:50, 0:40], s.frame())
    assert (sheet[26:50, 42:] == [0, 0, 0, 255]).all(), "the empty cell stays black"
