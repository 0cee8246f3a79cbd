// Writes files so that they are either complete or absent: data goes to a temporary name in the
// destination folder, then is renamed over the final name. No GL needed.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <span>
#include <string>

#include "core/Result.h"

namespace toyhost {

// Whether a writer creates the folders above the file (a single output) or needs them to be there
// (the frames of a sequence after the first: a folder that vanished mid-run is an error, not
// silently made again with part of the frames).
enum class ParentFolders { Create, MustExist };

// Calls `write(tempPath)`, which must create the file at tempPath; on success renames it to
// `path`, on failure removes the temporary file. Parent folders are created unless `parents`
// says they must exist.
Status writeFileAtomically(const std::filesystem::path& path,
                           const std::function<Status(const std::filesystem::path&)>& write,
                           ParentFolders parents = ParentFolders::Create);

// A unique hidden name beside `path` (".name.PID.N.partial"; a name too long for that gets a
// shortened form with a hash, so any legal output name works) for output that is renamed into
// place when complete, by writers that cannot use writeFileAtomically (a file an ffmpeg process
// writes over a whole run).
std::filesystem::path temporarySibling(const std::filesystem::path& path);

// Convenience for in-memory bytes.
Status writeBytesAtomically(const std::filesystem::path& path, std::span<const std::byte> bytes);

// The most readTextFile reads unless told otherwise: manifests, exports, scripts and shader
// sources are far smaller; a larger file is refused instead of filling memory.
inline constexpr std::size_t kDefaultReadLimitBytes = std::size_t(64) << 20;

// Ok when `path` is a regular file that exists; else an error that says what it is instead:
// missing, a folder, a link loop, a device or FIFO (`what` names it in the message: "texture").
Status checkRegularFile(const std::filesystem::path& path, const std::string& what = "");

// Reads a whole regular file (a folder, a device such as /dev/zero or a FIFO is refused, so is a
// file over `limitBytes`); errors name the path and the cause.
Result<std::string> readTextFile(const std::filesystem::path& path, std::size_t limitBytes = kDefaultReadLimitBytes);

}  // namespace toyhost
