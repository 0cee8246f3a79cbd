#include "render/SampleAccumulator.h"

#include <GLES3/gl3.h>

#include "gl/ShaderProgram.h"
#include "shader/ShaderAssembly.h"

namespace toyhost {

namespace {

// texelFetch: one texel per pixel, no filtering; an RGBA8 sample reads as k / 255 exactly.
constexpr const char* kAddShader = R"(#version 300 es
precision highp float;
precision highp sampler2D;
uniform sampler2D toyhostSample;
uniform sampler2D toyhostSum;
uniform int toyhostFirst;
out vec4 toyhostOut;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 s = texelFetch(toyhostSample, p, 0);
    toyhostOut = toyhostFirst == 1 ? s : texelFetch(toyhostSum, p, 0) + s;
}
)";

// The 8x8 Bayer matrix from the bits of x ^ y and y interleaved and reversed: thresholds
// (0.5 .. 63.5) / 64, centred on zero, a level of 8 bits wide.
constexpr const char* kResolveShader = R"(#version 300 es
precision highp float;
precision highp sampler2D;
uniform sampler2D toyhostSum;
uniform float toyhostScale;
uniform int toyhostDither;
out vec4 toyhostOut;
int bayer8(ivec2 p) {
    int x = p.x & 7, y = p.y & 7, xy = x ^ y;
    return ((xy & 1) << 5) | ((y & 1) << 4) | ((xy & 2) << 2) | ((y & 2) << 1) | ((xy & 4) >> 1) | ((y & 4) >> 2);
}
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 c = texelFetch(toyhostSum, p, 0) * toyhostScale;
    if (toyhostDither == 1) c.rgb += ((float(bayer8(p)) + 0.5) / 64.0 - 0.5) / 255.0;
    toyhostOut = c;
}
)";

Result<GlProgram> build(const char* fragment, const char* what) {
    ProgramBuild built = buildProgram(fullscreenVertexShader(), fragment);
    if (!built.ok) return Error(std::string("GL: the ") + what + " program did not build: " + built.log, Code::GlSetup);
    return std::move(built.program);
}

Result<std::array<RenderTexture, 2>> makeSums(int width, int height, const TextureAllocator& allocate) {
    std::array<RenderTexture, 2> sums;
    for (RenderTexture& sum : sums) {
        Result<RenderTexture> made = allocate(width, height, GL_RGBA32F, false);
        if (!made) return made.error();
        sum = std::move(*made);
    }
    return sums;
}

}  // namespace

Result<SampleAccumulator> SampleAccumulator::create(int width, int height, const TextureAllocator& allocate) {
    SampleAccumulator a;
    Result<GlProgram> add = build(kAddShader, "sample sum");
    if (!add) return add.error();
    Result<GlProgram> resolve = build(kResolveShader, "sample average");
    if (!resolve) return resolve.error();
    Programs& p = a.programs_;
    p.add = std::move(*add);
    p.resolve = std::move(*resolve);
    p.addSample = glGetUniformLocation(p.add.id(), "toyhostSample");
    p.addSum = glGetUniformLocation(p.add.id(), "toyhostSum");
    p.addFirst = glGetUniformLocation(p.add.id(), "toyhostFirst");
    p.resolveSum = glGetUniformLocation(p.resolve.id(), "toyhostSum");
    p.resolveScale = glGetUniformLocation(p.resolve.id(), "toyhostScale");
    p.resolveDither = glGetUniformLocation(p.resolve.id(), "toyhostDither");
    glUseProgram(p.add.id());
    glUniform1i(p.addSample, 0);
    glUniform1i(p.addSum, 1);
    glUseProgram(p.resolve.id());
    glUniform1i(p.resolveSum, 0);
    glUseProgram(0);
    Result<std::array<RenderTexture, 2>> sums = makeSums(width, height, allocate);
    if (!sums) return sums.error();
    a.sums_ = std::move(*sums);
    return a;
}

void SampleAccumulator::add(unsigned int sample, bool first) {
    const int next = first ? 0 : 1 - current_;
    glBindFramebuffer(GL_FRAMEBUFFER, sums_[next].framebuffer.id());
    glUseProgram(programs_.add.id());
    glUniform1i(programs_.addFirst, first ? 1 : 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, sample);
    glBindSampler(0, 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, first ? 0 : sums_[current_].texture.id());
    glBindSampler(1, 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTexture(GL_TEXTURE_2D, 0);  // no sampled texture stays bound to a target being drawn
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    current_ = next;
}

void SampleAccumulator::resolve(unsigned int framebuffer, int count, bool dither) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glUseProgram(programs_.resolve.id());
    glUniform1f(programs_.resolveScale, 1.0f / static_cast<float>(count));
    glUniform1i(programs_.resolveDither, dither ? 1 : 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, sums_[current_].texture.id());
    glBindSampler(0, 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTexture(GL_TEXTURE_2D, 0);
}

Status SampleAccumulator::resize(int width, int height, const TextureAllocator& allocate) {
    Result<std::array<RenderTexture, 2>> sums = makeSums(width, height, allocate);
    if (!sums) return sums.error();
    sums_ = std::move(*sums);
    current_ = 0;
    return okStatus();
}

}  // namespace toyhost
