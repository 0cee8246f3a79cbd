// `toyhost farm`: options in, the library's plan, frame states and video out (see FarmCommand.h).
#include "FarmCommand.h"

#include <algorithm>
#include <climits>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "Commands.h"
#include "Console.h"
#include "NumberOptions.h"
#include "core/AtomicFile.h"
#include "core/Defaults.h"
#include "core/InFlight.h"
#include "export/LoadShadertoy.h"
#include "farm/FarmPlan.h"
#include "farm/FarmStatus.h"
#include "farm/frames/FrameCheck.h"
#include "farm/frames/JoinFrames.h"
#include "session/StopSignals.h"

namespace toyhost::cli {

namespace fs = std::filesystem;

namespace {

std::string readText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
}

// The run options are those of `toyhost run`: parsed by its own definition, so a typo is caught
// here and not on every node of the farm.
std::optional<std::string> runOptionProblem(const std::string& target, const std::vector<std::string>& options) {
    CLI::App check{"run"};
    RunCommand run;
    run.define(check);
    std::vector<std::string> reversed(options.rbegin(), options.rend());
    reversed.push_back(target);
    try {
        check.parse(reversed);
    } catch (const CLI::ParseError& e) {
        return std::string(e.what());
    }
    return std::nullopt;
}

std::string thisProgram() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    return ec ? std::string("toyhost") : self.string();
}

// `layout` when its shards split its frames (toyhost::shardSpan's rule), else --shards' error.
Result<farm::FrameLayout> withShardsChecked(farm::FrameLayout layout) {
    if (!shardSpan(layout.frames, layout.shards, 0))
        return Error("--shards " + std::to_string(layout.shards) + ": expected 1 .. --frames (" +
                         std::to_string(layout.frames) + ")",
                     Code::Usage);
    return layout;
}

// The layout of DIR: its farm.json, or a plain folder of numbered frames.
Result<farm::FrameLayout> layoutOf(const fs::path& dir, std::optional<int> frames, std::optional<int> shards,
                                   const std::string& pattern) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return fileError(dir.string(), "not a folder", Code::IoNotAFolder);
    if (fs::exists(dir / "farm.json")) {
        Result<farm::FrameLayout> layout = farm::layoutFromPlan(readText(dir / "farm.json"), dir);
        if (!layout) return layout;
        if (frames && *frames != layout->frames)
            return Error("--frames " + std::to_string(*frames) + ": the plan in " + (dir / "farm.json").string() +
                             " renders " + std::to_string(layout->frames),
                         Code::Usage);
        if (shards) layout->shards = *shards;
        return withShardsChecked(std::move(*layout));
    }
    if (!frames) return Error(dir.string() + " has no farm.json (from farm plan): give --frames", Code::Usage);
    farm::FrameLayout layout;
    layout.frameDir = dir;
    layout.frames = *frames;
    layout.shards = shards.value_or(1);
    if (!pattern.empty()) {
        if (std::optional<std::string> problem = farm::frameNameProblem(pattern))
            return Error("--pattern " + pattern + ": " + *problem, Code::Usage);
        layout.frameName = pattern;
    } else {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir, ec)) names.push_back(entry.path().filename().string());
        Result<std::string> found = farm::framePatternOf(names);
        if (!found) return inFile(dir.string(), found.error());
        layout.frameName = *found;
    }
    return withShardsChecked(std::move(layout));
}

// `--fps X` or `--fps=X` among the plan's run options.
std::optional<double> fpsOption(const std::vector<std::string>& options) {
    for (std::size_t i = 0; i < options.size(); ++i) {
        if (options[i] == "--fps" && i + 1 < options.size()) return std::stod(options[i + 1]);
        if (options[i].rfind("--fps=", 0) == 0) return std::stod(options[i].substr(6));
    }
    return std::nullopt;
}

// The first folder of `dir`'s path that does not exist yet (what create_directories makes), or
// empty when `dir` exists.
fs::path firstMissingFolder(const fs::path& dir) {
    std::error_code ec;
    fs::path missing;
    for (fs::path at = dir; !at.empty() && !fs::exists(at, ec); at = at.parent_path()) {
        missing = at;
        if (at == at.parent_path()) break;
    }
    return missing;
}

