"""Every numeric (and path-like) parameter of the Python module, given a value that cannot be meant
(NaN, infinities, 0 or negative where those mean nothing, past what C++ holds, a wrong type), raises
toyhost.UsageError naming the parameter: never pybind11's "incompatible function arguments", a
silent default, a crash or a hang. The table covers every parameter of the public callables; a
parameter added to the API without a row here fails the coverage test."""

import inspect
import math
import os
import signal
import sys
import threading
import time

import numpy
import pytest

import toyhost
from support import DATE, SOURCE_DIR

TOY = SOURCE_DIR / "shadertoys/bench-trivial"
SOUND = SOURCE_DIR / "shadertoys/cube-probe"
NAN, INF = math.nan, math.inf
HUGE = 2**31
NUMBERS = [NAN, INF, -INF]
WRONG = ["3", None, object(), [1, 2]]


@pytest.fixture(scope="module")
def session():
    with toyhost.Session(toyhost.load(SOUND), size=(16, 8), date=DATE) as s:
        yield s


# (callable name, parameter): the bad values, and how the call is made with one of them.
def session_kwargs(**kw):
    return lambda: toyhost.Session(TOY, **{"size": (16, 8), **kw}).close()


def compare_kwargs(**kw):
    return lambda: toyhost.compare(TOY, TOY, **{"frames": 1, "size": (16, 8), **kw})


IMAGE = numpy.zeros((4, 4, 4), numpy.uint8)


def images_kwargs(**kw):
    return lambda: toyhost.compare_images(IMAGE, IMAGE, **kw)


CONSTRUCTOR_CASES = {
    ("Session", "size"): [(0, 8), (8, 0), (-1, 8), (HUGE, 8), (8, -HUGE), (320.7, 180), (NAN, 8), "16x8", 16,
                          (1, 2, 3), (True, 8), (20000, 100)],
    ("Session", "fps"): NUMBERS + [0, -5, 1e300, "60", True],
    ("Session", "start_time"): NUMBERS + [1e300, "0", None],
    ("Session", "date"): ["", "2026-13-45T99:99:99", 5],
    ("Session", "media_folders"): [5, [5]],
    ("Session", "media_files"): [5, ["a"], {"Forest": 5}],
    ("Session", "float_image"): ["yes", 2, None],
    ("Session", "frame_timeout"): NUMBERS + [-1, 1e300, "5"],
    ("Session", "compile_timeout"): NUMBERS + [-1, 1e300, "5"],
    ("Session", "mouse_script"): [5, "/nonexistent/script.json"],
    ("Session", "key_script"): [5, "/nonexistent/script.json"],
    ("Session", "supersample"): [0, -1, HUGE, 17, 2.5, "2", NAN],
    ("Session", "motion_blur"): [0, -1, HUGE, 257, 2.5, "2", NAN],
    ("Session", "shutter"): NUMBERS + [-1, 1e300, "180"],
    ("Session", "dither"): ["yes", 2, None],
    ("Session", "shutter_offset"): ["middle", "", 5],
    ("Session", "sample_space"): ["gamma", "", 5],
    ("Session", "defines"): ["1X", ["A=1", "A=2"], ["GL_X"], 5, [5], {"A": object()}, {"A": False}, {5: 1}],
}
COMPARE_CASES = {
    ("compare", "frames"): [0, -1, HUGE, 2.5, "3", NAN],
    ("compare", "size"): [(0, 8), (HUGE, 8), (16.5, 8), "16x8", (20000, 100)],
    ("compare", "fps"): NUMBERS + [0, -5, "60"],
    ("compare", "start_time"): NUMBERS + ["0"],
    ("compare", "date"): ["", 5],
    ("compare", "pass_"): [None, 5, "Buffer Z"],
    ("compare", "min_psnr"): [NAN, 0, -1, -INF, "30"],
    ("compare", "max_diff"): [-1, 256, HUGE, 2.5, "3"],
    ("compare", "mouse"): [(NAN, 0), (0, INF), (1e40, 0), "abc", (1, 2, 3), 5],
    ("compare", "mouse_script"): [5, "/nonexistent/script.json"],
    ("compare", "key_script"): [5, "/nonexistent/script.json"],
    ("compare", "keep_diff_images"): ["yes", 2],
    ("compare", "diff_gain"): [-1, 256, HUGE, 2.5, "8"],
    ("compare", "stop_at_first_difference"): ["yes", 2],
    ("compare", "media_folders"): [5, [5]],
    ("compare", "media_files"): [5, {"Forest": 5}],
    ("compare", "frame_timeout"): NUMBERS + [-1, "5"],
    ("compare", "compile_timeout"): NUMBERS + [-1, "5"],
    ("compare_images", "channels"): [0, 2, 5, -1, HUGE, 3.5, "3"],
    ("compare_images", "min_psnr"): [NAN, 0, -1, "30"],
    ("compare_images", "max_diff"): [-1, 256, HUGE, "3"],
    ("compare_images", "diff_image"): ["yes", 2],
    ("compare_images", "diff_gain"): [-1, 256, HUGE, "8"],
}


