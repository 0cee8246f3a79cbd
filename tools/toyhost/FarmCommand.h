// `toyhost farm plan|status|join`: parses their options and prints what runtime/farm and
// runtime/farm/frames decide (the scheduler files, the frames' states, the joined video). No GL.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

namespace toyhost::cli {

class FarmCommand {
public:
    // Declares `farm` and its three subcommands on `app`.
    void define(CLI::App& app);
    bool parsed() const { return farm_ && farm_->parsed(); }
    // Runs the parsed subcommand; returns the exit code.
    int execute();

private:
    int plan();
    int status();
    int join();

    CLI::App* farm_ = nullptr;
    CLI::App* plan_ = nullptr;
    CLI::App* status_ = nullptr;
    CLI::App* join_ = nullptr;
    // plan
    std::string target_, scheduler_, job_, frameName_ = "f_%06d.png", toyhost_, time_, image_ = "toyhost:latest";
    std::string partition_, account_, qos_, mem_, gres_;
    std::vector<std::string> schedulerArgs_;
    int frames_ = 0, shards_ = 0, cpusPerTask_ = 0, parallelism_ = 0;
    bool force_ = false;
    // status and join
    std::string dir_, pattern_, out_, audio_, codec_, videoPreset_;
    std::optional<int> checkFrames_, checkShards_, videoQuality_;
    std::optional<double> fps_;
};

}  // namespace toyhost::cli