// Writes `text` to `file`; errors carry the system's reason (ENOSPC: "No space left on device").
Status writeWhole(const fs::path& file, const std::string& text, const fs::path& shownAs) {
    std::FILE* out = std::fopen(file.c_str(), "wb");
    if (!out) return fileError(shownAs.string(), std::string("cannot be written: ") + std::strerror(errno), Code::IoWrite);
    const bool wrote = std::fwrite(text.data(), 1, text.size(), out) == text.size();
    int error = wrote ? 0 : errno;
    if (std::fclose(out) != 0 && !error) error = errno;
    if (wrote && !error) return okStatus();
    return fileError(shownAs.string(), std::string("cannot be written: ") + std::strerror(error),
                     error == ENOSPC ? Code::IoNoSpace : Code::IoWrite);
}

// The plan's files in `dir`, all or none: each is written under a hidden temporary name beside
// its own, and only when every one is complete are they renamed into place, farm.json (whose
// presence means "a job is planned here") last. On a failure nothing of the plan is left, nor the
// job folder when this call made it.
Status writePlan(const fs::path& dir, const std::vector<farm::PlanFile>& files) {
    std::error_code ec;
    const fs::path made = firstMissingFolder(dir);
    fs::create_directories(dir, ec);
    if (ec) {
        const Status failure = fileError(dir.string(), "cannot create the job folder: " + ec.message(), Code::IoWrite);
        std::error_code ignored;
        if (!made.empty()) fs::remove_all(made, ignored);  // the folders above it that were made
        return failure;
    }
    std::vector<std::pair<fs::path, fs::path>> written;  // temporary, final
    auto undo = [&](Status failure) {
        std::error_code ignored;
        for (const auto& [temp, final] : written) {
            fs::remove(temp, ignored);
            inflight::removeFile(temp);
        }
        if (!made.empty()) fs::remove_all(made, ignored);
        return failure;
    };
    for (const farm::PlanFile& file : files) {
        const fs::path path = dir / file.name;
        const fs::path temp = temporarySibling(path);
        if (!inflight::addFile(temp)) return undo(fileError(path.string(), "not written: toyhost is stopping", Code::Interrupted));
        written.push_back({temp, path});
        if (Status done = writeWhole(temp, file.text, path); !done) return undo(done);
        if (file.executable) {
            fs::permissions(temp, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                            fs::perm_options::add, ec);
            if (ec) return undo(fileError(path.string(), "cannot be made executable: " + ec.message(), Code::IoWrite));
        }
    }
    // farm.json is the first file of the plan: renamed last. A rename within one folder fails only
    // when the folder itself changes under us; the files already renamed are then taken back.
    std::vector<std::size_t> order;
    for (std::size_t i = 1; i <= written.size(); ++i) order.push_back(i % written.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        const auto& [temp, final] = written[order[k]];
        fs::rename(temp, final, ec);
        if (ec) {
            const Status failure = fileError(final.string(), "cannot be put in place: " + ec.message(), Code::IoWrite);
            std::error_code ignored;
            for (std::size_t j = 0; j < k; ++j) fs::remove(written[order[j]].second, ignored);
            return undo(failure);
        }
        inflight::removeFile(temp);
    }
    return okStatus();
}

// Whether a shard is redone from its first frame (`again`): its frames are damaged, or it finished
// (its checkpoint is at its end, so resuming would render nothing); else it resumes.
bool redoAgain(const farm::ShardStatus& shard) {
    for (const farm::FrameProblem& p : shard.problems)
        if (p.state != farm::FrameState::Missing) return true;
    return shard.exitCode == 0;
}

}  // namespace

