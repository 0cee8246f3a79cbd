"""A frame from Python equals the CLI's PNG byte for byte: the same session underneath, the same
time step, date and inputs; the CLI runs as a child process and its files are decoded here."""

import numpy
import pytest

import toyhost
from support import DATE, SOURCE_DIR, read_png, require_shared, run_cli


def cli_frames(tmp_path, target, size, frames, fps, *extra):
    code, output = run_cli("run", target, "--headless", "--size", f"{size[0]}x{size[1]}", "--frames", frames,
                           "--fps", fps, "--date", DATE, "--quiet", "--out", tmp_path / "f_%d.png", *extra)
    assert code == 0, output
    return [read_png(tmp_path / f"f_{n}.png") for n in range(frames)]


def python_frames(target, size, frames, fps, mouse=None):
    with toyhost.Session(toyhost.load(target), size=size, fps=fps, date=DATE) as session:
        return [image for _, image in session.render(frames, mouse=mouse)]


def assert_same(cli, python):
    assert len(cli) == len(python)
    for n, (expected, got) in enumerate(zip(cli, python)):
        assert got.shape == expected.shape, f"frame {n}"
        differing = int((got != expected).any(axis=2).sum())
        assert differing == 0, f"frame {n}: {differing} pixels differ from the CLI's PNG"
        assert got.tobytes() == expected.tobytes()


def test_the_ocean_equals_the_clis_png(tmp_path):
    require_shared("shadertoys/MdXyzX/image.glsl")
    ocean = SOURCE_DIR / "shadertoys/ocean"
    assert_same(cli_frames(tmp_path, ocean, (96, 54), 3, 30), python_frames(ocean, (96, 54), 3, 30))


def test_buffers_textures_and_feedback_equal_the_clis_pngs(tmp_path):
    probe = SOURCE_DIR / "shadertoys/uniform-probe"
    assert_same(cli_frames(tmp_path, probe, (40, 24), 4, 60), python_frames(probe, (40, 24), 4, 60))


def test_a_held_mouse_equals_the_clis(tmp_path):
    probe = SOURCE_DIR / "shadertoys/window-probe"
    cli = cli_frames(tmp_path, probe, (48, 32), 3, 24, "--mouse", "12,9")
    assert_same(cli, python_frames(probe, (48, 32), 3, 24, mouse=(12, 9)))
    assert tuple(cli[0][0, 0, :3]) == (12, 9, 12), "the mouse reached the shader"


def test_a_one_pixel_different_mouse_differs(tmp_path):
    # The comparison can fail: the probe shows iMouse, so a click one pixel away is another frame.
    probe = SOURCE_DIR / "shadertoys/window-probe"
    cli = cli_frames(tmp_path, probe, (48, 32), 1, 24, "--mouse", "12,9")
    other = python_frames(probe, (48, 32), 1, 24, mouse=(13, 9))
    assert not numpy.array_equal(other[0], cli[0])


def test_a_buffer_equals_the_clis_png_of_that_pass(tmp_path):
    # ripple-pool's height field after a click: dozens of distinct values, changing every frame. Seen
    # from above (TOP_VIEW), where the click at the centre lands on the water (in the 3-D view the
    # centre of so small a canvas is the sphere, where a click drops nothing).
    pool = SOURCE_DIR / "shadertoys/ripple-pool"
    cli = cli_frames(tmp_path, pool, (40, 24), 6, 60, "--capture-pass", "Buffer A", "--mouse", "20,12",
                     "--define", "TOP_VIEW")
    with toyhost.Session(pool, size=(40, 24), fps=60, date=DATE, defines=["TOP_VIEW"]) as session:
        python = [image for _, image in session.render(6, pass_="Buffer A", mouse=(20, 12))]
    assert len(numpy.unique(python[-1].reshape(-1, 4), axis=0)) > 10, "a frame worth comparing"
    assert_same(cli, python)
