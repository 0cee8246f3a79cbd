#include "render/SampleAccumulator.h"

#include <GLES3/gl3.h>

#include "gl/ShaderProgram.h"
#include "shader/ShaderAssembly.h"

namespace toyhost {

namespace {

// toyhostMode: 0 the raw floats (a float Image), 1 display values (clamped as an 8-bit target
// clamps), 2 linear light (clamped, then the sRGB transfer function's inverse: IEC 61966-2-1).
// texelFetch: one texel per pixel, no filtering.
constexpr const char* kAddShader = R"(#version 300 es
precision highp float;
precision highp sampler2D;
uniform sampler2D toyhostSample;
uniform sampler2D toyhostSum;
uniform int toyhostFirst;
uniform int toyhostMode;
out vec4 toyhostOut;
vec3 toLinear(vec3 c) {
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c));
}
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 s = texelFetch(toyhostSample, p, 0);
    if (toyhostMode >= 1) s = clamp(s, 0.0, 1.0);
    if (toyhostMode == 2) s.rgb = toLinear(s.rgb);
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
uniform int toyhostMode;
out vec4 toyhostOut;
int bayer8(ivec2 p) {
    int x = p.x & 7, y = p.y & 7, xy = x ^ y;
    return ((xy & 1) << 5) | ((y & 1) << 4) | ((xy & 2) << 2) | ((y & 2) << 1) | ((xy & 4) >> 1) | ((y & 4) >> 2);
}
vec3 toSrgb(vec3 c) {
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 c = texelFetch(toyhostSum, p, 0) * toyhostScale;
    if (toyhostMode == 2) c.rgb = toSrgb(clamp(c.rgb, 0.0, 1.0));
    if (toyhostDither == 1) c.rgb += ((float(bayer8(p)) + 0.5) / 64.0 - 0.5) / 255.0;
    toyhostOut = c;
}
)";

Result<GlProgram> build(const char* fragment, const char* what) {
    ProgramBuild built = buildProgram(fullscreenVertexShader(), fragment);
    if (!built.ok) return Error(std::string("GL: the ") + what + " program did not build: " + built.log, Code::GlSetup);
    return std::move(built.program);
}

}  // namespace

Result<SampleAccumulator::Targets> SampleAccumulator::makeTargets(int width, int height,
                                                                  const TextureAllocator& allocate) {
    Targets targets;
    Result<RenderTexture> sample = allocate(width, height, GL_RGBA32F, false);
    if (!sample) return sample.error();
    targets.sample = std::move(*sample);
    for (RenderTexture& sum : targets.sums) {
        Result<RenderTexture> made = allocate(width, height, GL_RGBA32F, false);
        if (!made) return made.error();
        sum = std::move(*made);
    }
    return targets;
}

int SampleAccumulator::mode() const { return average_.floatTarget ? 0 : average_.linear ? 2 : 1; }

Result<SampleAccumulator> SampleAccumulator::create(int width, int height, SampleAverage average,
                                                    const TextureAllocator& allocate) {
    SampleAccumulator a;
    a.average_ = average;
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
    p.addMode = glGetUniformLocation(p.add.id(), "toyhostMode");
    p.resolveSum = glGetUniformLocation(p.resolve.id(), "toyhostSum");
    p.resolveScale = glGetUniformLocation(p.resolve.id(), "toyhostScale");
    p.resolveDither = glGetUniformLocation(p.resolve.id(), "toyhostDither");
    p.resolveMode = glGetUniformLocation(p.resolve.id(), "toyhostMode");
    glUseProgram(p.add.id());
    glUniform1i(p.addSample, 0);
    glUniform1i(p.addSum, 1);
    glUniform1i(p.addMode, a.mode());
    glUseProgram(p.resolve.id());
    glUniform1i(p.resolveSum, 0);
    glUniform1i(p.resolveMode, a.mode());
    glUniform1i(p.resolveDither, average.dither && !average.floatTarget ? 1 : 0);
    glUseProgram(0);
    Result<Targets> targets = makeTargets(width, height, allocate);
    if (!targets) return targets.error();
    a.sample_ = std::move(targets->sample);
    a.sums_ = std::move(targets->sums);
    return a;
}

void SampleAccumulator::seed(unsigned int canvas) {
    // The add program's first draw in raw mode is a copy.
    glBindFramebuffer(GL_FRAMEBUFFER, sample_.framebuffer.id());
    glUseProgram(programs_.add.id());
    glUniform1i(programs_.addFirst, 1);
    glUniform1i(programs_.addMode, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, canvas);
    glBindSampler(0, 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTexture(GL_TEXTURE_2D, 0);
    glUniform1i(programs_.addMode, mode());
}

void SampleAccumulator::add(bool first) {
    const int next = first ? 0 : 1 - current_;
    glBindFramebuffer(GL_FRAMEBUFFER, sums_[next].framebuffer.id());
    glUseProgram(programs_.add.id());
    glUniform1i(programs_.addFirst, first ? 1 : 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, sample_.texture.id());
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

void SampleAccumulator::resolve(unsigned int framebuffer, int count) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glUseProgram(programs_.resolve.id());
    glUniform1f(programs_.resolveScale, 1.0f / static_cast<float>(count));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, sums_[current_].texture.id());
    glBindSampler(0, 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTexture(GL_TEXTURE_2D, 0);
}

Status SampleAccumulator::resize(int width, int height, const TextureAllocator& allocate) {
    Result<Targets> targets = makeTargets(width, height, allocate);
    if (!targets) return targets.error();
    sample_ = std::move(targets->sample);
    sums_ = std::move(targets->sums);
    current_ = 0;
    return okStatus();
}

}  // namespace toyhost