void FarmCommand::define(CLI::App& app) {
    farm_ = app.add_subcommand("farm", "Render farms: plan a sharded job for Slurm, Kubernetes or GNU parallel, check "
                                       "its frames, join them into a video (docs/farm.md)");
    // At most one; none is answered by execute() with the three to choose from (CLI11's own words,
    // "A subcommand is required", named none of them).
    farm_->require_subcommand(0, 1);

    plan_ = farm_->add_subcommand(
        "plan", "Write the job files of a render split into shards: run-shard.sh (the one command, with the run "
                "options), the checkpoint chain for shadertoys with buffers, and the scheduler's files. Options after "
                "TARGET that farm plan does not know are run options, given to every shard");
    plan_->allow_extras();
    plan_->add_option("target", target_, "Folder holding manifest.json, a manifest file, or a Shadertoy JSON export")
        ->required();
    plan_->add_option("--frames", frames_, "Frames of the whole run")->required()->check(CLI::Range(1, INT_MAX));
    plan_->add_option("--shards", shards_, "Shards (array tasks, completions, parallel jobs)")
        ->required()
        ->check(CLI::Range(1, INT_MAX));
    plan_->add_option("--scheduler", scheduler_, "slurm (sbatch array), k8s (Indexed Job) or parallel (GNU parallel)")
        ->required()
        ->check(CLI::IsMember({"slurm", "k8s", "kubernetes", "parallel"}));
    plan_->add_option("--job", job_,
                      "Job folder on storage every node shares: the plan's files, frames/, checkpoints/, exit/, logs/")
        ->required();
    plan_->add_option("--frame-name", frameName_, "File name of the frames in JOB/frames (default f_%06d.png; .exr for floats)");
    plan_->add_option("--toyhost", toyhost_, "The toyhost program as the nodes find it (default: this one's path; k8s: toyhost, the image's)");
    plan_->add_option("--time", time_, "Slurm: sbatch --time of each task (at the limit a task checkpoints and is requeued)");
    plan_->add_option("--cpus-per-task", cpusPerTask_, "Slurm --cpus-per-task; Kubernetes cpu request")
        ->check(CLI::Range(1, 4096));
    plan_->add_option("--parallelism", parallelism_, "Shards running at once (default: all)")->check(CLI::Range(1, INT_MAX));
    plan_->add_option("--partition", partition_, "Slurm: sbatch --partition of every job file");
    plan_->add_option("--account", account_, "Slurm: sbatch --account of every job file");
    plan_->add_option("--qos", qos_, "Slurm: sbatch --qos of every job file");
    plan_->add_option("--mem", mem_, "Slurm --mem (16G); Kubernetes memory request and limit");
    plan_->add_option("--gres", gres_, "Slurm --gres (gpu:1); Kubernetes: gpu:N, an nvidia.com/gpu limit");
    plan_->add_option("--scheduler-arg", schedulerArgs_,
                      "Slurm: any further sbatch option as one word, written as an #SBATCH line; repeatable: "
                      "--scheduler-arg=--constraint=avx2")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    plan_->add_option("--image", image_, "Kubernetes: the container image (packaging/Containerfile)");
    plan_->add_flag("--force", force_, "Replace the plan files of an existing job folder");

    status_ = farm_->add_subcommand(
        "status", "List a job's frames that are missing, truncated or undecodable (each is decoded), per shard, with "
                  "each shard's exit code; exit 0 when complete, 1 when not");
    status_->add_option("dir", dir_, "A job folder (farm plan --job) or a folder of numbered frames")->required();
    status_->add_option("--frames", checkFrames_, "Frames of the run (read from the job's farm.json when there is one)");
    status_->add_option("--shards", checkShards_, "Shards to report by (default: the plan's, or 1)");
    status_->add_option("--pattern", pattern_, "Frame file names (f_%04d.png) when the folder holds several sequences");

    join_ = farm_->add_subcommand("join", "Encode a job's complete frame sequence into one video (refuses, listing the "
                                          "frames, when any is missing or damaged)");
    join_->add_option("dir", dir_, "A job folder (farm plan --job) or a folder of numbered frames")->required();
    join_->add_option("--out", out_, "The video: .mp4, .mov, .mkv (H.264) or .webm (VP9)")->required();
    join_->add_option("--frames", checkFrames_, "Frames of the run (read from the job's farm.json when there is one)");
    join_->add_option("--pattern", pattern_, "Frame file names (f_%04d.png) when the folder holds several sequences");
    join_->add_option("--fps", fps_, "Frames per second (default: the plan's --fps, else 60)");
    join_->add_option("--audio", audio_, "A sound track to mux in, such as the Sound pass's from `toyhost sound TARGET --out track.wav`");
    join_->add_option("--codec", codec_, "Video encoder (ffmpeg name), as run --codec");
    join_->add_option("--video-preset", videoPreset_, "ffmpeg -preset, as run --video-preset");
    join_->add_option("--video-quality", videoQuality_, "Constant rate factor, as run --video-quality");

    // Numbers as text first, as every toyhost command takes them (0x10 or 010 are not numbers here).
    const CLI::Validator wholeNumber = wholeNumberOption();
    for (const char* name : {"--frames", "--shards", "--cpus-per-task", "--parallelism"})
        plan_->get_option(name)->transform(wholeNumber);
    for (const char* name : {"--frames", "--shards"})
        status_->get_option(name)->check(CLI::Range(1, INT_MAX))->transform(wholeNumber);
    join_->get_option("--frames")->check(CLI::Range(1, INT_MAX))->transform(wholeNumber);
    join_->get_option("--video-quality")->transform(wholeNumber);
    join_->get_option("--fps")->transform(decimalNumberOption());
}

