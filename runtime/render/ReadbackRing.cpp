#include "render/ReadbackRing.h"

#include <GLES3/gl3.h>
#include <cstring>
#include <string>

#include "gl/GlContext.h"

namespace toyhost {

namespace {
GLenum glType(PixelFormat format) { return format == PixelFormat::Rgba8 ? GL_UNSIGNED_BYTE : GL_FLOAT; }
}  // namespace

Result<ReadbackRing> ReadbackRing::create(int width, int height, PixelFormat format, int slots) {
    if (slots < 1) return Error("readback ring: needs at least one slot", Code::CaptureReadback);
    ReadbackRing ring;
    ring.width_ = width;
    ring.height_ = height;
    ring.format_ = format;
    ring.bytes_ = toyhost::frameBytes(width, height, format);
    ring.slots_.resize(static_cast<std::size_t>(slots));
    for (Slot& slot : ring.slots_) {
        slot.buffer = makeBuffer();
        glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.buffer.id());
        glBufferData(GL_PIXEL_PACK_BUFFER, static_cast<GLsizeiptr>(ring.bytes_), nullptr, GL_STREAM_READ);
    }
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    if (GLenum error = glGetError(); error != GL_NO_ERROR)
        return Error(std::string("GL: cannot create the readback buffers: ") + glErrorName(error), Code::GlReadback);
    return ring;
}

void ReadbackRing::start(unsigned int framebuffer, int frame) {
    Slot& slot = slots_[(oldest_ + pending_) % slots_.size()];
    slot.frame = frame;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.buffer.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    // With a pack buffer bound, the last argument is an offset into it and the call only queues
    // the copy.
    glReadPixels(0, 0, width_, height_, GL_RGBA, glType(format_), nullptr);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    slot.fence = GlFence(glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0));
    // Submit now, so the GPU works on this frame while the render thread prepares the next.
    glFlush();
    ++pending_;
}

bool ReadbackRing::oldestReady() {
    const GLenum state = glClientWaitSync(slots_[oldest_].fence.get(), 0, 0);
    return state == GL_ALREADY_SIGNALED || state == GL_CONDITION_SATISFIED;
}

void ReadbackRing::dropOldest() {
    slots_[oldest_].fence.reset();
    oldest_ = (oldest_ + 1) % static_cast<int>(slots_.size());
    --pending_;
}

Status ReadbackRing::takeOldest(std::span<std::byte> out) {
    Slot& slot = slots_[oldest_];
    if (out.size() != bytes_) return Error("readback ring: destination has the wrong size", Code::CaptureReadback);
    for (;;) {
        // One second at a time: a large frame on a CPU renderer can take longer than any fixed
        // timeout, and GL_TIMEOUT_EXPIRED only means "not yet".
        const GLenum state = glClientWaitSync(slot.fence.get(), GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000);
        if (state == GL_ALREADY_SIGNALED || state == GL_CONDITION_SATISFIED) break;
        if (state == GL_WAIT_FAILED)
            return Error(std::string("GL: waiting for a frame's readback failed: ") + glErrorName(glGetError()),
                         Code::GlReadback);
    }
    slot.fence.reset();
    glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.buffer.id());
    const void* mapped = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, static_cast<GLsizeiptr>(bytes_), GL_MAP_READ_BIT);
    Status copied = okStatus();
    if (!mapped) {
        copied = Error(std::string("GL: cannot map a readback buffer: ") + glErrorName(glGetError()), Code::GlReadback);
    } else {
        std::memcpy(out.data(), mapped, bytes_);
        if (glUnmapBuffer(GL_PIXEL_PACK_BUFFER) != GL_TRUE)
            copied = Error("GL: a readback buffer's content was lost (glUnmapBuffer)", Code::GlReadback);
    }
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    oldest_ = (oldest_ + 1) % static_cast<int>(slots_.size());
    --pending_;
    return copied;
}

void readFramebuffer(unsigned int framebuffer, int width, int height, PixelFormat format, std::span<std::byte> out) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, glType(format), out.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

}  // namespace toyhost
