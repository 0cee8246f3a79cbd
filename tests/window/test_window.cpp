// Window mode, driven from outside as a user would: toyhost opens a GLFW window on the X server
// of $DISPLAY (each case under its own xvfb-run, a CTest entry of its own), xdotool sends real X
// input events, F12 writes a screenshot of the shown frame, and the pixels of
// shadertoys/window-probe say what the shader saw (iMouse, keyboard texture, iFrame, iResolution,
// a colour and a texture the hot-reload cases edit). Nothing waits for a time: the cases wait for
// the frame counter in the window's title, or for a line toyhost prints.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>

#include "Processes.h"
#include "ScreenGrab.h"
#include "image/ImageFile.h"
#include "image/ImageWriters.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const fs::path kSource = TOYHOST_SOURCE_DIR;
const fs::path kToyhost = TOYHOST_BIN;
const fs::path kOutput = fs::path(TOYHOST_TEST_OUTPUT_DIR) / "window";

// Polls `done` until it holds or `seconds` pass (a poll interval, not a wait for the effect).
template <class Done>
bool within(double seconds, Done done) {
    const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
    while (Clock::now() < deadline) {
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return done();
}

class WindowMode : public ::testing::Test {
protected:
    void SetUp() override {
        if (!std::getenv("DISPLAY")) GTEST_FAIL() << "no $DISPLAY: CTest runs these under xvfb-run";
        if (shell("command -v xdotool").first != 0) GTEST_FAIL() << "xdotool is not installed";
        dir_ = kOutput / ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "probe");
        for (const char* file : {"manifest.json", "buffer_a.glsl", "image.glsl", "probe.png"})
            fs::copy_file(kSource / "shadertoys/window-probe" / file, dir_ / "probe" / file);
    }
    void TearDown() override {
        if (toyhost_ && toyhost_->running()) {
            closeWindow();
            toyhost_->wait(10);
        }
    }
    // Esc: the window may be gone before xdotool sends the key's release (BadWindow), so only
    // toyhost's exit says whether it worked.
    void closeWindow() { shell("xdotool key --window " + window_ + " Escape 2>&1"); }

    // Starts toyhost in a window on `toy` (the probe by default), in the test's folder (where
    // screenshots go), and waits until the window is there.
    void start(std::vector<std::string> extra = {}, fs::path toy = {}, const std::string& name = "window-probe",
               const std::string& size = "200x100") {
        if (toy.empty()) toy = dir_ / "probe";
        std::vector<std::string> args = {"run", toy.string(), "--window", "--size", size};
        args.insert(args.end(), extra.begin(), extra.end());
        toyhost_.emplace(kToyhost, args, dir_ / "toyhost.log", dir_);
        auto [code, id] = shell("timeout 20 xdotool search --sync --onlyvisible --name '^" + name + "' | head -n1");
        ASSERT_EQ(code, 0) << toyhost_->log();
        window_ = id.substr(0, id.find('\n'));
        ASSERT_FALSE(window_.empty()) << toyhost_->log();
        xdo("windowfocus --sync " + window_);
    }
    void xdo(const std::string& command) {
        auto [code, out] = shell("xdotool " + command + " 2>&1");
        EXPECT_EQ(code, 0) << "xdotool " << command << ": " << out;
    }
    std::string title() { return shell("xdotool getwindowname " + window_).second; }
    // iFrame of the frame the window shows, from its title; -1 before the first.
    int shownFrame() {
        std::smatch m;
        const std::string t = title();
        return std::regex_search(t, m, std::regex("iFrame (\\d+)")) ? std::stoi(m[1]) : -1;
    }
    // Waits until `frames` more frames were shown (the input sent before has been rendered).
    void waitFrames(int frames = 2) {
        const int from = shownFrame();
        EXPECT_TRUE(within(30, [&] { return shownFrame() >= from + frames; }))
            << "iFrame stayed at " << from << "\n" << title() << "\n" << toyhost_->log();
    }
    // F12, then the screenshot it wrote (its path comes from toyhost's notice).
    Image8 screenshot(fs::path* written = nullptr) {
        const std::string said = "notice: screenshot written";
        std::size_t before = 0;
        const std::string log = toyhost_->log();
        for (std::size_t at = log.find(said); at != std::string::npos; at = log.find(said, at + 1)) ++before;
        xdo("key --window " + window_ + " F12");
        if (!toyhost_->waitForLog(said, 20, before + 1)) {
            ADD_FAILURE() << "no screenshot after F12:\n" << toyhost_->log();
            return {};
        }
        const std::string now = toyhost_->log();
        const std::size_t end = now.rfind(": " + said);
        const std::size_t begin = now.rfind("toyhost: ", end) + 9;
        fs::path file = now.substr(begin, end - begin);
        if (file.is_relative()) file = dir_ / file;
        if (written) *written = file;
        Result<Image8> image = readPng(file);
        EXPECT_TRUE(image.ok()) << image.error().text();
        return image.ok() ? *image : Image8{};
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
    // What the X server shows in the window (the overlay included).
    Image8 grab() { return grabWindow(window_); }
    // Pixels whose RGB differ (alpha aside: the X server has none); -1 when the sizes differ.
    static long differingPixels(const Image8& a, const Image8& b) {
        if (a.width != b.width || a.height != b.height || a.rgba.empty()) return -1;
        long n = 0;
        for (std::size_t i = 0; i < a.rgba.size(); i += 4)
            if (a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1] || a.rgba[i + 2] != b.rgba[i + 2]) ++n;
        return n;
    }
    // The RGB at window pixel (x, y), top-left origin as xdotool counts.
    static std::array<int, 3> at(const Image8& image, int x, int y) {
        if (image.rgba.empty()) return {-1, -1, -1};
        const std::size_t i = (static_cast<std::size_t>(image.height - 1 - y) * image.width + x) * 4;
        return {image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]};
    }
    static bool near(const std::array<int, 3>& a, const std::array<int, 3>& b, int tolerance = 1) {
        for (int c = 0; c < 3; ++c)
            if (std::abs(a[c] - b[c]) > tolerance) return false;
        return true;
    }
    void edit(const fs::path& file, const std::string& from, const std::string& to) {
        std::ifstream in(file);
        std::string text((std::istreambuf_iterator<char>(in)), {});
        const std::size_t at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
        std::ofstream(file) << text;
    }

    fs::path dir_;
    std::optional<BackgroundProcess> toyhost_;
    std::string window_;
};

