// WindowRun: the `toyhost run --window` driver. A Player on a GLFW window's context: a real-time
// clock (or a fixed step with --fps), GLFW's mouse and keys turned into the same InputEvents the
// scripts make (iMouse in canvas pixels as the site computes it, keys as JavaScript keyCodes,
// auto-repeat ignored), the canvas following the window's framebuffer size, a few control keys
// (window/WindowControls.h), hot reload through a ShadertoyWatcher, a title with the state, and
// --out recording what is shown. It checks everything prepareSession checks before opening the window.
#pragma once

#include "core/Result.h"
#include "session/SessionObserver.h"
#include "session/SessionObserver.h"
#include "session/SessionOptions.h"

namespace toyhost {

// `options.interactive` should be set (frames and fps then default to "until closed" and real
// time). Ends when the window closes, Esc / Ctrl+Q, the observer asks to stop, or after --frames.
Result<SessionReport> runWindow(const SessionOptions& options, SessionObserver& observer);

}  // namespace toyhost
