#include "render/PassProgram.h"

#include <algorithm>
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

// `text` compiled, then its browser-style expansion (prepared off the GL thread) when the driver's
// compile refuses the text and one was prepared: where Mesa's preprocessor is the one that refuses
// it, the expansion compiles. The driver's own messages stand otherwise.
ProgramBuild compileText(const std::string& text, const std::optional<std::string>& expanded, bool& preprocessed) {
    ProgramBuild build = buildProgram(fullscreenVertexShader(), text);
    if (!build.ok && build.failedStage == ProgramBuild::Stage::Fragment && expanded) {
        ProgramBuild retry = buildProgram(fullscreenVertexShader(), *expanded);
        if (retry.ok) {
            preprocessed = true;
            return retry;
        }
    }
    return build;
}

// The warning that `rule` was left out of the rewrite because the driver refused the text with it:
// where (the driver's first error about the user's text) and why (its words).
Diagnostic skippedRule(RewriteRule rule, const std::string& why, const CompilerLogNames& names) {
    Diagnostic d;
    d.severity = Severity::Warning;
    d.code = Code::ShaderRuleSkipped;
    d.pass = names.pass;
    d.file = names.passFile;
    std::string driver = why;
    for (const Diagnostic& problem : parseCompilerLog(why, names)) {
        if (problem.severity != Severity::Error) continue;
        d.file = problem.file;
        d.line = problem.line;
        driver = problem.message;
        break;
    }
    while (!driver.empty() && (driver.back() == '\n' || driver.back() == ' ')) driver.pop_back();
    d.message = std::string("the WebGL rule '") + rewriteRuleName(rule) + "' of the source rewrite was skipped: the driver refused the text it made (" +
                driver + "); " + rewriteRuleEffect(rule) + "; every other rule still applies";
    return d;
}

// The driver refused the rewritten text. Never the plain text silently: the rename alone first
// (without it Mesa refuses shaders the browser compiles), else the plain text, then each other rule
// added back in turn and kept when the driver accepts the text; every rule left out gets a warning
// with the driver's words. Only on a refusal: a text the driver accepts is compiled once. When even
// the plain text is refused, its messages stand (the user's own text) and no rule is blamed.
ProgramBuild compileWithoutRefusedRules(const PassSource& source, const CompilerLogNames& names, bool& preprocessed,
                                        std::vector<Diagnostic>& warnings) {
    GlslRewriteOptions options = source.parts.options;
    std::vector<RewriteRule> wanted;
    for (RewriteRule rule : kRewriteRules) {
        if (ruleSwitch(options, rule)) wanted.push_back(rule);
        ruleSwitch(options, rule) = false;
    }
    ProgramBuild build;
    std::string current;
    if (std::find(wanted.begin(), wanted.end(), RewriteRule::Rename) != wanted.end()) {
        ruleSwitch(options, RewriteRule::Rename) = true;
        current = rewrittenShader(source.parts, options);
        if (current != source.plainText) {
            build = buildProgram(fullscreenVertexShader(), current);
            if (!build.ok) {
                warnings.push_back(skippedRule(RewriteRule::Rename, build.log, names));
                ruleSwitch(options, RewriteRule::Rename) = false;
            }
        }
    }
    if (!build.ok) {
        preprocessed = false;
        build = compileText(source.plainText, source.browserPlainText, preprocessed);
        current = source.plainText;
        if (!build.ok) {
            warnings.clear();
            return build;
        }
    }
    for (RewriteRule rule : wanted) {
        if (rule == RewriteRule::Rename) continue;
        ruleSwitch(options, rule) = true;
        std::string text = rewrittenShader(source.parts, options);
        if (text == current) continue;  // the rule changes nothing in this text
        if (preprocessed) {
            // The base compiled only as browsers expand it, and that expansion (a child process)
            // is made off the GL thread for the whole and the plain texts only.
            warnings.push_back(skippedRule(rule, "the text compiles only after the browser-style preprocessing, made "
                                                 "for the whole rewrite and the plain text only", names));
            ruleSwitch(options, rule) = false;
            continue;
        }
        ProgramBuild tried = buildProgram(fullscreenVertexShader(), text);
        if (tried.ok) {
            build = std::move(tried);
            current = std::move(text);
        } else {
            warnings.push_back(skippedRule(rule, tried.log, names));
            ruleSwitch(options, rule) = false;
        }
    }
    return build;
}

}  // namespace

Result<PassProgram> compilePassProgram(const ManifestDesc& manifest, const PassDesc& pass, const PassSource& source) {
    bool preprocessed = false;
    std::vector<Diagnostic> warnings;
    const CompilerLogNames names{passName(pass.id), pass.sourceName, manifest.commonName};
    // The rewritten text first (WebGL's semantics); when the driver refuses it, the rules it
    // accepts (the messages of the last try stand when it accepts none: the user's own text).
    ProgramBuild build = compileText(source.text, source.browserText, preprocessed);
    if (!build.ok && build.failedStage == ProgramBuild::Stage::Fragment && source.text != source.plainText)
        build = compileWithoutRefusedRules(source, names, preprocessed, warnings);
    if (!build.ok) {
        const char* name = passName(pass.id);
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
    made.warnings = std::move(warnings);
    return made;
}

}  // namespace toyhost
