#include "core/ChildProcess.h"

#include "core/InFlight.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace toyhost {
namespace fs = std::filesystem;

namespace {
// access(X_OK) also holds for a searchable folder, which exec then refuses (EACCES).
bool isExecutableFile(const fs::path& path) {
    std::error_code ec;
    return ::access(path.c_str(), X_OK) == 0 && fs::is_regular_file(path, ec);
}
}  // namespace

std::optional<fs::path> findExecutable(const std::string& program) {
    if (program.find('/') != std::string::npos) {
        if (isExecutableFile(program)) return fs::path(program);
        return std::nullopt;
    }
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
    size_t start = 0;
    while (start <= dirs.size()) {
        size_t end = dirs.find(':', start);
        if (end == std::string::npos) end = dirs.size();
        const std::string dir = dirs.substr(start, end - start);
        const fs::path candidate = fs::path(dir.empty() ? "." : dir) / program;
        if (isExecutableFile(candidate)) return candidate;
        start = end + 1;
    }
    return std::nullopt;
}

Result<ChildProcess> ChildProcess::spawn(const std::vector<std::string>& argv, const fs::path& logFile) {
    return start(argv, logFile, false);
}

Result<ChildProcess> ChildProcess::spawnReading(const std::vector<std::string>& argv, const fs::path& logFile) {
    return start(argv, logFile, true);
}

Result<std::size_t> ChildProcess::read(std::span<std::byte> bytes) {
    if (!output_) return Error(name_ + ": its output is not read by toyhost", Code::Process);
    while (true) {
        const ssize_t n = ::read(output_.get(), bytes.data(), bytes.size());
        if (n >= 0) return static_cast<std::size_t>(n);
        if (errno != EINTR) return Error(name_ + ": reading its output failed: " + std::strerror(errno), Code::Process);
    }
}

Result<ChildProcess> ChildProcess::start(const std::vector<std::string>& argv, const fs::path& logFile, bool readOutput) {
    if (argv.empty()) return Error("no program to run", Code::Process);
    const std::string name = argv[0];
    std::optional<fs::path> program = findExecutable(name);
    if (!program) return Error(name + ": program not found in PATH", Code::Process);

    // One pipe, closed on exec in toyhost: the child's stdin (its read end, through dup2 below),
    // or with `readOutput` its stdout (its write end); a reading child's stdin is /dev/null.
    int ends[2];
    if (::pipe2(ends, O_CLOEXEC) != 0) return Error(name + ": cannot create a pipe: " + std::strerror(errno), Code::Process);
    FileDescriptor readEnd(ends[0]), writeEnd(ends[1]);
    FileDescriptor log(::open(logFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
    if (!log) return Error(logFile.string() + ": cannot create: " + std::strerror(errno), Code::Process);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (readOutput) posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    else posix_spawn_file_actions_adddup2(&actions, readEnd.get(), STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&actions, readOutput ? writeEnd.get() : log.get(), STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, log.get(), STDERR_FILENO);
    // The child starts with default signal handling whatever its parent set (SIGPIPE ignored by
    // the CLI would otherwise be inherited).
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t defaults, none;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGPIPE);
    sigemptyset(&none);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setsigmask(&attributes, &none);
    // Its own process group: Ctrl-C in a terminal signals the foreground group, and the encoder
    // must hear about it from toyhost (which finishes or discards the output), not on its own.
    posix_spawnattr_setpgroup(&attributes, 0);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETPGROUP);

    std::vector<char*> args;
    for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
    args.push_back(nullptr);
    pid_t pid = -1;
    const int spawned = ::posix_spawn(&pid, program->c_str(), &actions, &attributes, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    if (spawned != 0) return Error(name + ": cannot start: " + std::strerror(spawned), Code::Process);
    inflight::addChild(pid);  // an emergency exit kills it (core/InFlight.h)

    ChildProcess child;
    child.pid_ = pid;
    child.pidfd_ = FileDescriptor(static_cast<int>(::syscall(SYS_pidfd_open, pid, 0)));
    if (readOutput) child.output_ = std::move(readEnd);
    else child.input_ = std::move(writeEnd);
    child.name_ = name;
    return child;
}

ChildProcess::ChildProcess(ChildProcess&& other) noexcept
    : pid_(std::exchange(other.pid_, -1)),
      pidfd_(std::move(other.pidfd_)),
      input_(std::move(other.input_)),
      output_(std::move(other.output_)),
      name_(std::move(other.name_)) {}

ChildProcess& ChildProcess::operator=(ChildProcess&& other) noexcept {
    if (this != &other) {
        kill();
        pid_ = std::exchange(other.pid_, -1);
        pidfd_ = std::move(other.pidfd_);
        input_ = std::move(other.input_);
        output_ = std::move(other.output_);
        name_ = std::move(other.name_);
    }
    return *this;
}

ChildProcess::~ChildProcess() { kill(); }

Status ChildProcess::write(std::span<const std::byte> bytes, const CancelSignal* cancel) {
    if (!input_) return Error(name_ + ": its input is already closed", Code::Process);
    return writeAll(input_.get(), bytes, name_ + "'s input", cancel);
}

namespace {
// SIGKILL to the child's process group (its own: started with POSIX_SPAWN_SETPGROUP, so the group's
// id is its pid), then to the child in case it left the group. Only while the child is not reaped:
// until then its pid, and so the group's id, cannot name another process.
void killGroupOf(pid_t pid) {
    ::kill(-pid, SIGKILL);
    ::kill(pid, SIGKILL);
}
}  // namespace

Result<int> ChildProcess::closeAndWait(int killAfterMs) {
    input_.reset();
    output_.reset();
    if (pid_ < 0) return Error(name_ + ": not running", Code::Process);
    if (killAfterMs >= 0 && pidfd_) {
        pollfd ended{pidfd_.get(), POLLIN, 0};
        int polled;
        do polled = ::poll(&ended, 1, killAfterMs);
        while (polled < 0 && errno == EINTR);
        if (polled == 0) killGroupOf(pid_);
    }
    int status = 0;
    pid_t waited;
    do waited = ::waitpid(pid_, &status, 0);
    while (waited < 0 && errno == EINTR);
    inflight::removeChild(pid_);
    pid_ = -1;
    if (waited < 0) return Error(name_ + ": waitpid failed: " + std::strerror(errno), Code::Process);
    if (WIFSIGNALED(status)) return Error(name_ + ": killed by signal " + std::to_string(WTERMSIG(status)), Code::Process);
    return WEXITSTATUS(status);
}

void ChildProcess::killFromAnyThread() const {
    if (pidfd_) ::syscall(SYS_pidfd_send_signal, pidfd_.get(), SIGKILL, nullptr, 0);
}

void ChildProcess::kill() {
    input_.reset();
    output_.reset();
    if (pid_ < 0) return;
    killGroupOf(pid_);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    inflight::removeChild(pid_);
    pid_ = -1;
}

}  // namespace toyhost
