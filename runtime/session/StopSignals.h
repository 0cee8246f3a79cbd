// StopSignals: SIGINT, SIGTERM and SIGHUP (unless ignored, as under nohup) as requests to stop. The handler only records the first signal
// and writes a byte per signal to a pipe that a Watchdog (session/Watchdog.h) reads, which
// acknowledges it, asks the session to stop before its next frame, and ends the process if the
// render thread cannot stop in time. Process-wide: the CLI installs it; a program that embeds
// toyhost decides itself (SessionCore::requestStop does the same from any thread). SIGPIPE and
// SIGXFSZ are ignored, so a closed stdout or encoder pipe, or a file past `ulimit -f`, is a write
// error (EPIPE, EFBIG), not the end of the process.
// No GL needed.
#pragma once

namespace toyhost {

void installStopSignals();
// The first SIGINT/SIGTERM/SIGHUP received, or 0.
int stopSignal();
// Readable while signals are waiting to be acknowledged (one byte each, the signal's number);
// -1 before installStopSignals().
int stopSignalFd();
// "SIGINT", "SIGTERM", "SIGHUP".
const char* stopSignalName(int signal);

}  // namespace toyhost
