// Background processes for tests that drive toyhost from outside (window mode through xdotool,
// --watch): start with output to a log file, send signals, wait with a deadline.
#pragma once

#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace toyhost::testing {

class BackgroundProcess {
public:
    // Runs `program` with `arguments` (in `workingDir` when given); stdout and stderr go to `log`;
    // its stdin is `stdinFd` when given (a pipe the test writes to), else the test's.
    BackgroundProcess(const std::filesystem::path& program, const std::vector<std::string>& arguments,
                      const std::filesystem::path& log, const std::filesystem::path& workingDir = {}, int stdinFd = -1)
        : log_(log) {
        pid_ = ::fork();
        if (pid_ == 0) {
            if (!workingDir.empty() && ::chdir(workingDir.c_str()) != 0) std::_Exit(126);
            if (stdinFd >= 0 && ::dup2(stdinFd, 0) < 0) std::_Exit(126);
            const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            ::dup2(fd, 1);
            ::dup2(fd, 2);
            std::vector<char*> argv;
            std::string name = program.string();
            argv.push_back(name.data());
            std::vector<std::string> copies = arguments;
            for (std::string& a : copies) argv.push_back(a.data());
            argv.push_back(nullptr);
            ::execv(name.c_str(), argv.data());
            std::_Exit(127);
        }
    }
    ~BackgroundProcess() {
        if (pid_ > 0 && exitCode_ == kRunning) {
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, nullptr, 0);
        }
    }
    BackgroundProcess(const BackgroundProcess&) = delete;
    BackgroundProcess& operator=(const BackgroundProcess&) = delete;

    void signal(int sig) const { ::kill(pid_, sig); }
    pid_t pid() const { return pid_; }
    // Waits until the process's main thread sleeps in the kernel function whose name holds one of
    // `places` (/proc/PID/wchan, e.g. "poll" or "pipe_read"), or `seconds` passed, or it ended.
    bool waitUntilBlockedIn(const std::vector<std::string>& places, double seconds) {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (std::chrono::steady_clock::now() < deadline && running()) {
            std::ifstream in("/proc/" + std::to_string(pid_) + "/wchan");
            std::string where;
            std::getline(in, where);
            for (const std::string& place : places)
                if (where.find(place) != std::string::npos) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return false;
    }
    bool running() {
        poll();
        return exitCode_ == kRunning;
    }
    // The exit code (128 + signal when killed), or -1 after `seconds` (the process is killed).
    int wait(double seconds) {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (running()) {
            if (std::chrono::steady_clock::now() > deadline) {
                ::kill(pid_, SIGKILL);
                ::waitpid(pid_, nullptr, 0);
                exitCode_ = -1;
                return -1;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        return exitCode_;
    }
    std::string log() const {
        std::ifstream in(log_);
        std::stringstream text;
        text << in.rdbuf();
        return text.str();
    }
    // Waits until the log contains `text` (or the process ended, or `seconds` passed).
    bool waitForLog(const std::string& text, double seconds, std::size_t occurrences = 1) {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (std::chrono::steady_clock::now() < deadline) {
            const std::string now = log();
            std::size_t count = 0;
            for (std::size_t at = now.find(text); at != std::string::npos; at = now.find(text, at + 1)) ++count;
            if (count >= occurrences) return true;
            if (!running()) return false;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        return false;
    }

private:
    static constexpr int kRunning = -1000;
    void poll() {
        if (exitCode_ != kRunning) return;
        int status = 0;
        if (::waitpid(pid_, &status, WNOHANG) == pid_)
            exitCode_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    pid_t pid_ = -1;
    int exitCode_ = kRunning;
    std::filesystem::path log_;
};

// Output of a shell command (stdout), with its exit status.
inline std::pair<int, std::string> shell(const std::string& command) {
    std::string out;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return {-1, out};
    char chunk[4096];
    std::size_t n;
    while ((n = std::fread(chunk, 1, sizeof chunk, pipe)) > 0) out.append(chunk, n);
    const int status = ::pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

}  // namespace toyhost::testing
