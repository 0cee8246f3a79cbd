#include "gl/GpuActivity.h"

#include <algorithm>

#include <GLES3/gl3.h>

namespace toyhost {

namespace {
GLsync sync(void* fence) { return static_cast<GLsync>(fence); }
bool signaled(void* fence) { return glClientWaitSync(sync(fence), 0, 0) != GL_TIMEOUT_EXPIRED; }
}  // namespace

void GpuActivity::attach(RunActivity* activity, bool watchDraws) {
    activity_ = activity;
    watchDraws_ = watchDraws && activity;
}

GpuActivity::Compiling::Compiling(GpuActivity& gpu, const char* pass) : gpu_(gpu) {
    if (gpu_.activity_) gpu_.activity_->begin(RunActivity::Phase::Compiling, pass);
}
GpuActivity::Compiling::~Compiling() {
    if (gpu_.activity_) gpu_.activity_->idle();
}

GpuActivity::Wait::Wait(GpuActivity* gpu) : gpu_(gpu) {
    if (gpu_) gpu_->publishPending();
}
GpuActivity::Wait::~Wait() {
    if (gpu_) gpu_->publishPending();
}

void GpuActivity::beforeDraw(const char* pass, int frame) {
    if (!watchDraws_) return;
    // While the call has not returned, this pass is what the run waits for, whatever older draws
    // are pending; what was published before comes back once it returns (afterDraw).
    beforeCall_ = activity_->snapshot();
    activity_->begin(RunActivity::Phase::DrawCall, pass, frame);
}

void GpuActivity::afterDraw(const char* pass, int frame) {
    if (!watchDraws_) return;
    if (count_ == items_.size()) dropOldest();
    items_[count_++] = {glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0), pass, frame};
    if (count_ == 1) {
        // Nothing older: the GPU now draws this pass, timed from the start of its call.
        published_ = items_[0].fence;
        activity_->rephase(RunActivity::Phase::Drawing);
    } else {
        activity_->restore(beforeCall_);  // the oldest pending draw, with its own start time
    }
}

void GpuActivity::beforeSample(const char* pass, int frame, int sample, int samples) {
    if (!watchDraws_) return;
    if (count_) {  // the frame's buffers: published as the pass still drawing, as a readback's wait
        publishPending();
        if (count_) waitFor(items_[count_ - 1].fence);
        dropAll();
        published_ = nullptr;
    }
    activity_->begin(RunActivity::Phase::DrawCall, pass, frame, sample, samples);
}

void GpuActivity::afterSample() {
    if (!watchDraws_) return;
    activity_->rephase(RunActivity::Phase::Drawing);  // timed from the sample's call
    void* fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    waitFor(fence);
    glDeleteSync(sync(fence));
    activity_->idle();
}

void GpuActivity::waitFor(void* fence) {
    // Without a limit of its own: a watchdog ends a wait that takes too long.
    while (glClientWaitSync(sync(fence), GL_SYNC_FLUSH_COMMANDS_BIT, 1000000000) == GL_TIMEOUT_EXPIRED) {
    }
}

void GpuActivity::publishPending() {
    if (!watchDraws_) return;
    // The GPU finishes passes in order: when the newest is done, all are (one query, the usual
    // case between frames); else the oldest unfinished is searched from the front.
    if (count_ && signaled(items_[count_ - 1].fence)) dropAll();
    while (count_ && signaled(items_[0].fence)) dropOldest();
    if (!count_) {
        published_ = nullptr;
        activity_->idle();
        return;
    }
    if (items_[0].fence == published_) return;
    published_ = items_[0].fence;
    activity_->begin(RunActivity::Phase::Drawing, items_[0].pass, items_[0].frame);
}

void GpuActivity::clear() {
    dropAll();
    published_ = nullptr;
}

void GpuActivity::dropAll() {
    for (std::size_t i = 0; i < count_; ++i) glDeleteSync(sync(items_[i].fence));
    count_ = 0;
}

void GpuActivity::dropOldest() {
    glDeleteSync(sync(items_[0].fence));
    std::move(items_.begin() + 1, items_.begin() + static_cast<std::ptrdiff_t>(count_), items_.begin());
    --count_;
}

}  // namespace toyhost
