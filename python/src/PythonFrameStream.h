// PythonFrameStream: Session.render()'s frames, rendered ahead of the Python loop that takes them,
// through the library's frame stream (Session::Rendering: the capture-every rule, the reads in
// flight, each frame handed over as soon as its read completes). On the GL worker, one job per
// frame (Rendering::advance), so that jobs of other calls run between frames; frames are read
// straight into the memory their numpy arrays will own, and up to kReady wait for Python. Python
// takes them in order, waiting with the GIL released. While it waits, a signal (Ctrl-C) reaches the
// stream through Python's wakeup fd (signalWakeupFd): the worker sees it before starting another
// frame and hands the question back to Python, so the rendering stops after the frame that was
// being rendered when the signal came. No GL of its own: the jobs use the session's.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <toyhost/Result.h>
#include <toyhost/Session.h>

#include "GlWorker.h"
#include "Signals.h"

namespace toyhost::python {

struct RenderRequest {
    Session::RenderRequest frames;  // which frames, which pass, the events before the first
    bool floats = false;            // float32 values, else uint8
};

// One frame read, in memory a numpy array can take over (rows top first).
struct RenderedFrame {
    int frame = 0;
    int width = 0;
    int height = 0;
    std::unique_ptr<std::uint8_t[]> bytes;  // width * height * 4, when !floats
    std::unique_ptr<float[]> floats;        // width * height * 4, when floats
};

class PythonFrameStream : public std::enable_shared_from_this<PythonFrameStream> {
public:
    // Frames rendered ahead of the one Python takes: enough to keep the worker busy while Python
    // handles a frame; each costs its pixels' memory.
    static constexpr std::size_t kReady = 4;
    // Python, finding no frame ready, sleeps until this many are (one wake-up per kWakeAt frames
    // when every frame is read), or until a frame is ready and no other read is on its way, or a
    // frame went by with nothing handed over.
    static constexpr std::size_t kWakeAt = 2;

    // What next() throws when `interrupted` said so (a Python exception, such as KeyboardInterrupt,
    // is set): the caller raises it.
    struct Interrupted {};

    // `session` lives on `worker` and outlives the stream's jobs (cancel() before closing it).
    static std::shared_ptr<PythonFrameStream> start(GlWorker& worker, Session& session, RenderRequest request);
    ~PythonFrameStream();
    PythonFrameStream(const PythonFrameStream&) = delete;
    PythonFrameStream& operator=(const PythonFrameStream&) = delete;

    // The write end of the stream's signal pipe (non-blocking), for Python's wakeup fd
    // (PySignal_SetWakeupFd) while the main thread waits in next(): a signal's byte written there
    // pauses the rendering before its next frame and wakes next(), which asks `interrupted`.
    int signalWakeupFd() const { return signals_.writeFd(); }
    // The signal bytes the stream received (read by the worker, or still in the pipe), taken: the
    // caller hands them on to the wakeup fd that was there before.
    std::string takeSignalBytes();

    // The next frame, waiting for it (call without the GIL); nothing once every frame was taken.
    // Throws ToyhostError with what stopped the rendering, after the frames read before it.
    // `interrupted` (called without the stream's lock, may take the GIL) is asked whenever the
    // wait wakes with no frame, and before anything else once a signal arrived through
    // signalWakeupFd(): true ends the wait (Interrupted thrown); false after a signal lets the
    // rendering go on.
    std::optional<RenderedFrame> next(const std::function<bool()>& interrupted = {});
    // Stops rendering after the frame being rendered; frames not taken are dropped. The session
    // stays where the rendering got (its later calls run after this). Idempotent. With `reason`
    // (the session closing under the loop), every later next() throws it: the loop must not end
    // as if every frame was rendered (once a defect: a close() from another thread raced the
    // Python side's look at the session and the loop ended normally 4 times in 5).
    void cancel(std::optional<Error> reason = std::nullopt);

private:
    PythonFrameStream(GlWorker& worker, Session& session, RenderRequest request);
    void post();       // the next job
    void resume();           // under mutex_: the next job, unless running, ended or enough frames wait
    void renderOne();  // on the worker: one frame, then the next job when there is room
    bool take(const Session::RenderedFrame& frame);  // on the worker: a frame handed over, into ready_

    GlWorker& worker_;
    Session& session_;
    const RenderRequest request_;
    // On the worker only.
    std::unique_ptr<Session::Rendering> rendering_;
    bool started_ = false;
    std::optional<Error> takeFailed_;
    // Shared, under mutex_.
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<RenderedFrame> ready_;
    std::optional<Error> failed_;
    bool finished_ = false;  // every frame rendered and read
    bool running_ = false;   // a job is posted or running
    bool cancelled_ = false;
    std::optional<Error> cancelledBecause_;  // what next() throws once cancelled, if anything
    bool waiting_ = false;   // Python waits in next()
    unsigned wakes_ = 0;     // wake-ups given to a waiting next()
    bool signalled_ = false;  // a signal arrived: no frame starts before Python looked at it
    // The signal pipe (without it, signals are still seen between frames: the wake after each
    // frame); what it carried is kept for the wakeup fd before ours.
    SignalPipe signals_;
};

}  // namespace toyhost::python
