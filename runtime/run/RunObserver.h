// RunObserver: how a run talks to whoever started it (the CLI) while it runs: notices, progress,
// and the question "should I stop?". The library never prints; the CLI decides how to show these.
// No GL needed.
#pragma once

#include <cstdint>

#include "core/Diagnostic.h"
#include "timing/ProgressLine.h"

namespace toyhost {

class RunObserver {
public:
    virtual ~RunObserver() = default;
    virtual void notice(const Diagnostic& notice) = 0;
    // Called on the render thread after every frame; keep it cheap.
    virtual void progress(const RunProgress& progress) { (void)progress; }
    // Polled before every frame; true ends the run with an "interrupted" error, cleanly (a video
    // being encoded is discarded, image files already written stay).
    virtual bool stopRequested() const { return false; }
};

}  // namespace toyhost
