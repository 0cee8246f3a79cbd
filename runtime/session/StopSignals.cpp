#include "session/StopSignals.h"

#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <unistd.h>

namespace toyhost {

namespace {
volatile std::sig_atomic_t firstSignal = 0;
int signalPipe[2] = {-1, -1};

extern "C" void onStopSignal(int signal) {
    const int savedErrno = errno;
    if (!firstSignal) firstSignal = signal;
    const unsigned char byte = static_cast<unsigned char>(signal);
    (void)!::write(signalPipe[1], &byte, 1);
    errno = savedErrno;
}
}  // namespace

void installStopSignals() {
    if (signalPipe[0] < 0 && ::pipe2(signalPipe, O_CLOEXEC | O_NONBLOCK) != 0) signalPipe[0] = signalPipe[1] = -1;
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    ::sigaction(SIGINT, &action, nullptr);
    ::sigaction(SIGTERM, &action, nullptr);
    // SIGHUP (the terminal or the ssh session went away) ends a run as SIGTERM does, unless it is
    // ignored already: `nohup toyhost ...` keeps running.
    struct sigaction hangup {};
    if (::sigaction(SIGHUP, nullptr, &hangup) == 0 && hangup.sa_handler != SIG_IGN) ::sigaction(SIGHUP, &action, nullptr);
    std::signal(SIGPIPE, SIG_IGN);
    // A file past `ulimit -f` is a write error (EFBIG, "File too large") that the writers report and
    // clean up after, not the end of the process with the hidden temporary files left behind.
    std::signal(SIGXFSZ, SIG_IGN);
}

int stopSignal() { return firstSignal; }

int stopSignalFd() { return signalPipe[0]; }

const char* stopSignalName(int signal) {
    switch (signal) {
        case SIGTERM: return "SIGTERM";
        case SIGINT: return "SIGINT";
        case SIGHUP: return "SIGHUP";
        default: return "a signal";
    }
}

}  // namespace toyhost
