"""Session.set_channel and from_code's array channels: a numpy array shown in a channel as a texture
whose size and format follow the array. Each test renders a shader that copies the channel to its
output at the same size, so the frame must hold the array's own values (uint8 exactly; float32
exactly, through a float buffer), in the same orientation (top row first both ways)."""

import numpy
import pytest

import toyhost

SIZE = (24, 10)  # width, height: not square, so a transposed upload cannot pass
COPY = "void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel0, p / iResolution.xy); }\n"
FETCH = "void mainImage(out vec4 c, in vec2 p) { c = texelFetch(iChannel0, ivec2(p), 0); }\n"


def gradient(components, dtype=numpy.uint8):
    """A gradient different in every pixel and component: x in the first, y in the second, both in
    the third and a checker in the fourth."""
    height, width = SIZE[1], SIZE[0]
    y, x = numpy.mgrid[0:height, 0:width]
    planes = [x * 10 + 3, y * 25, (x * 7 + y * 13) % 256, ((x + y) % 2) * 200 + 40][:components]
    values = numpy.stack(planes, axis=-1).astype(dtype)
    return values[:, :, 0] if components == 1 else values


def shown_as_rgba8(array):
    """What the Image shows of a uint8 array: missing components are 0 (green, blue), as a
    one-channel texture samples (r, 0, 0, 1); alpha is 255, as the site's opaque canvas shows it
    (the array's alpha is checked through a buffer below)."""
    array = array if array.ndim == 3 else array[:, :, None]
    out = numpy.zeros(array.shape[:2] + (4,), numpy.uint8)
    out[:, :, :min(3, array.shape[2])] = array[:, :, :3]
    out[:, :, 3] = 255
    return out


@pytest.mark.parametrize("components", [1, 3, 4])
@pytest.mark.parametrize("shader", [COPY, FETCH], ids=["texture", "texelFetch"])
def test_a_uint8_array_shows_its_pixels(components, shader):
    pixels = gradient(components)
    with toyhost.Session(toyhost.from_code(shader), size=SIZE) as session:
        session.set_channel("Image", 0, pixels, filter="nearest")
        session.step()
        numpy.testing.assert_array_equal(session.frame(), shown_as_rgba8(pixels))


def test_a_uint8_arrays_alpha_reaches_a_buffer_as_its_level_over_255():
    pixels = gradient(4)
    shadertoy = toyhost.from_code("void mainImage(out vec4 c, in vec2 p) { c = vec4(0); }\n",
                                  buffers={"A": FETCH})
    with toyhost.Session(shadertoy, size=SIZE) as session:
        session.set_channel("Buffer A", 0, pixels)
        session.step()
        numpy.testing.assert_allclose(session.frame("Buffer A", dtype="float32"), pixels / 255.0, atol=1e-6)


@pytest.mark.parametrize("components", [1, 3, 4])
def test_a_float32_array_keeps_its_values_unclamped(components):
    pixels = (gradient(components, numpy.float32) - 100.0) / 7.0  # negatives, fractions, above 1
    buffer = "void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel0, p / iResolution.xy); }\n"
    shadertoy = toyhost.from_code("void mainImage(out vec4 c, in vec2 p) { c = vec4(0); }\n",
                                  buffers={"A": buffer})
    with toyhost.Session(shadertoy, size=SIZE) as session:
        session.set_channel("Buffer A", "iChannel0", pixels, filter="nearest")
        session.step()
        got = session.frame("Buffer A", dtype="float32")
    expected = numpy.zeros(got.shape, numpy.float32)
    expected[:, :, 3] = 1.0
    values = pixels if pixels.ndim == 3 else pixels[:, :, None]
    expected[:, :, :values.shape[2]] = values
    numpy.testing.assert_array_equal(got, expected)


