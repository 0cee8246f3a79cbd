"""toyhost.Session: frames as numpy arrays of the right shape, type and row order; the mouse and
keys reach the shader as on the site; render() yields the frames the CLI would capture."""

import numpy
import pytest

import toyhost
from support import DATE, SOURCE_DIR, egl_device_platform_absence, write_shadertoy

# Top half red, bottom half blue; Buffer A holds an unclamped float (2.5) and iFrame.
ROWS = {
    "Buffer A": "void mainImage(out vec4 c, in vec2 p) { c = vec4(2.5, -1.0, float(iFrame), 0.125); }\n",
    "Image": ("void mainImage(out vec4 c, in vec2 p) {\n"
              "    c = p.y > iResolution.y * 0.5 ? vec4(1, 0, 0, 1) : vec4(0, 0, 1, 1);\n"
              "}\n"),
}


@pytest.fixture(scope="module")
def rows(tmp_path_factory):
    return toyhost.load(write_shadertoy(tmp_path_factory.mktemp("rows") / "rows", ROWS))


@pytest.fixture(scope="module")
def probe():
    return toyhost.load(SOURCE_DIR / "shadertoys/window-probe")


def test_frames_are_height_width_rgba_with_the_top_row_first(rows):
    with toyhost.Session(rows, size=(16, 8)) as session:
        assert session.size == (16, 8)
        assert session.step() == 0
        image = session.frame()
        assert image.shape == (8, 16, 4) and image.dtype == numpy.uint8
        assert (image[0] == [255, 0, 0, 255]).all(), "row 0 is the top of the canvas (red)"
        assert (image[-1] == [0, 0, 255, 255]).all()
        levels = session.frame(dtype="float32")
        assert levels.shape == (8, 16, 4) and levels.dtype == numpy.float32
        assert numpy.array_equal(levels, image.astype(numpy.float32) / 255), "Image's floats are its 8-bit levels"
        assert session.frame(dtype=numpy.float32).dtype == numpy.float32
        reused = numpy.zeros((8, 16, 4), numpy.uint8)
        assert session.frame(out=reused) is reused and numpy.array_equal(reused, image)
        floats = numpy.zeros((8, 16, 4), numpy.float32)
        assert numpy.array_equal(session.frame(dtype="float32", out=floats), levels)
        for wrong in (numpy.zeros((8, 16, 3), numpy.uint8), numpy.zeros((8, 16, 4), numpy.float32),
                      numpy.zeros((16, 8, 4), numpy.uint8), numpy.zeros((8, 32, 4), numpy.uint8)[:, ::2]):
            with pytest.raises(toyhost.UsageError):
                session.frame(out=wrong)


def test_a_buffer_reads_as_its_floats_or_clamped_bytes(rows):
    with toyhost.Session(rows, size=(4, 2)) as session:
        for _ in range(3):
            session.step()
        floats = session.frame("Buffer A", "float32")
        assert (floats[..., 0] == 2.5).all() and (floats[..., 1] == -1.0).all()
        assert (floats[..., 2] == 2.0).all(), "iFrame of the latest frame"
        assert (floats[..., 3] == 0.125).all()
        assert (session.frame("Buffer A")[0, 0] == [255, 0, 255, 32]).all(), "clamped and rounded"


def test_the_default_size_and_a_float_image(rows):
    with toyhost.Session(rows, float_image=True) as session:
        assert session.size == (800, 450)
        assert session.fps == 60
        session.step()
        assert session.frame(dtype="float32").shape == (450, 800, 4)


def test_bad_reads_raise_usage_errors(rows):
    session = toyhost.Session(rows, size=(4, 2))
    session.step()
    with pytest.raises(toyhost.UsageError) as raised:
        session.frame("Buffer C")
    assert raised.value.code == "usage" and "Buffer C" in str(raised.value)
    with pytest.raises(toyhost.UsageError):
        session.frame(dtype="int16")
    with pytest.raises(toyhost.UsageError):
        toyhost.Session(rows, size=(4, 2), date="yesterday")
    with pytest.raises(toyhost.UsageError):
        toyhost.Session(rows, size=(0, 2))
    for fps in (0, -30, float("nan"), 1e9):
        with pytest.raises(toyhost.UsageError):
            toyhost.Session(rows, size=(4, 2), fps=fps)
    # None is "the default"; a value given is checked by the library, which names the setting.
    for settings, setting in (({"size": (0, 0)}, "size"), ({"fps": 0}, "fps"), ({"date": ""}, "date"),
                              ({"frame_timeout": 0.01}, "frame_timeout")):
        with pytest.raises(toyhost.UsageError) as raised:
            toyhost.Session(rows, **settings)
        assert [d.field for d in raised.value.diagnostics] == [setting], str(raised.value)
    with toyhost.Session(rows, size=(4, 2), fps=None, date=None, frame_timeout=None, compile_timeout=None,
                         mouse_script=None, key_script=None) as defaults:
        defaults.step()
    session.close()
    assert session.closed
    with pytest.raises(toyhost.UsageError):
        session.step()
    session.close()  # twice is fine


