#include "core/ProblemDigest.h"

#include <algorithm>
#include <string>

namespace toyhost {

namespace {

// `file` relative to `folder` when it lies inside it; as it is otherwise (another folder, a
// pseudo-name such as "code [Image]").
std::string relativeTo(const std::string& file, const std::filesystem::path& folder) {
    if (file.empty() || folder.empty()) return file;
    const std::filesystem::path path(file);
    if (!path.is_absolute()) return file;
    const std::filesystem::path relative = path.lexically_normal().lexically_relative(folder.lexically_normal());
    if (relative.empty() || *relative.begin() == "..") return file;
    return relative.string();
}

}  // namespace

ProblemDigest digestProblems(const std::vector<Diagnostic>& problems, const std::filesystem::path& folder) {
    ProblemDigest digest;
    std::vector<std::string> seen;
    for (const Diagnostic& problem : problems) {
        const std::string key = problem.pass.empty() ? "file " + problem.file : "pass " + problem.pass;
        if (std::find(seen.begin(), seen.end(), key) != seen.end()) {
            ++digest.more;
            continue;
        }
        seen.push_back(key);
        Diagnostic shown = problem;
        shown.file = relativeTo(problem.file, folder);
        digest.shown.push_back(std::move(shown));
    }
    return digest;
}

}  // namespace toyhost
