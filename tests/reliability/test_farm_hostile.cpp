// `toyhost farm` and `toyhost new` given what a hostile or careless user gives them (issue 46):
// values that would end a line of a generated script (a newline in the job folder, the target's
// folder, --time), names that are not UTF-8, names too long, a 120,000-character pattern, a hostile
// GNU parallel joblog, 2^31 frames with 8 on disk, farm.json numbers that wrap, a full disk. Each
// is run through the CLI with its arguments passed as they are (no shell in between); the verdict
// is the exit code, one "toyhost: ... error:" line naming the option or file, no crash and nothing
// left behind or run. The planted command is always `touch PWNED`: no file of that name may
// appear. Scripts that are planned are run with stand-ins for toyhost, sbatch, scontrol and kubectl
// on PATH (GNU parallel is the real one), to show that quoted paths reach the program exactly.
#include "GlTestSupport.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include "Processes.h"
#include "image/ImageWriters.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

// Runs `argv` (argv[0] a path) with `env` added, output captured, killed after `seconds`. A
// crash shows as a negative code (-signal).
CommandResult runArgv(std::vector<std::string> argv, const std::vector<std::string>& env = {}, int seconds = 120) {
    argv.insert(argv.begin(), {"/usr/bin/timeout", "-s", "KILL", std::to_string(seconds)});
    int out[2];
    CommandResult result;
    if (::pipe(out) != 0) return result;
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::dup2(out[1], 1);
        ::dup2(out[1], 2);
        ::close(out[0]);
        ::close(out[1]);
        ::unsetenv("DISPLAY");
        ::unsetenv("WAYLAND_DISPLAY");
        for (const std::string& setting : env) ::putenv(const_cast<char*>(setting.c_str()));
        std::vector<char*> args;
        for (std::string& arg : argv) args.push_back(arg.data());
        args.push_back(nullptr);
        ::execv(args[0], args.data());
        ::_exit(127);
    }
    ::close(out[1]);
    char chunk[4096];
    ssize_t n;
    while ((n = ::read(out[0], chunk, sizeof chunk)) > 0) result.output.append(chunk, static_cast<std::size_t>(n));
    ::close(out[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);
    // timeout(1) reports a child killed by a signal as 128 + the signal.
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
    if (result.exitCode > 128 && result.exitCode != 130 && result.exitCode != 143) result.exitCode = -(result.exitCode - 128);
    return result;
}

CommandResult toyhost(std::vector<std::string> args, const std::vector<std::string>& env = {}) {
    args.insert(args.begin(), toyhostBinary().string());
    return runArgv(std::move(args), env);
}

std::vector<std::string> errorLines(const std::string& output) {
    std::vector<std::string> lines;
    std::istringstream in(output);
    for (std::string line; std::getline(in, line);)
        if (line.find("error:") != std::string::npos) lines.push_back(line);
    return lines;
}

// One usage or failure message, in toyhost's form, naming each of `mentions`.
void expectOneError(const CommandResult& result, int exitCode, const std::vector<std::string>& mentions,
                    const std::string& what) {
    EXPECT_EQ(result.exitCode, exitCode) << what << "\n" << result.output;
    const std::vector<std::string> errors = errorLines(result.output);
    ASSERT_EQ(errors.size(), 1u) << what << "\n" << result.output;
    EXPECT_EQ(errors[0].rfind("toyhost: ", 0), 0u) << what << ": " << errors[0];
    for (const std::string& mention : mentions)
        EXPECT_NE(errors[0].find(mention), std::string::npos) << what << ": the message does not name \"" << mention
                                                             << "\": " << errors[0];
}

// Whether a file named PWNED exists anywhere under `dir` (or in the current folder).
bool pwned(const fs::path& dir) {
    std::error_code ec;
    if (fs::exists("PWNED", ec)) return true;
    for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
        if (it->path().filename() == "PWNED") return true;
    return false;
}

// A copy of the gallery's stateful probe (buffers: the plan has a checkpoint chain) at `dir`.
void copyShadertoy(const fs::path& dir) {
    fs::create_directories(dir);
    fs::copy(sourceDir() / "shadertoys" / "pingpong-probe", dir, fs::copy_options::recursive);
}

void writeExecutable(const fs::path& path, const std::string& text) {
    writeFile(path, text);
    fs::permissions(path, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                              fs::perms::others_exec);
}

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
}

const char* const kSchedulers[] = {"slurm", "k8s", "parallel"};

