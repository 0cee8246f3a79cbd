"""toyhost.compare and compare_images: two shadertoys rendered with the same inputs and compared
frame by frame (tests/gl/compare/ differ in known ways: one constant, a divergence from iTime 0.25,
the mouse while held), problems raised as toyhost errors, and frames from sessions compared."""

import math

import numpy
import pytest

import toyhost
from support import DATE, SHARED_DIR, SOURCE_DIR, require_shared, run_cli

FIXTURES = SOURCE_DIR / "tests/gl/compare"
SMALL = dict(size=(40, 20), fps=10, date=DATE)  # frame n at iTime n / 10


def test_the_same_shadertoy_is_equal_on_every_frame():
    report = toyhost.compare(FIXTURES / "base", FIXTURES / "base", frames=6, **SMALL)
    assert isinstance(report, toyhost.CompareReport)
    assert report.equal and report.first_differing_frame is None
    assert (report.width, report.height, report.fps, report.pass_) == (40, 20, 10, "Image")
    assert [f.frame for f in report.frames] == list(range(6))
    assert all(math.isinf(f.psnr) and f.differing_pixels == 0 and f.first_x is None for f in report.frames)
    assert math.isinf(report.min_psnr) and report.max_diff == 0
    assert "equal" in str(report) and "inf" in str(report)
    # A notebook shows the repr: the one-line summary, not the dataclass of every frame (issue 45).
    assert repr(report) == f"<toyhost.CompareReport {report}>"


def test_a_divergence_is_found_at_its_frame_and_place():
    report = toyhost.compare(toyhost.load(FIXTURES / "base"), FIXTURES / "diverge", frames=6, keep_diff_images=True,
                             **SMALL)
    assert not report.equal
    assert report.first_differing_frame == 3, "iTime 0.3 is the first frame at or after 0.25"
    assert all(math.isinf(f.psnr) and f.diff_image is None for f in report.frames[:3])
    third = report.frames[3]
    assert math.isfinite(third.psnr) and not third.within_tolerance
    assert (third.first_x, third.first_y) == (0, 10), "the bottom half, rows counted from the top"
    assert third.differing_pixels == 40 * 10
    assert third.diff_image.shape == (20, 40, 4) and third.diff_image.dtype == numpy.uint8
    assert not third.diff_image[:10, :, :3].any() and third.diff_image[10:, :, 0].any()
    assert "first differs at frame 3" in str(report)
    stopped = toyhost.compare(FIXTURES / "base", FIXTURES / "diverge", frames=6, stop_at_first_difference=True, **SMALL)
    assert len(stopped.frames) == 4 and stopped.first_differing_frame == 3


def test_the_tolerance_decides_equality():
    assert toyhost.compare(FIXTURES / "base", FIXTURES / "constant", frames=1, max_diff=255, **SMALL).equal
    assert not toyhost.compare(FIXTURES / "base", FIXTURES / "constant", frames=1, min_psnr=11, **SMALL).equal
    assert toyhost.compare(FIXTURES / "base", FIXTURES / "constant", frames=1, min_psnr=10, **SMALL).equal


def test_both_get_the_same_mouse():
    assert toyhost.compare(FIXTURES / "base", FIXTURES / "mouse", frames=4, **SMALL).equal, "no input: the same"
    held = toyhost.compare(FIXTURES / "base", FIXTURES / "mouse", frames=4, mouse=(3, 4), **SMALL)
    assert held.first_differing_frame == 0, "pressed before frame 0, as the CLI's --mouse"
    scripted = toyhost.compare(FIXTURES / "base", FIXTURES / "mouse", frames=4, mouse_script=FIXTURES / "mouse-down.json",
                               **SMALL)
    assert scripted.first_differing_frame == 2


