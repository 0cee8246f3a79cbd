// FrameStream: when reads start, when they are handed over, and what a stop drops.
#include "capture/FrameStream.h"

namespace toyhost {

Status FrameStream::rendered(int frame, FrameReads& reads) {
    if (stopRequested()) return okStatus();
    if (captures(frame)) {
        // The bound: a read slot is freed before the next read starts (the only place the stream
        // waits while frames are left to render).
        while (reads.pending() >= settings_.inFlight && !stopRequested())
            if (Status handed = reads.handOverOldest(); !handed) return handed;
        if (stopRequested()) return okStatus();
        if (Status started = reads.start(frame); !started) return started;
    }
    return poll(reads);
}

Status FrameStream::poll(FrameReads& reads) {
    while (!stopRequested() && reads.pending() > 0 && reads.oldestDone())
        if (Status handed = reads.handOverOldest(); !handed) return handed;
    return okStatus();
}

Status FrameStream::finish(FrameReads& reads) {
    while (!stopRequested() && reads.pending() > 0)
        if (Status handed = reads.handOverOldest(); !handed) return handed;
    if (stopRequested()) reads.dropAll();
    return okStatus();
}

}  // namespace toyhost
