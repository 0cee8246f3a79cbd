// Window mode, driven from outside as a user would: toyhost opens a GLFW window on the X server
// of $DISPLAY (CTest runs this under xvfb-run), xdotool sends real X input events, F12 writes a
// screenshot of the shown frame, and the pixels of shadertoys/window-probe say what the shader
// saw (iMouse, keyboard texture, iFrame, iResolution, a colour the hot-reload test edits).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "Processes.h"
#include "TestFolder.h"
#include "image/ImageWriters.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = TOYHOST_SOURCE_DIR;
const fs::path kToyhost = TOYHOST_BIN;
const fs::path kOutput = fs::path(TOYHOST_TEST_OUTPUT_DIR) / "window";

void pause(double seconds) { std::this_thread::sleep_for(std::chrono::duration<double>(seconds)); }

class WindowMode : public ::testing::Test {
protected:
    void SetUp() override {
        if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no $DISPLAY (CTest runs these under xvfb-run)";
        if (shell("command -v xdotool").first != 0) GTEST_SKIP() << "xdotool is not installed";
        dir_ = kOutput / ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        for (const char* file : {"manifest.json", "buffer_a.glsl", "image.glsl"})
            fs::copy_file(kSource / "shadertoys/window-probe" / file, dir_ / file);
    }
    void TearDown() override {
        if (toyhost_ && toyhost_->running()) {
            xdo("key Escape");
            toyhost_->wait(10);
        }
    }

    // Starts toyhost in a window on the probe (or on a copy of shadertoys/`gallery` in the test's
    // folder, where F12 then writes) and waits until the window is there.
    void start(std::vector<std::string> extra = {}, const std::string& gallery = "") {
        fs::path toy = dir_;
        if (!gallery.empty()) {
            toy = dir_ / gallery;
            fs::copy(kSource / "shadertoys" / gallery, toy, fs::copy_options::recursive);
            shots_ = toy;
        }
        std::vector<std::string> args = {"run", toy.string(), "--window", "--size", "200x100"};
        args.insert(args.end(), extra.begin(), extra.end());
        toyhost_.emplace(kToyhost, args, dir_ / "toyhost.log");
        const std::string name = gallery.empty() ? "window-probe" : gallery;
        auto [code, id] = shell("timeout 20 xdotool search --sync --onlyvisible --name '^" + name + "' | head -n1");
        ASSERT_EQ(code, 0) << toyhost_->log();
        window_ = id.substr(0, id.find('\n'));
        ASSERT_FALSE(window_.empty()) << toyhost_->log();
        xdo("windowfocus --sync " + window_);
        pause(0.3);
    }
    void xdo(const std::string& command) {
        auto [code, out] = shell("xdotool " + command + " 2>&1");
        EXPECT_EQ(code, 0) << "xdotool " << command << ": " << out;
    }
    // F12, then the screenshot it wrote.
    Image8 screenshot() {
        const fs::path shots = shots_.empty() ? dir_ : shots_;
        for (const auto& entry : fs::directory_iterator(shots))
            if (entry.path().extension() == ".png") fs::remove(entry.path());
        pause(0.3);  // let the frames after the last input render
        xdo("key F12");
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (std::chrono::steady_clock::now() < deadline) {
            for (const auto& entry : fs::directory_iterator(shots))
                if (entry.path().extension() == ".png") {
                    Result<Image8> image = readPng(entry.path());
                    EXPECT_TRUE(image.ok()) << image.error().text();
                    return image.ok() ? *image : Image8{};
                }
            pause(0.05);
        }
        ADD_FAILURE() << "no screenshot after F12:\n" << toyhost_->log();
        return {};
    }
    // Column x of the bottom row, as 0..255 values.
    static std::array<int, 4> column(const Image8& image, int x) {
        if (image.rgba.empty()) return {-1, -1, -1, -1};
        const std::size_t at = static_cast<std::size_t>(x) * 4;
        return {image.rgba[at], image.rgba[at + 1], image.rgba[at + 2], image.rgba[at + 3]};
    }
    // Buffer A counts frames since its last clear and iFrame counts frames since the last restart
    // (both mod 256 in the picture): counter - iFrame is 1 while nothing cleared the buffer.
    static int sinceClear(const Image8& image) { return (column(image, 3)[0] - column(image, 3)[1] + 256) % 256; }
    std::string title() { return shell("xdotool getwindowname " + window_).second; }

