// libFuzzer target: input-script JSON through toyhost::parseMouseScript and parseKeyScript
// (runtime/input/InputScript.h); a parsed script is then played a few hundred frames, plus a few
// far-off ones, through MouseScriptPlayer / KeyScriptPlayer to exercise the playback arithmetic.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>

#include <glm/vec4.hpp>

#include "input/InputScript.h"
#include "input/InputScriptPlayer.h"
#include "input/KeyboardState.h"
#include "input/MouseState.h"

namespace {

constexpr std::int64_t kFrames = 300;
constexpr double kFps = 60.0;
// After the first kFrames frames: frames far apart, as a long run (or a huge "frame") reaches them.
constexpr std::int64_t kLater[] = {1000, 123457, 100000000, std::int64_t(1) << 40, std::int64_t(1) << 53,
                                   std::numeric_limits<std::int64_t>::max() / 2,
                                   std::numeric_limits<std::int64_t>::max()};

template <class Step>
void playFrames(Step&& step) {
    for (std::int64_t frame = 0; frame < kFrames; ++frame) step(frame, double(frame) / kFps);
    for (std::int64_t frame : kLater) step(frame, double(frame) / kFps);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    volatile float sink = 0.0f;

    toyhost::Result<toyhost::MouseScript> mouse = toyhost::parseMouseScript(text, "mouse.json");
    if (mouse) {
        toyhost::MouseScriptPlayer player(std::move(*mouse));
        toyhost::MouseState state;
        playFrames([&](std::int64_t frame, double iTime) {
            player.applyBeforeFrame(frame, iTime, state);
            const glm::vec4 uniform = state.uniform();
            sink = sink + uniform.x + uniform.y + uniform.z + uniform.w;
            state.endFrame();
        });
        sink = sink + float(player.finished());
    } else {
        sink = sink + float(mouse.error().text().size());
    }

    toyhost::Result<toyhost::KeyScript> keys = toyhost::parseKeyScript(text, "keys.json");
    if (keys) {
        toyhost::KeyScriptPlayer player(std::move(*keys));
        toyhost::KeyboardState keyboard;
        playFrames([&](std::int64_t frame, double iTime) {
            player.applyBeforeFrame(frame, iTime, keyboard);
            sink = sink + float(keyboard.revision() & 0xff);
            keyboard.endFrame();
        });
        sink = sink + float(player.finished());
    } else {
        sink = sink + float(keys.error().text().size());
    }
    (void)sink;
    return 0;
}
