// libFuzzer target: the --out argument through toyhost::OutputPattern::parse
// (runtime/capture/OutputPattern.h), then pathFor() of a few frame numbers, large ones included.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

#include "capture/OutputPattern.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    toyhost::Result<toyhost::OutputPattern> pattern = toyhost::OutputPattern::parse(text);
    volatile std::size_t sink = 0;
    if (!pattern) {
        sink = pattern.error().text().size();
        return 0;
    }
    // Frame numbers are never negative (FrameRecorder counts from 0).
    static constexpr int kFrames[] = {0, 1, 7, 9999, 123456789, std::numeric_limits<int>::max()};
    for (int frame : kFrames) sink = sink + pattern->pathFor(frame).native().size();
    sink = sink + pattern->extension().size() + pattern->text().size() + std::size_t(pattern->format()) +
           std::size_t(pattern->numbered()) + std::size_t(pattern->streamed());
    (void)sink;
    return 0;
}