    fs::path dir_;
    fs::path shots_;  // where F12 writes, when not dir_
    std::optional<BackgroundProcess> toyhost_;
    std::string window_;
};

TEST_F(WindowMode, FramesArePixelIdenticalToHeadless) {
    for (const char* mode : {"--window", "--headless"}) {
        auto run = shell("'" + kToyhost.string() + "' run '" + (kSource / "shadertoys/uniform-probe").string() + "' " +
                         mode + " --size 96x48 --frames 4 --fps 30 --quiet --out '" + (dir_ / mode).string() +
                         "_%d.png' 2>&1");
        ASSERT_EQ(run.first, 0) << run.second;
        if (std::string(mode) == "--window") EXPECT_NE(run.second.find("in a window on GLFW window"), std::string::npos) << run.second;
    }
    for (int frame : {0, 3}) {
        std::ifstream a(dir_ / ("--window_" + std::to_string(frame) + ".png"), std::ios::binary);
        std::ifstream b(dir_ / ("--headless_" + std::to_string(frame) + ".png"), std::ios::binary);
        const std::string windowBytes((std::istreambuf_iterator<char>(a)), {});
        const std::string headlessBytes((std::istreambuf_iterator<char>(b)), {});
        EXPECT_FALSE(windowBytes.empty());
        EXPECT_EQ(windowBytes, headlessBytes) << "frame " << frame;
    }
}

// Every gallery shader runs in a window too, and with --fps its frames equal the headless ones.
TEST_F(WindowMode, GalleryShadersRenderTheSameInAWindow) {
    for (const char* gallery : {"raymarched-sea", "exp-sine-ocean", "lake-optics", "caustics-pool", "ripple-pool",
                                "coastal-foam"}) {
        SCOPED_TRACE(gallery);
        std::string bytes[2];
        int i = 0;
        for (const char* mode : {"--window", "--headless"}) {
            const fs::path out = dir_ / (std::string(gallery) + mode + ".png");
            auto run = shell("'" + kToyhost.string() + "' run '" + (kSource / "shadertoys" / gallery).string() + "' " + mode +
                             " --size 96x54 --frames 3 --capture-every 2 --start-time 2 --fps 30 --quiet --out '" +
                             (dir_ / (std::string(gallery) + mode + "_%d.png")).string() + "' 2>&1");
            ASSERT_EQ(run.first, 0) << run.second;
            std::ifstream file(dir_ / (std::string(gallery) + mode + "_2.png"), std::ios::binary);
            bytes[i++].assign(std::istreambuf_iterator<char>(file), {});
        }
        EXPECT_FALSE(bytes[0].empty());
        EXPECT_EQ(bytes[0], bytes[1]) << "window and headless frames differ";
    }
}

// ripple-pool with a real drag: the ripples are where the pointer went, and nowhere else.
TEST_F(WindowMode, RipplePoolDragLeavesRipplesWhereThePointerWent) {
    start({}, "ripple-pool");
    const Image8 calm = screenshot();
    xdo("mousemove --window " + window_ + " 30 70 mousedown 1");
    for (int x = 40; x <= 100; x += 10) {
        xdo("mousemove --window " + window_ + " " + std::to_string(x) + " 70");
        pause(0.03);
    }
    xdo("mouseup 1");
    xdo("key F6");  // pause: the rings stop spreading
    const Image8 dragged = screenshot();
    ASSERT_EQ(calm.rgba.size(), dragged.rgba.size());
    // Window y 70 is canvas row 100 - 70 = 30 (origin bottom-left). In real time the window may
    // render hundreds of frames during the drag, so rings can reach anywhere; what must hold is
    // that the water is disturbed along the path, and much more there than in the far corner
    // (x 170.., y 75..: over 70 px from any drop, where rings arrive spread out and damped).
    auto meanChange = [&](int x0, int y0, int x1, int y1) {
        double sum = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                const std::size_t i = (static_cast<std::size_t>(y) * calm.width + x) * 4;
                for (int c = 0; c < 3; ++c) sum += std::abs(calm.rgba[i + c] - dragged.rgba[i + c]);
            }
        return sum / ((x1 - x0) * (y1 - y0));
    };
    const double near = meanChange(30, 22, 100, 38), far = meanChange(170, 75, 200, 100);
    std::printf("mean change: %.2f along the drag, %.2f in the far corner\n", near, far);
    EXPECT_GT(near, 3.0) << "no ripples along the drag";
    EXPECT_GT(near, 2.0 * far) << "the far corner moved as much as the drag's path";
}

