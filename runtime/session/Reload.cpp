#include "session/Reload.h"

namespace toyhost {

Diagnostic describeReload(const ReloadOutcome& outcome) {
    std::string files;
    for (const std::filesystem::path& file : outcome.changed)
        files += (files.empty() ? "" : ", ") + file.filename().string();
    std::string what;
    if (!outcome.problems.empty()) what = outcome.applied ? "partly applied" : "not applied";
    else if (!outcome.applied) what = "nothing to recompile: what runs already matches the files";
    else {
        std::string passes;
        for (const std::string& pass : outcome.recompiled) passes += (passes.empty() ? "" : ", ") + pass;
        what = outcome.structureChanged ? "new structure (buffers that still exist keep their content): " + passes
                                        : "recompiled " + passes;
    }
    Diagnostic d;
    d.severity = Severity::Notice;
    d.code = Code::WatchChanged;
    d.message = (files.empty() ? std::string("the shadertoy") : files) + " changed: " + what;
    return d;
}

}  // namespace toyhost