std::string fileBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
}

TEST_F(WindowMode, FramesArePixelIdenticalToHeadless) {
    for (const char* mode : {"--window", "--headless"}) {
        auto run = shell("'" + kToyhost.string() + "' run '" + (kSource / "shadertoys/uniform-probe").string() + "' " +
                         mode + " --size 96x48 --frames 4 --fps 30 --quiet --out '" + (dir_ / mode).string() +
                         "_%d.png' 2>&1");
        ASSERT_EQ(run.first, 0) << run.second;
        if (std::string(mode) == "--window") EXPECT_NE(run.second.find("in a window on GLFW window"), std::string::npos) << run.second;
    }
    for (int frame : {0, 3}) {
        const std::string windowBytes = fileBytes(dir_ / ("--window_" + std::to_string(frame) + ".png"));
        EXPECT_FALSE(windowBytes.empty());
        EXPECT_EQ(windowBytes, fileBytes(dir_ / ("--headless_" + std::to_string(frame) + ".png"))) << "frame " << frame;
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
            auto run = shell("'" + kToyhost.string() + "' run '" + (kSource / "shadertoys" / gallery).string() + "' " + mode +
                             " --size 96x54 --frames 3 --capture-every 2 --start-time 2 --fps 30 --quiet --out '" +
                             (dir_ / (std::string(gallery) + mode + "_%d.png")).string() + "' 2>&1");
            ASSERT_EQ(run.first, 0) << run.second;
            bytes[i++] = fileBytes(dir_ / (std::string(gallery) + mode + "_2.png"));
        }
        EXPECT_FALSE(bytes[0].empty());
        EXPECT_EQ(bytes[0], bytes[1]) << "window and headless frames differ";
    }
}

// ripple-pool with a real drag: the ripples are where the pointer went, and nowhere else.
TEST_F(WindowMode, RipplePoolDragLeavesRipplesWhereThePointerWent) {
    fs::copy(kSource / "shadertoys/ripple-pool", dir_ / "ripple-pool", fs::copy_options::recursive);
    // straight from above (TOP_VIEW): window pixel (x, y) is the water's cell (x, 100 - y)
    start({"--define", "TOP_VIEW"}, dir_ / "ripple-pool", "ripple-pool");
    waitFrames();
    const Image8 calm = screenshot();
    // Paused, every input paints exactly one frame (the site's rule), so the rings spread for a
    // known number of frames however fast or loaded the machine is.
    xdo("key --window " + window_ + " F6");
    ASSERT_TRUE(within(10, [&] { return title().find("paused") != std::string::npos; })) << title();
    const int before = shownFrame();
    // The frame counter is read before each input: read after it, the one frame that input paints
    // may already be shown, and waiting for one more would wait forever (paused).
    auto inputPaintsAFrame = [&](const std::string& input) {
        const int from = shownFrame();
        xdo(input);
        EXPECT_TRUE(within(30, [&] { return shownFrame() >= from + 1; }))
            << input << ": iFrame stayed at " << from << "\n" << title() << "\n" << toyhost_->log();
    };
    inputPaintsAFrame("mousemove --window " + window_ + " 30 70 mousedown 1");
    for (int x = 40; x <= 100; x += 10)
        inputPaintsAFrame("mousemove --window " + window_ + " " + std::to_string(x) + " 70");
    inputPaintsAFrame("mouseup 1");
    const int painted = shownFrame() - before;
    const Image8 dragged = screenshot();
    EXPECT_LE(painted, 12) << "paused, only input paints frames";
    ASSERT_EQ(calm.rgba.size(), dragged.rgba.size());
    // Window y 70 is canvas row 100 - 70 = 30 (origin bottom-left). The water must be disturbed
    // along the path, and much more there than in the far corner (x 170.., y 75..).
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
    waitFrames();
    Image8 before = screenshot();
    EXPECT_EQ(column(before, 0), (std::array<int, 4>{0, 0, 0, 255})) << "before any click";
    EXPECT_EQ(column(before, 1), (std::array<int, 4>{0, 0, 0, 255}));
    xdo("mousemove --window " + window_ + " 50 30 mousedown 1");
    waitFrames();
    xdo("mousemove --window " + window_ + " 80 40");
    waitFrames();
    Image8 held = screenshot();
    // xy = (80, floor(100 - 40)), z = +click x, w = -click y (not the click frame any more).
    EXPECT_EQ(column(held, 0), (std::array<int, 4>{80, 60, 50, 255}));
    EXPECT_EQ(column(held, 1), (std::array<int, 4>{70, 255, 0, 255})) << "|w| = 70, z > 0, w < 0";
    xdo("mouseup 1");
    xdo("mousemove --window " + window_ + " 150 90");
    waitFrames();
    Image8 released = screenshot();
    EXPECT_EQ(column(released, 0), (std::array<int, 4>{80, 60, 50, 255})) << "xy keeps the last dragged position";
    EXPECT_EQ(column(released, 1), (std::array<int, 4>{70, 0, 0, 255})) << "z and w negative after release";
}

