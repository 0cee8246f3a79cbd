#include "render/ReadbackRing.h"

#include <GLES3/gl3.h>
#include <cstring>

namespace toyhost {

Result<ReadbackRing> ReadbackRing::create(int width, int height, PixelFormat format, int slots, GpuActivity* gpu) {
    if (slots < 1) return Error("readback ring: needs at least one slot", Code::CaptureReadback);
    ReadbackRing ring;
    ring.reads_ = PendingReads(gpu);
    ring.width_ = width;
    ring.height_ = height;
    ring.format_ = format;
    ring.bytes_ = toyhost::frameBytes(width, height, format);
    ring.slots_ = static_cast<std::size_t>(slots);
    if (Status reserved = ring.reads_.reserve(ring.bytes_, ring.slots_); !reserved) return reserved.error();
    return ring;
}

Status ReadbackRing::start(unsigned int framebuffer, int frame) {
    return reads_.start(framebuffer, PendingReads::Read{frame, width_, height_, format_});
}

Status ReadbackRing::takeOldest(std::span<std::byte> out) {
    if (out.size() != bytes_) return Error("readback ring: destination has the wrong size", Code::CaptureReadback);
    Result<std::span<const std::byte>> pixels = reads_.mapOldest();
    if (!pixels) {
        (void)reads_.releaseOldest();
        return pixels.error();
    }
    std::memcpy(out.data(), pixels->data(), bytes_);
    return reads_.releaseOldest();
}

void readFramebuffer(unsigned int framebuffer, int width, int height, PixelFormat format, std::span<std::byte> out,
                     GpuActivity* gpu) {
    GpuActivity::Wait wait(gpu);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, format == PixelFormat::Rgba8 ? GL_UNSIGNED_BYTE : GL_FLOAT, out.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

}  // namespace toyhost
