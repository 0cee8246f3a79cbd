#include "Signals.h"

#include <cerrno>
#include <fcntl.h>
#include <unistd.h>

#include <utility>

namespace py = pybind11;

namespace toyhost::python {

bool onMainThread() {
    static const unsigned long mainThread =
        py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
    return PyThread_get_thread_ident() == mainThread;
}

bool signalRaised() {
    const PyGILState_STATE gil = PyGILState_Ensure();
    const bool raised = PyErr_CheckSignals() != 0;
    PyGILState_Release(gil);
    return raised;
}

SignalPipe::SignalPipe() {
    int ends[2];
    if (::pipe2(ends, O_NONBLOCK | O_CLOEXEC) == 0) {
        read_ = ends[0];
        write_ = ends[1];
    }
}

SignalPipe::~SignalPipe() {
    if (read_ >= 0) ::close(read_);
    if (write_ >= 0) ::close(write_);
}

bool SignalPipe::drain() {
    if (read_ < 0) return false;
    bool any = false;
    char bytes[64];
    for (;;) {
        const ssize_t got = ::read(read_, bytes, sizeof bytes);
        if (got > 0) {
            bytes_.append(bytes, static_cast<std::size_t>(got));
            any = true;
        } else if (!(got < 0 && errno == EINTR)) {
            return any;
        }
    }
}

std::string SignalPipe::take() {
    drain();
    return std::exchange(bytes_, {});
}

// signal.set_wakeup_fd (PySignal_SetWakeupFd is not exported by every Python build).
WakeupFdGuard::WakeupFdGuard(int fd, std::function<std::string()> takeBytes)
    : takeBytes_(std::move(takeBytes)), setWakeupFd_(py::module_::import("signal").attr("set_wakeup_fd")) {
    if (fd >= 0) {
        previous_ = setWakeupFd_(fd).cast<int>();
        installed_ = true;
    }
}

WakeupFdGuard::~WakeupFdGuard() {
    if (!installed_) return;
    const py::error_scope pending;  // a KeyboardInterrupt on its way stays set around the call
    try {
        setWakeupFd_(previous_);
    } catch (py::error_already_set& e) {  // a destructor does not throw; Python says why
        e.discard_as_unraisable("restoring the signal wakeup fd");
    }
    const std::string bytes = takeBytes_();
    if (previous_ >= 0 && !bytes.empty()) {
        const ssize_t written = ::write(previous_, bytes.data(), bytes.size());  // non-blocking, as Python's is
        (void)written;  // a full or closed wakeup fd loses the wake-up, as it would in Python
    }
}

}  // namespace toyhost::python
