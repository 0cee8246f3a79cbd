// The window driver: what a window brings to a SessionCore (session/SessionCore.h): a real-time clock
// (or a fixed step with --fps, timing/RealTimeClock.h), the mouse and keys from WindowEvents, a
// few controls (F5 restart, F6 pause, F7 step, F12 screenshot, F1 help, F2 inspector;
// input/WindowControls.h), the overlay over the canvas (errors, inspector: drivers/window/Overlay.h),
// the canvas following the window's framebuffer (not while recording), the frame presented, and a
// title with the state (name, measured frame rate, iFrame, iTime, paused, the current error).
// runWindow handles events on the calling (main) thread and renders on a GL thread of its own.
#pragma once

#include "core/Result.h"
#include "session/SessionCore.h"
#include "session/SessionObserver.h"
#include "session/SessionOptions.h"
#include "session/Watchdog.h"

namespace toyhost {

// `options.interactive` should be set (frames and fps then default to "until closed" and real
// time). Ends when the window closes (Esc, Ctrl+Q, the close button: outputs are completed),
// after --frames, or at a stop. `watchdog` may be null.
Result<SessionReport> runWindow(const SessionOptions& options, SessionObserver& observer, Watchdog* watchdog);

}  // namespace toyhost
