#include "session/ShadertoyWatcher.h"

#include <algorithm>
#include <system_error>

#include "export/LoadShadertoy.h"

namespace toyhost {
namespace fs = std::filesystem;

std::vector<fs::path> watchedFiles(const fs::path& target, const ManifestDesc& manifest) {
    std::vector<fs::path> files;
    auto add = [&](const fs::path& file) {
        if (!file.empty() && std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
    };
    std::error_code ec;
    add(fs::is_directory(target, ec) ? target / "manifest.json" : target);
    add(manifest.manifestPath);
    if (manifest.commonSource) add(*manifest.commonSource);
    for (const PassDesc& pass : manifest.passes) {
        add(pass.source);
        for (const ChannelDesc& channel : pass.channels)
            if (!channel.file.empty()) add(channel.file);  // images, cubemaps, volumes, videos, audio
    }
    return files;
}

ShadertoyWatcher::ShadertoyWatcher(fs::path target, MediaOptions media, MacroDefines defines, const ManifestDesc& current,
                                   Clock::duration interval)
    : target_(std::move(target)), media_(std::move(media)), defines_(std::move(defines)), interval_(interval), files_(watchedFiles(target_, current)) {
    thread_ = std::thread([this] { run(); });
}

ShadertoyWatcher::~ShadertoyWatcher() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

std::map<fs::path, ShadertoyWatcher::Stamp> ShadertoyWatcher::stampAll() const {
    std::map<fs::path, Stamp> stamps;
    for (const fs::path& file : files_) {
        Stamp stamp;
        std::error_code ec;
        const auto status = fs::status(file, ec);
        stamp.exists = !ec && fs::is_regular_file(status);
        if (stamp.exists) {
            stamp.modified = fs::last_write_time(file, ec);
            stamp.size = fs::file_size(file, ec);
        }
        stamps[file] = stamp;
    }
    return stamps;
}

void ShadertoyWatcher::run() {
    auto seen = stampAll();
    std::unique_lock lock(mutex_);
    while (!stopping_) {
        changed_.wait_for(lock, interval_, [&] { return stopping_; });
        if (stopping_) break;
        lock.unlock();
        auto now = stampAll();
        if (now != seen) {
            // Wait until the files stay put for one more interval (an editor's save in steps).
            for (;;) {
                std::this_thread::sleep_for(interval_);
                auto again = stampAll();
                if (again == now) break;
                now = std::move(again);
            }
            std::vector<fs::path> changed;
            for (const auto& [file, stamp] : now)
                if (auto before = seen.find(file); before == seen.end() || !(before->second == stamp))
                    changed.push_back(file);
            seen = now;
            Result<PlayerPlan> plan = [&]() -> Result<PlayerPlan> {
                Result<ManifestDesc> manifest = loadShadertoy(target_);
                if (!manifest) return manifest.error();
                return planPlayer(std::move(*manifest), media_, defines_);
            }();
            if (plan) {
                files_ = watchedFiles(target_, plan->manifest);  // passes may have come or gone
                seen = stampAll();
            }
            lock.lock();
            // Changes not taken yet are merged: the driver sees every file that changed.
            if (ready_)
                for (fs::path& file : ready_->files)
                    if (std::find(changed.begin(), changed.end(), file) == changed.end()) changed.push_back(std::move(file));
            ready_.emplace(ShadertoyChange{std::move(changed), std::move(plan)});
            changed_.notify_all();
            continue;
        }
        lock.lock();
    }
}

std::optional<ShadertoyChange> ShadertoyWatcher::take() {
    std::lock_guard lock(mutex_);
    std::optional<ShadertoyChange> out = std::move(ready_);
    ready_.reset();
    return out;
}

std::optional<ShadertoyChange> ShadertoyWatcher::wait(const std::function<bool()>& stop) {
    std::unique_lock lock(mutex_);
    while (!ready_ && !stop()) changed_.wait_for(lock, interval_);
    std::optional<ShadertoyChange> out = std::move(ready_);
    ready_.reset();
    return out;
}

}  // namespace toyhost
