"""Session.seek: the frames after a seek are byte for byte those of a session that stepped there,
for a shadertoy with buffers and a mouse script, one with Cube A only, one without either (its
mouse script's events still reach it) and one whose Image discards; a seek backwards is refused.
render(every=) counts on iFrame, so a render after a seek hands over the frames a render from
frame 0 would. Small canvases: everything runs on llvmpipe."""

import numpy
import pytest

import toyhost
from support import DATE, SOURCE_DIR, write_shadertoy

POOL = SOURCE_DIR / "shadertoys" / "ripple-pool"
DRAG = POOL / "drag.json"

# No buffers: iFrame, iTime and iMouse (the drag's position and button) as colours.
CLOCK = {"Image": ("void mainImage(out vec4 c, in vec2 f) {\n"
                   "    c = vec4(mod(float(iFrame), 256.0) / 255.0, fract(iTime), iMouse.x / 400.0,\n"
                   "             iMouse.z > 0.0 ? 1.0 : 0.5);\n"
                   "}\n")}

# Cube A only: its alpha counts frames in its own previous frame; Image shows the count.
CUBE_COUNTER = {
    "Cube A": ("void mainCubemap(out vec4 c, in vec2 f, in vec3 ro, in vec3 rd) {\n"
               "    c = vec4(0.0, 0.0, 0.0, texture(iChannel0, rd).a + 1.0);\n"
               "}\n", {"iChannel0": {"buffer": "Cube A", "filter": "nearest"}}),
    "Image": ("void mainImage(out vec4 c, in vec2 f) {\n"
              "    c = vec4(mod(texture(iChannel0, vec3(1.0, 0.0, 0.0)).a, 256.0) / 255.0, 0.0, 0.0, 1.0);\n"
              "}\n", {"iChannel0": {"buffer": "Cube A", "filter": "nearest"}}),
}

# No buffers, but Image discards the left columns after frame 1: they keep frame 1's pixels, as
# the site's preserved canvas does, so the frames a seek passes must still draw Image.
DISCARD = {"Image": ("void mainImage(out vec4 c, in vec2 f) {\n"
                     "    if (f.x < 4.0 && iFrame > 1) discard;\n"
                     "    c = vec4(mod(float(iFrame), 256.0) / 255.0, 0.25, 0.5, 1.0);\n"
                     "}\n")}


def stepped(path, target, frames, **options):
    """Frames target .. target + frames - 1 of a session that stepped (rendering every pass) there."""
    with toyhost.Session(toyhost.load(path), **options) as session:
        for _ in range(target):
            session.step()
        return list(session.render(frames))


def sought(path, target, frames, **options):
    with toyhost.Session(toyhost.load(path), **options) as session:
        session.seek(target)
        assert session.next_frame == target
        return list(session.render(frames))


def cube_count(image):
    return image[0, 0, 0]  # Cube A's frame count, as Image shows it


def left_columns(image):
    return set(image[:, :4, 0].ravel())  # what frame 1 drew there: iFrame 1


@pytest.mark.parametrize("passes, target, options, check", [
    (None, 9, {"mouse_script": DRAG}, None),
    (CLOCK, 9, {"mouse_script": DRAG}, None),
    (CUBE_COUNTER, 5, {}, lambda image: cube_count(image) == 6),
    (DISCARD, 6, {}, lambda image: left_columns(image) == {1}),
], ids=["buffers", "no-buffers", "cube-a", "image-discards"])
def test_the_frames_after_a_seek_are_those_of_a_session_that_stepped_there(tmp_path, passes, target, options, check):
    path = POOL if passes is None else write_shadertoy(tmp_path / "toy", passes)
    options = dict(size=(32, 18), date=DATE, **options)
    expected = stepped(path, target, 3, **options)
    got = sought(path, target, 3, **options)
    assert [i for i, _ in got] == [i for i, _ in expected] == [target, target + 1, target + 2]
    for (i, a), (_, b) in zip(got, expected):
        assert numpy.array_equal(a, b), f"frame {i} after seek({target}) differs from stepping there"
    if check is not None:  # the past the seek simulated shows in the frame (frame 0 counts 1)
        assert check(got[0][1]), f"frame {target}: {got[0][1][0, :6, 0]}"


def test_a_seek_backwards_is_refused_and_a_seek_to_the_next_frame_does_nothing():
    with toyhost.Session(POOL, size=(16, 8), date=DATE) as session:
        session.seek(4)
        session.seek(4)
        assert session.next_frame == 4
        with pytest.raises(toyhost.UsageError, match="before the next frame"):
            session.seek(3)
        assert session.next_frame == 4
        with pytest.raises(toyhost.UsageError):
            session.seek(2**40)
        with pytest.raises(toyhost.UsageError):
            session.seek("5")
        session.restart()
        session.seek(2)
        assert session.next_frame == 2


def test_render_counts_every_on_iframe(tmp_path):
    clock = write_shadertoy(tmp_path / "clock", CLOCK)
    with toyhost.Session(clock, size=(16, 8), date=DATE) as session:
        assert [i for i, _ in session.render(7, every=3)] == [0, 3, 6]
        assert [i for i, _ in session.render(5, every=3)] == [9, 11], "from iFrame 7: 9, and the last (11)"
        session.seek(100)
        yielded = list(session.render(70, every=30))
        assert [i for i, _ in yielded] == [120, 150, 169]
        for i, image in yielded:
            assert image[0, 0, 0] == i % 256, "each array is its iFrame's"
        assert [i for i, _ in session.render(3, every=10)] == [170, 172], "a multiple, then the last"