TEST_F(WindowMode, KeysReachTheKeyboardTextureAndControlKeysDoNot) {
    start();
    xdo("keydown --window " + window_ + " a");
    waitFrames();
    Image8 held = screenshot();
    EXPECT_EQ(column(held, 2), (std::array<int, 4>{255, 0, 255, 255})) << "A held, went down earlier, toggled on";
    EXPECT_EQ(column(held, 3)[2], 0) << "Space not held";
    xdo("keyup --window " + window_ + " a");
    xdo("keydown --window " + window_ + " space");
    waitFrames();
    Image8 released = screenshot();
    EXPECT_EQ(column(released, 2), (std::array<int, 4>{0, 0, 255, 255})) << "A released, toggle stays";
    EXPECT_EQ(column(released, 3)[2], 255) << "Space held";
    xdo("keyup --window " + window_ + " space");
    xdo("key --window " + window_ + " F1");
    EXPECT_TRUE(toyhost_->waitForLog("F5 or Ctrl+R restart", 10)) << toyhost_->log();
    EXPECT_NE(toyhost_->log().find("F2 inspector"), std::string::npos) << toyhost_->log();
}

// Pause (F6) shows "paused" at once and renders nothing; restart (F5) while paused shows frame 0
// with cleared buffers, as the site does; step (F7) renders exactly one frame.
TEST_F(WindowMode, PauseRestartAndStepGiveFrameZeroWithClearedBuffers) {
    start();
    waitFrames();
    EXPECT_EQ(sinceClear(screenshot()), 1);
    xdo("key --window " + window_ + " F6");
    ASSERT_TRUE(within(10, [&] { return title().find("paused") != std::string::npos; })) << title();
    xdo("key --window " + window_ + " F5");
    ASSERT_TRUE(within(10, [&] { return shownFrame() == 0; })) << "restarted while paused: " << title();
    Image8 restarted = screenshot();
    EXPECT_EQ(column(restarted, 3)[0], 1) << "Buffer A counted one frame since the restart";
    EXPECT_EQ(column(restarted, 3)[1], 0) << "iFrame 0";
    xdo("key --window " + window_ + " F7");
    ASSERT_TRUE(within(10, [&] { return shownFrame() == 1; })) << title();
    Image8 stepped = screenshot();
    EXPECT_EQ(column(stepped, 3)[0], 2);
    EXPECT_EQ(column(stepped, 3)[1], 1);
    EXPECT_NE(title().find("paused"), std::string::npos) << title();
    xdo("key --window " + window_ + " F6");
    ASSERT_TRUE(within(10, [&] { return title().find("paused") == std::string::npos; })) << title();
    waitFrames();
}

// An edit while paused: the shown frame is painted again with the new code at once, at the same
// iFrame (the title's and the one the shader sees), and Buffer A takes one more step, as the
// site's compile repaints every pass (docs/window.md); an edit that does not compile changes
// nothing; F7 then steps on from there.
TEST_F(WindowMode, AnEditWhilePausedRepaintsTheShownFrameWithoutAdvancingIFrame) {
    start();
    waitFrames();
    xdo("key --window " + window_ + " F6");
    ASSERT_TRUE(within(10, [&] { return title().find("paused") != std::string::npos; })) << title();
    const int frame = shownFrame();
    const Image8 before = screenshot();
    ASSERT_EQ(column(before, 5), (std::array<int, 4>{10, 20, 30, 255}));
    ASSERT_EQ(sinceClear(before), 1);
    ASSERT_EQ(column(before, 3)[1], frame % 256) << "the title and the shader agree on iFrame";

    const fs::path image = dir_ / "probe/image.glsl";
    edit(image, "vec4(10, 20, 30, 255)", "vec4(40, 50, 60, 255)");
    ASSERT_TRUE(toyhost_->waitForLog("image.glsl changed: recompiled Image", 20)) << toyhost_->log();
    // The repaint comes with the reload, before the F12 that follows is handled.
    const Image8 repainted = screenshot();
    EXPECT_EQ(column(repainted, 5), (std::array<int, 4>{40, 50, 60, 255})) << "the new code's picture";
    EXPECT_EQ(column(repainted, 3)[1], column(before, 3)[1]) << "iFrame did not advance";
    EXPECT_EQ(sinceClear(repainted), 2) << "Buffer A took one more step, as on the site";
    EXPECT_EQ(shownFrame(), frame) << title();
    EXPECT_NE(title().find("paused"), std::string::npos) << title();
    // What the window shows (polled: the paused window presents the canvas a few times a second).
    EXPECT_TRUE(within(10, [&] { return near(at(grab(), 5, 99), {40, 50, 60}, 0); })) << "the window shows it";

    edit(image, "vec4(40, 50, 60, 255)", "vec4(40, 50, undefined_name, 255)");
    ASSERT_TRUE(toyhost_->waitForLog("undefined_name", 20)) << toyhost_->log();
    ASSERT_TRUE(within(10, [&] { return title().find("image.glsl:22:") != std::string::npos; })) << title();
    const Image8 failed = screenshot();
    EXPECT_EQ(differingPixels(failed, repainted), 0) << "a failed compile while paused changes nothing";
    EXPECT_EQ(column(failed, 3), column(repainted, 3));
    EXPECT_EQ(shownFrame(), frame) << title();

    xdo("key --window " + window_ + " F7");
    ASSERT_TRUE(within(10, [&] { return shownFrame() == frame + 1; })) << title();
    const Image8 stepped = screenshot();
    EXPECT_EQ(column(stepped, 3)[1], (frame + 1) % 256);
    EXPECT_EQ(sinceClear(stepped), 2) << "the extra step stays in the buffer";
}