// ---- injection --------------------------------------------------------------------------------

TEST(FarmHostile, ALineBreakInAJobFolderTargetOrTimeIsRefusedForEverySchedulerAndNothingRuns) {
    const fs::path dir = freshOutputDir("farm-hostile/injection");
    const fs::path toy = dir / "toy";
    copyShadertoy(toy);
    const fs::path newlineToy = dir / "x\ntouch PWNED\nx";
    copyShadertoy(newlineToy);
    for (const char* scheduler : kSchedulers) {
        const std::string job = (dir / "x" / "job\ntouch PWNED\nx").string();
        const std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> cases = {
            {{"farm", "plan", toy.string(), "--frames", "4", "--shards", "2", "--scheduler", scheduler, "--job", job},
             {"--job", "line break"}},
            {{"farm", "plan", newlineToy.string(), "--frames", "4", "--shards", "2", "--scheduler", scheduler, "--job",
              (dir / "plain-job").string()},
             {"the target", "line break"}},
            {{"farm", "plan", toy.string(), "--frames", "4", "--shards", "2", "--scheduler", scheduler, "--job",
              (dir / "plain-job").string(), "--time", "1\ntouch PWNED"},
             {"--time", "line break"}},
            {{"farm", "plan", toy.string(), "--frames", "4", "--shards", "2", "--scheduler", scheduler, "--job",
              (dir / "plain-job").string(), "--toyhost", "/usr/bin/toyhost\rtouch PWNED"},
             {"--toyhost", "carriage return"}},
            // Not UTF-8: farm.json could not hold it (nlohmann aborted the plan with farm.json half-made).
            {{"farm", "plan", toy.string(), "--frames", "4", "--shards", "2", "--scheduler", scheduler, "--job",
              (dir / "plain-job").string(), "--define", "X=\xff"},
             {"--define", "UTF-8"}},
        };
        for (const auto& [args, mentions] : cases) {
            const std::string what = std::string(scheduler) + ": " + mentions[0];
            const CommandResult result = toyhost(args);
            expectOneError(result, 2, mentions, what);
            EXPECT_FALSE(fs::exists(dir / "x")) << what << ": the job folder was made";
            EXPECT_FALSE(fs::exists(dir / "plain-job")) << what << ": the job folder was made";
            EXPECT_FALSE(pwned(dir)) << what;
        }
    }
}

