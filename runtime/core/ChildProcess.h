// ChildProcess: runs a program with a pipe to its standard input and its output sent to a file,
// for feeding encoders such as ffmpeg. RAII: a child that is still running when its owner goes
// away is killed and reaped, so no failure path leaves a process behind. No GL needed.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <sys/types.h>
#include <vector>

#include "core/FileDescriptor.h"
#include "core/Result.h"

namespace toyhost {

// The absolute path of `program` found through $PATH, or std::nullopt.
std::optional<std::filesystem::path> findExecutable(const std::string& program);

class ChildProcess {
public:
    // Starts argv[0] (looked up in $PATH). Its stdout and stderr both go to `logFile` (created,
    // truncated), which callers read back to explain a failure.
    static Result<ChildProcess> spawn(const std::vector<std::string>& argv, const std::filesystem::path& logFile);
    // The same the other way round: stdin /dev/null, stdout on a pipe toyhost reads (read() or
    // outputFd()), only stderr in `logFile`: for a decoder that streams its output (video, live
    // audio).
    static Result<ChildProcess> spawnReading(const std::vector<std::string>& argv, const std::filesystem::path& logFile);

    ChildProcess(ChildProcess&& other) noexcept;
    ChildProcess& operator=(ChildProcess&& other) noexcept;
    ~ChildProcess();

    // Writes to the child's standard input. With `cancel`, a write blocked on a child that stopped
    // reading returns (Code::Cancelled) once it fires, even when the pipe is held open by a process
    // the child started (a shell script's own child).
    Status write(std::span<const std::byte> bytes, const CancelSignal* cancel = nullptr);
    // Reads what the child wrote to its stdout (spawnReading only): up to `bytes.size()`, blocking
    // until some is there; 0 at its end (the child closed it or exited).
    Result<std::size_t> read(std::span<std::byte> bytes);
    // The read end of the child's stdout (spawnReading), for poll() or readv(); -1 otherwise.
    int outputFd() const { return output_.get(); }
    // Closes the child's standard input (and the read end of its output) and waits for it; its
    // exit code, or an error when a signal ended it. With `killAfterMs` >= 0, a child still
    // running after that long is killed.
    Result<int> closeAndWait(int killAfterMs = -1);
    // Kills the child and its process group (SIGKILL: what it started, such as a wrapper script's
    // own ffmpeg or sleep) and reaps it; a no-op once it was waited for.
    void kill();
    // Sends SIGKILL without reaping or touching the pipe: safe to call from another thread while
    // this one writes to the child or waits for it (both then return). Uses a pidfd, so it can
    // never hit another process that reused the pid.
    void killFromAnyThread() const;

    const std::string& name() const { return name_; }

private:
    ChildProcess() = default;
    pid_t pid_ = -1;
    FileDescriptor pidfd_;  // refers to this child for as long as the object lives
    FileDescriptor input_;
    FileDescriptor output_;  // spawnReading: the read end of the child's stdout
    std::string name_;
    static Result<ChildProcess> start(const std::vector<std::string>& argv, const std::filesystem::path& logFile,
                                      bool readOutput);
};

}  // namespace toyhost
