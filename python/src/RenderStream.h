// RenderStream: Session.render()'s frames, rendered ahead of the Python loop that takes them, as
// the CLI's recorder renders ahead of its encoders. On the GL worker, one job per frame: step
// frame n, queue its read (Session::queueRead), and take the reads of earlier frames that are
// complete straight into the memory their numpy arrays will own (waiting only when kInFlight are
// queued); up to kReady frames wait for Python. Python takes them in
// order, waiting with the GIL released. Jobs of other calls run between frames. No GL of its own:
// the jobs use the session's.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <toyhost/Input.h>
#include <toyhost/Result.h>
#include <toyhost/Session.h>

#include "GlWorker.h"

namespace toyhost::python {

struct RenderRequest {
    std::vector<InputEvent> firstEvents;  // applied before the first frame
    int frames = 0;
    int every = 1;  // frames 0, every, 2 * every, ... and the last are read
    std::string pass = "Image";
    bool floats = false;  // float32 values, else uint8
};

// One frame read, in memory a numpy array can take over (rows top first).
struct RenderedFrame {
    int frame = 0;
    int width = 0;
    int height = 0;
    std::unique_ptr<std::uint8_t[]> bytes;  // width * height * 4, when !floats
    std::unique_ptr<float[]> floats;        // width * height * 4, when floats
};

class RenderStream : public std::enable_shared_from_this<RenderStream> {
public:
    // Frames rendered ahead of the one Python takes: enough to keep the worker busy while Python
    // handles a frame; each costs its pixels' memory.
    static constexpr std::size_t kReady = 4;
    // Python, finding no frame ready, sleeps until this many are (or the rendering stopped): one
    // wake-up per kWakeAt frames. Half of kReady, so that the worker keeps rendering meanwhile.
    static constexpr std::size_t kWakeAt = 2;
    // Reads queued and not yet complete before the oldest is waited for (the CLI's readback ring
    // has as many).
    static constexpr int kInFlight = 3;

    // `session` lives on `worker` and outlives the stream's jobs (cancel() before closing it).
    static std::shared_ptr<RenderStream> start(GlWorker& worker, Session& session, RenderRequest request);

    // The next frame, waiting for it (call without the GIL); nothing once every frame was taken.
    // Throws ToyhostError with what stopped the rendering, after the frames read before it.
    std::optional<RenderedFrame> next();
    // Stops rendering after the frame being rendered; frames not taken are dropped. The session
    // stays where the rendering got (its later calls run after this). Idempotent.
    void cancel();

private:
    RenderStream(GlWorker& worker, Session& session, RenderRequest request)
        : worker_(worker), session_(session), request_(std::move(request)) {}
    void post();   // the next job
    void renderOne();  // on the worker: one frame, then the next job when there is room
    Status takeOne();  // on the worker: the oldest queued read into ready_
    void dropReads();  // on the worker: reads queued but never to be taken

    GlWorker& worker_;
    Session& session_;
    const RenderRequest request_;
    // On the worker only.
    int next_ = 0;    // frames rendered
    int queued_ = 0;  // reads queued and not taken
    // Shared, under mutex_.
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<RenderedFrame> ready_;
    std::optional<Error> failed_;
    bool finished_ = false;   // every frame rendered and read
    bool running_ = false;    // a job is posted or running
    bool cancelled_ = false;
};

}  // namespace toyhost::python