// Paths with a space, an apostrophe, a double quote, $( ), ;, # and `: every script passes them to
// toyhost exactly, and nothing they hold runs. The scripts are run with stand-ins for toyhost,
// sbatch, scontrol and kubectl on PATH, and the real GNU parallel.
TEST(FarmHostile, PathsWithQuotesAndShellWordsReachToyhostExactlyFromEveryScript) {
    const fs::path dir = freshOutputDir("farm-hostile/quoted");
    const std::string odd = "it's a \"job\" $(touch PWNED); `touch PWNED` #1";
    const fs::path toy = dir / ("toy " + odd);
    copyShadertoy(toy);
    const fs::path bin = dir / "bin";
    const fs::path log = dir / "calls.log";
    // toyhost: records the target it was given, one line each.
    writeExecutable(bin / "toyhost-stub", "#!/bin/bash\nprintf '%s\\n' \"$2\" >> \"$STUB_LOG\"\n");
    writeExecutable(bin / "sbatch", "#!/bin/bash\necho 1\n");
    writeExecutable(bin / "scontrol", "#!/bin/bash\nexit 0\n");
    // kubectl: every call succeeds, except a wait for the chain's failure (the chain completed).
    writeExecutable(bin / "kubectl", "#!/bin/bash\ncase \"$*\" in *condition=failed*) exit 1;; esac\nexit 0\n");
    // GNU parallel itself (tests/reliability needs it installed, as the shard test does): it runs
    // its command through a shell, which evaluated a job folder's $( ) before parallel.sh used -q.
    const std::vector<std::string> env = {"PATH=" + bin.string() + ":/usr/bin:/bin", "STUB_LOG=" + log.string(),
                                          "SLURM_ARRAY_TASK_ID=0", "SLURM_ARRAY_JOB_ID=1", "JOB_COMPLETION_INDEX=0"};
    for (const char* scheduler : kSchedulers) {
        const fs::path job = dir / (std::string(scheduler) + " " + odd);
        const CommandResult planned = toyhost({"farm", "plan", toy.string(), "--frames", "4", "--shards", "2", "--scheduler",
                                               scheduler, "--job", job.string(), "--toyhost", (bin / "toyhost-stub").string(),
                                               "--time", "1-0:10"});
        ASSERT_EQ(planned.exitCode, 0) << scheduler << "\n" << planned.output;
        fs::remove(log);
        std::vector<std::vector<std::string>> runs;
        if (std::string(scheduler) == "slurm") {
            runs = {{"/bin/bash", (job / "job.sbatch").string()}, {"/bin/bash", (job / "checkpoints.sbatch").string()},
                    {"/bin/bash", (job / "submit.sh").string()}};
        } else if (std::string(scheduler) == "k8s") {
            // The Job's command as Kubernetes runs it: the YAML's list, read by a YAML parser.
            const std::string runYaml =
                "import subprocess, sys, yaml\n"
                "spec = yaml.safe_load(open(sys.argv[1]))['spec']['template']['spec']['containers'][0]\n"
                "sys.exit(subprocess.run(spec['command']).returncode)\n";
            writeFile(dir / "run_yaml.py", runYaml);
            runs = {{"/usr/bin/python3", (dir / "run_yaml.py").string(), (job / "job.yaml").string()},
                    {"/usr/bin/python3", (dir / "run_yaml.py").string(), (job / "checkpoints.yaml").string()},
                    {"/bin/bash", (job / "submit.sh").string()}};
        } else {
            runs = {{"/bin/bash", (job / "parallel.sh").string()}};
        }
        for (const std::vector<std::string>& run : runs) {
            const CommandResult ran = runArgv(run, env, 60);
            EXPECT_EQ(ran.exitCode, 0) << scheduler << ": " << run.back() << "\n" << ran.output;
        }
        std::ifstream in(log);
        std::vector<std::string> targets;
        for (std::string line; std::getline(in, line);) targets.push_back(line);
        EXPECT_FALSE(targets.empty()) << scheduler << ": toyhost was never run";
        for (const std::string& target : targets) EXPECT_EQ(target, toy.string()) << scheduler;
        EXPECT_FALSE(pwned(dir)) << scheduler;
        if (std::string(scheduler) == "parallel") {
            // The shards' exit codes come back from parallel's joblog, whose command field -q quotes.
            const CommandResult status = toyhost({"farm", "status", job.string()});
            EXPECT_NE(status.output.find("shard 1 (frames 2-3): 0/2 ok; missing 2-3; exit 0 (finished)"), std::string::npos)
                << status.output;
            // The shard finished without its frames: the command that renders it again, from its start.
            EXPECT_NE(status.output.find("/run-shard.sh 1 again\n"), std::string::npos) << status.output;
        }
        if (std::string(scheduler) == "slurm") {
            const CommandResult status = toyhost({"farm", "status", job.string()});
            EXPECT_NE(status.output.find("  redo: sbatch --array=1 "), std::string::npos) << status.output;
        }
    }
}

