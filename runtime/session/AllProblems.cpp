#include "session/AllProblems.h"

#include "export/LoadShadertoy.h"
#include "gl/HeadlessContext.h"
#include "render/PassProgram.h"
#include "shader/CompilerLog.h"

namespace toyhost {

Error withCompileProblems(const RunOptions& options, Error failure) {
    for (const Diagnostic& d : failure.diagnostics)
        if (d.code.rfind("usage", 0) == 0 || d.code.rfind("shader.", 0) == 0 || d.code.rfind("manifest.", 0) == 0 ||
            d.code.rfind("export.", 0) == 0 || d.code.rfind("json.", 0) == 0 || d.code == "interrupted")
            return failure;
    Result<ManifestDesc> manifest = loadShadertoy(options.target);
    if (!manifest) return failure;
    HeadlessOptions headless;
    headless.platform = options.eglPlatform;
    Result<std::shared_ptr<GlContext>> context = createHeadlessContext(headless);
    if (!context) return failure;  // the inputs' problems are still worth reporting alone
    for (const PassDesc& pass : manifest->passes) {
        Result<PassProgram> program = compilePassProgram(*manifest, pass);
        if (!program) mergeCompileProblems(failure.diagnostics, program.error().diagnostics, *manifest);
    }
    return failure;
}

}  // namespace toyhost
