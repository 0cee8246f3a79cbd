// The capture pipeline against the synchronous path: the ring of pixel-pack buffers returns the
// same bytes as a direct glReadPixels with several frames in flight, and the CLI's async capture
// (PNG of Image, PNG and EXR of a buffer) writes files whose pixels equal --sync-capture's. Raw
// stdout carries exactly frames * width * height * 4 bytes, rows top first.
#include "GlTestSupport.h"

#include <cstring>
#include <fstream>

#include "image/ImageWriters.h"
#include "render/ReadbackRing.h"
#include "image/ImageFile.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

const fs::path kProbe = sourceDir() / "shadertoys/pingpong-probe";

class CapturePipeline : public GlTest {};

TEST_F(CapturePipeline, RingReturnsTheSameBytesAsASynchronousReadWithFramesInFlight) {
    auto toy = loadSession(context_, kProbe, 24, 10);
    ASSERT_TRUE(toy);
    for (PassId pass : {PassId::Image, PassId::BufferA}) {
        const PixelFormat format = playerOf(*toy).output(pass).format;
        auto ring = ReadbackRing::create(24, 10, format, 3);
        ASSERT_TRUE(ring.ok()) << ring.error().text();
        std::vector<std::vector<std::byte>> expected;
        std::vector<std::byte> got(ring->frameBytes());
        for (int frame = 0; frame < 8; ++frame) {
            stepAt(*toy);
            expected.emplace_back(ring->frameBytes());
            readFramebuffer(playerOf(*toy).output(pass).framebuffer, 24, 10, format, expected.back());
            if (ring->full()) {
                const int oldest = ring->oldestFrame();
                ASSERT_TRUE(ring->takeOldest(got).ok());
                EXPECT_EQ(got, expected[oldest]) << passName(pass) << " frame " << oldest;
            }
            ASSERT_TRUE(ring->start(playerOf(*toy).output(pass).framebuffer, frame).ok());
        }
        while (!ring->empty()) {
            const int oldest = ring->oldestFrame();
            ASSERT_TRUE(ring->takeOldest(got).ok());
            EXPECT_EQ(got, expected[oldest]) << passName(pass) << " frame " << oldest;
        }
        // The probe's frames differ from each other, so a mixed-up slot would have been caught.
        EXPECT_NE(expected[1], expected[2]);
    }
}

struct Case {
    const char* name;
    const char* pass;
    const char* extension;
    friend void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }
};

class AsyncMatchesSync : public ::testing::TestWithParam<Case> {};

TEST_P(AsyncMatchesSync, DecodedPixelsAreIdentical) {
    const Case& c = GetParam();
    const fs::path dir = freshOutputDir(std::string("capture-async-sync/") + c.name);
    const std::string common = "run " + quoted(kProbe) + " --size 40x24 --frames 9 --capture-every 2 --quiet " +
                               "--capture-pass '" + c.pass + "' ";
    auto async = runToyhost(common + "--encoder-threads 3 --out " + quoted(dir / "async" / (std::string("f_%02d") + c.extension)));
    ASSERT_EQ(async.exitCode, 0) << async.output;
    auto sync = runToyhost(common + "--sync-capture --out " + quoted(dir / "sync" / (std::string("f_%02d") + c.extension)));
    ASSERT_EQ(sync.exitCode, 0) << sync.output;
    int compared = 0;
    for (int frame : {0, 2, 4, 6, 8}) {
        char name[32];
        std::snprintf(name, sizeof name, "f_%02d%s", frame, c.extension);
        if (std::string(c.extension) == ".exr") {
            auto a = readExr(dir / "async" / name);
            auto s = readExr(dir / "sync" / name);
            ASSERT_TRUE(a.ok() && s.ok()) << name;
            EXPECT_EQ(0, std::memcmp(a->rgba.data(), s->rgba.data(), a->rgba.size() * sizeof(float))) << name;
            EXPECT_EQ(a->rgba.size(), s->rgba.size());
        } else {
            auto a = loadImageFile(dir / "async" / name);
            auto s = loadImageFile(dir / "sync" / name);
            ASSERT_TRUE(a.ok() && s.ok()) << name;
            EXPECT_EQ(a->rgba, s->rgba) << name;
        }
        ++compared;
    }
    EXPECT_EQ(compared, 5);
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();
}

INSTANTIATE_TEST_SUITE_P(Outputs, AsyncMatchesSync,
                         ::testing::Values(Case{"image_png", "Image", ".png"}, Case{"buffer_png", "Buffer A", ".png"},
                                           Case{"buffer_exr", "Buffer B", ".exr"}, Case{"image_exr", "Image", ".exr"}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(RawStdout, CarriesEveryFrameTopFirstAndMessagesGoToStderr) {
    const fs::path dir = freshOutputDir("capture-raw");
    const std::string common = "run " + quoted(kProbe) + " --size 20x12 --frames 5 ";
    // Only stdout goes to the file; anything the CLI says must be on stderr.
    const std::string command = "'" + toyhostBinary().string() + "' " + common + "--out - > " +
                                quoted(dir / "frames.rgba") + " 2> " + quoted(dir / "stderr.txt");
    ASSERT_EQ(std::system(command.c_str()), 0);
    auto pngs = runToyhost(common + "--quiet --sync-capture --out " + quoted(dir / "f_%d.png"));
    ASSERT_EQ(pngs.exitCode, 0) << pngs.output;

    const std::size_t frameSize = 20 * 12 * 4;
    ASSERT_EQ(fs::file_size(dir / "frames.rgba"), 5 * frameSize);
    std::ifstream raw(dir / "frames.rgba", std::ios::binary);
    std::vector<char> bytes(5 * frameSize);
    raw.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    for (int frame = 0; frame < 5; ++frame) {
        auto png = loadImageFile(dir / ("f_" + std::to_string(frame) + ".png"));  // rows top first
        ASSERT_TRUE(png.ok());
        EXPECT_EQ(0, std::memcmp(bytes.data() + frame * frameSize, png->rgba.data(), frameSize)) << "frame " << frame;
    }
}

}  // namespace
}  // namespace toyhost::testing