def column(image, x):
    """The probe's value in pixel column x (the same on every row)."""
    return tuple(int(v) for v in image[0, x, :3])


def test_the_mouse_follows_the_sites_rules(probe):
    with toyhost.Session(probe, size=(64, 32), date=DATE) as session:
        session.step()
        assert column(session.frame(), 0) == (0, 0, 0), "no click yet"
        session.step(mouse=(10, 20))
        image = session.frame()
        assert column(image, 0) == (10, 20, 10), "xy and |z| at the click"
        assert column(image, 1) == (20, 255, 255), "|w|, z > 0 (held), w > 0 (the click's frame)"
        session.step(mouse=(30, 5))
        image = session.frame()
        assert column(image, 0) == (30, 5, 10), "a drag moves xy only"
        assert column(image, 1) == (20, 255, 0), "w < 0 after the click's frame"
        session.step(mouse=False)
        image = session.frame()
        assert column(image, 0) == (30, 5, 10)
        assert column(image, 1) == (20, 0, 0), "z < 0 after release"
        session.step(mouse=(40, 7))
        assert column(session.frame(), 0) == (40, 7, 40), "a new click"


def test_keys_held_pressed_and_toggled(probe):
    with toyhost.Session(probe, size=(64, 32), date=DATE) as session:
        session.step(keys={"a"})
        assert column(session.frame(), 2) == (255, 255, 255), "A held, went down, toggled on"
        session.step(keys=["A", "Space"])
        image = session.frame()
        assert column(image, 2) == (255, 0, 255), "still held: not down this frame"
        assert column(image, 3)[2] == 255, "Space held"
        session.step()
        assert column(session.frame(), 2) == (255, 0, 255), "keys=None keeps them held"
        session.step(keys=())
        image = session.frame()
        assert column(image, 2) == (0, 0, 255), "released; the toggle stays"
        assert column(image, 3)[2] == 0
        session.step(keys=65)
        assert column(session.frame(), 2) == (255, 255, 0), "a second press toggles off"
        session.step(keys=[], events=[toyhost.InputEvent.key_down(32)])
        assert column(session.frame(), 3)[2] == 255, "events as data"
    with pytest.raises(ValueError):
        toyhost.key_code("NoSuchKey")
    assert toyhost.key_code("Left") == 37 and toyhost.key_code(";") == 186 and toyhost.key_code("F5") == 116


def test_render_yields_the_frames_the_cli_captures(probe):
    with toyhost.Session(probe, size=(32, 16), date=DATE) as session:
        yielded = list(session.render(10, every=4))
        assert [index for index, _ in yielded] == [0, 4, 8, 9], "0, every 4th, and the last"
        for index, image in yielded:
            assert image.shape == (16, 32, 4)
            assert column(image, 3)[1] == index, "the array is that frame's (iFrame in column 3)"
        assert session.next_frame == 10
        more = list(session.render(3, mouse=(5, 6)))
        assert [index for index, _ in more] == [10, 11, 12]
        assert column(more[0][1], 0) == (5, 6, 5)
        buffers = list(session.render(2, pass_="Buffer A", dtype="float32"))
        assert buffers[-1][1].dtype == numpy.float32 and buffers[-1][1][0, 0, 0] == 15.0, "frames counted in Buffer A"
        with pytest.raises(toyhost.UsageError):
            list(session.render(3, every=0))
        with pytest.raises(toyhost.UsageError):
            list(session.render(3, pass_="Buffer B"))
        assert session.next_frame == 15, "nothing rendered for a pass that does not exist"