def call_with(owner, parameter, value):
    if owner == "Session":
        return session_kwargs(**{parameter: value})
    if owner == "compare":
        return compare_kwargs(**{parameter: value})
    return images_kwargs(**{parameter: value})


@pytest.mark.parametrize("owner,parameter,value", [
    (owner, parameter, value) for (owner, parameter), values in {**CONSTRUCTOR_CASES, **COMPARE_CASES}.items()
    for value in values], ids=repr)
def test_a_value_that_cannot_be_meant_raises_a_toyhost_error(owner, parameter, value):
    with pytest.raises(toyhost.Error) as raised:
        call_with(owner, parameter, value)()
    assert "incompatible function arguments" not in str(raised.value)
    if isinstance(raised.value, toyhost.UsageError) and raised.value.field:
        assert raised.value.field in (parameter, parameter.rstrip("_"), "size", "seconds", "mouse", "pass"), \
            f"{parameter}: the error names {raised.value.field!r}"


METHOD_CASES = {
    ("step", "time"): NUMBERS + ["1"],
    ("step", "time_delta"): NUMBERS + [-1, "0.1"],
    ("step", "frame_rate"): NUMBERS + [-1, "60"],
    ("step", "mouse"): [(NAN, 0), (0, INF), (1e40, 0), (-1e40, 0), "abc", (1, 2, 3), 5, True],
    ("step", "keys"): [{-1}, {256}, {HUGE}, {"NotAKey"}, {None}, {2.5}],
    ("step", "events"): [[5], ["a"], [toyhost.InputEvent.mouse_down(NAN, INF)], [toyhost.InputEvent.key_down(300)]],
    ("frame", "pass_"): [None, 5, "Buffer Z"],
    ("frame", "dtype"): ["int64", None, 5],
    ("frame", "out"): [5, numpy.zeros((2, 2, 4), numpy.uint8)],
    ("render", "frames"): [-1, HUGE, 10**12, 2.5, "3", NAN, None],
    ("render", "every"): [0, -1, HUGE, 2.5, "1"],
    ("render", "pass_"): [None, 5, "Buffer Z"],
    ("render", "dtype"): ["int64", None],
    ("render", "mouse"): [(NAN, 0), "abc"],
    ("render", "keys"): [{-1}, {"NotAKey"}],
    ("render_sound", "seconds"): NUMBERS + [-1, 1e7, 1e300, "5", None],
    ("resize", "size"): [(0, 8), (HUGE, 8), (-1, -1), (8.5, 8), "16x8", None],
}


def call_method(session, method, parameter, value):
    if method == "render":
        return next(session.render(**{"frames": 1, parameter: value}))
    return getattr(session, method)(**{parameter: value})


@pytest.mark.parametrize("method,parameter,value", [
    (method, parameter, value) for (method, parameter), values in METHOD_CASES.items() for value in values],
    ids=repr)
def test_a_session_call_refuses_what_cannot_be_meant_and_renders_nothing(session, method, parameter, value):
    before = session.next_frame
    with pytest.raises(toyhost.Error) as raised:
        call_method(session, method, parameter, value)
    assert "incompatible function arguments" not in str(raised.value)
    assert session.next_frame == before, "nothing was rendered"
    assert session.size == (16, 8)


# Parameters that are not numbers or paths: the shadertoy itself, and values checked elsewhere.
NOT_NUMERIC = {("Session", "shadertoy"), ("compare", "a"), ("compare", "b"), ("compare_images", "a"),
               ("compare_images", "b")}


