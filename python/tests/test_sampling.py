"""Supersampling and motion blur from Python: Session(supersample=, motion_blur=, shutter=,
dither=, shutter_offset=, sample_space=) gives the CLI's frames byte for byte (its --out - raw stream), the options change the
picture (the comparison can fail), and a value out of range is refused naming the setting. The
arithmetic checks (box average, shutter average) are tests/gl/test_sampling.cpp's."""

import subprocess

import numpy
import pytest

import toyhost
from support import DATE, SOURCE_DIR, TOYHOST_BIN as TOYHOST

PROBE = SOURCE_DIR / "shadertoys/sampling-probe"
SIZE = (40, 24)


def cli_frames(*flags):
    raw = subprocess.run([str(TOYHOST), "run", str(PROBE), "--headless", "--quiet", "--size", "40x24", "--frames",
                          "3", "--fps", "4", "--date", DATE, "--out", "-", *flags],
                         check=True, capture_output=True).stdout
    return numpy.frombuffer(raw, numpy.uint8).reshape(3, SIZE[1], SIZE[0], 4)


def session_frames(**sampling):
    with toyhost.Session(PROBE, size=SIZE, fps=4, date=DATE, **sampling) as session:
        return numpy.stack([image for _, image in session.render(3)])


def test_sampled_frames_equal_the_clis():
    cli = cli_frames("--supersample", "3", "--motion-blur", "2", "--shutter", "270", "--dither")
    ours = session_frames(supersample=3, motion_blur=2, shutter=270, dither=True)
    assert numpy.array_equal(ours, cli)
    assert not numpy.array_equal(ours, session_frames()), "the options change the picture"


def test_the_shutter_offset_and_sample_space_equal_the_clis():
    cli = cli_frames("--supersample", "2", "--motion-blur", "3", "--shutter-offset", "centre", "--sample-space",
                     "display")
    ours = session_frames(supersample=2, motion_blur=3, shutter_offset="centre", sample_space="display")
    assert numpy.array_equal(ours, cli)
    assert not numpy.array_equal(ours, session_frames(supersample=2, motion_blur=3)), "the options change the picture"


def test_one_sample_is_the_default_picture():
    assert numpy.array_equal(session_frames(supersample=1, motion_blur=1), session_frames())


@pytest.mark.parametrize("keyword, value, setting", [("supersample", 0, "supersample"),
                                                     ("motion_blur", 300, "motion_blur"),
                                                     ("shutter", 0, "shutter"),
                                                     ("dither", True, "dither")])
def test_out_of_range_is_refused_naming_the_setting(keyword, value, setting):
    with pytest.raises(toyhost.UsageError) as raised:
        toyhost.Session(PROBE, size=SIZE, **{keyword: value})
    assert setting in str(raised.value)
