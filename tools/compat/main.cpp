// toyhost-compat: runs every Shadertoy export of a folder headless for a few frames at a small
// size, each in its own process (so a hang or crash is contained), and writes a table
// (markdown + JSON) of what compiled, rendered and looked degenerate.
#include <CLI/CLI.hpp>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include "CompatProbe.h"
#include "core/AtomicFile.h"
#include "core/Defaults.h"
#include "gl/GlThread.h"

namespace fs = std::filesystem;
using namespace toyhost;
using namespace toyhost::compat;

namespace {

// The wall-time guard of a probe whose CPU time is limited to `timeoutSeconds`: generous, since a
// loaded machine stretches wall time; it is there for a probe that waits without computing.
int wallGuardSeconds(int timeoutSeconds) { return std::max(10 * timeoutSeconds, 300); }

// Runs one probe in a child process; the child writes its JSON result into a pipe.
ProbeResult probeInChild(const fs::path& file, const ProbeSettings& settings, int timeoutSeconds) {
    ProbeResult result;
    result.file = file.filename().string();
    result.id = file.stem().string();
    int fds[2];
    if (pipe(fds) != 0) {
        result.error = "cannot create a pipe for the probe";
        return result;
    }
    const pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        // The limit is CPU time (SIGXCPU, then SIGKILL), so a slow shader's verdict does not
        // depend on the machine's load; the parent's wall-time guard below only catches a probe
        // blocked without using the CPU.
        const rlimit cpu{static_cast<rlim_t>(timeoutSeconds), static_cast<rlim_t>(timeoutSeconds) + 5};
        setrlimit(RLIMIT_CPU, &cpu);
        // One JSON line per phase as it starts (the best result so far), then the final result: a
        // probe killed at its CPU limit leaves the verdict it had reached and the phase that ran out.
        auto send = [&](const ProbeResult& result, ProbePhase phase) {
            const std::string text = nlohmann::json{{"phase", phaseName(phase)}, {"result", toJson(result)}}.dump() + "\n";
            size_t done = 0;
            while (done < text.size()) {
                ssize_t n = write(fds[1], text.data() + done, text.size() - done);
                if (n <= 0) break;
                done += static_cast<size_t>(n);
            }
        };
        // On a GL thread, as every toyhost run: large shaders need its stack.
        runOnGlThread([&] { send(runProbe(file, settings, send), ProbePhase::Done); });
        _exit(0);
    }
    close(fds[1]);
    std::string text;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(wallGuardSeconds(timeoutSeconds));
    bool timedOut = false;
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            timedOut = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        if (poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
        char chunk[4096];
        const ssize_t n = read(fds[0], chunk, sizeof chunk);
        if (n <= 0) break;
        text.append(chunk, static_cast<size_t>(n));
    }
    close(fds[0]);
    if (timedOut) kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);

    // The last complete line: the final result, or the phase that was running and the result so far.
    std::optional<ProbeResult> last;
    ProbePhase running = ProbePhase::Compile;
    for (std::size_t start = 0, end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
        const nlohmann::json line = nlohmann::json::parse(text.substr(start, end - start), nullptr, false);
        if (line.is_discarded() || !line.contains("result")) continue;
        last = fromJson(line["result"]);
        running = phaseNamed(line.value("phase", "")).value_or(ProbePhase::Compile);
    }
    const bool cpuLimit = WIFSIGNALED(status) && (WTERMSIG(status) == SIGXCPU || WTERMSIG(status) == SIGKILL);
    if (last && running == ProbePhase::Done && !timedOut && !WIFSIGNALED(status)) return *last;
    if (last && (timedOut || cpuLimit)) {
        result = timedOutResult(*last, running, timeoutSeconds);
        if (timedOut && !result.error.empty())  // the wall-time guard, not the CPU limit
            result.error = "no progress after " + std::to_string(wallGuardSeconds(timeoutSeconds)) +
                           " s (wall time) in the " + phaseName(running) + " phase";
        else if (timedOut)
            result.ranOutIn = std::string(phaseName(running)) + " (wall-time guard)";
        return result;
    }
    if (last) result = *last;
    if (timedOut) result.error = "no progress after " + std::to_string(wallGuardSeconds(timeoutSeconds)) + " s (wall time)";
    else if (cpuLimit) result.error = "timed out after " + std::to_string(timeoutSeconds) + " s of CPU time";
    else if (WIFSIGNALED(status))
        result.error = "crashed (signal " + std::to_string(WTERMSIG(status)) + ") in the " + phaseName(running) + " phase";
    else result.error = "no result from the probe";
    return result;
}

