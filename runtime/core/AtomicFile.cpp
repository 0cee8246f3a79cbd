#include "core/AtomicFile.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace toyhost {
namespace fs = std::filesystem;

fs::path temporarySibling(const fs::path& path) {
    static std::atomic<unsigned> counter{0};
    // Starts with a dot and ends in .partial so a glob for the final pattern never matches it.
    // Built by appending: GCC 12 reports a false -Wrestrict for "." + std::string here.
    std::string name(".");
    name += path.filename().string();
    for (const std::string& part : {std::to_string(::getpid()), std::to_string(counter++)}) {
        name += '.';
        name += part;
    }
    name += ".partial";
    return path.parent_path() / name;
}

Status writeFileAtomically(const fs::path& path,
                           const std::function<Status(const fs::path&)>& write) {
    std::error_code ec;
    if (path.has_parent_path()) {
        fs::create_directories(path.parent_path(), ec);
        if (ec) return Error{path.parent_path().string() + ": cannot create folder: " + ec.message()};
    }
    const fs::path temp = temporarySibling(path);
    Status written = write(temp);
    if (!written) {
        fs::remove(temp, ec);
        return written;
    }
    fs::rename(temp, path, ec);
    if (ec) {
        std::error_code ignored;  // `ec` carries the rename's reason into the message
        fs::remove(temp, ignored);
        return Error{path.string() + ": cannot rename temporary file into place: " + ec.message()};
    }
    return okStatus();
}

Status writeBytesAtomically(const fs::path& path, std::span<const std::byte> bytes) {
    return writeFileAtomically(path, [&](const fs::path& temp) -> Status {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out) return Error{path.string() + ": cannot open for writing: " + std::strerror(errno)};
        out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (!out) return Error{path.string() + ": write failed: " + std::strerror(errno)};
        return okStatus();
    });
}

Result<std::string> readTextFile(const fs::path& path) {
    std::error_code dirError;
    // A folder opens like a file on Linux and then reads as "", which parsers report as empty input.
    if (fs::is_directory(path, dirError)) return Error{path.string() + ": is a folder, not a file"};
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::error_code ec;
        if (!fs::exists(path, ec)) return Error{path.string() + ": file not found"};
        return Error{path.string() + ": cannot open: " + std::strerror(errno)};
    }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace toyhost
