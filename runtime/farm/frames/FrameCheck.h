// FrameCheck: reads a farm's frames back to say which are missing, truncated or undecodable (the
// project's PNG and EXR decoders, not just names and sizes), shard by shard. CPU only; no GL.
#pragma once

#include <filesystem>
#include <string>

#include "farm/FarmStatus.h"

namespace toyhost {

// The state of one frame file: Missing when absent, Truncated when it ends before the format's end
// (a PNG without its IEND chunk, an empty file, an EXR whose data stops early), Undecodable when
// complete but not a picture the decoders read; `reason` gets their words.
farm::FrameState checkFrameFile(const std::filesystem::path& file, std::string& reason);

// Every frame of `layout`, per shard, with the exit code each shard's last attempt recorded. The
// frame folder is listed once: only the frames found are read, absent ones are counted in runs
// (so any frame count costs what the folder holds). A file over 256 MiB is judged from its first
// and last bytes, not decoded.
farm::FarmStatus checkFarm(const farm::FrameLayout& layout);

}  // namespace toyhost