TEST_F(WindowMode, TheCanvasFollowsTheWindowSize) {
    start();
    waitFrames();
    Image8 small = screenshot();
    EXPECT_EQ(small.width, 200);
    EXPECT_EQ(column(small, 4), (std::array<int, 4>{50, 25, 0, 255}));
    xdo("windowsize --sync " + window_ + " 240 120");
    ASSERT_TRUE(within(20, [&] { return column(screenshot(), 4) == std::array<int, 4>{60, 30, 0, 255}; }));
    Image8 large = screenshot();
    EXPECT_EQ(large.width, 240);
    EXPECT_EQ(large.height, 120);
    // counter = iFrame + 1 as long as nothing cleared the buffer, resize included.
    EXPECT_EQ(sinceClear(small), 1);
    EXPECT_EQ(sinceClear(large), 1) << "the buffer kept its content through the resize";
    xdo("key --window " + window_ + " F11");
    auto [code, screen] = shell("xdotool getdisplaygeometry");
    EXPECT_TRUE(within(20, [&] {
        const Image8 full = screenshot();
        return std::to_string(full.width) + " " + std::to_string(full.height) + "\n" == screen;
    })) << "F11: the whole screen";
    xdo("key --window " + window_ + " F11");
    EXPECT_TRUE(within(20, [&] { return screenshot().width == 240; })) << "F11 again: the window as it was";
}

// Hot reload with real files changing under the running window: an edit recompiles Image only
// (the buffer and iFrame go on); a compile error is shown with file:line while the last good
// program runs; undoing the mistake clears the error; a texture rewritten in place is uploaded
// again; a structure change keeps the buffers that still exist.
TEST_F(WindowMode, HotReloadAppliesEditsUndoImagesAndStructureAndKeepsTheBuffers) {
    start();
    waitFrames();
    const fs::path image = dir_ / "probe/image.glsl";
    EXPECT_EQ(column(screenshot(), 5), (std::array<int, 4>{10, 20, 30, 255}));
    edit(image, "vec4(10, 20, 30, 255)", "vec4(40, 50, 60, 255)");
    ASSERT_TRUE(toyhost_->waitForLog("image.glsl changed: recompiled Image", 20)) << toyhost_->log();
    waitFrames();
    const Image8 reloaded = screenshot();
    EXPECT_EQ(column(reloaded, 5), (std::array<int, 4>{40, 50, 60, 255}));
    EXPECT_EQ(sinceClear(reloaded), 1) << "Buffer A kept counting, iFrame went on (no restart)";

    // A mistake, then exactly the previous text again: the error goes away.
    edit(image, "vec4(40, 50, 60, 255)", "vec4(40, 50, undefined_name, 255)");
    ASSERT_TRUE(toyhost_->waitForLog("undefined_name", 20)) << toyhost_->log();
    EXPECT_NE(toyhost_->log().find(image.string() + ":22:"), std::string::npos) << toyhost_->log();
    ASSERT_TRUE(within(10, [&] { return title().find("image.glsl:22:") != std::string::npos; })) << title();
    waitFrames();
    EXPECT_EQ(column(screenshot(), 5), (std::array<int, 4>{40, 50, 60, 255})) << "the last good program runs on";
    edit(image, "vec4(40, 50, undefined_name, 255)", "vec4(40, 50, 60, 255)");
    ASSERT_TRUE(toyhost_->waitForLog("nothing to recompile", 20)) << toyhost_->log();
    EXPECT_TRUE(within(10, [&] { return title().find("error") == std::string::npos; })) << "undo clears: " << title();

    // The texture rewritten in place (same path, new pixels).
    EXPECT_EQ(column(screenshot(), 6), (std::array<int, 4>{100, 150, 200, 255}));
    const std::vector<std::uint8_t> pixel = {30, 60, 90, 255};
    ASSERT_TRUE(writePng(dir_ / "probe/probe.png", 1, 1, pixel).ok());
    ASSERT_TRUE(toyhost_->waitForLog("probe.png changed: new structure", 20)) << toyhost_->log();
    waitFrames();
    const Image8 retextured = screenshot();
    EXPECT_EQ(column(retextured, 6), (std::array<int, 4>{30, 60, 90, 255}));
    EXPECT_EQ(sinceClear(retextured), 1) << "a new texture keeps the buffers";

    // A structure change: the texture now read with linear filtering (a new channel setting).
    edit(dir_ / "probe/manifest.json", "\"filter\": \"nearest\"", "\"filter\": \"linear\"");
    ASSERT_TRUE(toyhost_->waitForLog("manifest.json changed: new structure", 20)) << toyhost_->log();
    waitFrames();
    EXPECT_EQ(sinceClear(screenshot()), 1) << "Buffer A kept its content through the new structure";
}