def test_a_new_array_replaces_the_last_and_its_size_is_iChannelResolution():
    probe = ("void mainImage(out vec4 c, in vec2 p) {\n"
             "    c = vec4(iChannelResolution[0].xy, texelFetch(iChannel0, ivec2(0), 0).r, iChannelResolution[1].x);\n"
             "}\n")
    shadertoy = toyhost.from_code("void mainImage(out vec4 c, in vec2 p) { c = vec4(0); }\n", buffers={"A": probe})
    with toyhost.Session(shadertoy, size=(4, 4)) as session:
        session.step()  # unbound: iChannelResolution 0, texelFetch of nothing
        assert session.frame("Buffer A", dtype="float32")[0, 0, :2].tolist() == [0.0, 0.0]
        session.set_channel("Buffer A", 0, numpy.full((3, 5), 0.5, numpy.float32))
        session.step()
        assert session.frame("Buffer A", dtype="float32")[0, 0, :3].tolist() == [5.0, 3.0, 0.5]
        session.set_channel("Buffer A", 0, numpy.full((7, 2, 4), 51, numpy.uint8))  # new size and type
        session.step()
        numpy.testing.assert_allclose(session.frame("Buffer A", dtype="float32")[0, 0], [2.0, 7.0, 0.2, 0.0], atol=1e-6)
        session.restart()  # inputs stay through a restart
        session.step()
        numpy.testing.assert_allclose(session.frame("Buffer A", dtype="float32")[0, 0], [2.0, 7.0, 0.2, 0.0], atol=1e-6)
        session.resize((6, 5))  # and through a resize
        session.step()
        numpy.testing.assert_allclose(session.frame("Buffer A", dtype="float32")[0, 0], [2.0, 7.0, 0.2, 0.0], atol=1e-6)


def test_linear_filtering_and_repeat_follow_the_array():
    # Two texels, 0 and 255, drawn across 8 pixels: linear clamp ramps between them, nearest steps.
    pixels = numpy.array([[[0], [255]]], numpy.uint8)
    with toyhost.Session(toyhost.from_code(COPY), size=(8, 1)) as session:
        session.set_channel("Image", 0, pixels, filter="linear")
        session.step()
        linear = session.frame()[0, :, 0].astype(int)
        session.set_channel("Image", 0, pixels, filter="nearest")
        session.step()
        nearest = session.frame()[0, :, 0].astype(int)
    # u = (i + 0.5) / 8 of a 2-texel texture: texel coordinate 2u - 0.5, clamped to the edges.
    expected = [round(255 * min(1.0, max(0.0, 2 * (i + 0.5) / 8 - 0.5))) for i in range(8)]
    assert numpy.abs(linear - numpy.array(expected)).max() <= 1, linear
    assert nearest.tolist() == [0, 0, 0, 0, 255, 255, 255, 255]
    # Repeat: the Image samples u in 0..2, so the two texels show twice.
    twice = "void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel0, 2.0 * p / iResolution.xy); }\n"
    with toyhost.Session(toyhost.from_code(twice), size=(8, 1)) as session:
        session.set_channel("Image", 0, pixels, filter="nearest", wrap="repeat")
        session.step()
        assert session.frame()[0, :, 0].tolist() == [0, 0, 255, 255, 0, 0, 255, 255]


def test_mipmap_filtering_of_a_uint8_array_averages_it():
    # A 16x16 checker of 0 and 255, drawn into 1x1: the mipmapped sample is the average (~128), not
    # one texel.
    y, x = numpy.mgrid[0:16, 0:16]
    checker = (((x + y) % 2) * 255).astype(numpy.uint8)
    with toyhost.Session(toyhost.from_code(COPY), size=(1, 1)) as session:
        session.set_channel("Image", 0, checker, filter="mipmap")
        session.step()
        assert abs(int(session.frame()[0, 0, 0]) - 128) <= 2


def test_from_code_takes_arrays_as_channels_and_every_session_shows_them():
    pixels = gradient(4)
    shadertoy = toyhost.from_code(FETCH, channels={"Image": {0: pixels}})
    for _ in range(2):
        with toyhost.Session(shadertoy, size=SIZE) as session:
            session.step()
            numpy.testing.assert_array_equal(session.frame(), shown_as_rgba8(pixels))


def test_a_non_contiguous_array_is_shown_as_its_values():
    pixels = gradient(4)
    flipped = pixels[::-1]  # a view with negative strides
    with toyhost.Session(toyhost.from_code(FETCH), size=SIZE) as session:
        session.set_channel("Image", 0, flipped)
        session.step()
        numpy.testing.assert_array_equal(session.frame(), shown_as_rgba8(flipped))