int FarmCommand::execute() {
    if (plan_->parsed()) return plan();
    if (status_->parsed()) return status();
    if (join_->parsed()) return join();
    return usage("toyhost farm: give a subcommand: plan (write a sharded job's files), status (check its frames) or "
                 "join (encode them into a video); toyhost farm SUBCOMMAND --help for its options");
}

int FarmCommand::plan() {
    const std::vector<std::string> runOptions = plan_->remaining();
    Result<ManifestDesc> shadertoy = loadShadertoy(target_);
    if (!shadertoy) return fail(shadertoy.error());
    if (std::optional<std::string> problem = runOptionProblem(target_, runOptions))
        return usage("farm plan: run options: " + *problem);

    farm::PlanRequest request;
    request.scheduler = *farm::schedulerNamed(scheduler_);
    // Pods run the image's toyhost (packaging/Containerfile installs it on PATH); other nodes
    // share this machine's installation.
    if (!toyhost_.empty()) request.toyhost = toyhost_;
    else request.toyhost = request.scheduler == farm::Scheduler::Kubernetes ? "toyhost" : thisProgram();
    std::error_code cwd;
    request.target = fs::absolute(target_, cwd).lexically_normal().string();
    request.jobDir = fs::absolute(job_, cwd).lexically_normal().string();
    if (cwd) return fail(Error("farm plan: the current folder cannot be read: " + cwd.message(), Code::IoWrite));
    if (request.jobDir.size() > 1 && request.jobDir.back() == '/') request.jobDir.pop_back();
    request.frames = frames_;
    request.shards = shards_;
    request.frameName = frameName_;
    request.runOptions = runOptions;
    request.stateful = shadertoy->hasStatefulPasses();
    request.slurmTime = time_;
    request.cpusPerTask = cpusPerTask_;
    request.parallelism = parallelism_;
    request.image = image_;
    request.partition = partition_;
    request.account = account_;
    request.qos = qos_;
    request.mem = mem_;
    request.gres = gres_;
    request.schedulerArgs = schedulerArgs_;
    Result<std::vector<farm::PlanFile>> files = farm::planFarm(request);
    if (!files) return fail(files.error());

    const fs::path dir = request.jobDir;
    std::error_code ec;
    const bool planned = fs::exists(dir / "farm.json", ec);
    if (ec && ec != std::errc::no_such_file_or_directory && ec != std::errc::not_a_directory)
        return fail(fileError(dir.string(), "the job folder cannot be used: " + ec.message(), Code::IoWrite));
    if (planned && !force_)
        return fail(fileError((dir / "farm.json").string(), "a job is planned here already (--force replaces its files)",
                              Code::IoExists));
    if (Status written = writePlan(dir, *files); !written) return fail(written.error());
    for (const std::string& warning : farm::planWarnings(request)) std::cerr << "toyhost farm: warning: " << warning << "\n";
    std::cout << "toyhost farm: " << request.shards << " shards of " << request.frames << " frames"
              << (request.stateful && request.shards > 1 ? ", starting from a checkpoint chain (checkpoints.sh)" : "")
              << ", in " << dir.string() << ":\n";
    for (const farm::PlanFile& file : *files) std::cout << "  " << file.name << "\n";
    const char* next = request.scheduler == farm::Scheduler::Parallel ? "parallel.sh" : "submit.sh";
    std::cout << "Run " << (dir / next).string() << ", then: toyhost farm status " << dir.string() << "\n";
    return kExitOk;
}