TEST_F(WindowMode, MouseFollowsTheSitesIMouseRules) {
    start();
    Image8 before = screenshot();
    EXPECT_EQ(column(before, 0), (std::array<int, 4>{0, 0, 0, 255})) << "before any click";
    EXPECT_EQ(column(before, 1), (std::array<int, 4>{0, 0, 0, 255}));
    xdo("mousemove --window " + window_ + " 50 30 mousedown 1");
    pause(0.2);
    xdo("mousemove --window " + window_ + " 80 40");
    Image8 held = screenshot();
    // xy = (80, floor(100 - 40)), z = +click x, w = -click y (not the click frame any more).
    EXPECT_EQ(column(held, 0), (std::array<int, 4>{80, 60, 50, 255}));
    EXPECT_EQ(column(held, 1), (std::array<int, 4>{70, 255, 0, 255})) << "|w| = 70, z > 0, w < 0";
    xdo("mouseup 1");
    xdo("mousemove --window " + window_ + " 150 90");
    Image8 released = screenshot();
    EXPECT_EQ(column(released, 0), (std::array<int, 4>{80, 60, 50, 255})) << "xy keeps the last dragged position";
    EXPECT_EQ(column(released, 1), (std::array<int, 4>{70, 0, 0, 255})) << "z and w negative after release";
}

TEST_F(WindowMode, KeysReachTheKeyboardTextureAndControlKeysDoNot) {
    start();
    xdo("keydown a");
    Image8 held = screenshot();
    EXPECT_EQ(column(held, 2), (std::array<int, 4>{255, 0, 255, 255})) << "A held, went down earlier, toggled on";
    EXPECT_EQ(column(held, 3)[2], 0) << "Space not held";
    xdo("keyup a");
    xdo("keydown space");
    Image8 released = screenshot();
    EXPECT_EQ(column(released, 2), (std::array<int, 4>{0, 0, 255, 255})) << "A released, toggle stays";
    EXPECT_EQ(column(released, 3)[2], 255) << "Space held";
    xdo("keyup space");
    xdo("key F1");
    EXPECT_TRUE(toyhost_->waitForLog("F5 or Ctrl+R restart", 5)) << toyhost_->log();
}

TEST_F(WindowMode, PauseRestartAndStepGiveFrameZeroWithClearedBuffers) {
    start();
    Image8 running = screenshot();
    EXPECT_EQ(sinceClear(running), 1);
    xdo("key F6");
    xdo("key F5");
    xdo("key F7");
    Image8 first = screenshot();
    EXPECT_EQ(column(first, 3)[0], 1) << "Buffer A counted one frame since the restart";
    EXPECT_EQ(column(first, 3)[1], 0) << "iFrame 0";
    xdo("key F7");
    Image8 second = screenshot();
    EXPECT_EQ(column(second, 3)[0], 2);
    EXPECT_EQ(column(second, 3)[1], 1);
    EXPECT_NE(title().find("paused"), std::string::npos) << title();
}

