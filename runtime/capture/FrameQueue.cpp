#include "capture/FrameQueue.h"

#include <algorithm>
#include <chrono>

namespace toyhost {

FrameQueue::FrameQueue(std::size_t capBytes) : cap_(capBytes) {}

std::optional<std::vector<std::byte>> FrameQueue::acquire(std::size_t bytes, bool wait,
                                                          const std::function<bool()>& cancelled) {
    std::unique_lock lock(mutex_);
    for (;;) {
        if (aborted_) return std::nullopt;
        // A pooled buffer of the right size costs nothing new: every frame of a run has one size.
        auto fits = std::find_if(pool_.begin(), pool_.end(), [&](const auto& b) { return b.size() == bytes; });
        if (fits != pool_.end()) {
            std::vector<std::byte> buffer = std::move(*fits);
            pool_.erase(fits);
            return buffer;
        }
        // Pooled buffers of another size are released before anything new is allocated.
        while (!pool_.empty() && allocated_ + bytes > cap_) {
            allocated_ -= pool_.back().size();
            pool_.pop_back();
        }
        if (allocated_ + bytes <= cap_ || allocated_ == 0) {
            allocated_ += bytes;
            peak_ = std::max(peak_, allocated_);
            lock.unlock();
            return std::vector<std::byte>(bytes);
        }
        if (!wait) return std::nullopt;
        ++blockedProducers_;
        if (cancelled) bufferFreed_.wait_for(lock, std::chrono::milliseconds(50));
        else bufferFreed_.wait(lock);
        --blockedProducers_;
        if (cancelled && cancelled()) return std::nullopt;
    }
}

void FrameQueue::push(CapturedFrame frame) {
    {
        std::lock_guard lock(mutex_);
        if (aborted_) return;
        frames_.push_back(std::move(frame));
    }
    frameQueued_.notify_one();
}

std::optional<CapturedFrame> FrameQueue::pop() {
    std::unique_lock lock(mutex_);
    ++blockedConsumers_;
    frameQueued_.wait(lock, [&] { return aborted_ || closed_ || !frames_.empty(); });
    --blockedConsumers_;
    if (aborted_ || frames_.empty()) return std::nullopt;
    CapturedFrame frame = std::move(frames_.front());
    frames_.pop_front();
    return frame;
}

void FrameQueue::recycle(std::vector<std::byte> buffer) {
    {
        std::lock_guard lock(mutex_);
        if (aborted_) {
            allocated_ -= std::min(allocated_, buffer.size());
            return;
        }
        pool_.push_back(std::move(buffer));
    }
    bufferFreed_.notify_one();
}

void FrameQueue::close() {
    {
        std::lock_guard lock(mutex_);
        closed_ = true;
    }
    frameQueued_.notify_all();
}

void FrameQueue::abort() {
    {
        std::lock_guard lock(mutex_);
        aborted_ = true;
        for (const CapturedFrame& frame : frames_) allocated_ -= std::min(allocated_, frame.pixels.size());
        frames_.clear();
    }
    frameQueued_.notify_all();
    bufferFreed_.notify_all();
}

std::size_t FrameQueue::allocatedBytes() const {
    std::lock_guard lock(mutex_);
    return allocated_;
}

std::size_t FrameQueue::blockedProducers() const {
    std::lock_guard lock(mutex_);
    return blockedProducers_;
}

std::size_t FrameQueue::queuedFrames() const {
    std::lock_guard lock(mutex_);
    return frames_.size();
}

std::size_t FrameQueue::blockedConsumers() const {
    std::lock_guard lock(mutex_);
    return blockedConsumers_;
}

std::size_t FrameQueue::peakAllocatedBytes() const {
    std::lock_guard lock(mutex_);
    return peak_;
}

}  // namespace toyhost
