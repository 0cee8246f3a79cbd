"""Threads: rendering releases the GIL (another Python thread runs while a frame renders), and a
session may be called from any Python thread (its GL context lives on the session's own thread).
No timing: the checks wait on events and counters."""

import sys
import threading

import numpy
import pytest

import toyhost
from support import DATE, SOURCE_DIR, write_shadertoy

# A few milliseconds of shading per frame at 64x64 on llvmpipe, so that a frame is long enough for
# the other thread to be scheduled inside it.
BUSY = ("void mainImage(out vec4 c, in vec2 p) {\n"
        "    float v = 0.0;\n"
        "    for (int i = 0; i < 400; i++) v += sin(p.x * 0.01 + float(i) + iTime);\n"
        "    c = vec4(fract(v), 0, 0, 1);\n"
        "}\n")


@pytest.fixture
def never_switch():
    """With a huge switch interval the interpreter never takes the GIL away from a running thread:
    another thread only runs where the running one releases it (a blocking call, or toyhost's)."""
    before = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    yield
    sys.setswitchinterval(before)


def run_while_rendering(render_one):
    """Calls render_one() until a second Python thread has run; returns what that thread saw."""
    go = threading.Event()
    inside = [False]
    seen = []

    def other():
        go.wait()
        seen.append(inside[0])  # runs only when the main thread releases the GIL

    thread = threading.Thread(target=other)
    thread.start()
    go.set()  # does not release the GIL: `other` cannot run yet
    for _ in range(2000):
        inside[0] = True
        render_one()
        inside[0] = False
        if seen:
            break
    thread.join()  # releases the GIL: `other` runs here at the latest
    return seen


def test_step_releases_the_gil(tmp_path, never_switch):
    with toyhost.Session(write_shadertoy(tmp_path / "busy", {"Image": BUSY}), size=(64, 64)) as session:
        assert run_while_rendering(session.step) == [True], "the other thread ran while a frame rendered"


def test_frame_and_render_release_the_gil(tmp_path, never_switch):
    with toyhost.Session(write_shadertoy(tmp_path / "busy", {"Image": BUSY}), size=(64, 64)) as session:
        session.step()
        assert run_while_rendering(session.frame) == [True]
        frames = session.render(10**6)
        assert run_while_rendering(lambda: next(frames)) == [True]
        frames.close()


def test_a_session_is_usable_from_any_thread():
    probe = toyhost.load(SOURCE_DIR / "shadertoys/pingpong-probe")
    made = {}
    creator = threading.Thread(target=lambda: made.setdefault("session", toyhost.Session(probe, size=(16, 8))))
    creator.start()
    creator.join()
    session = made["session"]
    errors = []

    def step_there():
        try:
            session.step()
        except Exception as e:  # noqa: BLE001 - handed to the main thread
            errors.append(e)

    for _ in range(3):
        other = threading.Thread(target=step_there)
        other.start()
        other.join()
    assert not errors, errors
    session.step()
    assert session.next_frame == 4
    with toyhost.Session(probe, size=(16, 8)) as alone:
        for _ in range(4):
            alone.step()
        assert numpy.array_equal(session.frame("Buffer A", "float32"), alone.frame("Buffer A", "float32"))
    session.close()


