// Checkpoint: a run's full state in one file (--checkpoint), so that --resume continues with
// frames byte-identical to an uninterrupted run: the Player's state (both slots of every buffer
// as raw floats, iFrame and the ping-pong step, mouse and keyboard) and the clock the frames were
// made with (fps, start time, the iDate of frame 0), plus what identifies the shadertoy. Files are
// written atomically. No GL needed.
//
// Format: the line "TOYHOST-CHECKPOINT 1", a line of JSON (name, code hash, clock, frame, step,
// canvas, mouse, keyboard in hex, the buffers present), then for each buffer in that order slot 0
// and slot 1 as width*height*4 little-endian 32-bit floats, rows bottom first.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "core/Result.h"
#include "manifest/ManifestDesc.h"
#include "player/Player.h"
#include "shader/MacroDefines.h"

namespace toyhost {

class BackgroundWriter;

struct Checkpoint {
    PlayerState state;
    double fps = 0;
    double startTime = 0;
    double wallClock = 0;    // iDate of frame 0 (FrameClock's form)
    std::string shadertoy;   // the manifest's name
    std::string codeHash;    // codeHash() of the shadertoy it was made from
    std::vector<std::string> media;  // the stock media and image files its channels show
};

// A hash of Common and every pass's code, and of the run's --define macros when there are any: a
// resume against other code is not the same run.
std::string codeHash(const ManifestDesc& manifest, std::span<const MacroDefine> defines = {});
// The media ids and image files of `manifest`'s channels, sorted.
std::vector<std::string> channelMedia(const ManifestDesc& manifest);

Status writeCheckpoint(const std::filesystem::path& path, const Checkpoint& checkpoint);
// `checkpoint` written to `path` on `writer`'s thread (the GL thread goes on meanwhile), waited
// for so that at most one copy of the state is in memory: the path written, or why not.
Result<std::filesystem::path> writeCheckpointOffThread(BackgroundWriter& writer, const std::filesystem::path& path,
                                                       Checkpoint checkpoint);
// Errors name the file and what is wrong with it (not a checkpoint, truncated, inconsistent).
Result<Checkpoint> readCheckpoint(const std::filesystem::path& path);

}  // namespace toyhost