def test_render_runs_ahead_of_the_loop_and_stops_when_left(probe):
    with toyhost.Session(probe, size=(32, 16), date=DATE) as session:
        for index, image in session.render(100):
            assert column(image, 3)[1] == index, "each array is its own frame's, while later ones render"
            if index == 3:
                break
        ahead = session.next_frame
        assert 4 <= ahead <= 4 + 7, f"at most 7 frames (4 ready, 3 being read) rendered past the last one yielded, not {ahead - 4}"
        more = list(session.render(2))
        assert [index for index, _ in more] == [ahead, ahead + 1], "the next render goes on from there"
        assert column(more[1][1], 3)[1] == ahead + 1
        session.step()
        assert column(session.frame(), 3)[1] == ahead + 2, "no read of the render was left queued"
    # Closing the session while a render is under way ends it with an error, not a hang.
    session = toyhost.Session(probe, size=(32, 16), date=DATE)
    frames = session.render(1000)
    assert next(frames)[0] == 0
    session.close()
    with pytest.raises(toyhost.UsageError, match="closed"):
        next(frames)


def test_time_restart_and_resize(tmp_path):
    clock = write_shadertoy(tmp_path / "clock", {"Image": (
        "void mainImage(out vec4 c, in vec2 p) {\n"
        "    c = vec4(fract(iTime), iTimeDelta * 10.0, iFrameRate / 255.0, 1);\n"
        "}\n")})
    with toyhost.Session(toyhost.load(clock), size=(8, 4), fps=20, start_time=0.15) as session:
        session.step()
        session.step()
        assert tuple(session.frame()[0, 0, :3]) == (51, 128, 20), "iTime 0.2, iTimeDelta 1/20, iFrameRate 20"
        session.step(time=0.5, time_delta=0.1, frame_rate=51)
        assert tuple(session.frame()[0, 0, :3]) == (128, 255, 51)
        session.restart()
        assert session.next_frame == 0
        session.resize((6, 3))
        session.step()
        assert session.frame().shape == (3, 6, 4) and session.size == (6, 3)


def test_notices_are_diagnostics(tmp_path):
    stand_in = write_shadertoy(tmp_path / "standin", {"Image": (
        "void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel0, p / iResolution.xy); }\n",
        {"iChannel0": {"media": "/media/a/3083c722c0c738cad0f468383167a0d246f91af2bfa373e9c5c094fb8c8413e0.png"}})})
    with toyhost.Session(toyhost.load(stand_in), size=(8, 4)) as session:
        session.step()
        notices = session.notices
        assert notices and all(isinstance(n, toyhost.Diagnostic) for n in notices)
        assert any(n.code.startswith("media.") for n in notices), [str(n) for n in notices]
        assert all(n.severity in ("notice", "warning") for n in notices)
        assert len({str(n) for n in notices}) == len(notices), "each said once"


def test_notices_from_loading_are_the_sessions_too():
    import json
    # A channel reading a buffer the export does not define: left unbound, with a notice.
    code = "void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel0, p / iResolution.xy); }\n"
    text = json.dumps({"Shader": {"info": {"id": "n", "name": "N"}, "renderpass": [
        {"inputs": [{"id": 257, "channel": 0, "type": "buffer"}], "outputs": [{"id": 37, "channel": 0}],
         "code": code, "name": "Image", "type": "image"}]}})
    shadertoy = toyhost.load(text)
    assert shadertoy.notices, "the unbound channel is said when loading"
    with toyhost.Session(shadertoy, size=(8, 4)) as session:
        session.step()
        said = [str(n) for n in session.notices]
        for notice in shadertoy.notices:
            assert said.count(str(notice)) == 1, said


def test_reload_recompiles_without_restarting(tmp_path):
    counter = "void mainImage(out vec4 c, in vec2 p) { c = texelFetch(iChannel0, ivec2(0), 0) + vec4(1, 0, 0, 0); }\n"
    folder = write_shadertoy(tmp_path / "edit", {
        "Buffer A": (counter, {"iChannel0": {"buffer": "A"}}),
        "Image": ("void mainImage(out vec4 c, in vec2 p) {\n"
                  "    c = vec4(texelFetch(iChannel0, ivec2(0), 0).x / 255.0, 0.2, 0, 1);\n"
                  "}\n", {"iChannel0": {"buffer": "A"}})})
    with toyhost.Session(folder, size=(4, 2)) as session:
        for _ in range(3):
            session.step()
        assert tuple(session.frame()[0, 0, :2]) == (3, 51)
        (folder / "image.glsl").write_text((folder / "image.glsl").read_text().replace("0.2", "0.4"))
        outcome = session.reload()
        assert isinstance(outcome, toyhost.Reloaded)
        assert outcome.applied and outcome.recompiled == ["Image"] and not outcome.problems
        session.step()
        assert tuple(session.frame()[0, 0, :2]) == (4, 102), "the counter went on; the new code runs"
        (folder / "image.glsl").write_text("void mainImage(out vec4 c, in vec2 p) { c = oops; }\n")
        broken = session.reload()
        assert broken.problems and broken.problems[0].code == "shader.compile", broken
        assert broken.problems[0].pass_ == "Image"
        session.step()
        assert tuple(session.frame()[0, 0, :2]) == (5, 102), "the last good program runs"