def test_an_array_too_large_is_refused_before_any_copy():
    """Once a defect (issue 46): a 20000x20000 view of one pixel (zero strides: 4 bytes of memory) was
    first made contiguous, 1.49 GiB, and only then refused. Its shape is checked first: refused at
    once, with no copy (tracemalloc sees numpy's allocations)."""
    import tracemalloc

    view = numpy.lib.stride_tricks.as_strided(numpy.zeros(4, numpy.uint8), (20000, 20000, 4), (0, 0, 1))
    with toyhost.Session(toyhost.from_code(FETCH), size=(4, 4)) as session:
        tracemalloc.start()
        try:
            with pytest.raises(toyhost.UsageError) as raised:
                session.set_channel("Image", 0, view)
            _, peak = tracemalloc.get_traced_memory()
        finally:
            tracemalloc.stop()
        assert "array: shape (20000, 20000, 4): at most 16384 pixels a side" in str(raised.value)
        assert peak < 64 << 20, f"{peak} bytes allocated before the refusal"


def test_refusals_name_the_parameter_pass_and_channel():
    shadertoy = toyhost.from_code(COPY, buffers={"A": COPY}, channels={"Image": {1: "A"}})
    with toyhost.Session(shadertoy, size=(4, 4)) as session:
        cases = [
            (dict(pass_="Image", channel=1, array=numpy.zeros((2, 2), numpy.uint8)), "Image iChannel1: cannot show"),
            (dict(pass_="Buffer C", channel=0, array=numpy.zeros((2, 2), numpy.uint8)), "no pass \"Buffer C\""),
            (dict(pass_="Image", channel=4, array=numpy.zeros((2, 2), numpy.uint8)), "channel: 4 is out of range"),
            (dict(pass_="Image", channel=0, array=numpy.zeros((2, 2), numpy.int64)), "array: dtype int64"),
            (dict(pass_="Image", channel=0, array=numpy.zeros((2, 2, 2), numpy.uint8)), "array: shape (2, 2, 2)"),
            (dict(pass_="Image", channel=0, array=numpy.zeros((0, 2), numpy.uint8)), "has no pixels"),
            (dict(pass_="Image", channel=0, array="pixels"), "array: expected a numpy array"),
            # Once bare ValueErrors (issue 46): "²".isdigit() is true, but int("²") fails.
            (dict(pass_="Image", channel="iChannel\u00b2", array=numpy.zeros((2, 2), numpy.uint8)),
             "channel: expected 0..3 or"),
            (dict(pass_="Image", channel="iChannel", array=numpy.zeros((2, 2), numpy.uint8)), "channel: expected 0..3"),
            (dict(pass_="Image", channel=0, array=numpy.zeros((2, 2), numpy.float32), filter="mipmap"),
             "mipmap filtering takes uint8 arrays"),
            (dict(pass_="Image", channel=0, array=numpy.zeros((2, 2), numpy.uint8), wrap="mirror"), "wrap: must be"),
        ]
        for arguments, words in cases:
            with pytest.raises(toyhost.UsageError) as raised:
                session.set_channel(**arguments)
            assert words in str(raised.value), (arguments, str(raised.value))
        # Nothing refused reached the channels: the Image still shows the (unbound) channel 0.
        session.step()
        assert session.frame()[0, 0].tolist() == [0, 0, 0, 255]


def test_an_array_stays_through_reloads_that_keep_its_channel_and_goes_with_one_that_binds_it(tmp_path):
    from support import write_shadertoy

    pixels = gradient(3)
    folder = write_shadertoy(tmp_path / "toy", {"Image": FETCH})
    with toyhost.Session(folder, size=SIZE) as session:
        session.set_channel("Image", 0, pixels)
        session.step()
        numpy.testing.assert_array_equal(session.frame(), shown_as_rgba8(pixels))
        # New code, same structure: recompiled, the array stays.
        write_shadertoy(folder, {"Image": FETCH.replace("c = ", "c = 0.0 + ")})
        assert session.reload().recompiled == ["Image"]
        session.step()
        numpy.testing.assert_array_equal(session.frame(), shown_as_rgba8(pixels))
        # A new structure (a buffer added) that keeps Image's channel 0 unbound: the array stays.
        write_shadertoy(folder, {"Buffer A": "void mainImage(out vec4 c, in vec2 p) { c = vec4(1); }\n",
                                 "Image": FETCH})
        assert session.reload().structure_changed
        session.step()
        numpy.testing.assert_array_equal(session.frame(), shown_as_rgba8(pixels))
        # Channel 0 now bound to the buffer: the buffer shows, the array is dropped.
        write_shadertoy(folder, {"Buffer A": "void mainImage(out vec4 c, in vec2 p) { c = vec4(1); }\n",
                                 "Image": (FETCH, {"iChannel0": {"buffer": "A"}})})
        assert session.reload().structure_changed
        session.step()
        assert (session.frame() == 255).all()