// Esc and the close button complete a recording and exit 0; Esc during a frame that draws for
// longer than the grace period ends the process within it, as a signal does; SIGTERM interrupts
// (143) and discards the video.
TEST_F(WindowMode, EscapeEndsTheRunEvenDuringALongFrameAndSigtermInterruptsIt) {
    start();
    waitFrames();
    closeWindow();
    EXPECT_EQ(toyhost_->wait(10), 0) << toyhost_->log();
    EXPECT_NE(toyhost_->log().find("in a window on"), std::string::npos) << toyhost_->log();

    start({"--out", (dir_ / "movie.mp4").string(), "--fps", "30"});
    waitFrames();
    toyhost_->signal(SIGTERM);
    EXPECT_EQ(toyhost_->wait(10), 143) << toyhost_->log();
    EXPECT_FALSE(fs::exists(dir_ / "movie.mp4")) << "an interrupted video is discarded";

    // A frame that takes far longer than the test (see tests/reliability: llvmpipe caps loops near
    // 65535 iterations, so the work is in the loop body).
    fs::create_directories(dir_ / "heavy");
    std::ofstream(dir_ / "heavy/manifest.json") << R"({"name": "heavy", "passes": {"Image": {"source": "image.glsl"}}})";
    std::string body;
    for (int k = 1; k <= 20; ++k) body += "        s += sin(x * " + std::to_string(k) + ".0 + s);\n";
    std::ofstream(dir_ / "heavy/image.glsl") << "void mainImage(out vec4 c, in vec2 f) {\n    float s = 0.0;\n"
                                                "    for (int i = 0; i < int(iResolution.x) * 400; i++) {\n"
                                                "        float x = float(i) * f.x;\n" + body + "    }\n    c = vec4(s);\n}\n";
    start({}, dir_ / "heavy", "heavy");
    const auto pressed = Clock::now();
    closeWindow();
    const int code = toyhost_->wait(20);
    const double seconds = std::chrono::duration<double>(Clock::now() - pressed).count();
    EXPECT_EQ(code, 130) << toyhost_->log();
    EXPECT_LT(seconds, 6.0) << "the grace period is 3 s";
    EXPECT_NE(toyhost_->log().find("did not stop within 3 s"), std::string::npos) << toyhost_->log();
}

TEST_F(WindowMode, FramesEndsTheRunAndTheRecordingIsComplete) {
    auto run = shell("'" + kToyhost.string() + "' run '" + (dir_ / "probe").string() +
                     "' --window --size 64x32 --frames 12 --fps 24 --quiet --out '" + (dir_ / "movie.mp4").string() +
                     "' 2>&1");
    ASSERT_EQ(run.first, 0) << run.second;
    auto probe = shell("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames,width,height "
                       "-of csv=p=0 '" + (dir_ / "movie.mp4").string() + "'");
    EXPECT_EQ(probe.second, "64,32,12\n");
    // Real time, without --fps: a video would play at the wrong speed, so it is refused.
    auto realTime = shell("'" + kToyhost.string() + "' run '" + (dir_ / "probe").string() +
                          "' --window --frames 3 --out '" + (dir_ / "real.mp4").string() + "' 2>&1");
    EXPECT_EQ(realTime.first, 2) << realTime.second;
    EXPECT_NE(realTime.second.find("needs --fps"), std::string::npos) << realTime.second;
}

// A shadertoy that does not compile when the window opens: the window shows the error in its
// title and waits; the fix starts it.
TEST_F(WindowMode, AShaderThatFailsAtStartOpensTheWindowAndWaitsForTheFix) {
    edit(dir_ / "probe/image.glsl", "vec4(10, 20, 30, 255)", "vec4(10, 20, broken_name, 255)");
    start();
    ASSERT_TRUE(within(20, [&] { return title().find("image.glsl:22:") != std::string::npos; })) << title() << toyhost_->log();
    EXPECT_TRUE(toyhost_->running());
    // The error is drawn on the canvas (grey until the shadertoy compiles): more than one colour.
    EXPECT_TRUE(within(20, [&] {
        const Image8 shown = grab();
        for (std::size_t i = 4; i < shown.rgba.size(); i += 4)
            if (!std::equal(&shown.rgba[i], &shown.rgba[i + 3], &shown.rgba[0])) return true;
        return false;
    })) << "the window is one colour: no error on the canvas";
    edit(dir_ / "probe/image.glsl", "vec4(10, 20, broken_name, 255)", "vec4(10, 20, 30, 255)");
    ASSERT_TRUE(within(20, [&] { return shownFrame() >= 2; })) << title() << toyhost_->log();
    EXPECT_EQ(column(screenshot(), 5), (std::array<int, 4>{10, 20, 30, 255}));
    EXPECT_EQ(title().find("error"), std::string::npos) << title();
    // Fixed: the window shows exactly the frame, nothing over it.
    xdo("key --window " + window_ + " F6");
    ASSERT_TRUE(within(10, [&] { return title().find("paused") != std::string::npos; })) << title();
    const Image8 shot = screenshot();
    EXPECT_TRUE(within(20, [&] { return differingPixels(grab(), shot) == 0; }))
        << differingPixels(grab(), shot) << " pixels differ from the F12 screenshot";
}

