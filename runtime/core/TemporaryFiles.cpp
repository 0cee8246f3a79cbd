#include "core/TemporaryFiles.h"

#include <atomic>
#include <unistd.h>

#include "core/AtomicFile.h"
#include "core/InFlight.h"

namespace toyhost {
namespace fs = std::filesystem;

TemporaryFiles::TemporaryFiles(const std::string& what, std::initializer_list<const char*> extensions) {
    static std::atomic<unsigned> counter{0};
    std::error_code ec;
    const std::string stem = "toyhost-" + what + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    const fs::path folder = fs::temp_directory_path(ec);
    for (const char* extension : extensions) paths_.push_back(folder / (stem + "." + extension));
}

TemporaryFiles::~TemporaryFiles() {
    std::error_code ec;
    for (const fs::path& path : paths_) {
        fs::remove(path, ec);
        if (registered_) inflight::removeFile(path);
    }
}

bool TemporaryFiles::registerAll() {
    registered_ = true;
    for (const fs::path& path : paths_)
        if (!inflight::addFile(path)) return false;
    return true;
}

std::string logTail(const fs::path& log, int count) {
    Result<std::string> text = readTextFile(log, std::size_t(1) << 20);
    if (!text) return "";
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text->size()) {
        std::size_t end = text->find('\n', start);
        if (end == std::string::npos) end = text->size();
        std::string line = text->substr(start, end - start);
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        if (!line.empty()) lines.push_back(std::move(line));
        start = end + 1;
    }
    std::string tail;
    const std::size_t first = lines.size() > static_cast<std::size_t>(count) ? lines.size() - count : 0;
    for (std::size_t i = first; i < lines.size(); ++i) tail += (tail.empty() ? "" : "; ") + lines[i];
    return tail;
}

}  // namespace toyhost
