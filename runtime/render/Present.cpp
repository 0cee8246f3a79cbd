#include "render/Present.h"

#include <GLES3/gl3.h>
#include <algorithm>
#include <cmath>

#include "gl/GlContext.h"

namespace toyhost {

PresentRect presentRect(int canvasW, int canvasH, int framebufferW, int framebufferH) {
    if (canvasW == framebufferW && canvasH == framebufferH) return {0, 0, canvasW, canvasH};
    const double scale = std::min(static_cast<double>(framebufferW) / canvasW, static_cast<double>(framebufferH) / canvasH);
    const int w = std::max(1, static_cast<int>(std::lround(canvasW * scale)));
    const int h = std::max(1, static_cast<int>(std::lround(canvasH * scale)));
    return {(framebufferW - w) / 2, (framebufferH - h) / 2, w, h};
}

void blitOutput(const PassOutput& output, unsigned int framebuffer, const PresentRect& r) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, output.framebuffer);
    const bool same = r.width == output.width && r.height == output.height;
    glBlitFramebuffer(0, 0, output.width, output.height, r.x, r.y, r.x + r.width, r.y + r.height, GL_COLOR_BUFFER_BIT,
                      same ? GL_NEAREST : GL_LINEAR);
}

Status drawOutput(const PassOutput& output, unsigned int framebuffer, const PresentRect& rect) {
    blitOutput(output, framebuffer, rect);
    if (GLenum error = glGetError(); error != GL_NO_ERROR) return Error(glErrorName(error), Code::GlSetup);
    return okStatus();
}

void presentToDefaultFramebuffer(const PassOutput& output, int framebufferW, int framebufferH) {
    const PresentRect r = presentRect(output.width, output.height, framebufferW, framebufferH);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    if (r.width != framebufferW || r.height != framebufferH) {
        glViewport(0, 0, framebufferW, framebufferH);
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    blitOutput(output, 0, r);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

void clearDefaultFramebuffer(int framebufferW, int framebufferH) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, framebufferW, framebufferH);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

}  // namespace toyhost
