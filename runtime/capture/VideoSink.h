// VideoSink: streams captured frames as raw RGBA8 into an ffmpeg process that encodes one video
// file (.mp4/.mov/.mkv: H.264, .webm: VP9). ffmpeg writes to a hidden temporary name that is
// renamed into place only when it exits cleanly, so the video is complete or absent. ffmpeg is
// started by the first write (on an encoder thread), not by start(): the render thread that makes
// the recording never waits for its fork/exec or start-up. No GL needed.
#pragma once

#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "capture/FrameSink.h"
#include "core/ChildProcess.h"
#include "core/Defaults.h"

namespace toyhost {

struct VideoSettings {
    std::optional<std::string> codec;  // an ffmpeg encoder name, or "auto"; default: by container
    std::optional<std::string> preset; // --video-preset, passed to ffmpeg's -preset
    std::optional<int> quality;        // constant rate factor (lower is better); default: by codec
    // A sound track muxed in from its first sample (the Sound pass, rendered before the frames):
    // AAC in mp4/mov/mkv, Opus in webm. Shorter than the video: silence after its end.
    std::optional<std::filesystem::path> audio;
};

struct VideoRequest {
    std::filesystem::path output;  // where ffmpeg writes (the temporary name)
    std::string container;         // ".mp4", ".webm", ".mov" or ".mkv"
    int width = 0;
    int height = 0;
    double fps = defaults::kFps;
    VideoSettings settings;
};

// The ffmpeg command line (argv, "ffmpeg" first) for a request: raw top-first RGBA8 frames on
// stdin; H.264 (libx264, CRF 18, yuv420p, or yuv444p for odd sizes, which 4:2:0 H.264 cannot
// hold) for .mp4/.mov/.mkv, VP9 (libvpx-vp9, CRF 31) for .webm.
std::vector<std::string> ffmpegArguments(const VideoRequest& request);

class VideoSink final : public FrameSink {
public:
    // Prepares the video `path` (its extension picks the container): its folder, its temporary
    // names and ffmpeg's command line. Fails when ffmpeg is not installed. ffmpeg itself starts
    // with the first write() (or close(), for a video without frames).
    static Result<std::unique_ptr<VideoSink>> start(const std::filesystem::path& path, int width, int height,
                                                    double fps, const VideoSettings& settings);
    ~VideoSink() override;

    bool ordered() const override { return true; }
    Status write(const CapturedFrame& frame, EncodeScratch& scratch) override;
    Status close() override;
    void discard() override;
    void cancel() override;
    // Whether ffmpeg has been started (by a write or close).
    bool launched() const;
    // The ffmpeg encoder in use, and with --codec auto the line saying why it was chosen.
    const std::string& encoder() const { return encoder_; }
    const std::string& autoExplanation() const { return autoExplanation_; }

private:
    VideoSink() = default;
    Error ffmpegFailed(const std::string& what) const;
    // Starts ffmpeg unless it runs (the thread that writes; cancel() may race it).
    Status launch();

    std::filesystem::path path_;
    std::filesystem::path temp_;
    std::filesystem::path log_;
    std::vector<std::string> arguments_;  // ffmpeg's command line
    mutable std::mutex launchMutex_;     // ffmpeg_'s creation against cancel() from another thread
    std::optional<ChildProcess> ffmpeg_;
    bool cancelled_ = false;  // cancel() came before the launch: ffmpeg is never started
    // Fired by cancel(): a write blocked on an ffmpeg that stopped reading returns, whoever holds the
    // pipe open (once a defect: a wrapper script's child kept it open after the script was killed,
    // the encoder thread never returned and a stop never ended the run).
    CancelSignal writeCancel_;
    bool registered_ = false;  // temp_ and log_ are in core/InFlight.h
    bool closed_ = false;
    std::string encoder_;
    std::string autoExplanation_;
};

}  // namespace toyhost
