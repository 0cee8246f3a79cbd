#include "core/AtomicFile.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <algorithm>
#include <string>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/FileDescriptor.h"
#include "core/InFlight.h"

namespace toyhost {
namespace fs = std::filesystem;

fs::path temporarySibling(const fs::path& path) {
    static std::atomic<unsigned> counter{0};
    // Starts with a dot and ends in .partial so a glob for the final pattern never matches it.
    // Built by appending: GCC 12 reports a false -Wrestrict for "." + std::string here.
    std::string suffix;
    for (const std::string& part : {std::to_string(::getpid()), std::to_string(counter++)}) {
        suffix += '.';
        suffix += part;
    }
    suffix += ".partial";
    std::string stem = path.filename().string();
    // File names are limited to 255 bytes (NAME_MAX); a long legal output name keeps its first
    // characters and gets a hash of the whole name, so two long names still differ.
    constexpr std::size_t kNameMax = 255;
    if (1 + stem.size() + suffix.size() > kNameMax) {
        const std::string hash = std::to_string(std::hash<std::string>{}(stem));
        stem = stem.substr(0, kNameMax - 1 - suffix.size() - hash.size() - 1) + "~" + hash;
    }
    std::string name(".");
    name += stem;
    name += suffix;
    return path.parent_path() / name;
}

Status writeFileAtomically(const fs::path& path,
                           const std::function<Status(const fs::path&)>& write, ParentFolders parents) {
    std::error_code ec;
    if (path.has_parent_path() && parents == ParentFolders::Create) {
        fs::create_directories(path.parent_path(), ec);
        if (ec) return fileError(path.parent_path().string(), "cannot create folder: " + ec.message(), Code::IoWrite);
    }
    const fs::path temp = temporarySibling(path);
    // Registered while it exists, so an emergency exit removes it (core/InFlight.h).
    if (!inflight::addFile(temp)) return fileError(path.string(), "not written: toyhost is stopping", Code::Interrupted);
    Status written = write(temp);
    if (!written) {
        fs::remove(temp, ec);
        inflight::removeFile(temp);
        return written;
    }
    fs::rename(temp, path, ec);
    if (ec) {
        std::error_code ignored;  // `ec` carries the rename's reason into the message
        fs::remove(temp, ignored);
        inflight::removeFile(temp);
        return fileError(path.string(), "cannot rename the temporary file into place: " + ec.message(), Code::IoWrite);
    }
    inflight::removeFile(temp);
    return okStatus();
}

Status writeBytesAtomically(const fs::path& path, std::span<const std::byte> bytes) {
    return writeFileAtomically(path, [&](const fs::path& temp) -> Status {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out) return fileError(path.string(), std::string("cannot open for writing: ") + std::strerror(errno), Code::IoWrite);
        out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (!out)
            return fileError(path.string(), std::string("write failed: ") + std::strerror(errno),
                             errno == ENOSPC ? Code::IoNoSpace : Code::IoWrite);
        return okStatus();
    });
}

namespace {
// stat() with the reasons a user can act on; fills `info` when it is a regular file.
Status statRegularFile(const fs::path& path, const std::string& what, struct stat& info) {
    const std::string name = path.string();
    const std::string prefix = what.empty() ? "" : what + " ";
    if (::stat(path.c_str(), &info) != 0) {
        const int cause = errno;
        if (cause == ENOENT) {
            struct stat link {};
            if (::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode))
                return fileError(name, prefix + "is a symbolic link to nothing (its target is missing)", Code::IoNotFound);
            return fileError(name, prefix + "file not found", Code::IoNotFound);
        }
        if (cause == ELOOP) return fileError(name, prefix + "is a symbolic link loop", Code::IoLinkLoop);
        if (cause == ENOTDIR) return fileError(name, prefix + "file not found (a folder in its path is a file)", Code::IoNotFound);
        return fileError(name, prefix + "cannot be read: " + std::strerror(cause), Code::IoRead);
    }
    // A folder opens like a file on Linux and reads as ""; a device or FIFO may never end.
    if (S_ISDIR(info.st_mode)) return fileError(name, prefix + "is a folder, not a file", Code::IoNotAFile);
    if (!S_ISREG(info.st_mode))
        return fileError(name, prefix + "is not a regular file (a device, FIFO or socket)", Code::IoNotAFile);
    return okStatus();
}
}  // namespace

Status checkRegularFile(const fs::path& path, const std::string& what) {
    struct stat info {};
    return statRegularFile(path, what, info);
}

Result<std::string> readTextFile(const fs::path& path, std::size_t limitBytes) {
    const std::string name = path.string();
    struct stat info {};
    if (Status regular = statRegularFile(path, "", info); !regular) return regular.error();
    if (static_cast<std::uintmax_t>(info.st_size) > limitBytes)
        return fileError(name,
                         "is " + std::to_string(info.st_size) + " bytes, more than the limit of " +
                             std::to_string(limitBytes) + " bytes",
                         Code::IoTooLarge);
    FileDescriptor fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
    if (!fd) return fileError(name, std::string("cannot open: ") + std::strerror(errno), Code::IoRead);
    std::string text;
    text.resize(static_cast<std::size_t>(info.st_size));
    std::size_t done = 0;
    // Read until end of file, not just st_size bytes: the file may grow while it is read; it must
    // still stay under the limit.
    for (;;) {
        if (done == text.size()) {
            if (text.size() >= limitBytes + 1) break;
            text.resize(std::min(limitBytes + 1, std::max<std::size_t>(4096, text.size() * 2)));
        }
        const ssize_t n = ::read(fd.get(), text.data() + done, text.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            return fileError(name, std::string("read failed: ") + std::strerror(errno), Code::IoRead);
        }
        if (n == 0) break;
        done += static_cast<std::size_t>(n);
    }
    if (done > limitBytes)
        return fileError(name, "is more than the limit of " + std::to_string(limitBytes) + " bytes", Code::IoTooLarge);
    text.resize(done);
    return text;
}

}  // namespace toyhost
