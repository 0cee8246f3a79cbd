#include "render/DrawFences.h"

#include <GLES3/gl3.h>

#include <string>

#include "gl/GlContext.h"

namespace toyhost {

void DrawFences::submitted() { fences_.emplace_back(glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0)); }

Status DrawFences::waitBelow(std::size_t count) {
    while (!fences_.empty() && fences_.size() >= count) {
        GLenum state;
        {
            // The wait is for the GPU drawing: the watchdog is told which pass.
            GpuActivity::Wait wait(gpu_);
            // One second at a time: GL_TIMEOUT_EXPIRED only means "not yet".
            state = glClientWaitSync(fences_.front().get(), GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000);
        }
        if (state == GL_WAIT_FAILED)
            return Error(std::string("GL: waiting for a frame to be drawn failed: ") + glErrorName(glGetError()),
                         Code::GlReadback);
        if (state == GL_ALREADY_SIGNALED || state == GL_CONDITION_SATISFIED) fences_.pop_front();
    }
    return okStatus();
}

}  // namespace toyhost