TEST_F(WindowMode, TheCanvasFollowsTheWindowSize) {
    start();
    Image8 small = screenshot();
    EXPECT_EQ(small.width, 200);
    EXPECT_EQ(column(small, 4), (std::array<int, 4>{50, 25, 0, 255}));
    xdo("windowsize --sync " + window_ + " 240 120");
    Image8 large = screenshot();
    EXPECT_EQ(large.width, 240);
    EXPECT_EQ(large.height, 120);
    EXPECT_EQ(column(large, 4), (std::array<int, 4>{60, 30, 0, 255}));
    // Buffer A counts frames since its last clear and iFrame counts frames since the start (both
    // mod 256): counter = iFrame + 1 as long as nothing cleared the buffer, resize included.
    EXPECT_EQ(sinceClear(small), 1);
    EXPECT_EQ(sinceClear(large), 1) << "the buffer kept its content through the resize";
    xdo("key F11");
    Image8 full = screenshot();
    auto [code, screen] = shell("xdotool getdisplaygeometry");
    EXPECT_EQ(std::to_string(full.width) + " " + std::to_string(full.height) + "\n", screen) << "F11: the whole screen";
    xdo("key F11");
    Image8 back = screenshot();
    EXPECT_EQ(back.width, 240) << "F11 again: the window as it was";
    EXPECT_EQ(back.height, 120);
}

TEST_F(WindowMode, HotReloadKeepsTheLastGoodProgramAndShowsTheError) {
    start();
    EXPECT_EQ(column(screenshot(), 5), (std::array<int, 4>{10, 20, 30, 255}));
    auto edit = [&](const std::string& from, const std::string& to) {
        std::ifstream in(dir_ / "image.glsl");
        std::string code((std::istreambuf_iterator<char>(in)), {});
        const std::size_t at = code.find(from);
        ASSERT_NE(at, std::string::npos);
        code.replace(at, from.size(), to);
        std::ofstream(dir_ / "image.glsl") << code;
    };
    edit("vec4(10, 20, 30, 255)", "vec4(40, 50, 60, 255)");
    ASSERT_TRUE(toyhost_->waitForLog("reloaded: Image", 10)) << toyhost_->log();
    const Image8 reloaded = screenshot();
    EXPECT_EQ(column(reloaded, 5), (std::array<int, 4>{40, 50, 60, 255}));
    EXPECT_EQ(sinceClear(reloaded), 1) << "Buffer A kept counting, iFrame went on (no restart)";

    edit("vec4(40, 50, 60, 255)", "vec4(40, 50, undefined_name, 255)");
    ASSERT_TRUE(toyhost_->waitForLog("undefined_name", 10)) << toyhost_->log();
    EXPECT_NE(toyhost_->log().find((dir_ / "image.glsl").string() + ":21:"), std::string::npos) << toyhost_->log();
    EXPECT_EQ(column(screenshot(), 5), (std::array<int, 4>{40, 50, 60, 255})) << "the last good program runs on";
    EXPECT_NE(title().find("image.glsl:21:"), std::string::npos) << title();

    edit("vec4(40, 50, undefined_name, 255)", "vec4(70, 80, 90, 255)");
    ASSERT_TRUE(toyhost_->waitForLog("reloaded: Image", 10, 2)) << toyhost_->log();
    EXPECT_EQ(column(screenshot(), 5), (std::array<int, 4>{70, 80, 90, 255}));
    pause(0.4);
    EXPECT_EQ(title().find("error"), std::string::npos) << title();
}

TEST_F(WindowMode, EscapeEndsTheRunAndSigtermInterruptsIt) {
    start();
    xdo("key Escape");
    EXPECT_EQ(toyhost_->wait(10), 0) << toyhost_->log();
    EXPECT_NE(toyhost_->log().find("in a window on"), std::string::npos) << toyhost_->log();
    start({"--out", (dir_ / "movie.mp4").string()});
    toyhost_->signal(SIGTERM);
    EXPECT_EQ(toyhost_->wait(10), 143) << toyhost_->log();
    EXPECT_FALSE(fs::exists(dir_ / "movie.mp4")) << "an interrupted video is discarded";
}

TEST_F(WindowMode, FramesEndsTheRunAndTheRecordingIsComplete) {
    auto run = shell("'" + kToyhost.string() + "' run '" + dir_.string() +
                     "' --window --size 64x32 --frames 12 --fps 24 --quiet --out '" + (dir_ / "movie.mp4").string() +
                     "' 2>&1");
    ASSERT_EQ(run.first, 0) << run.second;
    auto probe = shell("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames,width,height "
                       "-of csv=p=0 '" + (dir_ / "movie.mp4").string() + "'");
    EXPECT_EQ(probe.second, "64,32,12\n");
}

}  // namespace
}  // namespace toyhost::testing