TEST(FarmHostile, ClusterOptionsReachEveryJobFileAndSubmitPassesItsArgumentsOn) {
    const fs::path dir = freshOutputDir("farm-hostile/cluster");
    const fs::path toy = dir / "toy";
    copyShadertoy(toy);
    const fs::path bin = dir / "bin";
    const fs::path log = dir / "sbatch.log";
    // sbatch: records its arguments, one line per call.
    writeExecutable(bin / "sbatch", "#!/bin/bash\nprintf '%s|' \"$@\" >> \"$STUB_LOG\"\necho >> \"$STUB_LOG\"\necho 7\n");
    const fs::path job = dir / "my job's";
    const CommandResult planned =
        toyhost({"farm", "plan", toy.string(), "--frames", "4", "--shards", "2", "--scheduler", "slurm", "--job", job.string(),
                 "--partition", "gpu nodes", "--account", "proj", "--qos", "normal", "--mem", "8G", "--gres", "gpu:1",
                 "--scheduler-arg=--constraint=avx2", "--scheduler-arg=--exclusive", "--size", "64x36"});
    ASSERT_EQ(planned.exitCode, 0) << planned.output;
    for (const char* name : {"job.sbatch", "checkpoints.sbatch"}) {
        const std::string text = readFile(job / name);
        for (const char* line : {"#SBATCH --partition=\"gpu nodes\"\n", "#SBATCH --account=proj\n", "#SBATCH --qos=normal\n",
                                 "#SBATCH --mem=8G\n", "#SBATCH --gres=gpu:1\n", "#SBATCH --constraint=avx2\n",
                                 "#SBATCH --exclusive\n"})
            EXPECT_NE(text.find(line), std::string::npos) << name << ": " << line << "\n" << text;
    }
    EXPECT_EQ(readFile(job / "farm.json").find("constraint"), std::string::npos) << "a scheduler argument became a run option";
    const CommandResult submitted = runArgv({"/bin/bash", (job / "submit.sh").string(), "--account=other", "--hold"},
                                            {"PATH=" + bin.string() + ":/usr/bin:/bin", "STUB_LOG=" + log.string()}, 60);
    ASSERT_EQ(submitted.exitCode, 0) << submitted.output;
    const std::string calls = readFile(log);
    EXPECT_EQ(calls, "--parsable|--account=other|--hold|" + (job / "checkpoints.sbatch").string() +
                         "|\n--parsable|--dependency=afterok:7|--kill-on-invalid-dep=yes|--account=other|--hold|" +
                         (job / "job.sbatch").string() + "|\n");
    // Slurm's own options are refused for Kubernetes (exit 2, naming the option), before anything is written.
    const CommandResult k8s = toyhost({"farm", "plan", toy.string(), "--frames", "4", "--shards", "2", "--scheduler", "k8s",
                                       "--job", (dir / "k8s").string(), "--partition", "gpu"});
    expectOneError(k8s, 2, {"--partition"}, "k8s --partition");
    EXPECT_FALSE(fs::exists(dir / "k8s"));
    // A target outside the job folder: a warning (the pods mount only the job folder).
    const CommandResult warned = toyhost({"farm", "plan", toy.string(), "--frames", "4", "--shards", "2", "--scheduler",
                                          "k8s", "--job", (dir / "k8s").string(), "--mem", "1G"});
    EXPECT_EQ(warned.exitCode, 0) << warned.output;
    EXPECT_NE(warned.output.find("warning: the target"), std::string::npos) << warned.output;
}

// ---- crashes ----------------------------------------------------------------------------------

TEST(FarmHostile, NewWithANameThatIsNotUtf8RefusesBeforeWritingAnything) {
    const fs::path dir = freshOutputDir("farm-hostile/new");
    const fs::path bad = dir / "x" / "bad\xffname";
    const CommandResult result = toyhost({"new", bad.string()});
    expectOneError(result, 2, {"UTF-8"}, "new");
    EXPECT_FALSE(fs::exists(dir / "x")) << "toyhost new wrote before refusing";
}

TEST(FarmHostile, AJobFolderNameTooLongIsAMessageNotAnAbort) {
    const fs::path dir = freshOutputDir("farm-hostile/long-name");
    const fs::path toy = dir / "toy";
    copyShadertoy(toy);
    const CommandResult result = toyhost({"farm", "plan", toy.string(), "--frames", "4", "--shards", "2", "--scheduler",
                                          "parallel", "--job", (dir / "x" / std::string(300, 'j')).string()});
    expectOneError(result, 1, {"File name too long"}, "--job x/<300 chars>");
    EXPECT_FALSE(fs::exists(dir / "x"));
}

TEST(FarmHostile, StatusTakesAHugePatternAndAHostileJoblogWithoutCrashing) {
    const fs::path dir = freshOutputDir("farm-hostile/status");
    const fs::path frames = dir / "frames";
    fs::create_directories(frames);
    const CommandResult pattern = toyhost({"farm", "status", frames.string(), "--frames", "8", "--pattern",
                                           std::string(120000, 'p') + "_%04d.png"});
    expectOneError(pattern, 2, {"--pattern", "255"}, "a 120,000-character --pattern");

    const fs::path toy = dir / "toy";
    copyShadertoy(toy);
    const fs::path job = dir / "job";
    ASSERT_EQ(toyhost({"farm", "plan", toy.string(), "--frames", "4", "--shards", "2", "--scheduler", "parallel", "--job",
                       job.string()})
                  .exitCode,
              0);
    writeFile(job / "logs" / "parallel.log",
              "Seq\tHost\tStarttime\tJobRuntime\tSend\tReceive\tExitval\tSignal\tCommand\n"
              "1\t:\t0\t1\t0\t0\t0\t0\t" + std::string(120000, 'c') + " run-shard.sh 0\n" +
                  "2\t:\t0\t1\t0\t0\t99999999999\t0\t" + job.string() + "/run-shard.sh 1\n");
    const CommandResult status = toyhost({"farm", "status", job.string()});
    EXPECT_EQ(status.exitCode, 1) << status.output;  // incomplete: no frame is there
    EXPECT_NE(status.output.find("0/4 frames ok"), std::string::npos) << status.output;
    EXPECT_TRUE(errorLines(status.output).empty()) << status.output;
}

