#include "media/VideoStream.h"

#include <algorithm>
#include <cmath>

#include "core/Defaults.h"
#include "image/PixelConversion.h"

namespace toyhost {

namespace {
// Frames the queue holds ahead of the one shown: defaults::kVideoAheadFrames, fewer for frames so
// large that they would pass kVideoAheadBytes, at least one.
std::size_t aheadFrames(int width, int height) {
    const std::size_t bytes = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
    const std::size_t fit = bytes ? defaults::kVideoAheadBytes / bytes : 1;
    return std::clamp<std::size_t>(fit, 1, static_cast<std::size_t>(defaults::kVideoAheadFrames));
}
}  // namespace

VideoStream::VideoStream(std::unique_ptr<VideoSource> source)
    : source_(std::move(source)), info_(source_->info()), live_(source_->live()) {
    const std::size_t bytes = static_cast<std::size_t>(info_.width) * static_cast<std::size_t>(info_.height) * 4;
    frameBytes_ = bytes;
    // The first frame, decoded while opening, is the one shown.
    shown_ = Image8{info_.width, info_.height, std::vector<std::uint8_t>(bytes)};
    source_->exchangeFrame(shown_.rgba);
    shownIndex_ = 0;
    shownVersion_ = 1;
    if (live_) {
        newest_.resize(bytes);
    } else {
        ring_.resize(aheadFrames(info_.width, info_.height));
        for (Entry& entry : ring_) entry.rgba.resize(bytes);
        decodeNext_ = info_.frameCount > 1 ? 1 : 0;
        // As VideoSource: reading ahead costs a few ms a frame, a restart of ffmpeg tenths of a
        // second, so up to about two seconds of video are read through rather than sought.
        maxSkip_ = std::max<std::int64_t>(30, std::llround(2 * info_.fps));
    }
}

Result<std::shared_ptr<VideoStream>> VideoStream::openFile(const std::filesystem::path& path) {
    Result<std::unique_ptr<VideoSource>> source = VideoSource::openFile(path);
    if (!source) return source.error();
    std::shared_ptr<VideoStream> stream(new VideoStream(std::move(*source)));
    stream->thread_ = std::thread([raw = stream.get()] { raw->decodeFiles(); });
    return stream;
}

Result<std::shared_ptr<VideoStream>> VideoStream::openDevice(const std::string& device) {
    Result<std::unique_ptr<VideoSource>> source = VideoSource::openDevice(device);
    if (!source) return source.error();
    std::shared_ptr<VideoStream> stream(new VideoStream(std::move(*source)));
    stream->thread_ = std::thread([raw = stream.get()] { raw->readCamera(); });
    return stream;
}

VideoStream::~VideoStream() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    changed_.notify_all();
    source_->interrupt();  // a read waiting on ffmpeg returns at once
    if (thread_.joinable()) thread_.join();
}

std::int64_t VideoStream::frameIndexAt(double seconds) const { return source_->frameIndexAt(seconds); }
double VideoStream::playbackTime(double seconds) const { return source_->playbackTime(seconds); }
int VideoStream::decoderStarts() const { return source_->decoderStarts(); }

std::uint64_t VideoStream::waits() const {
    std::lock_guard lock(mutex_);
    return waits_;
}

void VideoStream::waitUntilQueued() const {
    if (live_) return;
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return stop_ || error_.has_value() || count_ == ring_.size(); });
}

std::int64_t VideoStream::forward(std::int64_t from, std::int64_t to) const {
    const std::int64_t count = std::max<std::int64_t>(info_.frameCount, 1);
    return ((to - from) % count + count) % count;
}

void VideoStream::reposition(std::int64_t index) {
    head_ = 0;
    count_ = 0;
    decodeNext_ = index;
    ++generation_;
    error_.reset();
    errorReported_ = false;
    changed_.notify_all();
}

