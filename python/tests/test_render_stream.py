"""render() through the library's frame stream: a frame comes as soon as its read completes (not
once the next captured frame rendered), Ctrl-C stops a render after the frame being rendered when
it came (within one frame), a signal whose handler raises nothing lets it go on, and a closed
session leaves no thread behind. No timing: the checks wait on the session's frame counter."""

import os
import signal
import threading

import pytest

import toyhost
from support import DATE, SOURCE_DIR, require_shared


@pytest.fixture(scope="module")
def ocean():
    require_shared("shadertoys/MdXyzX/image.glsl")
    return toyhost.load(SOURCE_DIR / "shadertoys/ocean")


def test_frame_0_comes_before_frame_100_renders(ocean):
    with toyhost.Session(ocean, size=(160, 90), date=DATE) as session:
        frames = session.render(301, every=100)
        index, image = next(frames)
        assert index == 0 and image.shape == (90, 160, 4)
        rendered = session.next_frame
        assert rendered < 100, f"frame 0 was handed over only after frame {rendered - 1} rendered"
        assert [i for i, _ in frames] == [100, 200, 300]


def signal_during_wait(session, signum):
    """A helper thread that sends `signum` to the main thread a few frames into its wait; what
    it saw is in the returned dict ("at": the frames rendered when it was sent: the signal came
    before or while frame "at" rendered, as each question is answered between two frames)."""
    main = threading.get_ident()
    sent = {}

    def send():
        start = session.next_frame
        while (now := session.next_frame) < start + 3:
            pass
        sent["at"] = now
        signal.pthread_kill(main, signum)

    helper = threading.Thread(target=send)
    helper.start()
    return helper, sent


def test_ctrl_c_stops_a_render_within_one_frame(ocean):
    with toyhost.Session(ocean, size=(160, 90), date=DATE) as session:
        frames = session.render(301, every=100)
        assert next(frames)[0] == 0
        helper, sent = signal_during_wait(session, signal.SIGINT)
        with pytest.raises(KeyboardInterrupt):
            next(frames)  # waits for frame 100
        helper.join()
        stopped = session.next_frame
        assert stopped <= sent["at"] + 1, (
            f"SIGINT sent with {sent['at']} frames rendered, the render stopped after {stopped}")
        more = list(session.render(2))
        assert [i for i, _ in more] == [stopped, stopped + 1], "the session goes on from there"


def test_a_signal_whose_handler_raises_nothing_lets_the_render_go_on(ocean):
    seen = []
    before = signal.signal(signal.SIGUSR1, lambda signum, frame: seen.append(signum))
    read_end, write_end = os.pipe2(os.O_NONBLOCK)
    previous_fd = signal.set_wakeup_fd(write_end)  # someone else's (asyncio's, say)
    try:
        with toyhost.Session(ocean, size=(160, 90), date=DATE) as session:
            frames = session.render(101, every=100)
            assert next(frames)[0] == 0
            helper, _ = signal_during_wait(session, signal.SIGUSR1)
            assert [i for i, _ in frames] == [100]
            helper.join()
        assert seen == [signal.SIGUSR1]
        # The wakeup fd that was there before is back and got the signal's byte.
        assert signal.set_wakeup_fd(previous_fd) == write_end
        assert os.read(read_end, 16) == bytes([signal.SIGUSR1])
    finally:
        signal.set_wakeup_fd(previous_fd)
        signal.signal(signal.SIGUSR1, before)
        os.close(read_end)
        os.close(write_end)


def thread_count():
    return len(os.listdir("/proc/self/task"))


def virtual_bytes():
    with open("/proc/self/status", encoding="ascii") as status:
        for line in status:
            if line.startswith("VmSize:"):
                return int(line.split()[1]) * 1024
    raise AssertionError("no VmSize in /proc/self/status")


def test_closed_sessions_leave_no_threads():
    probe = toyhost.load(SOURCE_DIR / "shadertoys/pingpong-probe")
    toyhost.Session(probe, size=(16, 8)).close()  # whatever the driver keeps for the process
    threads, memory = thread_count(), virtual_bytes()
    closed = []  # kept alive: close() itself must free them, not garbage collection
    for _ in range(10):
        session = toyhost.Session(probe, size=(16, 8))
        session.step()
        for _ in session.render(3):
            pass
        session.close()
        closed.append(session)
    assert thread_count() == threads, "closed sessions left threads"
    assert virtual_bytes() - memory < (1 << 30), "closed sessions kept their GL threads' stacks"
    with pytest.raises(toyhost.UsageError, match="closed"):
        closed[0].step()