// ---- hangs ------------------------------------------------------------------------------------

TEST(FarmHostile, StatusOfTwoToTheThirtyOneFramesWithEightOnDiskAnswers) {
    const fs::path dir = freshOutputDir("farm-hostile/huge-count");
    std::vector<std::uint8_t> rgba(4 * 2 * 4, 200);
    for (int f = 0; f < 8; ++f) ASSERT_TRUE(writePng(dir / ("f_" + std::to_string(f) + ".png"), 4, 2, rgba));
    // Killed after 120 s by runArgv: before the fix it was still checking after 300 s.
    const CommandResult result = toyhost({"farm", "status", dir.string(), "--frames", "2147483647"});
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("8/2147483647 frames ok; to render again: 8-2147483646"), std::string::npos)
        << result.output;
}

// ---- numbers and messages ---------------------------------------------------------------------

TEST(FarmHostile, FarmJsonCountsThatWrapOrHaveFractionsAreRefused) {
    const fs::path dir = freshOutputDir("farm-hostile/farm-json");
    const fs::path toy = dir / "toy";
    copyShadertoy(toy);
    const fs::path job = dir / "job";
    ASSERT_EQ(toyhost({"farm", "plan", toy.string(), "--frames", "8", "--shards", "2", "--scheduler", "parallel", "--job",
                       job.string()})
                  .exitCode,
              0);
    std::ifstream in(job / "farm.json");
    const std::string plan((std::istreambuf_iterator<char>(in)), {});
    const std::size_t at = plan.find("\"frames\": 8");
    ASSERT_NE(at, std::string::npos) << plan;
    for (const char* frames : {"4294967304", "8.9"}) {
        std::string edited = plan;
        edited.replace(at, 11, std::string("\"frames\": ") + frames);
        writeFile(job / "farm.json", edited);
        const CommandResult result = toyhost({"farm", "status", job.string()});
        expectOneError(result, 2, {(job / "farm.json").string(), "\"frames\"", frames}, frames);
    }
}

TEST(FarmHostile, MessagesNameTheOptionsAndSubcommands) {
    const fs::path dir = freshOutputDir("farm-hostile/messages");
    expectOneError(toyhost({"farm", "status", dir.string(), "--frames", "0"}), 2, {"--frames"}, "status --frames 0");
    expectOneError(toyhost({"farm"}), 2, {"plan", "status", "join"}, "farm alone");
    std::vector<std::uint8_t> rgba(16 * 8 * 4, 90);
    for (int f = 0; f < 3; ++f) ASSERT_TRUE(writePng(dir / ("f_" + std::to_string(f) + ".png"), 16, 8, rgba));
    writeFile(dir / "notes.txt", "a text, not a sound track\n");
    const std::string frames = dir.string();
    expectOneError(toyhost({"farm", "join", frames, "--frames", "3", "--out", (dir / "m.mp4").string(), "--fps", "1e-300"}),
                   2, {"--fps"}, "join --fps 1e-300");
    expectOneError(toyhost({"farm", "join", frames, "--frames", "3", "--out", (dir / "m.png").string()}), 2,
                   {"--out", ".mp4"}, "join --out m.png");
    expectOneError(toyhost({"farm", "join", frames, "--frames", "3", "--out", (dir / "m.mp4").string(), "--audio",
                            (dir / "notes.txt").string()}),
                   2, {"--audio", "notes.txt"}, "join --audio notes.txt");
    EXPECT_FALSE(fs::exists(dir / "m.mp4"));
    EXPECT_FALSE(fs::exists(dir / "m.png"));
}

// ---- signals ----------------------------------------------------------------------------------

