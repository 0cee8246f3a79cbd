// RenderStream: the worker's side (one job per frame) and Python's (next, cancel).
#include "RenderStream.h"

#include <new>
#include <span>

#include "Errors.h"

namespace toyhost::python {

std::shared_ptr<RenderStream> RenderStream::start(GlWorker& worker, Session& session, RenderRequest request) {
    std::shared_ptr<RenderStream> stream(new RenderStream(worker, session, std::move(request)));
    std::lock_guard<std::mutex> lock(stream->mutex_);
    if (stream->request_.frames <= 0) {
        stream->finished_ = true;
    } else {
        stream->running_ = true;
        stream->post();
    }
    return stream;
}

void RenderStream::post() {
    worker_.post([self = shared_from_this()] { self->renderOne(); });
}

void RenderStream::renderOne() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (cancelled_) {
            running_ = false;
            changed_.notify_all();
            return;
        }
    }
    Status done = okStatus();
    const int frames = request_.frames;
    if (next_ < frames) {
        std::span<const InputEvent> events;
        if (next_ == 0) events = request_.firstEvents;
        done = session_.step(events);
        if (done && (next_ % request_.every == 0 || next_ == frames - 1)) {
            Result<Session::QueuedRead> queued = session_.queueRead(request_.pass);
            if (!queued) done = queued.error();
        }
        ++next_;
    }
    // Reads that are complete are taken (without waiting); the oldest is waited for only when
    // kInFlight wait, or when every frame was rendered: the frames just queued render meanwhile.
    try {
        while (done && session_.queuedReads() > 0 &&
               (next_ >= frames || session_.queuedReads() > kInFlight || session_.nextQueuedReadDone()))
            done = takeOne();
    } catch (const std::bad_alloc&) {  // a frame's memory: the job must not throw
        done = Error("render: out of memory for a frame's pixels", Code::Internal);
    }
    if (!done) dropReads();

    std::lock_guard<std::mutex> lock(mutex_);
    if (!done) {
        failed_ = done.error();
        running_ = false;
    } else if (next_ >= frames && session_.queuedReads() == 0) {
        finished_ = true;
        running_ = false;
    } else if (cancelled_ || ready_.size() >= kReady) {
        running_ = false;  // next() posts the next job once Python has taken a frame
    } else {
        post();
    }
    if (!running_) changed_.notify_all();  // finished, failed or paused: Python must look
}

Status RenderStream::takeOne() {
    const std::optional<Session::QueuedRead> read = session_.nextQueuedRead();
    if (!read) return okStatus();
    RenderedFrame frame;
    frame.width = read->width;
    frame.height = read->height;
    const std::size_t values = static_cast<std::size_t>(read->width) * read->height * 4;
    Result<Session::QueuedRead> taken = Session::QueuedRead{};
    if (request_.floats) {
        frame.floats = std::make_unique_for_overwrite<float[]>(values);
        taken = session_.takeRead(std::span<float>(frame.floats.get(), values), RowOrder::TopFirst);
    } else {
        frame.bytes = std::make_unique_for_overwrite<std::uint8_t[]>(values);
        taken = session_.takeRead(std::span<std::uint8_t>(frame.bytes.get(), values), RowOrder::TopFirst);
    }
    if (!taken) return taken.error();
    frame.frame = taken->frame;
    std::lock_guard<std::mutex> lock(mutex_);
    if (!cancelled_) ready_.push_back(std::move(frame));  // else dropped, as cancel() says
    if (ready_.size() >= kWakeAt) changed_.notify_all();
    return okStatus();
}

void RenderStream::dropReads() { session_.dropQueuedReads(); }

std::optional<RenderedFrame> RenderStream::next() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        if (cancelled_) return std::nullopt;
        if (!ready_.empty()) {
            RenderedFrame frame = std::move(ready_.front());
            ready_.pop_front();
            if (!running_ && !finished_ && !failed_ && !cancelled_ && ready_.size() < kReady) {
                running_ = true;
                post();
            }
            return frame;
        }
        if (failed_) {
            Error failure = std::move(*failed_);
            failed_.reset();
            finished_ = true;  // said once; the stream ends with it
            throw ToyhostError(std::move(failure));
        }
        if (finished_) return std::nullopt;
        // Woken once kWakeAt frames are ready (or the worker stopped), not for each frame: a
        // wake-up costs the Python thread and the renderer more than the frames' handing over.
        changed_.wait(lock, [&] { return cancelled_ || failed_ || finished_ || !running_ || ready_.size() >= kWakeAt; });
    }
}

void RenderStream::cancel() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (cancelled_) return;
        cancelled_ = true;
        ready_.clear();
        changed_.notify_all();
        if (finished_) return;  // nothing left queued in the session
    }
    // After the job running now (if any): reads it queued are dropped before any later call runs.
    worker_.post([self = shared_from_this()] { self->dropReads(); });
}

}  // namespace toyhost::python
