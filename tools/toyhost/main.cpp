// toyhost: the command-line interface. Parses arguments, runs the job, prints what the library
// reports and chooses the exit code. The reference of every command, option and exit code is
// docs/cli.md, which is this program's --help output (tests/gl/test_cli_reference.cpp keeps them
// equal).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <new>
#include <string>
#include <unistd.h>

#include "Commands.h"
#include "Console.h"
#include "FarmCommand.h"
#include "ArgumentChecks.h"
#include "core/Defaults.h"
#include "NumberOptions.h"
#include "gl/GlThread.h"
#include "session/StopSignals.h"

using namespace toyhost;
using namespace toyhost::cli;

namespace {

// The command's exit code, once what it printed on stdout (a report, a list, the help) has been
// written: a full disk, a closed stdout or a reader that went away is an error, not success.
// `lost` is the code for it (compare's 2, "no answer"; 1 elsewhere); an interruption's stays.
int afterStdout(int code, int lost) {
    if (flushStdout()) return code;
    const int error = stdoutWriteErrno();
    std::cerr << "toyhost: error: stdout: what this command printed was not completely written ("
              << (error ? std::strerror(error) : "a write error") << ") [io.write]\n";
    return code >= kExitWatchdog ? code : lost;
}

int commandLine(int argc, char** argv, bool& comparing);

}  // namespace

int main(int argc, char** argv) {
    bool comparing = false;
    try {
        const int code = commandLine(argc, argv, comparing);
        return afterStdout(code, comparing ? kExitUsage : kExitFailure);
    } catch (const std::bad_alloc&) {
        // The last resort: the library turns the allocations it can foresee (images, sound,
        // frames) into errors naming their size; one it could not is still a message, not an abort.
        std::cerr << "toyhost: error: out of memory (a larger canvas, image or --capture-memory than this "
                     "machine or its ulimit allows?) [internal]\n";
        return kExitFailure;
    }
}

