// The frame watchdog when a frame draws Image several times (supersampling, motion blur; issue 44):
// --frame-timeout bounds each sample's draw, not the frame's sum of them, and a sample that runs
// too long is named as a sample, not as a compile. The watchdog's rule is checked on a published
// activity (no GL); the runs go through the CLI.
#include "GlTestSupport.h"

#include <chrono>
#include <condition_variable>
#include <mutex>

#include "session/Watchdog.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

// What a watchdog with a frame limit says about `phase` published for sample `sample` of `samples`.
std::string expiryFor(RunActivity::Phase phase, int frame, int sample, int samples) {
    std::mutex mutex;
    std::condition_variable changed;
    std::optional<Diagnostic> expired;
    WatchdogDesc desc;
    desc.frameLimit = 0.1;
    desc.expire = [&](const Diagnostic& d, int) {
        std::lock_guard lock(mutex);
        expired = d;
        changed.notify_all();
    };
    Watchdog watchdog(desc);
    watchdog.activity().begin(phase, "Image", frame, sample, samples);
    std::unique_lock lock(mutex);
    // The bound is generous (the limit is 0.1 s); the wait ends at the expiry.
    changed.wait_for(lock, std::chrono::seconds(60), [&] { return expired.has_value(); });
    return expired ? "[" + std::string(codeName(expired->code)) + "] " + expired->pass + ": " + expired->message
                   : std::string("no expiry");
}

TEST(SamplingWatchdog, AnExpiredSampleIsNamedAsASampleNotACompile) {
    const std::string later = expiryFor(RunActivity::Phase::DrawCall, 0, 5, 128);
    EXPECT_NE(later.find("sample 6 of 128"), std::string::npos) << later;
    EXPECT_NE(later.find("each sample's draw"), std::string::npos) << later;
    EXPECT_EQ(later.find("compil"), std::string::npos) << later;
    EXPECT_NE(later.find("Image"), std::string::npos) << later;
    const std::string drawing = expiryFor(RunActivity::Phase::Drawing, 3, 0, 16);
    EXPECT_NE(drawing.find("sample 1 of 16"), std::string::npos) << drawing;
    // The first sample of frame 0 may still be llvmpipe's compile inside the draw: said as a maybe.
    const std::string first = expiryFor(RunActivity::Phase::DrawCall, 0, 0, 16);
    EXPECT_NE(first.find("sample 1 of 16"), std::string::npos) << first;
    EXPECT_NE(first.find("may also be the driver compiling"), std::string::npos) << first;
    // One draw a frame: today's words.
    const std::string single = expiryFor(RunActivity::Phase::Drawing, 3, -1, 0);
    EXPECT_EQ(single.find("sample"), std::string::npos) << single;
}

// About 0.05 s a draw at 64x36 on llvmpipe (4000 dependent iterations a pixel).
constexpr const char* kSlowDraw = "void mainImage(out vec4 c, in vec2 f) {\n    float v = f.x * 0.001 + iTime;\n"
                                  "    for (int i = 0; i < 4000; ++i) v = fract(sin(v) * 43758.5453 + f.y);\n"
                                  "    c = vec4(v, v, v, 1.0);\n}\n";

TEST(SamplingWatchdog, TheFrameLimitBoundsEachSampleNotTheFramesSum) {
    const fs::path dir = freshOutputDir("sampling-watchdog/each");
    writeFile(dir / "toy/manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    writeFile(dir / "toy/image.glsl", kSlowDraw);
    // 128 draws a frame, each far under the limit, the frame's sum far over it (the issue's ocean
    // at 640x360: 128 draws of about 0.5 s under the default 60 s).
    const auto started = std::chrono::steady_clock::now();
    const CommandResult run = runToyhost("run '" + (dir / "toy").string() +
                                         "' --headless --quiet --size 64x36 --supersample 4 --motion-blur 8 "
                                         "--frame-timeout 2 --out '" + (dir / "f.png").string() + "'");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_TRUE(fs::exists(dir / "f.png"));
    // Only meaningful when the frame took longer than the limit (it does on llvmpipe here: ~6 s).
    EXPECT_GT(seconds, 2.0) << "the frame took " << seconds << " s: make the shader slower for this machine";
}

// A sample that never ends (the later half of the shutter draws minutes): the run is ended at the
// limit, exit 124, and the message names the sample.
constexpr const char* kEndlessLaterSamples = R"(void mainImage(out vec4 c, in vec2 p) {
    float x = p.x / iResolution.x, s = 0.0;
    if (iTime > 0.3) {
        for (int j = 0; j < 1000; j++) {
            for (int i = 0; i < int(iResolution.x) * 200; i++) {
                s += sin(x * 1.0 + s); s += sin(x * 2.0 + s); s += sin(x * 3.0 + s); s += sin(x * 4.0 + s);
                s += sin(x * 5.0 + s); s += sin(x * 6.0 + s); s += sin(x * 7.0 + s); s += sin(x * 8.0 + s);
                s += sin(x * 9.0 + s); s += sin(x * 10.0 + s); s += sin(x * 11.0 + s); s += sin(x * 12.0 + s);
                s += sin(x * 13.0 + s); s += sin(x * 14.0 + s); s += sin(x * 15.0 + s); s += sin(x * 16.0 + s);
            }
        }
    }
    c = vec4(s);
}
)";

TEST(SamplingWatchdog, ARunawaySampleEndsTheRunNamingTheSample) {
    const fs::path dir = freshOutputDir("sampling-watchdog/runaway");
    writeFile(dir / "toy/manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    writeFile(dir / "toy/image.glsl", kEndlessLaterSamples);
    // --fps 1 --motion-blur 4 --shutter 360: samples at iTime 0.125, 0.375, 0.625, 0.875; the
    // second is the first that runs away.
    const CommandResult run = runToyhost("run '" + (dir / "toy").string() +
                                         "' --headless --size 320x180 --fps 1 --motion-blur 4 --shutter 360 "
                                         "--frame-timeout 1 --out '" + (dir / "out/f.png").string() + "'");
    EXPECT_EQ(run.exitCode, 124) << run.output;
    EXPECT_NE(run.output.find("sample 2 of 4"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("compil"), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir / "out/f.png"));
}

}  // namespace
}  // namespace toyhost::testing
