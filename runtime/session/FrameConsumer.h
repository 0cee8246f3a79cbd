// FrameConsumer: where a recording's frames go once rendered. After every frame the Recording
// hands the consumer the captured pass's rendered output, still on the GPU (its texture and
// framebuffer); the consumer takes the frames it captures and says at the end what it did. The CPU
// readback adapter (session/FrameRecorder.h: readback ring, encoder pool, file sinks) is one;
// startFrameConsumer is the one place it is chosen. Needs the player's GL context current.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/Result.h"
#include "core/RunActivity.h"
#include "image/ImageStats.h"
#include "manifest/ManifestDesc.h"
#include "player/Player.h"
#include "render/Renderer.h"
#include "session/SessionObserver.h"
#include "session/SessionOptions.h"

namespace toyhost {

// One rendered frame as a consumer is handed it.
struct RenderedFrame {
    int frame = 0;      // the recording's frame number (its iFrame, counted from the recording's start)
    PassOutput output;  // the captured pass's texture and framebuffer as drawn; empty for Cube A
    // What PassOutput does not describe: Cube A's six faces, read through the player.
    const Player& player;
};

// What a consumer did with a round's frames, for the report.
struct ConsumedFrames {
    std::uint64_t bytesWritten = 0;
    int encoderThreads = 0;
    std::string videoEncoder;  // a video's ffmpeg encoder, "" otherwise
    CaptureTimes times;        // all but `render`, which is the loop's
    std::vector<int> dropped;  // frames not recorded because the consumer was behind, by number
    // Float captures: the first frame that held NaN or Inf, when the consumer looked.
    std::optional<std::pair<int, NonFiniteFind>> firstNonFinite;
};

class FrameConsumer {
public:
    virtual ~FrameConsumer() = default;

    // Whether frame `frame` is one the consumer takes (capture/FrameStream.h's capture-every rule).
    virtual bool captures(int frame) const = 0;
    // After every rendered frame, captured or not: takes it when captured, and passes on what
    // earlier frames completed, without waiting.
    virtual Status rendered(const RenderedFrame& frame) = 0;
    // Waits for every frame taken and completes the output. Without a successful finish(),
    // destruction discards incomplete output.
    virtual Status finish() = 0;
    // Stops without completing (an interrupted run): frames not yet written are dropped, a
    // stream's output is discarded, complete image files stay.
    struct Abandoned {
        int written = 0;  // frames completed
        int dropped = 0;  // captured frames that were never written
    };
    virtual Abandoned abandon() = 0;
    // Read every frame for the progress line.
    virtual std::uint64_t bytesWritten() const = 0;
    virtual ConsumedFrames consumed() const = 0;
};

// Starts the consumer of `plan`'s output (plan.output set) for `player`'s current canvas: the CPU
// readback adapter. A notice to `observer` says which video encoder --codec auto chose.
// `stopRequested`: asked while the render thread waits for the consumer (RecorderSettings).
Result<std::unique_ptr<FrameConsumer>> startFrameConsumer(const SessionPlan& plan, const Player& player,
                                                          RunActivity* activity, std::function<bool()> stopRequested,
                                                          SessionObserver& observer);

}  // namespace toyhost