// Paused while waiting for a shadertoy that compiles: the fix paints frame 0 at once, as the
// site's first good compile starts its render loop, and the window stays paused.
TEST_F(WindowMode, AFixWhilePausedBeforeTheFirstFrameShowsFrameZero) {
    edit(dir_ / "probe/image.glsl", "vec4(10, 20, 30, 255)", "vec4(10, 20, broken_name, 255)");
    start();
    ASSERT_TRUE(within(20, [&] { return title().find("image.glsl:22:") != std::string::npos; })) << title() << toyhost_->log();
    xdo("key --window " + window_ + " F6");
    ASSERT_TRUE(within(10, [&] { return title().find("paused") != std::string::npos; })) << title();
    edit(dir_ / "probe/image.glsl", "vec4(10, 20, broken_name, 255)", "vec4(10, 20, 30, 255)");
    ASSERT_TRUE(within(20, [&] { return shownFrame() == 0; })) << title() << toyhost_->log();
    const Image8 first = screenshot();
    EXPECT_EQ(column(first, 5), (std::array<int, 4>{10, 20, 30, 255}));
    EXPECT_EQ(column(first, 3)[0], 1) << "Buffer A ran once";
    EXPECT_EQ(column(first, 3)[1], 0) << "iFrame 0";
    EXPECT_EQ(shownFrame(), 0) << "still paused: " << title();
    EXPECT_NE(title().find("paused"), std::string::npos) << title();
}

// A compile error while running is drawn over the canvas (the text stderr shows) for as long as it
// lasts; the F12 screenshot and the frames captured meanwhile hold none of it: they equal a
// headless run's byte for byte.
TEST_F(WindowMode, ErrorsAreDrawnOverTheCanvasButNeverCaptured) {
    fs::create_directories(dir_ / "frames");
    start({"--out", (dir_ / "frames/f_%d.png").string(), "--fps", "30"});
    waitFrames();
    xdo("key --window " + window_ + " F6");
    ASSERT_TRUE(within(10, [&] { return title().find("paused") != std::string::npos; })) << title();
    const Image8 clean = screenshot();
    ASSERT_TRUE(within(20, [&] { return differingPixels(grab(), clean) == 0; }))
        << "paused, the window shows exactly the F12 screenshot: " << differingPixels(grab(), clean) << " pixels differ";

    const fs::path image = dir_ / "probe/image.glsl";
    edit(image, "vec4(10, 20, 30, 255)", "vec4(10, 20, undefined_name, 255)");
    ASSERT_TRUE(toyhost_->waitForLog("undefined_name", 20)) << toyhost_->log();
    // A line of text at least: a few hundred pixels.
    ASSERT_TRUE(within(20, [&] { return differingPixels(grab(), clean) > 200; }))
        << differingPixels(grab(), clean) << " pixels differ\n" << toyhost_->log();
    const Image8 withError = grab();  // kept next to the log, to be looked at
    EXPECT_TRUE(writePng(dir_ / "grab-with-error.png", withError.width, withError.height, withError.rgba).ok());
    EXPECT_EQ(screenshot().rgba, clean.rgba) << "the F12 screenshot holds overlay pixels";
    // Two frames rendered and captured while the error is shown.
    for (int step = 1; step <= 2; ++step) {
        const int from = shownFrame();
        xdo("key --window " + window_ + " F7");
        ASSERT_TRUE(within(20, [&] { return shownFrame() == from + 1; })) << title();
    }
    const Image8 stepped = screenshot();
    EXPECT_GT(differingPixels(grab(), stepped), 200) << "the error is still shown";

    edit(image, "vec4(10, 20, undefined_name, 255)", "vec4(10, 20, 30, 255)");
    ASSERT_TRUE(toyhost_->waitForLog("nothing to recompile", 20)) << toyhost_->log();
    EXPECT_TRUE(within(20, [&] { return differingPixels(grab(), stepped) == 0; }))
        << "fixed, the overlay is gone: " << differingPixels(grab(), stepped) << " pixels differ";
    closeWindow();
    ASSERT_EQ(toyhost_->wait(20), 0) << toyhost_->log();

    int frames = 0;
    while (fs::exists(dir_ / ("frames/f_" + std::to_string(frames) + ".png"))) ++frames;
    ASSERT_GE(frames, 4) << "frames before the pause and the two steps";
    auto run = shell("'" + kToyhost.string() + "' run '" + (dir_ / "probe").string() + "' --headless --size 200x100 --frames " +
                     std::to_string(frames) + " --fps 30 --quiet --out '" + (dir_ / "frames/h_%d.png").string() + "' 2>&1");
    ASSERT_EQ(run.first, 0) << run.second;
    for (int frame = 0; frame < frames; ++frame) {
        const std::string windowBytes = fileBytes(dir_ / ("frames/f_" + std::to_string(frame) + ".png"));
        EXPECT_FALSE(windowBytes.empty());
        EXPECT_EQ(windowBytes, fileBytes(dir_ / ("frames/h_" + std::to_string(frame) + ".png"))) << "frame " << frame;
    }
}

