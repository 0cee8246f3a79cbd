// SamplingFlags: --supersample, --motion-blur, --shutter, --shutter-offset, --sample-space and
// --dither, declared once for `run`
// and `compare` and turned into the settings (timing/SamplePattern.h says what they do);
// prepareSession checks the values (session/SettingChecks.h) and its errors name the
// setting, which withFlagNames shows as the flag.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include <toyhost/Session.h>


namespace toyhost::cli {

class SamplingFlags {
public:
    void define(CLI::App& command);
    void applyTo(SessionSettings& settings) const;

private:
    std::optional<int> supersample_, motionBlur_;
    std::optional<double> shutter_;
    std::optional<std::string> shutterOffset_, sampleSpace_;
    bool dither_ = false;
};

}  // namespace toyhost::cli
