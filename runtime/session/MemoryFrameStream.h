// MemoryFrameStream: the frame stream (capture/FrameStream.h's rule) into memory instead of files:
// frames stepped by its user's clock, a pass of each captured frame read back while later frames
// render (render/PendingReads.h), each handed to a consumer mapped, as soon as its read completes,
// and frames submitted at most kFramesAhead ahead of the GPU's drawing (render/DrawFences.h). The
// library's Session::render and Session::Rendering (and through them Python's render()) run on it,
// as can any driver that wants frames in memory. Needs the session's GL context current for every
// call but requestStop(), and when it is destroyed.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>

#include "capture/FrameStream.h"
#include "core/Result.h"
#include "image/Image.h"
#include "manifest/ManifestDesc.h"
#include "render/DrawFences.h"
#include "render/PendingReads.h"

namespace toyhost {

class SessionCore;

struct MemoryStreamRequest {
    int frames = 0;  // frames to step (0 or more)
    int every = 1;   // iFrames 0, every, 2 * every, ... and the last are handed over (1 or more)
    PassId pass = PassId::Image;  // a pass the shadertoy has
    int inFlight = 3;             // reads in flight at once; the next waits for the oldest
    int first = 0;                // iFrame of the stream's frame 0, which `every` counts on (FrameStreamSettings)
};

// A frame handed over: its read complete, mapped until the consumer returns.
struct MemoryFrame {
    int frame = 0;  // iFrame of the frame
    int width = 0;
    int height = 0;
    PixelFormat format = PixelFormat::Rgba8;  // the values as read (the pass's target)
    const std::byte* pixels = nullptr;        // width * height RGBA values, rows bottom first
};

class MemoryFrameStream final : private FrameReads {
public:
    // Frames submitted and not yet drawn, at most. A GPU (llvmpipe above all) takes dozens of
    // frames before it makes the submitter wait: the frame counter would run that far ahead of the
    // pictures, and a stop would leave that much drawing to finish. Two keep it busy.
    static constexpr std::size_t kFramesAhead = 2;
    // Renders and submits the stream's frame `index` (0 first): the user's clock and input events
    // (the library's: Session::step()'s frame).
    using StepFrame = std::function<Status(int index)>;
    // Given each frame handed over, in order; false stops the stream.
    using TakeFrame = std::function<bool(const MemoryFrame&)>;

    // A stream of `request` (checked by the caller) on `core`, which must outlive it. The reads'
    // buffers are made now, at the pass's size: a failure to allocate them shows here.
    static Result<std::unique_ptr<MemoryFrameStream>> open(SessionCore& core, const MemoryStreamRequest& request);

    // One step: waits until fewer than kFramesAhead frames are being drawn, steps the next frame
    // (when frames are left), starts its read when it is captured (waiting for the oldest read only
    // when inFlight are in flight) and hands every complete read to `take`; once every frame is
    // stepped, waits for the reads left and hands them over. Returns whether there is more to do:
    // false once everything was handed over, or after a stop (take's false or requestStop()). An
    // error ends the stream: reads in flight are dropped.
    Result<bool> advance(const StepFrame& step, const TakeFrame& take);
    // Asks the stream to stop before its next frame; any thread. The next advance() steps nothing,
    // drops the reads not handed over and returns false.
    void requestStop() { stream_.requestStop(); }
    bool stopRequested() const { return stream_.stopRequested(); }
    int framesRendered() const { return rendered_; }
    int readsInFlight() const { return static_cast<int>(reads_.size()); }
    // Frames submitted whose drawing was not yet seen complete (at most kFramesAhead).
    std::size_t framesDrawing() const { return drawing_.pending(); }
    // Whether it holds reads or fences (drop() has GL work to do).
    bool holdsGl() const { return reads_.size() > 0 || drawing_.pending() > 0; }
    // Forgets the reads in flight and the fences.
    void drop();

private:
    MemoryFrameStream(SessionCore& core, const MemoryStreamRequest& request);
    // FrameReads: the stream's reads, driven by stream_.
    int pending() const override { return static_cast<int>(reads_.size()); }
    Status start(int frame) override;
    bool oldestDone() const override { return reads_.oldestDone(); }
    Status handOverOldest() override;
    void dropAll() override { reads_.clear(); }

    SessionCore& core_;
    const MemoryStreamRequest request_;
    FrameStream stream_;
    PendingReads reads_;
    DrawFences drawing_;
    int rendered_ = 0;
    const TakeFrame* take_ = nullptr;  // advance()'s, while it runs
};

}  // namespace toyhost