// F2: the inspector. A click on Buffer A's thumbnail shows the buffer full-canvas (values drawn
// as they are, NaN in magenta); a click on a texel prints the floats the buffer holds there,
// read back from its float target. Nothing of it reaches the F12 screenshot.
TEST_F(WindowMode, TheInspectorShowsABufferAndTheFloatsUnderTheCursor) {
    fs::create_directories(dir_ / "values");
    std::ofstream(dir_ / "values/manifest.json")
        << R"({"name": "values", "passes": {"Buffer A": {"source": "buffer_a.glsl"},)"
        << R"( "Image": {"source": "image.glsl"}}})";
    // Known floats, outside 0..1 too; NaN in the 20 columns on the left.
    std::ofstream(dir_ / "values/buffer_a.glsl")
        << "void mainImage(out vec4 c, in vec2 f) {\n"
           "    c = vec4(f.x / 100.0, f.y / 1000.0, 0.25, -2.0);\n"
           "    if (f.x < 20.0) c.g = sqrt(-1.0 - f.y);\n}\n";
    std::ofstream(dir_ / "values/image.glsl") << "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.0, 0.5, 0.0, 1.0); }\n";
    start({}, dir_ / "values", "values", "480x360");
    waitFrames();
    const std::array<int, 3> green = {0, 128, 0};
    EXPECT_TRUE(near(at(grab(), 440, 330), green)) << "the Image";

    xdo("key --window " + window_ + " F2");
    ASSERT_TRUE(toyhost_->waitForLog("inspector shown", 20)) << toyhost_->log();
    waitFrames();
    // The thumbnails are the panel's first row at the window's top-left corner: Buffer A first.
    xdo("mousemove --window " + window_ + " 30 30 click 1");
    ASSERT_TRUE(toyhost_->waitForLog("Buffer A full-canvas", 20)) << toyhost_->log();
    // (440, 330) is texel (440, 29): r = 4.405 (255 on screen), g = 0.0295, b = 0.25.
    EXPECT_TRUE(within(20, [&] { return near(at(grab(), 440, 330), {255, 8, 64}); })) << [&] {
        const auto p = at(grab(), 440, 330);
        return std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]);
    }();
    const Image8 inspected = grab();  // kept next to the log, to be looked at
    EXPECT_TRUE(writePng(dir_ / "grab-inspector.png", inspected.width, inspected.height, inspected.rgba).ok());
    EXPECT_EQ(at(inspected, 5, 300), (std::array<int, 3>{255, 0, 255})) << "NaN is drawn magenta";
    const Image8 shot = screenshot();
    EXPECT_EQ(shot.width, 480);
    bool allGreen = !shot.rgba.empty();
    for (std::size_t i = 0; i < shot.rgba.size(); i += 4)
        allGreen = allGreen && near({shot.rgba[i], shot.rgba[i + 1], shot.rgba[i + 2]}, green);
    EXPECT_TRUE(allGreen) << "the F12 screenshot is the Image alone (green everywhere)";

    xdo("mousemove --window " + window_ + " 440 330 click 1");
    ASSERT_TRUE(toyhost_->waitForLog("Buffer A texel (440, 29) = (", 20)) << toyhost_->log();
    std::smatch m;
    const std::string log = toyhost_->log();
    ASSERT_TRUE(std::regex_search(log, m, std::regex(R"(Buffer A texel \(440, 29\) = \(([^,]+), ([^,]+), ([^,]+), ([^)]+)\))")))
        << log;
    EXPECT_NEAR(std::stof(m[1]), 440.5f / 100.0f, 1e-5f);
    EXPECT_NEAR(std::stof(m[2]), 29.5f / 1000.0f, 1e-7f);
    EXPECT_EQ(std::stof(m[3]), 0.25f);
    EXPECT_EQ(std::stof(m[4]), -2.0f);

    xdo("key --window " + window_ + " F2");
    ASSERT_TRUE(toyhost_->waitForLog("inspector hidden", 20)) << toyhost_->log();
    EXPECT_TRUE(within(20, [&] { return near(at(grab(), 440, 330), green); })) << "the canvas as usual";
}

// The title's frame rate is the measured one (frames over real time), not a value that starts at
// 60 and creeps: a shader that renders a few frames a second shows a few frames a second.
TEST_F(WindowMode, TheTitleShowsTheMeasuredFrameRate) {
    fs::create_directories(dir_ / "slow");
    std::ofstream(dir_ / "slow/manifest.json") << R"({"name": "slow", "passes": {"Image": {"source": "image.glsl"}}})";
    std::ofstream(dir_ / "slow/image.glsl") << "void mainImage(out vec4 c, in vec2 f) {\n  float s = 0.0;\n"
                                               "  for (int i = 0; i < 6000; i++) s += sin(s + f.x * float(i));\n"
                                               "  c = vec4(s);\n}\n";
    start({}, dir_ / "slow", "slow");
    auto fps = [&]() -> double {
        std::smatch m;
        const std::string t = title();
        return std::regex_search(t, m, std::regex("\\| ([0-9.]+) fps")) ? std::stod(m[1]) : -1.0;
    };
    ASSERT_TRUE(within(30, [&] { return fps() >= 0 && shownFrame() >= 2; })) << title();
    const int first = shownFrame();
    const auto from = Clock::now();
    ASSERT_TRUE(within(60, [&] { return shownFrame() >= first + 6; })) << title();
    const double measured = (shownFrame() - first) / std::chrono::duration<double>(Clock::now() - from).count();
    const double shown = fps();
    std::printf("title %.1f fps, measured from iFrame %.1f fps\n", shown, measured);
    EXPECT_LT(measured, 40) << "the slow shader is not slow here: the test cannot tell";
    // The two rates cover different seconds and the machine's load changes between them, so the
    // bounds are wide; a title that starts at 60 and creeps is far outside them.
    EXPECT_LE(shown, 3.0 * measured + 2.0) << title();
    EXPECT_GE(shown, measured / 3.0 - 1.0) << title();
}

