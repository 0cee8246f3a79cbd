#include "NextCommand.h"

#include <cstdlib>
#include <unistd.h>

#include "drivers/window/WindowContext.h"

namespace toyhost::cli {

namespace fs = std::filesystem;

namespace {

// `text` as one shell word: as it is when it holds only characters no shell treats specially.
std::string shellWord(const std::string& text) {
    const bool plain = !text.empty() && text.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                               "0123456789_./+-=:,@%") == std::string::npos;
    if (plain) return text;
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

// `path` made canonical; the path itself when that fails.
fs::path resolved(const fs::path& path) {
    std::error_code ec;
    fs::path canonical = fs::canonical(path, ec);
    return ec ? path : canonical;
}

}  // namespace

std::string nextRunCommand(const NextCommandInputs& in) {
    std::string program;
    if (in.onPath && resolved(*in.onPath) == resolved(in.self)) {
        program = "toyhost";
    } else {
        // Below the working directory: relative, as the user would type it (build/tools/toyhost);
        // a name without a slash would be looked up on $PATH, hence ./ for a program right here.
        const fs::path self = resolved(in.self);
        const fs::path relative = self.lexically_relative(resolved(in.workingDirectory));
        const bool below = !relative.empty() && *relative.begin() != "..";
        program = below ? relative.string() : self.string();
        if (below && relative.parent_path().empty()) program = "./" + program;
    }
    std::string command = shellWord(program) + " run " + shellWord(in.target);
    if (!in.display) {
        // A headless run without --out renders and writes nothing: write one frame to look at.
        fs::path folder = fs::path(in.target).lexically_normal();
        if (folder.filename().empty()) folder = folder.parent_path();  // "my-port/"
        std::string name = folder.filename().string();
        if (name.empty() || name == "." || name == "..") name = "frame";
        if (in.frames > 1) command += " --frames 1";
        command += " --out " + shellWord(name + ".png");
    }
    return command;
}

std::string nextRunCommand(const std::string& target, int frames) {
    NextCommandInputs in;
    in.self = resolved("/proc/self/exe");
    in.target = target;
    in.display = displayAvailable();
    in.frames = frames;
    std::error_code ec;
    in.workingDirectory = fs::current_path(ec);
    if (const char* path = std::getenv("PATH")) {
        const std::string list = path;
        for (std::size_t start = 0; start <= list.size();) {
            const std::size_t colon = std::min(list.find(':', start), list.size());
            const fs::path dir = list.substr(start, colon - start);
            start = colon + 1;
            if (dir.empty()) continue;
            const fs::path candidate = dir / "toyhost";
            if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate, ec)) {
                in.onPath = candidate;  // the first one is what the shell runs
                break;
            }
        }
    }
    return nextRunCommand(in);
}

}  // namespace toyhost::cli
