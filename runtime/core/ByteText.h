// ByteText: a byte count, and a count of things, as people read them, for progress lines, summaries
// and messages. No GL.
#pragma once

#include <cstdint>
#include <string>

namespace toyhost {

// "812 B", "3.4 KiB", "12.4 MiB", "1.20 GiB".
std::string formatBytes(std::uint64_t bytes);
// "1 frame", "3 frames".
inline std::string plural(long long n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

}  // namespace toyhost
