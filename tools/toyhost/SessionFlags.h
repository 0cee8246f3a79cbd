// SessionFlags: the flags `run`, `compare` and `sound` share (canvas, clock, date, input, media,
// watchdog limits, --define), declared once with one help text each and turned into the library's settings;
// and the other direction: the library names a setting in its errors (Diagnostic::field "size",
// session/SettingChecks.h), the CLI shows the flag the user typed ("--size").
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <toyhost/Session.h>

#include "core/Result.h"

namespace toyhost::cli {

class SessionFlags {
public:
    enum Group : unsigned { Canvas = 1, Clock = 2, Input = 4, Media = 8, Limits = 16, Shader = 32, All = 63 };
    // Declares the flags of `groups` on `command`.
    void define(CLI::App& command, unsigned groups);
    // What was given, into the library's settings (a run's SessionOptions::settings, compare's
    // session); what was not stays absent, for the defaults. The values are checked where every
    // session's are (prepareSession); --mouse becomes `mouse`, the point pressed on frame 0.
    Status applyTo(SessionSettings& settings, std::optional<glm::vec2>& mouse) const;

private:
    Status parseMouse(std::optional<glm::vec2>& mouse) const;
    Status parseMedia(std::vector<std::filesystem::path>& folders,
                      std::vector<std::pair<std::string, std::filesystem::path>>& files) const;

    std::string size_, date_, mouse_, mouseScript_, keyScript_;
    std::optional<double> fps_, startTime_, frameTimeout_, compileTimeout_;
    std::vector<std::string> mediaFolders_, mediaFiles_, defines_;
};

// `error` with each setting the library names (Diagnostic::field) shown as the CLI's flag.
Error withFlagNames(Error error);

}  // namespace toyhost::cli
