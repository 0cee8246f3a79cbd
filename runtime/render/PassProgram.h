// PassProgram: one pass's GL program (the assembled Shadertoy fragment shader and the shared
// full-screen triangle), with every uniform location looked up once after linking. Compile
// errors come back as diagnostics naming the user's file, pass, line and column. Needs a current
// GL context.
#pragma once

#include <array>
#include <vector>

#include "core/Result.h"
#include "gl/GlObjects.h"
#include "manifest/ManifestDesc.h"
#include "shader/PassSource.h"

namespace toyhost {

// Uniform locations; -1 where the shader does not use one (glUniform* ignores -1).
struct UniformLocations {
    GLint resolution = -1, time = -1, timeDelta = -1, frameRate = -1, frame = -1, mouse = -1, date = -1,
          sampleRate = -1, channelTime = -1, channelResolution = -1;
    std::array<GLint, kChannelCount> channel{-1, -1, -1, -1};  // iChannelN
    std::array<GLint, kChannelCount> chSampler{-1, -1, -1, -1}, chSize{-1, -1, -1, -1}, chTime{-1, -1, -1, -1},
        chLoaded{-1, -1, -1, -1};  // the Image pass's iChN struct members
    GLint viewport = -1, corners = -1;         // Cube A: unViewport, unCorners
    GLint timeOffset = -1, sampleOffset = -1;  // Sound: iTimeOffset, iSampleOffset
    GLint fragOffset = -1;  // Image: the sample's offset of fragCoord (shader/ShaderAssembly.h)
    GLint zero = -1;        // toyhost_zero, 0u: hides divisors from Mesa's folder (shader/OpaqueDivisors.h)
};

struct PassProgram {
    GlProgram program;
    UniformLocations uniforms;
    // Compiled from the browser-style preprocessed text (shader/BrowserPreprocess.h) because the
    // driver refused the original.
    bool browserPreprocessed = false;
    // One warning (Code::ShaderRuleSkipped) for each rule of the WebGL rewrite left out because the
    // driver refused the text it made (compilePassProgram): never silent.
    std::vector<Diagnostic> warnings;
};

// Builds `pass` of `manifest` from its texts prepared off the GL thread (shader/PassSource.h:
// preparePassSource, which planPlayer runs); `manifest` and `pass` name the files in errors.
// Only compiles: no child process runs here.
Result<PassProgram> compilePassProgram(const ManifestDesc& manifest, const PassDesc& pass, const PassSource& source);

}  // namespace toyhost