def test_the_report_is_the_clis(tmp_path):
    import json
    import subprocess

    from support import TOYHOST_BIN

    args = ["--size", "40x20", "--fps", "10", "--frames", "5", "--date", DATE, "--max-diff", "3", "--json"]
    done = subprocess.run([str(TOYHOST_BIN), "compare", str(FIXTURES / "base"), str(FIXTURES / "diverge"), *args],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, check=False)
    assert done.returncode == 1, done.stderr  # different
    cli = json.loads(done.stdout)
    report = toyhost.compare(FIXTURES / "base", FIXTURES / "diverge", frames=5, max_diff=3, **SMALL)
    assert report.first_differing_frame == cli["first_differing_frame"] == 3
    assert report.max_diff == cli["max_diff"] and math.isclose(report.min_psnr, cli["min_psnr"])
    for mine, theirs in zip(report.frames, cli["frames"], strict=True):
        assert mine.frame == theirs["frame"] and mine.within_tolerance == theirs["equal"]
        assert (mine.max_diff, mine.differing_pixels) == (theirs["max_diff"], theirs["differing_pixels"])
        assert math.isclose(mine.mean_diff, theirs["mean_diff"])
        assert (None if math.isinf(mine.psnr) else mine.psnr) == theirs["psnr"]
        pixel = theirs["first_differing_pixel"]
        assert (mine.first_x, mine.first_y) == ((pixel["x"], pixel["y"]) if pixel else (None, None))


def test_problems_raise_toyhost_errors():
    with pytest.raises(toyhost.CompileError) as raised:
        toyhost.compare(FIXTURES / "base", FIXTURES / "broken", frames=1, **SMALL)
    assert "broken" in raised.value.file
    with pytest.raises(toyhost.UsageError):
        toyhost.compare(FIXTURES / "base", FIXTURES / "base", frames=1, pass_="Buffer A", **SMALL)
    with pytest.raises(toyhost.UsageError):
        toyhost.compare(FIXTURES / "base", FIXTURES / "base", frames=0)
    with pytest.raises(toyhost.InputError):
        toyhost.compare(FIXTURES / "base", FIXTURES / "base", frames=1, mouse_script=FIXTURES / "no-such.json", **SMALL)


def test_frames_from_sessions_compare_as_compare_does():
    report = toyhost.compare(FIXTURES / "base", FIXTURES / "diverge", frames=5, **SMALL)
    with toyhost.Session(FIXTURES / "base", **SMALL) as a, toyhost.Session(FIXTURES / "diverge", **SMALL) as b:
        for n, ((_, frame_a), (_, frame_b)) in enumerate(zip(a.render(5), b.render(5))):
            d = toyhost.compare_images(frame_a, frame_b, diff_image=True)
            expected = report.frames[n]
            assert (d.psnr, d.max_diff, d.differing_pixels, d.first_x, d.first_y) == (
                expected.psnr, expected.max_diff, expected.differing_pixels, expected.first_x, expected.first_y), n
            assert d.diff_image.shape == (20, 40, 4), "asked for: made for every frame"
            assert d.diff_image[..., :3].any() == (not d.within_tolerance)
    same = toyhost.compare_images(frame_a, frame_a)
    assert math.isinf(same.psnr) and same.within_tolerance and same.diff_image is None
    with pytest.raises(toyhost.UsageError):
        toyhost.compare_images(frame_a, frame_a[:10])
    with pytest.raises(toyhost.UsageError):
        toyhost.compare_images(frame_a.astype(numpy.float32), frame_a)


def test_an_export_equals_its_imported_folder_and_a_changed_constant_does_not(tmp_path):
    # The acceptance, from Python: inf dB for an export against its imported folder, a
    # finite value with the first differing frame for a one-constant change.
    require_shared("shadertoys/MdXyzX/MdXyzX.json")
    export = SHARED_DIR / "shadertoys/MdXyzX/MdXyzX.json"
    port = tmp_path / "port"
    code, output = run_cli("import", export, port)
    assert code == 0, output
    ocean = dict(size=(48, 27), fps=30, date=DATE, frames=2)
    same = toyhost.compare(export, port, **ocean)
    assert same.equal and math.isinf(same.min_psnr), str(same)
    image = port / "image.glsl"
    code = image.read_text()
    changed = code.replace("0.04823", "0.04923", 1)
    assert changed != code, "the constant to change is in the ocean's code"
    image.write_text(changed)
    different = toyhost.compare(export, port, **ocean)
    assert not different.equal and math.isfinite(different.min_psnr)
    assert different.first_differing_frame == 0
