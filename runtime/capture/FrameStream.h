// FrameStream: the one stream of frames every recording and every render into memory goes through
// (the CLI's recorder, the library's Session::render, Python's render()): which frames are handed
// over (the capture-every rule), the reads of those frames in flight while later frames render,
// each handed over as soon as it is complete, and a stop request seen between frames. Pure: the
// reads themselves (GL) are the FrameReads its user drives it with.
#pragma once

#include <atomic>

#include <toyhost/Shards.h>

#include "core/Result.h"

namespace toyhost {

// The reads a FrameStream queues and hands over: a recording's readback ring, the memory frame
// stream's reads (session/MemoryFrameStream.h), or (in tests) a fake. Called on the thread that
// renders.
class FrameReads {
public:
    virtual ~FrameReads() = default;
    // Reads queued and not yet handed over.
    virtual int pending() const = 0;
    // Starts reading frame `frame`, just rendered, and returns at once (or reads it at once: then
    // pending() does not grow).
    virtual Status start(int frame) = 0;
    // Whether the oldest pending read is complete (handOverOldest() would not wait). pending() > 0.
    virtual bool oldestDone() const = 0;
    // Waits for the oldest pending read, gives its pixels to their consumer and frees it.
    // pending() > 0.
    virtual Status handOverOldest() = 0;
    // Forgets every pending read (a stream stopped before its end).
    virtual void dropAll() = 0;
};

struct FrameStreamSettings {
    int frames = 0;    // frames in the run, the last of which is handed over; 0: no end
    int every = 1;     // frames numbered 0, every, 2 * every, ... are handed over
    int inFlight = 3;  // reads queued at once; the next waits for the oldest (a readback ring's slots)
    // The number of the stream's frame 0, which `every` counts on: a rendering that starts at
    // iFrame 100 with every 30 hands over iFrames 120, 150, ... (the frames a run from iFrame 0
    // captures), not its own 0th, 30th, ...
    int first = 0;
};

class FrameStream {
public:
    // The capture-every rule (toyhost/Shards.h): frames n with n % every == 0, and the last of
    // `frames` (0: no end).
    static bool captured(int frame, int frames, int every) { return capturedFrame(frame, frames, every); }

    explicit FrameStream(const FrameStreamSettings& settings) : settings_(settings) {}

    const FrameStreamSettings& settings() const { return settings_; }
    // Whether the stream's frame `frame` (0 .. frames - 1, counted from settings.first) is handed over.
    bool captures(int frame) const {
        const int end = settings_.frames > 0 ? settings_.first + settings_.frames : 0;
        return captured(settings_.first + frame, end, settings_.every);
    }

    // After frame `frame` was rendered (submitted, not necessarily drawn): its read starts when the
    // frame is captured (the oldest handed over first when inFlight are pending), then every read
    // that is already complete is handed over, without waiting. Called after every frame, captured
    // or not, so that no frame waits for a later capture to be handed over. Nothing is handed over
    // once a stop was requested.
    Status rendered(int frame, FrameReads& reads);
    // Hands over every read already complete, without waiting.
    Status poll(FrameReads& reads);
    // Waits for every pending read and hands it over (the end of the stream), unless a stop was
    // requested: then they are dropped.
    Status finish(FrameReads& reads);

    // Asks the loop that renders to stop before its next frame; from any thread (a consumer, a
    // signal's watcher). Reads still pending are not handed over.
    void requestStop() { stop_.store(true, std::memory_order_release); }
    bool stopRequested() const { return stop_.load(std::memory_order_acquire); }

private:
    FrameStreamSettings settings_;
    std::atomic<bool> stop_{false};
};

}  // namespace toyhost
