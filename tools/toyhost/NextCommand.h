// NextCommand: the exact command that runs a shadertoy `toyhost import` or `toyhost new` just
// wrote, as the user can type it where they are: `toyhost` when that name on $PATH is this very
// program, else this program's path (relative to the working directory when it lies below it,
// e.g. build/tools/toyhost); and, without a display, with an --out that writes a frame, since a
// headless run without --out writes nothing.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace toyhost::cli {

struct NextCommandInputs {
    std::filesystem::path self;                   // this program, resolved (/proc/self/exe)
    std::optional<std::filesystem::path> onPath;  // what `toyhost` on $PATH resolves to, if anything
    std::filesystem::path workingDirectory;
    std::string target;                           // the folder as the user named it
    bool display = false;                         // a window will open ($DISPLAY / $WAYLAND_DISPLAY)
    int frames = 1;                               // the frames a plain run renders (manifest defaults)
};

// The command (shell-quoted where needed). Pure: no lookups.
std::string nextRunCommand(const NextCommandInputs& inputs);

// The same for this process: resolves /proc/self/exe, looks `toyhost` up on $PATH, reads the
// working directory and whether a display is there.
std::string nextRunCommand(const std::string& target, int frames);

}  // namespace toyhost::cli
