// PythonFrameStream: the worker's side (one Rendering::advance per job) and Python's (next, cancel).
#include "PythonFrameStream.h"

#include <new>
#include <span>
#include <utility>

#include "Errors.h"

namespace toyhost::python {

std::shared_ptr<PythonFrameStream> PythonFrameStream::start(GlWorker& worker, Session& session, RenderRequest request) {
    std::shared_ptr<PythonFrameStream> stream(new PythonFrameStream(worker, session, std::move(request)));
    std::lock_guard<std::mutex> lock(stream->mutex_);
    stream->running_ = true;
    stream->post();
    return stream;
}

PythonFrameStream::PythonFrameStream(GlWorker& worker, Session& session, RenderRequest request)
    : worker_(worker), session_(session), request_(std::move(request)) {}

std::string PythonFrameStream::takeSignalBytes() {
    std::lock_guard<std::mutex> lock(mutex_);
    return signals_.take();
}

void PythonFrameStream::resume() {
    if (!running_ && !finished_ && !failed_ && !cancelled_ && !signalled_ && ready_.size() < kReady) {
        running_ = true;
        post();
    }
}

PythonFrameStream::~PythonFrameStream() {
    // The rendering's GL buffers go on the session's thread (jobs run there before the session is
    // closed, and a closed worker runs nothing: then the session freed its context already).
    if (rendering_)
        worker_.post([rendering = std::shared_ptr<Session::Rendering>(std::move(rendering_))]() mutable {
            rendering.reset();
        });
}

void PythonFrameStream::post() {
    worker_.post([self = shared_from_this()] { self->renderOne(); });
}

bool PythonFrameStream::take(const Session::RenderedFrame& read) {
    RenderedFrame frame;
    frame.frame = read.frame;
    frame.width = read.width;
    frame.height = read.height;
    const std::size_t values = static_cast<std::size_t>(read.width) * read.height * 4;
    Status copied = okStatus();
    if (request_.floats) {
        frame.floats = std::make_unique_for_overwrite<float[]>(values);
        copied = read.read(std::span<float>(frame.floats.get(), values), RowOrder::TopFirst);
    } else {
        frame.bytes = std::make_unique_for_overwrite<std::uint8_t[]>(values);
        copied = read.read(std::span<std::uint8_t>(frame.bytes.get(), values), RowOrder::TopFirst);
    }
    if (!copied) {
        takeFailed_ = copied.error();
        return false;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    if (cancelled_) return false;  // dropped, as cancel() says; the rendering stops
    ready_.push_back(std::move(frame));
    return true;
}

void PythonFrameStream::renderOne() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (signals_.drain()) signalled_ = true;
        if (cancelled_ || signalled_) {  // a signal: Python looks at it before another frame starts
            running_ = false;
            ++wakes_;
            changed_.notify_all();
            return;
        }
    }
    Result<bool> more = true;
    std::size_t readyBefore = 0;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        readyBefore = ready_.size();
    }
    try {
        if (!started_) {
            started_ = true;
            Result<std::unique_ptr<Session::Rendering>> made = session_.startRendering(request_.frames);
            if (made) rendering_ = std::move(*made);
            else more = made.error();
        }
        if (rendering_) {
            more = rendering_->advance([this](const Session::RenderedFrame& frame) { return take(frame); });
            if (more && takeFailed_) more = *takeFailed_;
        }
    } catch (const std::bad_alloc&) {  // a frame's memory: the job must not throw
        more = Error("render: out of memory for a frame's pixels", Code::Internal);
    }
    const int inFlight = rendering_ ? rendering_->readsInFlight() : 0;
    if (!more || !*more) rendering_.reset();  // the end: reads not taken are dropped

    std::lock_guard<std::mutex> lock(mutex_);
    const bool handedOver = ready_.size() > readyBefore;
    if (!more) {
        failed_ = more.error();
        running_ = false;
    } else if (!*more) {
        finished_ = true;
        running_ = false;
    } else if (cancelled_ || ready_.size() >= kReady) {
        running_ = false;  // next() posts the next job once Python has taken a frame
    } else {
        post();
    }
    // Python is woken when it must look (finished, failed, paused), when enough frames wait, when a
    // frame waits and no other is on its way, or after a frame with nothing for it (to see Ctrl-C).
    const bool wake = !running_ || ready_.size() >= kWakeAt || (!ready_.empty() && inFlight == 0) ||
                      (waiting_ && !handedOver);
    if (wake) {
        ++wakes_;
        changed_.notify_all();
    }
}

std::optional<RenderedFrame> PythonFrameStream::next(const std::function<bool()>& interrupted) {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        if (cancelled_) {
            if (cancelledBecause_) throw ToyhostError(*cancelledBecause_);
            return std::nullopt;
        }
        if (signalled_) {
            bool stop = false;
            if (interrupted) {
                lock.unlock();
                stop = interrupted();
                lock.lock();
            }
            if (stop) throw Interrupted{};
            signalled_ = false;  // a signal whose handler raised nothing: the rendering goes on
            resume();
            continue;
        }
        if (!ready_.empty()) {
            RenderedFrame frame = std::move(ready_.front());
            ready_.pop_front();
            resume();
            return frame;
        }
        if (failed_) {
            Error failure = std::move(*failed_);
            failed_.reset();
            finished_ = true;  // said once; the stream ends with it
            throw ToyhostError(std::move(failure));
        }
        if (finished_) return std::nullopt;
        const unsigned seen = wakes_;
        waiting_ = true;
        changed_.wait(lock, [&] {
            return cancelled_ || failed_ || finished_ || !running_ || signalled_ || ready_.size() >= kWakeAt ||
                   wakes_ != seen;
        });
        waiting_ = false;
        if (ready_.empty() && !signalled_ && !cancelled_ && !failed_ && !finished_ && interrupted) {
            lock.unlock();
            const bool stop = interrupted();
            lock.lock();
            if (stop) throw Interrupted{};
        }
    }
}

void PythonFrameStream::cancel(std::optional<Error> reason) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (cancelled_) return;
        cancelled_ = true;
        cancelledBecause_ = std::move(reason);
        ready_.clear();
        changed_.notify_all();
        if (finished_) return;  // nothing left in the session
    }
    // After the job running now (if any, which stops at its next frame handed over): the
    // rendering's reads are dropped before any later call runs.
    worker_.post([self = shared_from_this()] { self->rendering_.reset(); });
}

}  // namespace toyhost::python
