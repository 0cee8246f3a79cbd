// ShadertoyWatcher: hot reload's eyes. A thread polls the files a shadertoy is made of (the
// manifest or export, Common, every pass file, image files) with stat() a few times a second; when
// one changes and then stays unchanged for a moment (editors write in several steps), it loads
// the shadertoy again and builds a PlayerPlan there, off the GL thread, and leaves the result for
// the driver to take. The driver gives the plan to Player::reload on its GL thread. A cheap stat
// poll rather than inotify: it also sees files replaced by rename, on any filesystem. No GL needed.
#pragma once

#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "core/Result.h"
#include "manifest/ManifestDesc.h"
#include "player/PlayerDesc.h"

namespace toyhost {

// The files whose change means "reload": the target, the manifest, Common, the pass files and
// the files every channel of `manifest` reads (images, cubemaps, volumes, videos, audio).
std::vector<std::filesystem::path> watchedFiles(const std::filesystem::path& target, const ManifestDesc& manifest);

// A change the watcher saw: which files changed, and the shadertoy loaded and planned again (or
// why it could not be).
struct ShadertoyChange {
    std::vector<std::filesystem::path> files;
    Result<PlayerPlan> plan;
};

class ShadertoyWatcher {
public:
    using Clock = std::chrono::steady_clock;
    // Starts watching the files of `current` (loaded from `target`); a change is planned with the
    // run's media settings and --define macros.
    ShadertoyWatcher(std::filesystem::path target, MediaOptions media, MacroDefines defines, const ManifestDesc& current,
                     Clock::duration interval = std::chrono::milliseconds(100));
    ~ShadertoyWatcher();
    ShadertoyWatcher(const ShadertoyWatcher&) = delete;
    ShadertoyWatcher& operator=(const ShadertoyWatcher&) = delete;

    // The change loaded after the latest change of the files, once; else nothing.
    std::optional<ShadertoyChange> take();
    // Waits until a change was loaded or `stop()` returns true (checked every `interval`).
    std::optional<ShadertoyChange> wait(const std::function<bool()>& stop);

private:
    struct Stamp {
        std::filesystem::file_time_type modified{};
        std::uintmax_t size = 0;
        bool exists = false;
        bool operator==(const Stamp&) const = default;
    };
    std::map<std::filesystem::path, Stamp> stampAll() const;
    void run();

    std::filesystem::path target_;
    MediaOptions media_;
    MacroDefines defines_;
    Clock::duration interval_;
    std::vector<std::filesystem::path> files_;  // watcher thread only
    std::mutex mutex_;
    std::condition_variable changed_;
    std::optional<ShadertoyChange> ready_;
    bool stopping_ = false;
    std::thread thread_;
};

}  // namespace toyhost
