#include "render/PendingReads.h"

#include <GLES3/gl3.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "gl/GlContext.h"

namespace toyhost {

Status PendingReads::newBuffer(std::size_t bytes, GlBuffer& out) {
    out = toyhost::makeBuffer();
    glBindBuffer(GL_PIXEL_PACK_BUFFER, out.id());
    glBufferData(GL_PIXEL_PACK_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_STREAM_READ);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    if (GLenum error = glGetError(); error != GL_NO_ERROR)
        return Error(std::string("GL: cannot create a buffer for reading frames: ") + glErrorName(error), Code::GlReadback);
    return okStatus();
}

Status PendingReads::reserve(std::size_t bytes, std::size_t count) {
    spareLimit_ = std::max(spareLimit_, count);
    for (std::size_t i = 0; i < count; ++i) {
        GlBuffer buffer;
        if (Status made = newBuffer(bytes, buffer); !made) return made;
        spare_.emplace_back(bytes, std::move(buffer));
    }
    return okStatus();
}

Status PendingReads::start(unsigned int framebuffer, const Read& read) {
    Pending next;
    next.read = read;
    next.bytes = frameBytes(read.width, read.height, read.format);
    for (auto spare = spare_.begin(); spare != spare_.end(); ++spare)
        if (spare->first == next.bytes) {
            next.buffer = std::move(spare->second);
            spare_.erase(spare);
            break;
        }
    if (!next.buffer)
        if (Status made = newBuffer(next.bytes, next.buffer); !made) return made;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, next.buffer.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    // With a pack buffer bound, the last argument is an offset into it and the call only queues
    // the copy.
    glReadPixels(0, 0, read.width, read.height, GL_RGBA,
                 read.format == PixelFormat::Rgba8 ? GL_UNSIGNED_BYTE : GL_FLOAT, nullptr);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    next.fence = GlFence(glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0));
    // Submitted now, so that the GPU works on it while the caller goes on.
    glFlush();
    pending_.push_back(std::move(next));
    return okStatus();
}

bool PendingReads::oldestDone() const {
    const Pending& read = pending_.front();
    if (!read.fence) return true;
    const GLenum state = glClientWaitSync(read.fence.get(), 0, 0);
    return state == GL_ALREADY_SIGNALED || state == GL_CONDITION_SATISFIED;
}

Result<std::span<const std::byte>> PendingReads::mapOldest() {
    Pending& read = pending_.front();
    GpuActivity::Wait wait(gpu_);
    while (read.fence) {
        // One second at a time: a large frame on a CPU renderer can take longer than any fixed
        // timeout, and GL_TIMEOUT_EXPIRED only means "not yet".
        const GLenum state = glClientWaitSync(read.fence.get(), GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000);
        if (state == GL_ALREADY_SIGNALED || state == GL_CONDITION_SATISFIED) read.fence.reset();
        else if (state == GL_WAIT_FAILED)
            return Error(std::string("GL: waiting for a frame's read failed: ") + glErrorName(glGetError()),
                         Code::GlReadback);
    }
    glBindBuffer(GL_PIXEL_PACK_BUFFER, read.buffer.id());
    const void* mapped = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, static_cast<GLsizeiptr>(read.bytes), GL_MAP_READ_BIT);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    if (!mapped)
        return Error(std::string("GL: cannot map a frame's read buffer: ") + glErrorName(glGetError()), Code::GlReadback);
    read.mapped = true;
    return std::span<const std::byte>(static_cast<const std::byte*>(mapped), read.bytes);
}

Status PendingReads::releaseOldest() {
    Pending read = std::move(pending_.front());
    pending_.pop_front();
    Status released = okStatus();
    if (read.mapped) {
        glBindBuffer(GL_PIXEL_PACK_BUFFER, read.buffer.id());
        if (glUnmapBuffer(GL_PIXEL_PACK_BUFFER) != GL_TRUE)
            released = Error("GL: a frame's read buffer lost its content (glUnmapBuffer)", Code::GlReadback);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    }
    if (spare_.size() < spareLimit_) spare_.emplace_back(read.bytes, std::move(read.buffer));
    return released;
}

void PendingReads::clear() {
    while (!pending_.empty()) (void)releaseOldest();
    spare_.clear();
}

}  // namespace toyhost