def test_every_parameter_of_the_public_callables_has_a_row():
    callables = {"Session": toyhost.Session.__init__, "compare": toyhost.compare,
                 "compare_images": toyhost.compare_images, "step": toyhost.Session.step,
                 "frame": toyhost.Session.frame, "render": toyhost.Session.render,
                 "render_sound": toyhost.Session.render_sound, "resize": toyhost.Session.resize}
    covered = set(CONSTRUCTOR_CASES) | set(COMPARE_CASES) | set(METHOD_CASES) | NOT_NUMERIC
    missing = [(owner, name) for owner, function in callables.items()
               for name in inspect.signature(function).parameters if name != "self" and (owner, name) not in covered]
    assert not missing, f"parameters without a row in this test: {missing}"


def test_a_canvas_beyond_one_target_is_refused_not_cut_to_a_tile():
    """Once a defect (issue 46): Session(size=(20000, 100)) became a 1024x100 session (one tile of a
    tiled still) and compare() of such a size said equal for frames that differed beyond x = 1024."""
    with pytest.raises(toyhost.UsageError) as raised:
        toyhost.Session(TOY, size=(20000, 100))
    assert raised.value.field == "size" and "at most 16384x16384" in str(raised.value)
    with pytest.raises(toyhost.UsageError) as raised:
        toyhost.compare(TOY, TOY, frames=1, size=(20000, 100))
    assert raised.value.field == "size" and "at most 16384x16384" in str(raised.value)


def test_a_nul_byte_in_a_path_is_a_usage_error(tmp_path):
    # Once bare ValueErrors ("embedded null byte") from the native conversion (issue 46).
    for call in (lambda: toyhost.load("toy\0folder"), lambda: toyhost.Session(TOY, size=(16, 8), mouse_script="a\0b"),
                 lambda: toyhost.compare(TOY, TOY, frames=1, size=(16, 8), key_script=tmp_path / "a\0b")):
        with pytest.raises(toyhost.UsageError, match="NUL byte"):
            call()
    with toyhost.Session(TOY, size=(16, 8)) as session:
        with pytest.raises(toyhost.UsageError, match="NUL byte"):
            session.record(str(tmp_path / "f\0_%d.png"), 1)


def test_a_media_folder_given_as_one_string_is_one_folder(tmp_path):
    # It was iterated by character: the error named folder "n".
    with pytest.raises(toyhost.InputError) as raised:
        toyhost.Session(TOY, size=(16, 8), media_folders=str(tmp_path / "missing"))
    assert str(tmp_path / "missing") in str(raised.value)
    with toyhost.Session(TOY, size=(16, 8), media_folders=str(tmp_path)) as s:
        s.step()


def test_ctrl_c_stops_a_long_compare_within_a_frame_or_so():
    """A compare of many frames: SIGINT once the main thread is inside the native compare raises
    KeyboardInterrupt there, long before the frames would end (it was ignored until the end)."""
    main = threading.main_thread().ident
    sent = {}

    def send_when_comparing():
        # The event: the main thread's Python frame is the call into the native compare.
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline:
            frame = sys._current_frames().get(main)
            if frame is not None and frame.f_code.co_name == "compare" and "_toyhost.compare" in \
                    open(frame.f_code.co_filename).read().splitlines()[frame.f_lineno - 1]:
                break
            time.sleep(0.005)
        time.sleep(0.2)  # inside the native call now: some frames compared
        sent["at"] = time.monotonic()
        signal.pthread_kill(main, signal.SIGINT)

    helper = threading.Thread(target=send_when_comparing)
    helper.start()
    try:
        with pytest.raises(KeyboardInterrupt) as raised:
            toyhost.compare(TOY, TOY, frames=200000, size=(16, 8), date=DATE)
        ended = time.monotonic()
    finally:
        helper.join()
    assert "at" in sent, "the signal was never sent"
    assert ended - sent["at"] < 10, f"compare went on {ended - sent['at']:.1f} s after SIGINT"
    assert raised.traceback[-1].name == "compare", "raised inside compare, not before it"


def test_a_signal_whose_handler_raises_nothing_lets_a_compare_finish():
    seen = []
    before = signal.signal(signal.SIGUSR1, lambda signum, frame: seen.append(signum))
    main = threading.main_thread().ident
    try:
        timer = threading.Timer(0.3, lambda: signal.pthread_kill(main, signal.SIGUSR1))
        timer.start()
        report = toyhost.compare(TOY, TOY, frames=400, size=(16, 8), date=DATE)
        timer.join()
    finally:
        signal.signal(signal.SIGUSR1, before)
    assert len(report.frames) == 400 and report.equal
    assert seen == [signal.SIGUSR1]