def test_sessions_in_parallel_threads_give_the_frames_of_sessions_in_turn():
    probe = toyhost.load(SOURCE_DIR / "shadertoys/window-probe")

    def frames():
        with toyhost.Session(probe, size=(32, 16), date=DATE) as session:
            return [image for _, image in session.render(6, mouse=(3, 4), keys={"A"})]

    expected = frames()
    results = [None] * 3

    def run(i):
        results[i] = frames()

    threads = [threading.Thread(target=run, args=(i,)) for i in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for result in results:
        assert result is not None and len(result) == len(expected)
        for got, want in zip(result, expected):
            assert numpy.array_equal(got, want)


def in_forked_child(work):
    """Runs work(put) in a forked child; returns what it put (each within a bound, not a hang)."""
    import multiprocessing

    context = multiprocessing.get_context("fork")
    result = context.Queue()

    def child():
        try:
            work(result.put)
        finally:
            result.put("end")

    process = context.Process(target=child)
    process.start()
    answers = []
    while not answers or answers[-1] != "end":
        answers.append(result.get(timeout=120))
    process.join()
    assert process.exitcode == 0
    return answers[:-1]


def test_a_child_forked_with_a_session_open_is_told_not_left_hanging():
    # Dataset generation forks workers (multiprocessing's default on Linux). Forked with a session
    # open, the child cannot start GL at all (the driver's threads stay in the parent): both using
    # the parent's session and making a new one raise, naming the way out. The parent goes on.
    probe = toyhost.load(SOURCE_DIR / "shadertoys/pingpong-probe")
    parent = toyhost.Session(probe, size=(8, 4))
    parent.step()

    def work(put):
        for attempt in (parent.step, lambda: toyhost.Session(probe, size=(8, 4)),
                        lambda: toyhost.compare(probe, probe, frames=1, size=(8, 4))):
            try:
                attempt()
                put("worked")
            except toyhost.UsageError as e:
                put("refused: fork" if "fork" in str(e) else f"wrong error: {e}")
        parent.close()  # forgets the parent's objects here; must not hang or raise
        put("closed")

    assert in_forked_child(work) == ["refused: fork", "refused: fork", "refused: fork", "closed"]
    parent.step()
    assert parent.next_frame == 2, "the parent's session is untouched"
    parent.close()


def test_a_child_forked_with_no_session_open_makes_its_own():
    probe = toyhost.load(SOURCE_DIR / "shadertoys/pingpong-probe")
    with toyhost.Session(probe, size=(8, 4)) as before:
        before.step()
        expected = before.frame("Buffer A", "float32")

    def work(put):
        with toyhost.Session(probe, size=(8, 4)) as own:
            own.step()
            put(bool(numpy.array_equal(own.frame("Buffer A", "float32"), expected)))

    assert in_forked_child(work) == [True]


def test_the_interpreter_exits_cleanly_while_a_daemon_thread_renders():
    # At exit, Python ends daemon threads when they take the GIL back (pthread_exit): that must
    # pass through toyhost's code rather than abort the process ("terminate called ...").
    import subprocess

    script = ("import threading, toyhost, sys\n"
              "s = toyhost.Session(sys.argv[1], size=(64, 36))\n"
              "started = threading.Event()\n"
              "def loop():\n"
              "    for _ in s.render(10**7):\n"
              "        started.set()\n"
              "threading.Thread(target=loop, daemon=True).start()\n"
              "started.wait()\n")
    for _ in range(3):
        done = subprocess.run([sys.executable, "-c", script, str(SOURCE_DIR / "shadertoys/bench-trivial")],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120, check=False)
        assert done.returncode == 0, done.stdout
        assert "terminate" not in done.stdout


def test_closing_while_the_loop_waits_for_a_frame_always_raises(tmp_path, never_switch):
    """Once a defect (issue 46): a close() that ran while the loop waited in next() ended the loop
    normally 4 times in 5 (the stream was cancelled, and the Python side looked at `closed` before
    the session was gone). The closing thread is released by an event the loop sets; with the GIL
    never taken from a running thread it runs only where the loop releases it: inside next()."""
    shadertoy = toyhost.load(write_shadertoy(tmp_path / "busy", {"Image": BUSY}))
    for attempt in range(8):
        session = toyhost.Session(shadertoy, size=(64, 64))
        go = threading.Event()
        closer = threading.Thread(target=lambda: (go.wait(), session.close()))
        closer.start()
        seen = 0
        with pytest.raises(toyhost.UsageError) as raised:
            for _ in session.render(10**6):
                seen += 1
                if seen == 2:
                    go.set()  # does not release the GIL: the closer runs once next() waits
        closer.join()
        assert "closed while render() ran" in str(raised.value), attempt
        assert seen < 10**6 and session.closed


def test_closing_from_another_thread_during_render_raises_usage_error_in_the_loop():
    """The loop learns the session went away: the documented UsageError, not a loop that just ends
    early as if all frames were rendered."""
    session = toyhost.Session(SOURCE_DIR / "shadertoys/bench-trivial", size=(32, 18))
    seen = 0
    with pytest.raises(toyhost.UsageError) as raised:
        for _ in session.render(1000):
            seen += 1
            if seen == 3:
                closer = threading.Thread(target=session.close)
                closer.start()
                closer.join()
    assert "closed while render() ran" in str(raised.value)
    assert seen < 1000
    assert session.closed