int FarmCommand::status() {
    Result<farm::FrameLayout> layout = layoutOf(dir_, checkFrames_, checkShards_, pattern_);
    if (!layout) return fail(layout.error());
    const farm::FarmStatus state = checkFarm(*layout);
    long long good = 0, expected = 0;
    for (const farm::ShardStatus& shard : state.shards) {
        good += shard.good;
        expected += shard.expected;
        std::cout << "shard " << shard.index << " (frames " << shard.span.first << "-" << shard.span.end - 1
                  << "): " << shard.good << "/" << shard.expected << " ok";
        for (farm::FrameState kind : {farm::FrameState::Missing, farm::FrameState::Truncated, farm::FrameState::Undecodable}) {
            std::vector<FrameSpan> frames;
            for (const farm::FrameProblem& p : shard.problems)
                if (p.state == kind) frames.push_back({p.frame, p.lastFrame() + 1});
            if (!frames.empty()) std::cout << "; " << farm::frameStateName(kind) << " " << farm::frameList(frames);
        }
        if (shard.exitCode)
            std::cout << "; exit " << *shard.exitCode << " (" << farm::exitMeaning(*shard.exitCode) << ")";
        std::cout << "\n";
        for (const farm::FrameProblem& p : shard.problems)
            if (!p.reason.empty())
                std::cout << "  " << layout->frameFile(p.frame).string() << ": " << farm::frameStateName(p.state)
                          << ": " << p.reason << "\n";
        if (layout->scheduler && shard.bad() > 0)
            std::cout << "  redo: " << farm::redoCommand(*layout->scheduler, layout->jobDir.string(), shard.index, redoAgain(shard))
                      << "\n";
    }
    std::cout << good << "/" << expected << " frames ok";
    if (!state.complete()) std::cout << "; to render again: " << farm::frameList(state.badSpans());
    std::cout << "\n";
    return state.complete() ? kExitOk : kExitFailure;
}

int FarmCommand::join() {
    Result<farm::FrameLayout> layout = layoutOf(dir_, checkFrames_, std::nullopt, pattern_);
    if (!layout) return fail(layout.error());
    const farm::FarmStatus state = checkFarm(*layout);
    if (!state.complete())
        return fail(Error("frames " + farm::frameList(state.badSpans()) + " of " + std::to_string(layout->frames) +
                              " are missing or damaged (toyhost farm status " + dir_ + " says which and why)",
                          Code::IoNotFound));
    std::vector<fs::path> frames;
    for (const farm::ShardStatus& shard : state.shards)
        for (int frame = shard.span.first; frame < shard.span.end; ++frame)
            if (layout->captured(frame, shard.span)) frames.push_back(layout->frameFile(frame));
    VideoSettings settings;
    if (!codec_.empty()) settings.codec = codec_;
    if (!videoPreset_.empty()) settings.preset = videoPreset_;
    if (videoQuality_) settings.quality = *videoQuality_;
    if (!audio_.empty()) settings.audio = fs::path(audio_);
    double fps = defaults::kFps;
    try {
        if (fps_) fps = *fps_;
        else if (std::optional<double> planned = fpsOption(layout->runOptions)) fps = *planned;
    } catch (const std::exception&) {
        return usage("farm join: the plan's --fps is not a number: give --fps");
    }
    if (!(fps >= defaults::kMinFps && fps <= defaults::kMaxFps))
        return usage("farm join: --fps " + std::to_string(fps) + ": expected from " + std::to_string(defaults::kMinFps) +
                     " to " + std::to_string(defaults::kMaxFps) + " frames per second, as run --fps");
    installStopSignals();
    if (Status joined = joinFrames(frames, out_, fps, settings, [] { return stopSignal() != 0; }); !joined)
        return fail(joined.error());
    std::cout << "toyhost farm: " << frames.size() << " frames joined into " << out_ << "\n";
    return kExitOk;
}

}  // namespace toyhost::cli
