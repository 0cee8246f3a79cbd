// Writes files so that they are either complete or absent: data goes to a temporary name in the
// destination folder, then is renamed over the final name. No GL needed.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <span>

#include "core/Result.h"

namespace toyhost {

// Calls `write(tempPath)`, which must create the file at tempPath; on success renames it to
// `path`, on failure removes the temporary file. Parent folders are created.
Status writeFileAtomically(const std::filesystem::path& path,
                           const std::function<Status(const std::filesystem::path&)>& write);

// A unique hidden name beside `path` (".name.PID.N.partial") for output that is renamed into
// place when complete, by writers that cannot use writeFileAtomically (a file an ffmpeg process
// writes over a whole run).
std::filesystem::path temporarySibling(const std::filesystem::path& path);

// Convenience for in-memory bytes.
Status writeBytesAtomically(const std::filesystem::path& path, std::span<const std::byte> bytes);

// Reads a whole text file; the error names the path.
Result<std::string> readTextFile(const std::filesystem::path& path);

}  // namespace toyhost