def test_toyhost_egl_platform_chooses_the_platform_as_for_the_cli(rows, monkeypatch):
    monkeypatch.setenv("TOYHOST_EGL_PLATFORM", "wayland")
    with pytest.raises(toyhost.UsageError, match="TOYHOST_EGL_PLATFORM=wayland"):
        toyhost.Session(rows, size=(16, 8))
    monkeypatch.setenv("TOYHOST_EGL_PLATFORM", "surfaceless")
    with toyhost.Session(rows, size=(16, 8)) as session:
        assert session.backend.startswith("EGL surfaceless;"), session.backend
    # Skipped only where the device platform is absent (support.egl_device_platform_absence says
    # exactly when); where EGL lists a device, a session that does not start there fails.
    absent = egl_device_platform_absence()
    if absent:
        pytest.skip(absent)
    monkeypatch.setenv("TOYHOST_EGL_PLATFORM", "device")
    with toyhost.Session(rows, size=(16, 8)) as session:
        assert session.backend.startswith("EGL device"), session.backend
        session.step()
        assert session.frame()[0, 0].tolist() == [255, 0, 0, 255], "it renders there too"


def test_step_then_frame_gives_each_frames_own_picture_whatever_comes_between(probe):
    """frame() shows the session as it is after whatever came between (iFrame in column 3's green,
    the canvas's size), and each array is the caller's own."""
    with toyhost.Session(probe, size=(32, 16), date=DATE) as session:
        for index in range(4):
            assert session.step() == index
            image = session.frame()
            assert column(image, 3)[1] == index
            image[:] = 0  # the caller's array: changing it changes nothing kept
        assert column(session.frame(), 3)[1] == 3, "a second frame() reads again"
        session.step()
        session.step()  # a step whose frame was not read
        assert column(session.frame(), 3)[1] == 5
        session.step()
        assert column(session.frame("Image"), 3)[1] == 6
        session.step()
        assert session.frame("Buffer A", dtype="float32")[0, 0, 0] == 8.0, "another pass"
        assert column(session.frame(), 3)[1] == 7
        session.step()
        session.frame()
        session.step()
        session.resize((24, 8))
        resized = session.frame()
        assert resized.shape == (8, 24, 4), "the new canvas"
        session.step()
        session.frame()
        session.step()
        frames = list(session.render(1))
        assert [index for index, _ in frames] == [12]
        assert column(session.frame(), 3)[1] == 12, "render()'s last frame"
        session.step()
        session.frame()
        session.step()
        session.restart()
        assert column(session.frame(), 3)[1] == 14, "restart renders nothing: the frame shown stays"


def test_render_sound_refuses_impossible_lengths_naming_seconds():
    cube = toyhost.load(SOURCE_DIR / "shadertoys/cube-probe")
    with toyhost.Session(cube, size=(16, 16)) as session:
        for seconds in (-1, float("nan"), float("inf"), 1e7):
            with pytest.raises(toyhost.UsageError) as raised:
                session.render_sound(seconds)
            assert "seconds" in str(raised.value), str(raised.value)
        assert session.render_sound(0.5).shape == (22050, 2)


def test_step_refuses_impossible_numbers_naming_them():
    probe = toyhost.load(SOURCE_DIR / "shadertoys/uniform-probe")
    with toyhost.Session(probe, size=(16, 16)) as session:
        for kwargs, name in (({"time": float("nan")}, "time"), ({"time": 1.0, "time_delta": -1.0}, "time_delta"),
                             ({"time": 1.0, "frame_rate": -1.0}, "frame_rate"), ({"mouse": (float("nan"), 0)}, "mouse"),
                             ({"mouse": (1e40, 5)}, "mouse")):
            with pytest.raises(toyhost.UsageError) as raised:
                session.step(**kwargs)
            assert name in str(raised.value), str(raised.value)
        assert session.next_frame == 0
        session.step(mouse=(3, 4))
        assert session.next_frame == 1
