// The toyhost subcommands: `run` (options parsed into SessionOptions), `import`, `inspect`, `new`,
// `media`, `sound` and `compare`.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "gl/GlThread.h"
#include "SamplingFlags.h"
#include "SessionFlags.h"
#include "session/SessionOptions.h"

namespace toyhost::cli {

class RunCommand {
public:
    // Declares the options of `run` on `command`.
    void define(CLI::App& command);
    // Turns the parsed options into SessionOptions and runs; returns the exit code.
    int execute(const GlProcess& process);

private:
    SessionOptions options_;
    SessionFlags flags_;
    SamplingFlags sampling_;
    std::string target_, capturePass_, codec_, frameRange_, shard_, exrCompression_, videoPreset_;
    std::optional<int> frames_, captureEvery_, pngLevel_, videoQuality_, captureMemoryMiB_, encoderThreads_;
    bool headless_ = false, window_ = false, watch_ = false, quiet_ = false, unpaced_ = false, paced_ = false;
};

int importCommand(const std::string& source, const std::string& dir, bool force);
int inspectCommand(const std::vector<std::string>& files, const std::string& regionText);
int newCommand(const std::string& dir, const std::string& passes, bool force);
int mediaCommand(const std::vector<std::string>& folders);

struct SoundCommandOptions {
    std::string target, out;
    double seconds = 0;
    SessionFlags flags;  // --media, --media-file
    bool quiet = false;
};
int soundCommand(const SoundCommandOptions& options, const GlProcess& process);

// `toyhost compare A B`: declares its options on a subcommand, then runs; exit 0 equal within the
// tolerance, 1 different, 2 anything that prevents an answer (usage, input, compile, GL, writing).
class CompareCommand {
public:
    void define(CLI::App& command);
    int execute(const GlProcess& process);

private:
    SessionFlags flags_;
    SamplingFlags sampling_;
    std::string a_, b_, pass_ = "Image", diffOut_, framesOut_;
    std::optional<int> frames_, maxDiff_;
    std::optional<double> tolerancePsnr_;
    bool json_ = false;
};

}  // namespace toyhost::cli
