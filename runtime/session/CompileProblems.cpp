#include "session/CompileProblems.h"

#include "export/LoadShadertoy.h"
#include "gl/HeadlessContext.h"
#include "render/PassProgram.h"
#include "shader/CompilerLog.h"

namespace toyhost {

Error withCompileProblems(const SessionOptions& options, Error failure) {
    // Usage errors and stops end the run as they are; problems of the code's text were found by
    // the same checks a compile would repeat; a manifest that does not load has nothing to compile.
    for (const Diagnostic& d : failure.diagnostics) {
        const Category category = categoryOf(d.code);
        if (category == Category::Usage || category == Category::Shader || category == Category::Interrupted)
            return failure;
    }
    Result<ManifestDesc> manifest = loadShadertoy(options.target);
    if (!manifest) return failure;
    // The texts first (a child process for the browser-style expansion), then GL only compiles.
    std::vector<PassSource> sources;
    for (const PassDesc& pass : manifest->passes) sources.push_back(preparePassSource(*manifest, pass));
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