void VideoStream::decodeFiles() {
    std::vector<std::uint8_t> work(frameBytes_);
    std::unique_lock lock(mutex_);
    for (;;) {
        changed_.wait(lock, [&] { return stop_ || (!error_ && count_ < ring_.size()); });
        if (stop_) return;
        const std::uint64_t generation = generation_;
        const std::int64_t index = decodeNext_;
        lock.unlock();
        // VideoSource reads forward to `index` or restarts ffmpeg there, whichever is cheaper.
        Result<const Image8*> decoded = source_->frameByIndex(index);
        if (decoded) source_->exchangeFrame(work);
        lock.lock();
        if (generation != generation_) continue;  // repositioned meanwhile: this frame is not wanted
        if (!decoded) {
            error_ = decoded.error();
            changed_.notify_all();
            continue;
        }
        Entry& slot = ring_[(head_ + count_) % ring_.size()];
        slot.index = index;
        std::swap(slot.rgba, work);
        ++count_;
        decodeNext_ = (index + 1) % std::max<std::int64_t>(info_.frameCount, 1);
        changed_.notify_all();
    }
}

void VideoStream::readCamera() {
    std::vector<std::uint8_t> work(frameBytes_);
    for (;;) {
        {
            std::lock_guard lock(mutex_);
            if (stop_) return;
        }
        Result<const Image8*> next = source_->nextCameraFrame();
        if (next) source_->exchangeFrame(work);
        std::lock_guard lock(mutex_);
        if (!next) {
            // The camera stopped: its last frame stays; the error is reported once.
            error_ = next.error();
            return;
        }
        std::swap(newest_, work);
        ++newestVersion_;
    }
}

Result<const Image8*> VideoStream::frame(std::int64_t index, const InputWait& wait) {
    if (live_) {
        std::lock_guard lock(mutex_);
        if (newestVersion_ != takenCameraVersion_) {
            std::swap(shown_.rgba, newest_);
            takenCameraVersion_ = newestVersion_;
            ++shownVersion_;
        } else if (error_) {
            Error failed = std::move(*error_);
            error_.reset();
            return failed;
        }
        return &shown_;
    }
    if (index < 0 || index >= info_.frameCount) index = 0;
    if (index == shownIndex_) return &shown_;

    std::unique_lock lock(mutex_);
    bool waited = false;
    bool repositioned = false;
    auto done = [&] {
        if (waited && wait.activity) wait.activity->idle();
    };
    for (;;) {
        // Queued frames before `index` (going forward, within reach) are not wanted any more.
        while (count_ > 0) {
            Entry& entry = ring_[head_];
            if (entry.index == index) {
                std::swap(shown_.rgba, entry.rgba);
                shownIndex_ = index;
                ++shownVersion_;
                head_ = (head_ + 1) % ring_.size();
                --count_;
                changed_.notify_all();
                done();
                return &shown_;
            }
            const std::int64_t ahead = forward(entry.index, index);
            if (ahead == 0 || ahead > maxSkip_) break;
            head_ = (head_ + 1) % ring_.size();
            --count_;
            changed_.notify_all();
        }
        if (error_ && !repositioned && !errorReported_ && count_ == 0 && forward(decodeNext_, index) <= maxSkip_) {
            // The decoder died on its way to this frame (and everything it queued was shown): say
            // so once, whenever the reader thread noticed; the next request starts another.
            errorReported_ = true;
            Error failed = *error_;
            done();
            return failed;
        }
        if (error_ && repositioned) {
            // The decoder failed on the way to this frame.
            Error failed = *error_;
            done();
            return failed;
        }
        // Behind the queue, far ahead of it, or after a failure: the decoder starts over there.
        const std::int64_t from = count_ > 0 ? ring_[head_].index : decodeNext_;
        if (!repositioned && (count_ > 0 || error_ || forward(from, index) > maxSkip_)) {
            reposition(index);
            repositioned = true;
            continue;
        }
        repositioned = true;  // from here on the decoder is on its way to `index`
        if (!waited) {
            waited = true;
            ++waits_;
            if (wait.activity) wait.activity->begin(RunActivity::Phase::WaitingForInput, wait.pass, wait.frame);
        }
        changed_.wait(lock, [&] { return count_ > 0 || error_.has_value(); });
    }
}

}  // namespace toyhost