std::map<std::string, std::string> readKnownIssues(const fs::path& file) {
    std::map<std::string, std::string> known;
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        const size_t tab = line.find('\t');
        if (tab != std::string::npos) known[line.substr(0, tab)] = line.substr(tab + 1);
    }
    return known;
}

std::string cell(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    std::string out;
    for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

std::string joined(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
    return out;
}

std::string outputVerdict(const ProbeResult& r) {
    if (!r.compiled) return "-";
    std::vector<std::string> problems;
    if (!r.glError.empty()) problems.push_back("GL error " + r.glError);
    if (r.uniformImage && r.uniformColourChanged) {
        if (problems.empty()) return "ok (full-screen colour changing over time)";
    } else if (r.uniformImage) {
        problems.push_back("nearly one colour");
    }
    std::string verdict;
    if (problems.empty() && r.firstNonUniformTime >= 0) {
        char text[64];
        std::snprintf(text, sizeof text, "ok (nearly one colour until iTime %.2f)", r.firstNonUniformTime);
        verdict = text;
    } else {
        verdict = problems.empty() ? "ok" : joined(problems);
    }
    if (r.drawsWithoutInput) {
        verdict += " without input (one colour with the probe's mouse drag)";
    } else if (!r.keyHeld.empty()) {
        verdict += " while " + r.keyHeld + " is held (one colour without keys)";
    } else if (!r.siteSize.empty() && r.passed() && r.judgedWidth == kSiteWidth) {
        verdict += " (at " + r.siteSize + ", the site's size; one colour at smaller sizes)";
    } else if (r.passed() && !r.secondSize.empty()) {
        verdict += " (at " + r.secondSize + ")";
    } else if (!r.passed() && !r.secondSize.empty()) {
        std::vector<std::string> tried{"at " + r.secondSize};
        if (!r.siteSize.empty()) tried.push_back("at " + r.siteSize);
        if (r.keysTried) tried.push_back("with keys held");
        verdict += " (also " + joined(tried) + ")";
    }
    // CPU time that ran out after the verdict: the verdict stands, the rest was not finished.
    if (!r.ranOutIn.empty()) verdict += "; CPU time ran out in the " + r.ranOutIn + " phase (verdict from before it)";
    // NaN/Inf in a buffer: a note with its pass and count, not a verdict.
    if (!r.nonFiniteBuffers.empty()) verdict += "; note: " + joined(r.nonFiniteBuffers);
    // A pass that rests on a stand-in's content says so: the site, with the real media, may differ.
    if (r.passed() && r.standInEffect == "verdict") verdict += "; depends on stand-ins";
    return verdict;
}

// A first explanation for a failure nobody has looked at yet (known-issues entries replace it).
std::string likelyReason(const ProbeResult& r) {
    if (!r.uniformImage) return "";
    // One colour with NaN or Inf in a buffer: most likely the shader's own NaN spreading.
    if (!r.nonFiniteBuffers.empty())
        return "one colour, with NaN/Inf in its buffers (" + joined(r.nonFiniteBuffers) +
               "): most likely its own NaN (a division by zero, a normalize(0)) spreading";
    std::vector<std::string> tried{"through iTime 5 s", "with the mouse dragged"};
    if (!r.secondSize.empty()) tried.push_back("at " + r.secondSize);
    if (!r.siteSize.empty()) tried.push_back("at " + r.siteSize);
    if (r.keysTried) tried.push_back("with Space, Enter, arrows, WASD, Shift and Control held in turn");
    return "nearly one colour " + joined(tried) + ": it may" +
           std::string(r.standIns.empty() ? "" : " depend on the real stock textures (stand-ins used), or") +
           " need more time or other input";
}

std::string markdown(const std::vector<ProbeResult>& results, const ProbeSettings& s, const fs::path& dir,
                     const std::map<std::string, std::string>& known) {
    const auto passed = std::count_if(results.begin(), results.end(), [](const ProbeResult& r) { return r.passed(); });
    std::ostringstream md;
    md << "# Compatibility: " << dir.filename().string() << "\n\n"
       << "Generated by `toyhost-compat` (tools/compat): every export rendered headless on llvmpipe for " << s.frames
       << " frames at " << s.width << "x" << s.height << ", iTime = frame/" << defaults::kFps << ", the mouse pressed on frame 1, dragged "
       << "across the canvas (never through its exact centre) and released two frames before the end, no keys. A "
       << "shader passes when it compiles, renders without a GL error, and its last frame is not degenerate. "
       << "Degenerate: fewer than " << 100 * s.minOtherShare << "% of the Image's pixels differ from its dominant "
       << "colour by more than " << kColourTolerance << "/255 in a channel (\"other %\" is that share of the last "
       << "frame judged), and that colour does not change over time (a full-screen colour that changes is a valid "
       << "flash). An Image still degenerate after those frames gets more frames, up to iTime " << s.patienceSeconds
       << " s, for fade-ins, then runs at 320x180 and at the site's 800x450 (shaders drawing at fixed pixel positions), "
          "then one with Space, Enter, the arrows, WASD, Shift and Control held in turn (shaders that draw while a key "
          "is held); the output says which of these made it draw, or that all were tried. A probe that runs out of "
          "CPU time after a verdict keeps that verdict and says which phase ran out; one that runs out before says "
          "which phase (compile, first frames...) it was in. NaN/Inf "
       << "in a buffer is a note with its pass and count, not a failure. ms/frame is the CPU time of the probe "
       << "process per frame (llvmpipe's threads included), not wall time, so it does not grow with the machine's "
       << "load. A passing shader that used stand-ins is rendered again with them unbound (black): the stand-ins "
       << "column says whether its picture was the same, depended on them, or was degenerate without them (then "
       << "the output says \"depends on stand-ins\": the pass rests on the stand-in's content).\n\n"
       << "**" << passed << " of " << results.size() << " pass ("
       << (results.empty() ? 0 : (100 * passed) / static_cast<long>(results.size())) << "%).**\n\n"
       << "| id | name | passes | compiled | ms/frame | other % | output | stand-ins | notes |\n"
       << "|---|---|---|---|---|---|---|---|---|\n";
    for (const ProbeResult& r : results) {
        std::string notes = r.error;
        if (auto it = known.find(r.id); it != known.end()) notes = it->second + (notes.empty() ? "" : " — " + notes);
        else if (!r.passed() && notes.empty()) notes = likelyReason(r);
        char ms[32];
        std::snprintf(ms, sizeof ms, "%.1f", r.msPerFrame);
        std::string standIns = joined(r.standIns);
        if (const std::string effect = standInEffectText(r); !effect.empty()) standIns += " (" + effect + ")";
        char other[32] = "-";
        if (r.compiled && r.framesRendered > 0) std::snprintf(other, sizeof other, "%.1f", 100.0 * r.share.otherShare);
        md << "| " << r.id << " | " << cell(r.name) << " | " << r.passes << " | " << (r.compiled ? "yes" : "**no**") << " | "
           << (r.compiled ? ms : "-") << " | " << other << " | " << cell(outputVerdict(r)) << " | " << cell(standIns)
           << " | " << cell(notes) << " |\n";
    }
    md << "\nStand-ins: stock textures are replaced by deterministic images of the real size and channel count "
          "(see docs/manifest.md, Stock media); supply real files with `--media DIR` to compare against the site.\n";
    return md.str();
}

}  // namespace

