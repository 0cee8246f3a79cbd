"""Session.record(): frames written through toyhost's own encoders, as the CLI's --out writes them:
PNG files byte for byte, a video with the same decoded frames; numbered from 0, every-th and the
last; checked as --out is; nothing half written left behind."""

import subprocess

import numpy
import pytest

import toyhost
from support import DATE, SOURCE_DIR, run_cli

TOY = SOURCE_DIR / "shadertoys/uniform-probe"  # buffers, feedback, textures: every frame differs
SIZE = (40, 24)


def cli(tmp_path, out, frames, *extra):
    code, output = run_cli("run", TOY, "--size", f"{SIZE[0]}x{SIZE[1]}", "--frames", frames, "--fps", 30,
                           "--date", DATE, "--quiet", "--out", out, *extra)
    assert code == 0, output


def test_png_files_equal_the_clis_byte_for_byte(tmp_path):
    (tmp_path / "cli").mkdir()
    (tmp_path / "py").mkdir()
    cli(tmp_path, tmp_path / "cli/f_%04d.png", 7, "--capture-every", 3)
    with toyhost.Session(TOY, size=SIZE, fps=30, date=DATE) as session:
        written = session.record(tmp_path / "py/f_%04d.png", 7, every=3)
        assert session.next_frame == 7
        last = session.frame()
    assert [p.name for p in written] == ["f_0000.png", "f_0003.png", "f_0006.png"]
    assert sorted(p.name for p in (tmp_path / "cli").iterdir()) == [p.name for p in written]
    for path in written:
        assert path.read_bytes() == (tmp_path / "cli" / path.name).read_bytes(), path.name
    from support import read_png
    assert (read_png(written[-1]) == last).all()


def decoded(path):
    done = subprocess.run(["ffmpeg", "-v", "error", "-i", str(path), "-f", "rawvideo", "-pix_fmt", "rgb24", "-"],
                          capture_output=True, check=True)
    return numpy.frombuffer(done.stdout, numpy.uint8)


def test_a_video_decodes_to_the_clis_frames(tmp_path):
    cli(tmp_path, tmp_path / "cli.mp4", 6)
    with toyhost.Session(TOY, size=SIZE, fps=30, date=DATE) as session:
        [video] = session.record(tmp_path / "py.mp4", 6)
    assert video == tmp_path / "py.mp4"
    expected = decoded(tmp_path / "cli.mp4")
    assert expected.size == SIZE[0] * SIZE[1] * 3 * 6
    assert (decoded(video) == expected).all()


def test_bad_requests_are_refused_and_leave_nothing(tmp_path):
    with toyhost.Session(TOY, size=SIZE, fps=30, date=DATE) as session:
        with pytest.raises(toyhost.UsageError) as raised:
            session.record(tmp_path / "one.png", 3)  # three frames, one file name
        assert "frame number placeholder" in str(raised.value)
        # The message names the parameter given, not the CLI's flag.
        assert f"out: {tmp_path / 'one.png'}: " in str(raised.value) and "--out" not in str(raised.value)
        assert raised.value.field == "out"
        with pytest.raises(toyhost.UsageError):
            session.record(tmp_path / "f_%04d.png", 0)
        with pytest.raises(toyhost.UsageError):
            session.record(tmp_path / "f_%04d.png", 2, pass_="Buffer Z")
        with pytest.raises(toyhost.UsageError):
            session.record("-", 1)
        assert session.next_frame == 0, "nothing rendered"
        assert list(tmp_path.iterdir()) == []
        # and the session still records afterwards, from where it is
        session.step()
        written = session.record(tmp_path / "g_%02d.png", 2)
        assert [p.name for p in written] == ["g_00.png", "g_01.png"]
