#include "drivers/window/OverlayRenderer.h"

#include <imgui.h>

#include <cstddef>
#include <cstdint>

#include "gl/GlStateGuard.h"
#include "gl/ShaderProgram.h"

namespace toyhost {

namespace {

const char* kVertex = R"(#version 300 es
uniform vec2 uScale;  // framebuffer pixels (top-left origin) to clip space
layout(location = 0) in vec2 aPosition;
layout(location = 1) in vec2 aUv;
layout(location = 2) in vec4 aColour;
out vec2 vUv;
out vec4 vColour;
void main() {
    vUv = aUv;
    vColour = aColour;
    gl_Position = vec4(aPosition * uScale + vec2(-1.0, 1.0), 0.0, 1.0);
}
)";

// uPicture: the texture is a pass's output, whose alpha means nothing on screen and whose
// non-finite texels must be seen (the inspector's NaN/Inf highlight).
const char* kFragment = R"(#version 300 es
precision highp float;
uniform sampler2D uTexture;
uniform bool uPicture;
in vec2 vUv;
in vec4 vColour;
out vec4 colour;
void main() {
    vec4 t = texture(uTexture, vUv);
    if (uPicture) {
        bool nonFinite = any(isnan(t)) || any(isinf(t));
        colour = nonFinite ? vec4(1.0, 0.0, 1.0, 1.0) : vec4(t.rgb, 1.0) * vColour;
    } else {
        colour = vColour * t;
    }
}
)";

GLuint textureName(ImTextureID id) { return static_cast<GLuint>(reinterpret_cast<std::uintptr_t>(id)); }

}  // namespace

Result<std::unique_ptr<OverlayRenderer>> OverlayRenderer::create() {
    std::unique_ptr<OverlayRenderer> r(new OverlayRenderer());
    ProgramBuild built = buildProgram(kVertex, kFragment);
    if (!built.ok) return Error("the window overlay's program does not build: " + built.log, Code::GlSetup);
    r->program_ = std::move(built.program);
    r->scaleLocation_ = glGetUniformLocation(r->program_.id(), "uScale");
    r->pictureLocation_ = glGetUniformLocation(r->program_.id(), "uPicture");
    r->textureLocation_ = glGetUniformLocation(r->program_.id(), "uTexture");

    GlStateGuard state;
    r->vertexArray_ = makeVertexArray();
    r->vertices_ = makeBuffer();
    r->indices_ = makeBuffer();
    glBindVertexArray(r->vertexArray_.id());
    glBindBuffer(GL_ARRAY_BUFFER, r->vertices_.id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->indices_.id());
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glEnableVertexAttribArray(2);
    const GLsizei stride = sizeof(ImDrawVert);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(ImDrawVert, pos)));
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(ImDrawVert, uv)));
    glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride, reinterpret_cast<void*>(offsetof(ImDrawVert, col)));
    glBindVertexArray(0);

    // Nearest everywhere: the font is drawn 1:1, and float targets need no filtering extension.
    r->sampler_ = makeSampler();
    glSamplerParameteri(r->sampler_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(r->sampler_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(r->sampler_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(r->sampler_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    r->font_ = makeTexture();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, r->font_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, width, height);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(r->font_.id())));
    return r;
}

void OverlayRenderer::render(const ImDrawData& data, int framebufferW, int framebufferH) {
    if (data.CmdListsCount == 0 || framebufferW <= 0 || framebufferH <= 0) return;
    GlStateGuard state;
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glViewport(0, 0, framebufferW, framebufferH);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_SCISSOR_TEST);
    glUseProgram(program_.id());
    glUniform2f(scaleLocation_, 2.0f / static_cast<float>(framebufferW), -2.0f / static_cast<float>(framebufferH));
    glUniform1i(textureLocation_, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindSampler(0, sampler_.id());
    glBindVertexArray(vertexArray_.id());
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());

    const ImVec2 origin = data.DisplayPos;
    for (int n = 0; n < data.CmdListsCount; ++n) {
        const ImDrawList& list = *data.CmdLists[n];
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(list.VtxBuffer.Size) * sizeof(ImDrawVert),
                     list.VtxBuffer.Data, GL_STREAM_DRAW);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(list.IdxBuffer.Size) * sizeof(ImDrawIdx),
                     list.IdxBuffer.Data, GL_STREAM_DRAW);
        for (const ImDrawCmd& cmd : list.CmdBuffer) {
            if (cmd.UserCallback) continue;  // the overlay installs none
            const float x0 = cmd.ClipRect.x - origin.x, y0 = cmd.ClipRect.y - origin.y;
            const float x1 = cmd.ClipRect.z - origin.x, y1 = cmd.ClipRect.w - origin.y;
            if (x1 <= x0 || y1 <= y0) continue;
            // The scissor box is bottom-left based.
            glScissor(static_cast<GLint>(x0), static_cast<GLint>(framebufferH - y1), static_cast<GLsizei>(x1 - x0),
                      static_cast<GLsizei>(y1 - y0));
            const GLuint texture = textureName(cmd.GetTexID());
            glUniform1i(pictureLocation_, texture != font_.id() ? 1 : 0);
            glBindTexture(GL_TEXTURE_2D, texture);
            glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(cmd.ElemCount),
                           sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT,
                           reinterpret_cast<void*>(static_cast<std::uintptr_t>(cmd.IdxOffset * sizeof(ImDrawIdx))));
        }
    }
    // What the guard does not restore: the renderer draws without blending and scissor, with its
    // own samplers bound where it samples.
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);
    glBindSampler(0, 0);
}

}  // namespace toyhost
