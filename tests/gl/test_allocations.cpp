// "Nothing per frame that need not be": once running, the Player's frame (input events, uniforms,
// every pass, the keyboard upload, a video channel's frames from its decoding thread, a music
// channel's analysis) makes no heap allocation. Counted by replacing the global operator new in
// this test executable, on every thread (Mesa's own allocations use malloc and are not counted).
#include "GlTestSupport.h"

#include "capture/WavFile.h"
#include "core/ChildProcess.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
    if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace toyhost::testing {
namespace {

class Allocations : public GlTest {};

TEST_F(Allocations, APlayerFrameAllocatesNothing) {
    TOYHOST_REQUIRE_SHARED("shadertoys/7tSSDD");
    // Mountains & Lakes: Common, four buffers with feedback, the keyboard, mipmapped buffers.
    auto toy = loadSession(context_, sourceDir() / "shadertoys/mountains-lakes", 64, 36);
    ASSERT_TRUE(toy);
    std::vector<InputEvent> events;
    events.reserve(8);
    for (int i = 0; i < 3; ++i) stepAt(*toy);  // warm-up: first uses of every program
    allocations = 0;
    counting = true;
    for (int i = 0; i < 20; ++i) {
        events.clear();
        if (i % 4 == 0) events.push_back(InputEvent::mouseDown(10.0f + i, 20.0f));
        if (i % 4 == 2) events.push_back(InputEvent::mouseUp());
        if (i % 5 == 0) events.push_back(InputEvent::keyDown(32));
        if (i % 5 == 3) events.push_back(InputEvent::keyUp(32));
        stepAt(*toy, events);
    }
    counting = false;
    playerOf(*toy).finish();
    EXPECT_EQ(allocations.load(), 0) << "heap allocations in 20 frames";
}

TEST_F(Allocations, AFrameWithVideoAndMusicChannelsAllocatesNothing) {
    if (!findExecutable("ffmpeg")) GTEST_FAIL() << "needs ffmpeg (scripts/install-deps.sh installs it)";
    const std::filesystem::path dir = freshOutputDir("allocations/media");
    writeFile(dir / "image.glsl",
              "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, f / iResolution.xy) + "
              "texture(iChannel1, f / iResolution.xy) + iChannelTime[0] + iChannelTime[1]; }\n");
    writeFile(dir / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl",
        "channels": {"iChannel0": {"video": "clip.mkv"}, "iChannel1": {"music": "tone.wav"}}}}})");
    const std::string encode = "ffmpeg -v error -nostdin -y -f lavfi -i testsrc2=s=64x36:r=30:d=4 -c:v ffv1 '" +
                               (dir / "clip.mkv").string() + "'";
    ASSERT_EQ(std::system(encode.c_str()), 0);
    std::vector<float> stereo(2 * 44100, 0.25f);
    ASSERT_TRUE(writeWav16(dir / "tone.wav", stereo, 44100));
    auto toy = loadSession(context_, dir, 32, 18);
    ASSERT_TRUE(toy);
    for (int i = 0; i < 3; ++i) stepAt(*toy);  // warm-up
    allocations = 0;
    counting = true;
    for (int i = 0; i < 20; ++i) stepAt(*toy, {}, 24.0);  // a new video frame on most frames
    counting = false;
    playerOf(*toy).finish();
    EXPECT_EQ(allocations.load(), 0) << "heap allocations in 20 frames";
}

}  // namespace
}  // namespace toyhost::testing