// A signal during `farm join` killed it with no message, orphaned ffmpeg and left a hidden
// .partial: now it stops before its next frame, ffmpeg killed, nothing left, exit 128 + signal.
// The moment is chosen by what the join has done (its ffmpeg is running), and 1000 frames of noise
// keep it encoding for seconds after that.
TEST(FarmHostile, ASignalDuringJoinStopsItWithFfmpegAndLeavesNothing) {
    if (shell("command -v ffmpeg >/dev/null 2>&1").first != 0) GTEST_FAIL() << "needs ffmpeg (scripts/install-deps.sh installs it)";
    const fs::path dir = freshOutputDir("farm-hostile/join-signal");
    const fs::path frames = dir / "frames";
    fs::create_directories(frames);
    std::vector<std::uint8_t> noise(320 * 180 * 4);
    std::uint32_t state = 12345;
    for (std::uint8_t& byte : noise) byte = static_cast<std::uint8_t>((state = state * 1664525u + 1013904223u) >> 24);
    ASSERT_TRUE(writePng(frames / "f_0000.png", 320, 180, noise));
    constexpr int kFrames = 1000;
    for (int f = 1; f < kFrames; ++f) {
        char name[32];
        std::snprintf(name, sizeof name, "f_%04d.png", f);
        fs::copy_file(frames / "f_0000.png", frames / name);
    }
    for (int sig : {SIGINT, SIGTERM}) {
        const fs::path out = dir / ("out-" + std::to_string(sig));
        fs::create_directories(out);
        BackgroundProcess join(toyhostBinary(),
                               {"farm", "join", frames.string(), "--frames", std::to_string(kFrames), "--out",
                                (out / "join-signal-marker.mp4").string()},
                               dir / ("log-" + std::to_string(sig)));
        auto ffmpegRuns = [] { return shell("pgrep -f '[f]fmpeg.*join-signal-marker' >/dev/null").first == 0; };
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        while (!ffmpegRuns() && join.running() && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        ASSERT_TRUE(join.running()) << "the join ended before ffmpeg was seen";
        ASSERT_TRUE(ffmpegRuns()) << "ffmpeg never started";
        join.signal(sig);
        const int code = join.wait(60);
        std::ifstream in(dir / ("log-" + std::to_string(sig)));
        const std::string log((std::istreambuf_iterator<char>(in)), {});
        EXPECT_EQ(code, 128 + sig) << log;
        EXPECT_NE(log.find("stopped by a signal"), std::string::npos) << log;
        std::vector<std::string> left;
        for (const auto& entry : fs::directory_iterator(out)) left.push_back(entry.path().filename().string());
        EXPECT_TRUE(left.empty()) << "left behind: " << (left.empty() ? "" : left.front());
        bool gone = false;
        for (int i = 0; i < 250 && !(gone = !ffmpegRuns()); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
        EXPECT_TRUE(gone) << "ffmpeg outlived the join";
    }
}

// ---- a full disk ------------------------------------------------------------------------------

TEST(FarmHostile, APlanOnAFullDiskLeavesNothingAndSaysWhy) {
    const fs::path dir = freshOutputDir("farm-hostile/full-disk");
    const fs::path toy = dir / "toy";
    copyShadertoy(toy);
    const fs::path disk = dir / "disk";
    fs::create_directories(disk);
    if (shell("mount -t tmpfs -o size=64k toyhost-farm-full '" + disk.string() + "' 2>/dev/null").first != 0)
        GTEST_SKIP() << "cannot mount a small tmpfs to fill (needs mount rights)";
    struct Unmount {
        fs::path at;
        ~Unmount() { shell("umount '" + at.string() + "'"); }
    } unmount{disk};
    // One page (4 KiB) left: farm.json fits, the next file does not.
    ASSERT_EQ(shell("head -c 61440 /dev/zero > '" + (disk / "fill").string() + "' 2>/dev/null; echo").first, 0);
    const std::vector<std::string> plan = {"farm", "plan", toy.string(), "--frames", "4", "--shards", "2", "--scheduler",
                                           "slurm", "--job", (disk / "job").string()};
    const CommandResult full = toyhost(plan);
    expectOneError(full, 1, {"No space left on device"}, "plan on a full disk");
    std::set<std::string> left;
    for (const auto& entry : fs::recursive_directory_iterator(disk)) left.insert(entry.path().filename().string());
    EXPECT_EQ(left, (std::set<std::string>{"fill"})) << "a plan was left half-written";
    // With room again, the same plan is made (not refused as planned already).
    fs::remove(disk / "fill");
    const CommandResult again = toyhost(plan);
    EXPECT_EQ(again.exitCode, 0) << again.output;
}

}  // namespace
}  // namespace toyhost::testing
