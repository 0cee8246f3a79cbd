#include "render/PassProgram.h"

#include <optional>
#include <string>
#include <utility>

#include "gl/ShaderProgram.h"
#include "shader/CompileMessages.h"
#include "shader/CompilerLog.h"
#include "shader/OpaqueDivisors.h"
#include "shader/ShaderAssembly.h"

namespace toyhost {

namespace {

UniformLocations locate(GLuint program) {
    auto at = [&](const std::string& name) { return glGetUniformLocation(program, name.c_str()); };
    UniformLocations u;
    u.resolution = at("iResolution");
    u.time = at("iTime");
    u.timeDelta = at("iTimeDelta");
    u.frameRate = at("iFrameRate");
    u.frame = at("iFrame");
    u.mouse = at("iMouse");
    u.date = at("iDate");
    u.sampleRate = at("iSampleRate");
    u.channelTime = at("iChannelTime");
    u.channelResolution = at("iChannelResolution");
    u.viewport = at("unViewport");
    u.corners = at("unCorners");
    u.timeOffset = at("iTimeOffset");
    u.sampleOffset = at("iSampleOffset");
    u.fragOffset = at(kFragOffsetUniform);
    u.zero = at(kZeroUniform);
    for (int i = 0; i < kChannelCount; ++i) {
        const std::string ch = "iCh" + std::to_string(i);
        u.channel[i] = at("iChannel" + std::to_string(i));
        u.chSampler[i] = at(ch + ".sampler");
        u.chSize[i] = at(ch + ".size");
        u.chTime[i] = at(ch + ".time");
        u.chLoaded[i] = at(ch + ".loaded");
    }
    return u;
}

}  // namespace

Result<PassProgram> compilePassProgram(const ManifestDesc& manifest, const PassDesc& pass, const PassSource& source) {
    ProgramBuild build;
    bool preprocessed = false;
    // The rewritten text first (WebGL's semantics); the plain text when the driver refuses it, so
    // a declaration the rewrite misread never stops a shader. The last try's messages stand: the
    // user's own text.
    const std::pair<const std::string*, const std::optional<std::string>*> tries[] = {
        {&source.text, &source.browserText}, {&source.plainText, &source.browserPlainText}};
    for (const auto& [text, expanded] : tries) {
        build = buildProgram(fullscreenVertexShader(), *text);
        if (!build.ok && build.failedStage == ProgramBuild::Stage::Fragment && *expanded) {
            // Browsers preprocess the text themselves; where Mesa's preprocessor is the one that
            // refuses it, their expansion (prepared off the GL thread) compiles. The driver's own
            // messages stand otherwise.
            ProgramBuild retry = buildProgram(fullscreenVertexShader(), **expanded);
            if (retry.ok) {
                build = std::move(retry);
                preprocessed = true;
            }
        }
        if (build.ok || source.text == source.plainText) break;
    }
    if (!build.ok) {
        const char* name = passName(pass.id);
        const CompilerLogNames names{name, pass.sourceName, manifest.commonName};
        std::vector<CompileSource> sources{{pass.sourceName, pass.code}};
        if (manifest.commonSource) sources.push_back({manifest.commonName, manifest.commonCode});
        std::vector<Diagnostic> diagnostics = explainCompileProblems(parseCompilerLog(build.log, names), sources);
        const char* what = build.failedStage == ProgramBuild::Stage::Link     ? "shader link failed"
                           : build.failedStage == ProgramBuild::Stage::Vertex ? "internal vertex shader failed"
                                                                               : "shader compile failed";
        if (diagnostics.empty()) {
            Diagnostic d;
            d.code = Code::ShaderCompile;
            d.pass = name;
            d.file = pass.sourceName;
            d.message = std::string(what) + " (the driver gave no message)";
            diagnostics.push_back(std::move(d));
        }
        if (build.failedStage == ProgramBuild::Stage::Link)
            for (Diagnostic& d : diagnostics) {
                d.code = Code::ShaderLink;
                // A message explainCompileProblems rewrote quotes the linker's words already.
                if (d.message.find("(link: ") == std::string::npos) d.message = "link: " + d.message;
            }
        return Error(std::move(diagnostics));
    }
    PassProgram made;
    made.uniforms = locate(build.program.id());
    made.program = std::move(build.program);
    made.browserPreprocessed = preprocessed;
    return made;
}

}  // namespace toyhost
