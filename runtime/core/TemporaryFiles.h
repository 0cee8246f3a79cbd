// TemporaryFiles: a few files in the system's temporary folder for one job done by a child process
// (an ffmpeg decode, a preprocessor run), named "toyhost-<what>-<pid>-<n>.<ext>", registered for an
// emergency exit (core/InFlight.h) and removed however the job ends. No GL needed.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace toyhost {

class TemporaryFiles {
public:
    // One path per extension ("f32", "log"), in that order; nothing is created yet.
    TemporaryFiles(const std::string& what, std::initializer_list<const char*> extensions);
    ~TemporaryFiles();
    TemporaryFiles(const TemporaryFiles&) = delete;
    TemporaryFiles& operator=(const TemporaryFiles&) = delete;

    // Registers every path for an emergency exit; false once one has begun (do not start).
    bool registerAll();
    const std::filesystem::path& operator[](std::size_t index) const { return paths_[index]; }

private:
    std::vector<std::filesystem::path> paths_;
    bool registered_ = false;
};

// The last `count` non-empty lines of a child's log file, joined with "; " (empty when unreadable).
std::string logTail(const std::filesystem::path& log, int count = 3);

}  // namespace toyhost
