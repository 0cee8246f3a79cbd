#include "core/InFlight.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <mutex>
#include <set>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace toyhost::inflight {

namespace {
struct Registry {
    std::mutex mutex;
    std::set<std::filesystem::path> files;
    std::set<pid_t> children;
    bool closed = false;
};

Registry& registry() {
    static Registry* r = new Registry();  // never destroyed: usable while the process ends
    return *r;
}

int removeFiles(Registry& r) {
    int removed = 0;
    for (const std::filesystem::path& file : r.files)
        if (::unlink(file.c_str()) == 0) ++removed;
    return removed;
}
}  // namespace

bool addFile(const std::filesystem::path& path) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    if (r.closed) return false;
    r.files.insert(path);
    return true;
}

void removeFile(const std::filesystem::path& path) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    if (!r.closed) r.files.erase(path);  // after a cleanup the set is kept for its second pass
}

void addChild(pid_t pid) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    r.children.insert(pid);
}

void removeChild(pid_t pid) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    r.children.erase(pid);
}

CleanupReport emergencyCleanup() {
    Registry& r = registry();
    CleanupReport report;
    std::set<pid_t> children;
    {
        std::lock_guard lock(r.mutex);
        r.closed = true;
        children = r.children;
    }
    // Each child leads its own process group (core/ChildProcess.h): what it started goes with it.
    for (pid_t pid : children)
        if (::kill(-pid, SIGKILL) == 0 || ::kill(pid, SIGKILL) == 0) ++report.children;
    // A child that is not dead yet could still create its output file.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
    for (pid_t pid : children) {
        while (std::chrono::steady_clock::now() < deadline) {
            const pid_t waited = ::waitpid(pid, nullptr, WNOHANG);
            if (waited == pid || (waited < 0 && errno == ECHILD)) break;  // reaped (here or by its owner)
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
    std::lock_guard lock(r.mutex);
    report.files = removeFiles(r);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    report.files += removeFiles(r);
    return report;
}

}  // namespace toyhost::inflight
