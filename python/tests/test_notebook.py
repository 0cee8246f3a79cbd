"""Frames in notebooks: Session and Shadertoy show a PNG inline (Jupyter's _repr_png_), and
Session.show() plays frames as an animated PNG. Tested for real: a notebook is executed by Jupyter
(jupyter nbconvert --execute, on a kernel running this interpreter) and the images in its outputs
are compared with the CLI's frames pixel for pixel."""

import base64
import json
import os
import pathlib
import re
import struct
import subprocess
import sys

import numpy
import pytest

import toyhost
from support import DATE, SOURCE_DIR, read_png, run_cli

TOY = SOURCE_DIR / "shadertoys/exp-sine-ocean"
SIZE = (48, 27)


def cli_frames(tmp_path, frames, every=1, fps=60):
    code, output = run_cli("run", TOY, "--size", f"{SIZE[0]}x{SIZE[1]}", "--frames", frames, "--capture-every", every,
                           "--fps", fps,
                           "--date", DATE, "--quiet", "--out", tmp_path / "cli_%03d.png")
    assert code == 0, output
    return {n: read_png(tmp_path / f"cli_{n:03d}.png") for n in range(frames) if (tmp_path / f"cli_{n:03d}.png").exists()}


def chunks(png):
    pos, found = 8, []
    while pos < len(png):
        (length,) = struct.unpack(">I", png[pos:pos + 4])
        found.append((png[pos + 4:pos + 8], png[pos + 8:pos + 8 + length]))
        pos += 12 + length
    return found


def test_a_session_shows_its_latest_frame_and_nothing_before_the_first(tmp_path):
    with toyhost.Session(TOY, size=SIZE, date=DATE) as session:
        assert session._repr_png_() is None
        with pytest.raises(toyhost.UsageError):
            session.frame()
        session.step()
        session.step()
        (tmp_path / "repr.png").write_bytes(session._repr_png_())
        assert (read_png(tmp_path / "repr.png") == session.frame()).all()
        assert (read_png(tmp_path / "repr.png") == cli_frames(tmp_path, 2)[1]).all()


def test_show_makes_an_animated_png_of_the_frames_kept(tmp_path):
    with toyhost.Session(TOY, size=SIZE, date=DATE, fps=30) as session:
        animation = session.show(frames=7, every=3)
    assert [n for n, _ in animation.frames] == [0, 3, 6]
    kinds = [kind for kind, _ in chunks(animation.png)]
    assert kinds.count(b"acTL") == 1 and kinds.count(b"fcTL") == 3 and kinds.count(b"fdAT") == 2
    (actl,) = [body for kind, body in chunks(animation.png) if kind == b"acTL"]
    assert struct.unpack(">II", actl) == (3, 0)
    fctl = [struct.unpack(">IIIIIHHBB", body) for kind, body in chunks(animation.png) if kind == b"fcTL"]
    assert all(f[5] / f[6] == pytest.approx(3 / 30, abs=1e-3) for f in fctl)  # 10 frames a second shown
    expected = cli_frames(tmp_path, 7, every=3, fps=30)
    (tmp_path / "first.png").write_bytes(animation.png)
    assert (read_png(tmp_path / "first.png") == expected[0]).all()  # the default image: frame 0
    html = animation._repr_html_()
    assert html.startswith('<img src="data:image/png;base64,')
    with toyhost.Session(TOY, size=SIZE, date=DATE, fps=30) as session:
        strip = session.show(frames=7, every=3, strip=True)
    (tmp_path / "strip.png").write_bytes(strip.png)
    assert (read_png(tmp_path / "strip.png") == numpy.concatenate([expected[n] for n in (0, 3, 6)], axis=1)).all()
    with toyhost.Session(TOY, size=SIZE, date=DATE) as session:
        with pytest.raises(toyhost.UsageError):
            session.show(frames=2, scale=0)
        # Once a bare ValueError from the animation (issue 46): no frames is no picture.
        with pytest.raises(toyhost.UsageError, match="frames"):
            session.show(frames=0)


def kernel_folder(tmp_path):
    """A Jupyter kernel that runs this very interpreter (the python3 first on PATH may be another
    one, without numpy), with the module the tests use."""
    spec = tmp_path / "jupyter" / "kernels" / "toyhost-test"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "toyhost test", "language": "python"}))
    return tmp_path / "jupyter"


def cell(source):
    return {"cell_type": "code", "execution_count": None, "metadata": {}, "outputs": [], "source": source}


def test_a_notebook_executed_by_jupyter_shows_the_clis_frames(tmp_path):
    notebook = {
        "cells": [
            cell("import toyhost\n"
                 f"session = toyhost.Session({str(TOY)!r}, size={SIZE!r}, date={DATE!r}, fps=30)\n"
                 "session.step()\nsession"),
            cell("session.show(frames=4, every=3)"),
            cell(f"toyhost.load({str(TOY)!r})"),
        ],
        "metadata": {"kernelspec": {"name": "toyhost-test", "display_name": "toyhost test", "language": "python"}},
        "nbformat": 4, "nbformat_minor": 5,
    }
    source = tmp_path / "frames.ipynb"
    source.write_text(json.dumps(notebook))
    module_dir = str(pathlib.Path(toyhost.__file__).resolve().parents[1])
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([module_dir, os.environ.get("PYTHONPATH", "")]),
           "JUPYTER_PATH": str(kernel_folder(tmp_path)), "JUPYTER_DATA_DIR": str(tmp_path / "data"),
           "JUPYTER_RUNTIME_DIR": str(tmp_path / "runtime"), "IPYTHONDIR": str(tmp_path / "ipython")}
    done = subprocess.run(["jupyter-nbconvert", "--to", "notebook", "--execute", "--ExecutePreprocessor.timeout=300",
                           "--ExecutePreprocessor.kernel_name=toyhost-test", "--output", "executed.ipynb", str(source)],
                          capture_output=True, text=True, env=env, cwd=tmp_path, check=False)
    assert done.returncode == 0, done.stderr[-3000:]
    executed = json.loads((tmp_path / "executed.ipynb").read_text())
    outputs = [c["outputs"] for c in executed["cells"]]
    for n, cell_outputs in enumerate(outputs):
        assert not [o for o in cell_outputs if o["output_type"] == "error"], f"cell {n}: {cell_outputs}"

    def image_of(cell_outputs, name):
        data = [o["data"] for o in cell_outputs if o["output_type"] == "execute_result"][0]
        (tmp_path / name).write_bytes(base64.b64decode(data["image/png"]))
        return read_png(tmp_path / name)

    expected = cli_frames(tmp_path, 5, fps=30)
    assert (image_of(outputs[0], "session.png") == expected[0]).all()
    html = [o["data"] for o in outputs[1] if o["output_type"] == "execute_result"][0]["text/html"]
    html = "".join(html) if isinstance(html, list) else html
    uri = re.search(r'src="data:image/png;base64,([^"]+)"', html).group(1)
    (tmp_path / "shown.png").write_bytes(base64.b64decode(uri))
    # The session had drawn frame 0 in the cell before: show() renders iFrames 1..4 and, `every`
    # counting on iFrame (issue 41), keeps 3 and the last, 4.
    assert "iFrame 3..4" in html
    assert (read_png(tmp_path / "shown.png") == expected[3]).all()
    assert sum(1 for kind, _ in chunks((tmp_path / "shown.png").read_bytes()) if kind == b"fcTL") == 2
    preview = image_of(outputs[2], "preview.png")
    assert preview.shape == (225, 400, 4)
