// Signals while native work runs without the GIL: Python's handlers (Ctrl-C: KeyboardInterrupt) run
// only on the main thread between bytecodes, so a call that waits in C++ would not see them. A
// SignalPipe, installed as Python's wakeup fd (WakeupFdGuard) while the main thread waits, wakes
// the wait; the fd that was there before (asyncio's, say) comes back afterwards with the bytes that
// arrived meanwhile. No GL.
#pragma once

#include <pybind11/pybind11.h>

#include <functional>
#include <string>

namespace toyhost::python {

// Whether this is Python's main thread, the one its signal handlers run on (elsewhere the
// question is not asked: a daemon thread taking the GIL while the interpreter finalizes is ended).
bool onMainThread();

// Whether Python has a signal to handle, its handler run (the exception it raised set) with the
// GIL taken for the question. Main thread only.
bool signalRaised();

// A non-blocking pipe whose write end is a wakeup fd; the bytes read are kept for the previous one.
class SignalPipe {
public:
    SignalPipe();
    ~SignalPipe();
    SignalPipe(const SignalPipe&) = delete;
    SignalPipe& operator=(const SignalPipe&) = delete;

    int writeFd() const { return write_; }
    int readFd() const { return read_; }
    // Moves what the pipe holds into the kept bytes; true if there was any.
    bool drain();
    std::string take();

private:
    int read_ = -1, write_ = -1;
    std::string bytes_;
};

// With the GIL held: `fd` is Python's wakeup fd while it lives; afterwards the previous one comes
// back and gets `takeBytes()` (the signal bytes that arrived meanwhile).
class WakeupFdGuard {
public:
    WakeupFdGuard(int fd, std::function<std::string()> takeBytes);
    ~WakeupFdGuard();
    WakeupFdGuard(const WakeupFdGuard&) = delete;
    WakeupFdGuard& operator=(const WakeupFdGuard&) = delete;

private:
    std::function<std::string()> takeBytes_;
    pybind11::object setWakeupFd_;
    int previous_ = -1;
    bool installed_ = false;
};

}  // namespace toyhost::python
