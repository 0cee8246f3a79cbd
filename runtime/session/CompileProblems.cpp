#include "session/CompileProblems.h"

#include "export/LoadShadertoy.h"
#include "gl/HeadlessContext.h"
#include "render/PassProgram.h"
#include "shader/CompilerLog.h"

namespace toyhost {

Error withCompileProblems(const SessionOptions& options, Error failure) {
    // Usage errors and stops end the run as they are; problems of the code's text were found by
    // the same checks a compile would repeat; a checkpoint made from other code or inputs is not a
    // problem of this code; a manifest that does not load has nothing to compile.
    for (const Diagnostic& d : failure.diagnostics) {
        const Category category = categoryOf(d.code);
        if (category == Category::Usage || category == Category::Shader || category == Category::Interrupted ||
            d.code == Code::CheckpointMismatch)
            return failure;
    }
    Result<ManifestDesc> manifest = options.shadertoy ? Result<ManifestDesc>(*options.shadertoy) : loadShadertoy(options.target);
    if (!manifest) return failure;
    // The run's --define macros are part of its code (once a defect: compiled without them, every
    // pass that uses one reported it "undeclared" after the real problem).
    Result<MacroDefines> defines = parseMacroDefines(options.settings.defines);
    if (!defines) return failure;
    // The texts first (a child process for the browser-style expansion), then GL only compiles.
    std::vector<PassSource> sources;
    for (const PassDesc& pass : manifest->passes) sources.push_back(preparePassSource(*manifest, pass, *defines));
    HeadlessOptions headless;
    headless.platform = options.eglPlatform;
    Result<std::shared_ptr<GlContext>> context = createHeadlessContext(headless);
    if (!context) return failure;  // the inputs' problems are still worth reporting alone
    for (std::size_t i = 0; i < manifest->passes.size(); ++i) {
        const PassDesc& pass = manifest->passes[i];
        Result<PassProgram> program = compilePassProgram(*manifest, pass, sources[i]);
        if (!program) mergeCompileProblems(failure.diagnostics, program.error().diagnostics, *manifest);
    }
    return failure;
}

}  // namespace toyhost
