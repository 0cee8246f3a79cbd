#include "session/Reload.h"

namespace toyhost {

Diagnostic describeReload(const ReloadOutcome& outcome, std::optional<int> rerunFrames) {
    std::string files;
    for (const std::filesystem::path& file : outcome.changed)
        files += (files.empty() ? "" : ", ") + file.filename().string();
    std::string passes;
    for (const std::string& pass : outcome.recompiled) passes += (passes.empty() ? "" : ", ") + pass;
    std::string what;
    if (!outcome.problems.empty()) what = outcome.applied ? "partly applied" : "not applied";
    else if (!outcome.applied) what = "nothing to recompile: what runs already matches the files";
    else if (!outcome.structureChanged) what = "recompiled " + passes;
    else if (rerunFrames) what = "new structure: " + passes;
    else what = "new structure (buffers that still exist keep their content): " + passes;
    if (rerunFrames) {
        if (!outcome.applied && !outcome.problems.empty())
            what += "; no frames written: the shadertoy as it is now does not run, the files of the last good round stay";
        else if (*rerunFrames > 0)
            what += "; rendering " + std::to_string(*rerunFrames) + (*rerunFrames == 1 ? " frame" : " frames") +
                    " again from frame 0";
    }
    Diagnostic d;
    d.severity = Severity::Notice;
    d.code = Code::WatchChanged;
    d.message = (files.empty() ? std::string("the shadertoy") : files) + " changed: " + what;
    return d;
}

}  // namespace toyhost