namespace {

int commandLine(int argc, char** argv, bool& comparing) {
    // Before any thread exists: the driver hints, TOYHOST_EGL_PLATFORM, standard streams.
    const Result<GlProcess> process = prepareGlProcess();
    CLI::App app{"toyhost: run Shadertoy shaders unmodified, in a window (GLFW) or headless on EGL (no display needed)"};
    app.name("toyhost");  // not argv[0]: the help text is the same however toyhost was started
    app.set_version_flag("--version", std::string("toyhost ") + TOYHOST_VERSION_TEXT);
    app.require_subcommand(1);
    app.footer("Exit codes: 0 success; 1 the run failed (bad manifest, missing file, shader compile error, GL or "
               "write error); 2 bad command-line usage; 124 the watchdog ended the run (a frame or a compile took longer "
               "than --frame-timeout / --compile-timeout, or the encoders stalled); 130 / 143 / 129 interrupted by "
               "SIGINT / SIGTERM / SIGHUP.");

    RunCommand runCommand;
    CLI::App* run = app.add_subcommand("run", "Run a shadertoy (manifest folder or file, or a Shadertoy JSON export)");
    runCommand.define(*run);

    std::string importSource, importDir;
    bool importForce = false;
    CLI::App* import = app.add_subcommand("import", "Turn a Shadertoy JSON export into an editable manifest folder");
    import->add_option("export", importSource, "Shadertoy export (API {\"Shader\": ...} or site form)")->required();
    import->add_option("dir", importDir, "Folder to write manifest.json and the pass files into")->required();
    import->add_flag("--force", importForce, "Overwrite an existing manifest.json");

    std::vector<std::string> inspectFiles;
    std::string regionText;
    CLI::App* inspect = app.add_subcommand("inspect", "Print per-channel statistics of EXR buffer dumps (or PNG frames)");
    inspect->add_option("files", inspectFiles,
                        "EXR files written by --out ... .exr (raw floats); PNG/JPEG files are read as levels 0..255")
        ->required();
    inspect->add_option("--region", regionText, "X,Y,W,H in pixels, origin bottom-left (default: whole image)");

    std::string newDir, newPasses = "image";
    bool newForce = false;
    CLI::App* create = app.add_subcommand("new", "Write a starter shadertoy folder that runs at once");
    create->add_option("dir", newDir, "Folder to create (its name becomes the shadertoy's name)")->required();
    create->add_option("--passes", newPasses,
                       "image (default: Image only), buffers (Buffer A with feedback, shown by Image), or a comma "
                       "list of common, a, b, c, d, image");
    create->add_flag("--force", newForce, "Overwrite files that already exist");

    std::vector<std::string> mediaFolders;
    CLI::App* media = app.add_subcommand("media", "List the stock media toyhost knows (bind them by name or id)");
    media->add_option("--media", mediaFolders,
                      "Folder with real stock media files, by hash or name (repeatable; also $TOYHOST_MEDIA): the "
                      "list says which are found");

    cli::SoundCommandOptions soundOptions;
    soundOptions.seconds = defaults::kSoundSeconds;
    CLI::App* sound = app.add_subcommand("sound", "Render a shadertoy's Sound pass (mainSound) to an audio file");
    sound->add_option("shadertoy", soundOptions.target, "Manifest folder or file, or a Shadertoy JSON export")->required();
    sound->add_option("--out", soundOptions.out, "Audio file: .wav (16-bit PCM), or .flac, .ogg, .opus, .mp3, .m4a through ffmpeg; - for WAV on stdout")
        ->required();
    sound->add_option("--seconds", soundOptions.seconds, "Length, as the site's 180 s by default")
        ->default_val(defaults::kSoundSeconds);
    soundOptions.flags.define(*sound, cli::SessionFlags::Media | cli::SessionFlags::Limits | cli::SessionFlags::Shader);
    sound->add_flag("--quiet", soundOptions.quiet, "Hide notices (stand-ins)");

    CompareCommand compareCommand;
    CLI::App* compare = app.add_subcommand(
        "compare", "Render two shadertoys with the same inputs and compare them frame by frame (exit 0 equal, 1 different)");
    compareCommand.define(*compare);
    compare->footer("Exit codes of compare (as cmp and diff): 0 equal within the tolerance; 1 different; 2 no answer "
                    "(bad usage, a shadertoy that does not load or compile, a pass one lacks, GL or write error); 124 "
                    "watchdog; 130 / 143 / 129 interrupted by SIGINT / SIGTERM / SIGHUP.");

    FarmCommand farmCommand;
    farmCommand.define(app);
    // Every numeric option of every command, read as decimal text (0x10, 010 and 4294967396 refused).
    readNumbersAsDecimal(app);

    if (std::optional<std::string> empty = emptyArgumentProblem(app, argc, argv)) return usage(*empty);
    if (std::optional<std::string> unknown = unknownCommandProblem(app, argc, argv)) return usage(*unknown);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // CLI11's own codes (105, 106, 109, ...) would leak through; every usage error is 2.
        return usage(e.what());
    }

    if (import->parsed()) return importCommand(importSource, importDir, importForce);
    if (inspect->parsed()) return inspectCommand(inspectFiles, regionText);
    if (create->parsed()) return newCommand(newDir, newPasses, newForce);
    if (media->parsed()) {
        if (const char* folder = std::getenv("TOYHOST_MEDIA"); folder && *folder) mediaFolders.emplace_back(folder);
        return mediaCommand(mediaFolders);
    }
    if (farmCommand.parsed()) return farmCommand.execute();
    // What renders: its GL work on a GL thread (gl/GlThread.h), SIGINT/SIGTERM asking it to stop.
    if (!process) return fail(process.error());
    installStopSignals();
    if (sound->parsed()) return soundCommand(soundOptions, *process);
    comparing = compare->parsed();
    if (comparing) return compareCommand.execute(*process);
    return runCommand.execute(*process);
}

}  // namespace
