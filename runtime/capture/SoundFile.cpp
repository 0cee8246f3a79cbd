#include "capture/SoundFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <optional>
#include <vector>

#include "capture/WavFile.h"
#include "core/AtomicFile.h"
#include "core/ChildProcess.h"
#include "core/Defaults.h"
#include "core/FileDescriptor.h"
#include "core/InFlight.h"
#include "core/TemporaryFiles.h"

namespace toyhost {
namespace fs = std::filesystem;

namespace {

struct SoundFormat {
    const char* extension;  // with the dot
    const char* muxer;      // ffmpeg's -f; "" for WAV, written here
};
// .m4a is AAC in an MP4 container ffmpeg calls "ipod"; the others are ffmpeg's own names.
constexpr std::array<SoundFormat, 6> kFormats{{
    {".wav", ""}, {".flac", "flac"}, {".ogg", "ogg"}, {".opus", "opus"}, {".mp3", "mp3"}, {".m4a", "ipod"}}};

// A device, FIFO or socket that exists: written as a stream, never replaced by a rename.
bool isSpecialFile(const fs::path& path) {
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode);
}

bool isStream(const fs::path& path) { return path == "-" || isSpecialFile(path); }

Result<SoundFormat> formatOf(const fs::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const SoundFormat& format : kFormats)
        if (extension == format.extension) return format;
    if (extension.empty() && isStream(path)) return kFormats[0];
    const std::string said = extension.empty() ? "has no extension" : "ends in " + extension;
    return fileError(path.string(),
                     "the audio format is chosen by the extension and this name " + said + ": give a name ending in " +
                         soundFileExtensions() + ", or - for WAV on stdout",
                     Code::UsageOut);
}

Code codeOfFfmpegMessage(const std::string& message) {
    return message.find("No space left") != std::string::npos ? Code::IoNoSpace : Code::SoundEncode;
}

// WAV to stdout, a device or a FIFO, as it is.
Status writeWavStream(const fs::path& path, std::span<const float> stereo) {
    const std::vector<std::uint8_t> bytes = encodeWav16(stereo, static_cast<int>(defaults::kSampleRate));
    const bool toStdout = path == "-";
    FileDescriptor opened;
    if (!toStdout) {
        opened = FileDescriptor(::open(path.c_str(), O_WRONLY | O_CLOEXEC));
        if (!opened)
            return fileError(path.string(), std::string("cannot open for writing: ") + std::strerror(errno), Code::IoWrite);
    }
    PipeSignalBlock noSigpipe;  // a reader that went away is an error, not the end of the process
    const std::string name = toStdout ? "stdout" : path.string();
    Status written = writeAll(toStdout ? STDOUT_FILENO : opened.get(), std::as_bytes(std::span(bytes)), name);
    if (!written && !toStdout) {
        // In the one form of file problems: "FILE: error: write failed: ...".
        Diagnostic problem = written.error().first();
        problem.file = name;
        if (problem.message.rfind(name + ": ", 0) == 0) problem.message.erase(0, name.size() + 2);
        return Error(std::move(problem));
    }
    if (!written) return written;
    if (!toStdout && !opened.reset())
        return fileError(path.string(), std::string("write failed: ") + std::strerror(errno),
                         errno == ENOSPC ? Code::IoNoSpace : Code::IoWrite);
    return okStatus();
}

// ffmpeg encodes a temporary WAV into `target` as `format`.
Status encodeWithFfmpeg(const fs::path& path, const fs::path& target, const SoundFormat& format,
                        std::span<const float> stereo) {
    if (!findExecutable("ffmpeg"))
        return fileError(path.string(),
                         std::string("writing ") + format.extension + " audio needs ffmpeg, which was not found in PATH "
                         "(or write a .wav)",
                         Code::SoundFfmpegMissing);
    TemporaryFiles temp("sound", {"wav", "log"});
    if (!temp.registerAll()) return fileError(path.string(), "not written: toyhost is stopping", Code::Interrupted);
    if (Status wav = writeWav16(temp[0], stereo, static_cast<int>(defaults::kSampleRate)); !wav) return wav;
    const std::vector<std::string> args = {"ffmpeg", "-nostdin", "-hide_banner", "-v", "error", "-y", "-i",
                                           "file:" + temp[0].string(), "-f", format.muxer, "file:" + target.string()};
    Result<ChildProcess> ffmpeg = ChildProcess::spawn(args, temp[1]);
    if (!ffmpeg) return inFile(path.string(), ffmpeg.error());
    Result<int> exit = ffmpeg->closeAndWait();
    if (!exit || *exit != 0) {
        const std::string said = logTail(temp[1]);
        return fileError(path.string(),
                         std::string("ffmpeg could not write ") + format.extension + " audio: " +
                             (said.empty() ? (exit ? "exit code " + std::to_string(*exit) : exit.error().first().message)
                                           : said),
                         codeOfFfmpegMessage(said));
    }
    return okStatus();
}

}  // namespace

std::string soundFileExtensions() {
    std::string text;
    for (std::size_t i = 0; i < kFormats.size(); ++i) {
        if (i > 0) text += i + 1 == kFormats.size() ? " or " : ", ";
        text += kFormats[i].extension;
    }
    return text;
}

Status checkSoundOutput(const fs::path& path) {
    if (path.empty()) return Error("no output file given for the sound", Code::UsageOut);
    Result<SoundFormat> format = formatOf(path);
    if (!format) return format.error();
    std::error_code ec;
    if (path != "-" && fs::is_directory(path, ec))
        return fileError(path.string(), "is a folder, not a file", Code::UsageOut);
    return okStatus();
}

Status writeSoundFile(const fs::path& path, std::span<const float> stereo) {
    if (Status usable = checkSoundOutput(path); !usable) return usable;
    if (stereo.size() % 2 != 0)
        return fileError(path.string(), "the samples are not whole left/right pairs", Code::Internal);
    const SoundFormat format = *formatOf(path);
    const bool wav = format.muxer[0] == '\0';
    if (isStream(path)) {
        if (wav) return writeWavStream(path, stereo);
        // A FIFO or device with an encoder's extension: ffmpeg writes into it directly.
        return encodeWithFfmpeg(path, path, format, stereo);
    }
    if (wav) return writeWav16(path, stereo, static_cast<int>(defaults::kSampleRate));
    // ffmpeg writes beside the target, which is renamed into place only when it succeeded.
    std::error_code ec;
    if (path.has_parent_path()) {
        fs::create_directories(path.parent_path(), ec);
        if (ec) return fileError(path.parent_path().string(), "cannot create folder: " + ec.message(), Code::IoWrite);
    }
    const fs::path partial = temporarySibling(path);
    if (!inflight::addFile(partial)) return fileError(path.string(), "not written: toyhost is stopping", Code::Interrupted);
    auto finish = [&](Status status) {
        std::error_code ignored;
        fs::remove(partial, ignored);
        inflight::removeFile(partial);
        return status;
    };
    if (Status encoded = encodeWithFfmpeg(path, partial, format, stereo); !encoded) return finish(encoded);
    fs::rename(partial, path, ec);
    if (ec) return finish(fileError(path.string(), "cannot write the audio file: " + ec.message(), Code::IoWrite));
    return finish(okStatus());
}

}  // namespace toyhost
