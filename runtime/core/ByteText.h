// ByteText: a byte count as people read it, for progress lines, summaries and memory errors. No GL.
#pragma once

#include <cstdint>
#include <string>

namespace toyhost {

// "812 B", "3.4 KiB", "12.4 MiB", "1.20 GiB".
std::string formatBytes(std::uint64_t bytes);

}  // namespace toyhost