// F12 writes NAME-YYYYMMDD-HHMMSS-frameN.png in the working directory (or --out's folder); two
// screenshots of the same frame get two files.
TEST_F(WindowMode, ScreenshotsGetUniqueNamesWhereTheUserIs) {
    start();
    waitFrames();
    xdo("key --window " + window_ + " F6");
    ASSERT_TRUE(within(10, [&] { return title().find("paused") != std::string::npos; })) << title();
    fs::path first, second;
    screenshot(&first);
    screenshot(&second);
    EXPECT_NE(first, second);
    for (const fs::path& file : {first, second}) {
        EXPECT_EQ(fs::canonical(file.parent_path()), fs::canonical(dir_)) << file;
        EXPECT_TRUE(std::regex_match(file.filename().string(),
                                     std::regex("window-probe-\\d{8}-\\d{6}-frame\\d+(-2)?\\.png")))
            << file;
    }
    closeWindow();
    EXPECT_EQ(toyhost_->wait(10), 0) << toyhost_->log();

    fs::create_directories(dir_ / "shots");
    start({"--out", (dir_ / "shots/f_%04d.png").string()});
    waitFrames();
    fs::path third;
    screenshot(&third);
    EXPECT_EQ(fs::canonical(third.parent_path()), fs::canonical(dir_ / "shots")) << third;
}

// Issue 27: while Esc's grace period runs (here: a frame that takes far longer than the test) the
// title says "stopping", and a second Esc ends the run at once instead of after the grace period.
TEST_F(WindowMode, TheTitleSaysStoppingAndASecondEscapeEndsAtOnce) {
    fs::create_directories(dir_ / "heavy");
    std::ofstream(dir_ / "heavy/manifest.json") << R"({"name": "heavy", "passes": {"Image": {"source": "image.glsl"}}})";
    std::string body;
    for (int k = 1; k <= 20; ++k) body += "        s += sin(x * " + std::to_string(k) + ".0 + s);\n";
    std::ofstream(dir_ / "heavy/image.glsl") << "void mainImage(out vec4 c, in vec2 f) {\n    float s = 0.0;\n"
                                                "    for (int i = 0; i < int(iResolution.x) * 400; i++) {\n"
                                                "        float x = float(i) * f.x;\n" + body + "    }\n    c = vec4(s);\n}\n";
    start({}, dir_ / "heavy", "heavy");
    closeWindow();
    ASSERT_TRUE(within(10, [&] { return title().find("stopping (Esc again: at once)") != std::string::npos; }))
        << title() << "\n" << toyhost_->log();
    closeWindow();
    EXPECT_EQ(toyhost_->wait(20), 130) << toyhost_->log();
    EXPECT_NE(toyhost_->log().find("closed again while stopping: stopped at once"), std::string::npos) << toyhost_->log();
    EXPECT_EQ(toyhost_->log().find("did not stop within"), std::string::npos) << toyhost_->log();
}

// Issue 27: with --fps F a window draws F frames per second of wall time (a preview of the
// recording's timing; iTime ran 21 s in 3 s before). Only a lower bound: a loaded machine is
// slower, never faster. --unpaced draws them as fast as it can.
TEST_F(WindowMode, FpsPacesTheWindowAtFFramesPerSecond) {
    const auto from = Clock::now();
    auto paced = shell("'" + kToyhost.string() + "' run '" + (dir_ / "probe").string() +
                       "' --window --size 64x32 --frames 11 --fps 5 --quiet 2>&1");
    const double seconds = std::chrono::duration<double>(Clock::now() - from).count();
    ASSERT_EQ(paced.first, 0) << paced.second;
    EXPECT_GE(seconds, 10 / 5.0) << "11 frames at --fps 5 took " << seconds << " s";
    auto unpaced = shell("'" + kToyhost.string() + "' run '" + (dir_ / "probe").string() +
                         "' --window --size 64x32 --frames 11 --fps 5 --unpaced --quiet 2>&1");
    EXPECT_EQ(unpaced.first, 0) << unpaced.second;
    auto alone = shell("'" + kToyhost.string() + "' run '" + (dir_ / "probe").string() + "' --window --unpaced 2>&1");
    EXPECT_EQ(alone.first, 2) << alone.second;
    EXPECT_NE(alone.second.find("--unpaced goes with --fps"), std::string::npos) << alone.second;
}

}  // namespace
}  // namespace toyhost::testing