int main(int argc, char** argv) {
    // Before any thread: the driver hints and TOYHOST_EGL_PLATFORM, as for toyhost itself.
    const Result<GlProcess> process = prepareGlProcess();
    if (!process) {
        std::cerr << "toyhost-compat: " << process.error().text() << "\n";
        return 2;
    }
    CLI::App app{"toyhost-compat: run a folder of Shadertoy exports and tabulate what works"};
    std::string dir, size = "160x90", markdownOut, jsonOut, knownFile;
    ProbeSettings settings;
    settings.eglPlatform = process->eglPlatform;
    int timeout = 60;
    double minPassRate = 0;
    std::vector<std::string> mediaFolders;
    app.add_option("folder", dir,
                   "Folder of <id>.json exports, or one shadertoy: an export file or a manifest folder")
        ->required();
    app.add_option("--size", size, "Canvas WxH")->capture_default_str();
    app.add_option("--frames", settings.frames, "Frames per shader")->capture_default_str();
    app.add_option("--timeout", timeout, "Seconds of CPU time before a shader is killed (a wall-time guard of 10x, at least 300 s, catches a probe that waits)")
        ->capture_default_str();
    app.add_option("--media", mediaFolders, "Folder with real stock media files");
    app.add_option("--known", knownFile, "TSV of id<TAB>explanation for known failures");
    app.add_option("--markdown", markdownOut, "Write the markdown table here");
    app.add_option("--json", jsonOut, "Write the machine-readable results here");
    app.add_option("--min-pass-rate", minPassRate, "Exit non-zero when fewer pass (0..1)");
    std::string framesOut;
    app.add_option("--frames-out", framesOut, "Write each shader's last judged Image frame here as <id>.png");
    app.add_option("--min-share", settings.minOtherShare,
                   "A frame is degenerate when fewer of its pixels differ from its dominant colour (0..1)")
        ->capture_default_str();
    app.add_flag("!--no-stand-in-check", settings.checkStandIns,
                 "Do not render a passing shader again with its stand-ins unbound");
    std::vector<std::string> resultFiles;
    app.add_option("--results", resultFiles,
                   "Write the table from these --json files of earlier runs (of parts of the folder) instead of "
                   "running anything");
    CLI11_PARSE(app, argc, argv);
    if (std::sscanf(size.c_str(), "%dx%d", &settings.width, &settings.height) != 2) {
        std::cerr << "toyhost-compat: --size " << size << ": expected WxH\n";
        return 2;
    }
    for (const std::string& m : mediaFolders) settings.mediaFolders.emplace_back(m);
    settings.framesOut = framesOut;
    if (const char* env = std::getenv("TOYHOST_MEDIA")) settings.mediaFolders.emplace_back(env);

    std::vector<fs::path> files;
    std::error_code ec;
    if (!resultFiles.empty()) {
        // Nothing runs: the results of earlier runs, in id order, as one table.
    } else if (fs::is_regular_file(dir, ec) || fs::is_regular_file(fs::path(dir) / "manifest.json", ec))
        files.push_back(fs::path(dir));  // one shadertoy: a port being checked
    else
        for (const auto& entry : fs::directory_iterator(dir, ec))
            if (entry.path().extension() == ".json") files.push_back(entry.path());
    if (resultFiles.empty() && (ec || files.empty())) {
        std::cerr << "toyhost-compat: " << dir << ": no .json exports found\n";
        return 2;
    }
    std::sort(files.begin(), files.end());
    const auto known = knownFile.empty() ? std::map<std::string, std::string>{} : readKnownIssues(knownFile);

    std::vector<ProbeResult> results;
    nlohmann::json all = nlohmann::json::array();
    for (const std::string& file : resultFiles) {
        std::ifstream in(file);
        const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
        if (json.is_discarded() || !json.contains("results")) {
            std::cerr << "toyhost-compat: " << file << ": not a --json file of toyhost-compat\n";
            return 2;
        }
        for (const nlohmann::json& r : json["results"]) results.push_back(fromJson(r));
    }
    std::sort(results.begin(), results.end(), [](const ProbeResult& a, const ProbeResult& b) { return a.file < b.file; });
    for (const ProbeResult& r : results) all.push_back(toJson(r));
    if (!files.empty())
        std::fprintf(stderr,
                     "toyhost-compat: one line per shader: id, pass/FAIL, CPU ms per frame, \"other\" (the share of the "
                     "last judged frame's pixels that differ from its dominant colour by more than %d/255 in a "
                     "channel; under %g%% and unchanging is degenerate), the output verdict\n",
                     kColourTolerance, 100 * settings.minOtherShare);
    for (const fs::path& file : files) {
        ProbeResult r = probeInChild(file, settings, timeout);
        const std::string effect = standInEffectText(r);
        std::fprintf(stderr, "%-10s %-6s %7.1f ms/frame  %5.1f%% other  %s%s%s\n", r.id.c_str(),
                     r.passed() ? "pass" : "FAIL", r.msPerFrame, 100.0 * r.share.otherShare, outputVerdict(r).c_str(),
                     effect.empty() ? "" : (" [stand-ins: " + effect + "]").c_str(),
                     r.error.empty() ? "" : ("  " + r.error.substr(0, 120)).c_str());
        all.push_back(toJson(r));
        results.push_back(std::move(r));
    }
    if (results.empty()) {
        std::cerr << "toyhost-compat: no results\n";
        return 2;
    }
    const auto passed = std::count_if(results.begin(), results.end(), [](const ProbeResult& r) { return r.passed(); });
    const double rate = static_cast<double>(passed) / static_cast<double>(results.size());
    std::fprintf(stderr, "toyhost-compat: %ld of %zu pass (%.1f%%)\n", static_cast<long>(passed), results.size(), 100 * rate);

    auto write = [](const std::string& path, const std::string& text) {
        Status s = writeBytesAtomically(path, std::as_bytes(std::span(text.data(), text.size())));
        if (!s) std::cerr << formatDiagnostics(s.error().diagnostics, "toyhost-compat: ") << "\n";
        return s.ok();
    };
    if (!markdownOut.empty() && !write(markdownOut, markdown(results, settings, dir, known))) return 1;
    if (!jsonOut.empty() &&
        !write(jsonOut, nlohmann::json{{"folder", fs::path(dir).filename().string()},
                                       {"width", settings.width}, {"height", settings.height},
                                       {"frames", settings.frames}, {"passed", passed},
                                       {"total", results.size()}, {"results", all}}.dump(2) + "\n"))
        return 1;
    return rate + 1e-9 >= minPassRate ? 0 : 1;
}
