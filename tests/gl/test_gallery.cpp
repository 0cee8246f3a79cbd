// The gallery (shadertoys/<name>/, our own water shaders): golden frames of each at 320x180 at
// fixed times, with the mouse for every port that reads it, scripted keys, and every #define
// variant (GalleryRender.h's cases, Golden.h's tolerance),
// and the checks on numbers that say the physics is what the README claims: ripple-pool's
// simulation (symmetry, steady ring speed, damping) and lake-optics' presets (float dumps).
#include "GalleryRender.h"
#include "GlTestSupport.h"
#include "Golden.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "core/AtomicFile.h"
#include "image/ImageWriters.h"
#include "input/InputScript.h"
#include "input/InputScriptPlayer.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

class GalleryGolden : public ::testing::TestWithParam<GalleryCase> {};

TEST_P(GalleryGolden, MatchesCheckedInFrame) {
    const GalleryCase& c = GetParam();
    const fs::path dir = freshOutputDir(std::string("golden/gallery/") + c.name);
    const auto frame = renderGalleryCase(c, dir);
    ASSERT_TRUE(frame);
    expectMatchesGolden(sourceDir(), std::string("gallery/") + c.name + ".png", *frame);
}

INSTANTIATE_TEST_SUITE_P(Shaders, GalleryGolden, ::testing::ValuesIn(galleryCases()),
                         [](const auto& info) { return std::string(info.param.name); });

// ---------------------------------------------------------------------------------------------
// ripple-pool: the height field (.x of Buffer D, the state at the end of a frame) after one
// click, as numbers

class RipplePool : public GlTest {};

// ripple-pool as loadSession starts it, with `defines` (--define) in every pass.
std::unique_ptr<SessionCore> loadPool(const std::shared_ptr<GlContext>& context, int width, int height,
                                      std::vector<std::string> defines) {
    return loadSession(context, sourceDir() / "shadertoys/ripple-pool", width, height, false, std::move(defines));
}

// Straight from above (TOP_VIEW), where pixel p is grid cell p / scale: the tests of the
// simulation click pixels and read those cells.
std::unique_ptr<SessionCore> loadTopView(const std::shared_ptr<GlContext>& context, int width, int height) {
    return loadPool(context, width, height, {"TOP_VIEW"});
}

constexpr int kWidth = 320, kHeight = 180;
constexpr int kDropX = 160, kDropY = 90;  // pixel; the drop is centred on its centre

float height(const std::vector<float>& rgba, int x, int y) {
    return rgba[(static_cast<std::size_t>(y) * kWidth + x) * 4];
}

TEST_F(RipplePool, OneDropSpreadsSymmetricallyAtSteadySpeedAndDecays) {
    auto toy = loadTopView(context_, kWidth, kHeight);
    ASSERT_TRUE(toy);
    stepAt(*toy);
    stepAt(*toy);
    const InputEvent click[] = {InputEvent::mouseDown(kDropX + 0.25f, kDropY + 0.75f), InputEvent::mouseUp()};
    stepAt(*toy, click);  // frame 2: the drop lands

    std::vector<float> field;
    std::vector<int> radii;
    std::vector<float> peaks;
    for (int after = 1; after <= 40; ++after) {
        stepAt(*toy);
        if (after % 10) continue;
        playerOf(*toy).readRgba32f(PassId::BufferD, field);
        // Four-fold symmetry about the drop's pixel centre (and the diagonal), out to the ring
        // and beyond, until reflections from the walls (70+ px away) could arrive.
        float peak = 0.0f;
        int radius = 0;
        for (int r = 0; r <= 60; ++r) {
            const float east = height(field, kDropX + r, kDropY);
            const float tolerance = 1e-5f;
            EXPECT_NEAR(height(field, kDropX - r, kDropY), east, tolerance) << "west, r " << r << ", " << after << " frames after";
            EXPECT_NEAR(height(field, kDropX, kDropY + r), east, tolerance) << "north, r " << r << ", " << after << " frames after";
            EXPECT_NEAR(height(field, kDropX, kDropY - r), east, tolerance) << "south, r " << r << ", " << after << " frames after";
            if (r <= 40)
                EXPECT_NEAR(height(field, kDropX + r / 2, kDropY + r), height(field, kDropX + r, kDropY + r / 2), tolerance)
                    << "diagonal mirror, r " << r;
            if (std::abs(east) > peak) {
                peak = std::abs(east);
                radius = r;
            }
        }
        radii.push_back(radius);
        peaks.push_back(peak);
        std::printf("%d frames after the drop: ring at %d px, peak %.6f\n", after, radius, peak);
    }
    ASSERT_EQ(radii.size(), 4u);
    // The ring moves out at a steady speed (the wave speed, about 0.7 px a frame): each 10 frames
    // add the same distance within a pixel.
    for (std::size_t i = 1; i < radii.size(); ++i) {
        const int step = radii[i] - radii[i - 1];
        EXPECT_GE(step, 5) << "frames " << 10 * i << " -> " << 10 * (i + 1);
        EXPECT_LE(step, 9) << "frames " << 10 * i << " -> " << 10 * (i + 1);
        EXPECT_LE(std::abs(step - (radii[1] - radii[0])), 1) << "the ring's speed changes";
        // Damping (and spreading): the peak height falls every 10 frames.
        EXPECT_LT(peaks[i], peaks[i - 1]) << "frames " << 10 * i << " -> " << 10 * (i + 1);
    }
}

// shadertoys/ripple-pool/drag.json, the script of the golden frames, as a user runs it: the
// height field is disturbed along the drag and still flat far from it.
TEST_F(RipplePool, ScriptedDragDisturbsTheWaterAlongItsPathOnly) {
    auto toy = loadTopView(context_, kWidth, kHeight);
    ASSERT_TRUE(toy);
    auto text = readTextFile(sourceDir() / "shadertoys/ripple-pool/drag.json");
    ASSERT_TRUE(text.ok());
    auto script = parseMouseScript(*text, "drag.json");
    ASSERT_TRUE(script.ok()) << script.error().text();
    MouseScriptPlayer mouse(*script);
    std::vector<InputEvent> events;
    for (int frame = 0; frame <= 45; ++frame) {  // the drag ends on frame 43
        events.clear();
        mouse.eventsBeforeFrame(frame, frame / 60.0, events);
        stepAt(*toy, events);
    }
    std::vector<float> field;
    playerOf(*toy).readRgba32f(PassId::BufferD, field);
    // Points of the drag: the start (60, 70), the turn (150, 100), the end (260, 40).
    for (auto [x, y] : {std::pair{60, 70}, {105, 85}, {150, 100}, {205, 70}, {260, 40}}) {
        float largest = 0.0f;
        for (int dy = -6; dy <= 6; ++dy)
            for (int dx = -6; dx <= 6; ++dx) largest = std::max(largest, std::abs(height(field, x + dx, y + dy)));
        EXPECT_GT(largest, 0.05f) << "no ripple near (" << x << ", " << y << ")";
    }
    // More than 45 frames * 0.7 px + the drop radius away from every point of the path: flat.
    for (auto [x, y] : {std::pair{300, 160}, {20, 160}, {60, 5}, {150, 10}, {310, 120}})
        EXPECT_EQ(height(field, x, y), 0.0f) << "ripple far from the drag at (" << x << ", " << y << ")";
}

// The grid is 180 rows on any canvas at least that tall: the same click (the same place in the
// picture) on a 320x180 and a 640x360 canvas gives the same height field, cell for cell, so drop
// size and ring speed are fractions of the picture, not pixels.
TEST_F(RipplePool, TheSameClickOnADoubleSizeCanvasGivesTheSameField) {
    std::vector<float> fields[2];
    for (int scale : {1, 2}) {
        auto toy = loadTopView(context_, kWidth * scale, kHeight * scale);
        ASSERT_TRUE(toy);
        stepAt(*toy);
        const InputEvent click[] = {InputEvent::mouseDown((kDropX + 0.25f) * scale, (kDropY + 0.75f) * scale),
                                    InputEvent::mouseUp()};
        stepAt(*toy, click);
        for (int i = 0; i < 20; ++i) stepAt(*toy);
        std::vector<float> field;
        playerOf(*toy).readRgba32f(PassId::BufferD, field);
        // the grid's cells: the lower-left 320x180 of the buffer
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x)
                fields[scale - 1].push_back(field[(static_cast<std::size_t>(y) * kWidth * scale + x) * 4]);
    }
    float largest = 0.0f;
    for (float h : fields[0]) largest = std::max(largest, std::abs(h));
    EXPECT_GT(largest, 0.05f) << "no ripple";
    EXPECT_EQ(fields[0], fields[1]) << "the double-size canvas simulates a different field";
}

// The ring's radius (the cell of the largest |h| east of the drop, out to 70 cells) in a field.
int ringRadius(const std::vector<float>& field) {
    int radius = 0;
    float peak = 0.0f;
    for (int r = 0; r <= 70; ++r)
        if (std::abs(height(field, kDropX + r, kDropY)) > peak) {
            peak = std::abs(height(field, kDropX + r, kDropY));
            radius = r;
        }
    return radius;
}

// Fixed step: the simulation takes 60 steps per second of iTime at any frame rate, so the same
// click seen at the same iTime has spread as far at 15, 30 and 60 fps (one step per frame, as
// before, would give rings 4x and 2x smaller at 15 and 30 fps).
TEST_F(RipplePool, RingsSpreadByTimeNotByFrames) {
    std::vector<int> radii;
    for (double fps : {60.0, 30.0, 15.0}) {
        auto toy = loadTopView(context_, kWidth, kHeight);
        ASSERT_TRUE(toy);
        const int perTick = int(60.0 / fps);  // frames per 1/15 s: 4, 2, 1
        for (int i = 0; i < 4 / perTick; ++i) stepAt(*toy, {}, fps);
        const InputEvent click[] = {InputEvent::mouseDown(kDropX + 0.25f, kDropY + 0.75f), InputEvent::mouseUp()};
        stepAt(*toy, click, fps);  // iTime 1/15 s (4 steps)
        for (int i = 0; i < int(fps * 0.5); ++i) stepAt(*toy, {}, fps);  // 0.5 s later (30 steps)
        std::vector<float> field;
        playerOf(*toy).readRgba32f(PassId::BufferD, field);
        radii.push_back(ringRadius(field));
        std::printf("%.0f fps: iFrame %d, ring at %d cells 0.5 s after the drop\n", fps, int(playerOf(*toy).frame()),
                    radii.back());
    }
    ASSERT_EQ(radii.size(), 3u);
    EXPECT_GE(radii[0], 15) << "the ring has not spread (about 0.67 cells a step, 30 steps)";
    // The drop lands at the start of its frame: at 15 fps up to 3 steps (2 cells) earlier than at 60.
    EXPECT_LE(std::abs(radii[1] - radii[0]), 2) << "30 fps spreads differently from 60 fps";
    EXPECT_LE(std::abs(radii[2] - radii[0]), 3) << "15 fps spreads differently from 60 fps";
}

TEST_F(RipplePool, CalmPoolStaysFlatWithoutInput) {
    auto toy = loadPool(context_, 64, 36, {});  // either view: no input, no motion
    ASSERT_TRUE(toy);
    for (int i = 0; i < 30; ++i) stepAt(*toy);
    std::vector<float> field;
    playerOf(*toy).readRgba32f(PassId::BufferD, field);
    for (std::size_t i = 0; i < field.size(); i += 4) ASSERT_EQ(field[i], 0.0f) << "pixel " << i / 4;
}

// ---------------------------------------------------------------------------------------------
// ripple-pool's default 3-D view at 320x180: the camera as its README and common.glsl describe it,
// written again here (not taken from the shader): grid 320x180 cells, world units = cells, water
// y = 0 over x in [0, 320], z in [0, 180], walls rising 30 above it; the eye at (160, 1.64, -1.22)
// * 180 looking 0.733 rad down (+z), focal length 1.8 canvas heights; a sphere of radius 45 resting
// on the floor (y = -0.36 * 180) at x = 0.62 * 320, z = 0.56 * 180.
struct PoolCamera {
    double eye[3] = {160.0, 1.64 * 180.0, -1.22 * 180.0};
    double pitch = 0.733, focal = 1.8;
    // the unit view ray through canvas point (px, py)
    std::array<double, 3> ray(double px, double py) const {
        const double ux = (px - 160.0) / 180.0, uy = (py - 90.0) / 180.0;
        std::array<double, 3> d = {ux, -std::sin(pitch) * focal + uy * std::cos(pitch),
                                   std::cos(pitch) * focal + uy * std::sin(pitch)};
        const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (double& c : d) c /= n;
        return d;
    }
    // the water point (x, z) seen at (px, py), ignoring walls and sphere
    std::pair<double, double> water(double px, double py) const {
        const auto d = ray(px, py);
        const double t = -eye[1] / d[1];
        return {eye[0] + d[0] * t, eye[2] + d[2] * t};
    }
    // canvas point of world point p
    std::pair<double, double> project(const std::array<double, 3>& p) const {
        const double v[3] = {p[0] - eye[0], p[1] - eye[1], p[2] - eye[2]};
        const double depth = -v[1] * std::sin(pitch) + v[2] * std::cos(pitch);
        const double up = v[1] * std::cos(pitch) + v[2] * std::sin(pitch);
        return {160.0 + v[0] * focal / depth * 180.0, 90.0 + up * focal / depth * 180.0};
    }
};

// A click in the 3-D view drops where the picture shows the water under the pointer: the drop's
// peak is in the cell the camera ray meets, and 30 frames later the ring around it has the same
// radius east, west, north and south of that cell (it is centred there). A click on the deck drops
// nothing.
TEST_F(RipplePool, ThreeDViewClickRaisesARingAroundTheClickedWater) {
    const PoolCamera camera;
    const float px = 110.25f, py = 70.75f;
    const auto [wx, wz] = camera.water(px, py);
    const int cx = int(std::floor(wx)), cz = int(std::floor(wz));
    std::printf("click (%.2f, %.2f) -> water (%.2f, %.2f), cell (%d, %d)\n", px, py, wx, wz, cx, cz);
    ASSERT_TRUE(cx > 30 && cx < kWidth - 30 && cz > 30 && cz < kHeight - 30) << "choose a click inside the pool";

    auto toy = loadPool(context_, kWidth, kHeight, {});
    ASSERT_TRUE(toy);
    stepAt(*toy);
    const InputEvent click[] = {InputEvent::mouseDown(px, py), InputEvent::mouseUp()};
    stepAt(*toy, click);
    std::vector<float> field;
    playerOf(*toy).readRgba32f(PassId::BufferD, field);
    int peakX = -1, peakZ = -1;
    float peak = 0.0f;
    for (int z = 0; z < kHeight; ++z)
        for (int x = 0; x < kWidth; ++x)
            if (height(field, x, z) > peak) {
                peak = height(field, x, z);
                peakX = x;
                peakZ = z;
            }
    std::printf("drop's peak %.3f at cell (%d, %d)\n", peak, peakX, peakZ);
    EXPECT_GT(peak, 0.5f);
    EXPECT_LE(std::abs(peakX - cx), 1) << "the drop is not under the pointer";
    EXPECT_LE(std::abs(peakZ - cz), 1) << "the drop is not under the pointer";

    for (int i = 0; i < 30; ++i) stepAt(*toy);
    playerOf(*toy).readRgba32f(PassId::BufferD, field);
    auto ring = [&](int dx, int dz) {
        int radius = 0;
        float top = 0.0f;
        for (int r = 0; r <= 28; ++r)
            if (std::abs(height(field, cx + dx * r, cz + dz * r)) > top) {
                top = std::abs(height(field, cx + dx * r, cz + dz * r));
                radius = r;
            }
        return radius;
    };
    const int east = ring(1, 0), west = ring(-1, 0), north = ring(0, 1), south = ring(0, -1);
    std::printf("ring radius 30 frames later: east %d, west %d, north %d, south %d cells\n", east, west, north, south);
    EXPECT_GE(east, 15) << "no ring has spread";
    for (int r : {west, north, south}) EXPECT_LE(std::abs(r - east), 1) << "the ring is not centred on the clicked water";

    // the near deck, below the pool's near rim in the picture: nothing drops
    auto deck = loadPool(context_, kWidth, kHeight, {});
    ASSERT_TRUE(deck);
    stepAt(*deck);
    const InputEvent offWater[] = {InputEvent::mouseDown(160.25f, 8.75f), InputEvent::mouseUp()};
    stepAt(*deck, offWater);
    for (int i = 0; i < 5; ++i) stepAt(*deck);
    playerOf(*deck).readRgba32f(PassId::BufferD, field);
    for (int z = 0; z < kHeight; ++z)
        for (int x = 0; x < kWidth; ++x) ASSERT_EQ(height(field, x, z), 0.0f) << "a click on the deck dropped at " << x << ", " << z;
}

// The 3-D view shows the sphere: the calm pool with and without it (--define NO_SPHERE) differs in
// the disc where the sphere projects and in a compact region around it (its shadow on the floor,
// darker, and its reflection), nowhere far from it.
TEST(RipplePoolView, ThreeDViewShowsTheSphere) {
    std::optional<Image8> frames[2];
    for (int i = 0; i < 2; ++i) {
        const fs::path dir = freshOutputDir(std::string("gallery/ripple-pool-sphere-") + (i ? "none" : "shown"));
        auto run = runToyhost("run " + shellQuoted(sourceDir() / "shadertoys/ripple-pool") + (i ? " --define NO_SPHERE" : "") +
                              " --size 320x180 --frames 1 --quiet --out " + shellQuoted(dir / "f.png"));
        ASSERT_EQ(run.exitCode, 0) << run.output;
        auto image = loadImageFile(dir / "f.png");
        ASSERT_TRUE(image.ok()) << image.error().text();
        frames[i] = std::move(*image);
    }
    const PoolCamera camera;
    const auto [sx, sy] = camera.project({0.62 * 320.0, -0.36 * 180.0 + 45.0, 0.56 * 180.0});
    const double dist = std::hypot(0.62 * 320.0 - camera.eye[0], -0.36 * 180.0 + 45.0 - camera.eye[1],
                                   0.56 * 180.0 - camera.eye[2]);
    const double radius = 45.0 * camera.focal * 180.0 / dist;  // the sphere's radius in pixels, about
    // Changed pixels (any channel by more than 12 levels); inside the sphere's disc, and beyond it
    // (its shadow and its reflection), where the sphere's frame is darker or brighter.
    std::size_t changed = 0, disc = 0, discChanged = 0, near = 0, outsideDarker = 0, outsideBrighter = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t at = (static_cast<std::size_t>(y) * kWidth + x) * 4;
            int largest = 0, sum = 0;
            for (int c = 0; c < 3; ++c) {
                const int d = frames[0]->rgba[at + c] - frames[1]->rgba[at + c];
                largest = std::max(largest, std::abs(d));
                sum += d;
            }
            const double r = std::hypot(x + 0.5 - sx, y + 0.5 - sy);
            if (r <= 0.8 * radius) ++disc;
            if (largest <= 12) continue;
            ++changed;
            if (r <= 0.8 * radius) ++discChanged;
            if (r <= 2.0 * radius) ++near;
            if (r > 1.1 * radius) (sum < 0 ? outsideDarker : outsideBrighter)++;
        }
    const double share = double(changed) / (kWidth * kHeight);
    std::printf("sphere projects to (%.1f, %.1f), radius %.1f px; %.1f%% of pixels change, %.1f%% of the disc, "
                "%.1f%% of them within 2 radii; beyond 1.1 radii %zu darker, %zu brighter\n", sx, sy, radius,
                share * 100.0, 100.0 * discChanged / std::max<std::size_t>(disc, 1),
                100.0 * near / std::max<std::size_t>(changed, 1), outsideDarker, outsideBrighter);
    EXPECT_GT(double(discChanged), 0.9 * disc) << "the sphere is not seen where it projects";
    EXPECT_LT(share, 0.15) << "more than the sphere changes";
    EXPECT_GT(double(near), 0.97 * changed) << "the change is not compact";
    // its shadow on the floor beside it: the floor it darkens outnumbers what it brightens there
    EXPECT_GT(outsideDarker, 200u) << "no shadow beside the sphere";
    EXPECT_GT(outsideDarker, 2 * outsideBrighter) << "no shadow beside the sphere";
}

// ---------------------------------------------------------------------------------------------
// lake-optics: the Image's float output (before 8-bit rounding) in a shallow and a deep region

class LakeOptics : public GlTest {};

struct Rgb {
    double r = 0, g = 0, b = 0;
    double blueShare() const { return b / (r + g + b); }
    double distance(const Rgb& o) const { return std::sqrt((r - o.r) * (r - o.r) + (g - o.g) * (g - o.g) + (b - o.b) * (b - o.b)); }
};

Rgb meanColour(const std::vector<float>& rgba, int width, int x0, int y0, int w, int h) {
    Rgb sum;
    for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x) {
            const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
            sum.r += rgba[i];
            sum.g += rgba[i + 1];
            sum.b += rgba[i + 2];
        }
    const double n = double(w) * h;
    return {sum.r / n, sum.g / n, sum.b / n};
}

struct LakeColours {
    Rgb shallow, deep;
};

// Each key of `keys` is pressed for one frame, one after the other (frames 1, 3, ...), then one
// more frame is rendered and read. Every frame is at iTime 2 so that only the keys differ.
LakeColours lakeColours(const std::shared_ptr<GlContext>& context, std::initializer_list<int> keys) {
    auto toy = loadSession(context, sourceDir() / "shadertoys/lake-optics", kWidth, kHeight, /*floatImage=*/true);
    EXPECT_TRUE(toy);
    if (!toy) return {};
    const FrameTime atTwo{2.0, 1.0 / 60.0, 60.0, glm::vec4(0.0f)};
    stepAt(*toy);
    for (int key : keys) {
        const InputEvent down[] = {InputEvent::keyDown(key)}, up[] = {InputEvent::keyUp(key)};
        (void)toy->renderFrame(atTwo, down);
        (void)toy->renderFrame(atTwo, up);
    }
    (void)toy->renderFrame(atTwo, {});
    std::vector<float> image;
    playerOf(*toy).readRgba32f(PassId::Image, image);
    // Regions at 320x180 (x, y, w, h; origin bottom-left) from the shader's README: water 0.3-1.4 m
    // deep over sand, and water whose floor lies 28.7-29.2 m down (depths read from the shader).
    return {meanColour(image, kWidth, 158, 0, 40, 22), meanColour(image, kWidth, 240, 72, 80, 40)};
}

TEST_F(LakeOptics, PresetsGiveDifferentWaterAndTropicalDeepIsBluerThanShallow) {
    const LakeColours tropical = lakeColours(context_, {});
    const LakeColours muddy = lakeColours(context_, {'2'});
    const LakeColours tannin = lakeColours(context_, {'3'});
    const LakeColours tropicalAgain = lakeColours(context_, {'3', '1'});
    for (const auto& [name, c] : {std::pair{"tropical", tropical}, {"muddy", muddy}, {"tannin", tannin}})
        std::printf("%-8s shallow %.3f %.3f %.3f  deep %.3f %.3f %.3f  (deep blue share %.3f, shallow %.3f)\n", name,
                    c.shallow.r, c.shallow.g, c.shallow.b, c.deep.r, c.deep.g, c.deep.b, c.deep.blueShare(),
                    c.shallow.blueShare());
    // The choice stays after the key is released, and key 1 brings the default back.
    EXPECT_LT(tropicalAgain.deep.distance(tropical.deep), 1e-6);
    // Three kinds of water: clearly different colours at the same place, deep and shallow.
    EXPECT_GT(tropical.deep.distance(muddy.deep), 0.1);
    EXPECT_GT(tropical.deep.distance(tannin.deep), 0.1);
    EXPECT_GT(muddy.deep.distance(tannin.deep), 0.1);
    EXPECT_GT(tropical.shallow.distance(muddy.shallow), 0.1);
    EXPECT_GT(tropical.shallow.distance(tannin.shallow), 0.1);
    // Clear tropical water absorbs red first: the long path of the deep water leaves it bluer.
    EXPECT_GT(tropical.deep.blueShare(), tropical.shallow.blueShare() + 0.03);
    // Muddy water is brown (red over blue); tannin water absorbs blue most: amber shallows.
    EXPECT_GT(muddy.deep.r, muddy.deep.b);
    EXPECT_GT(tannin.shallow.r, tannin.shallow.g);
    EXPECT_GT(tannin.shallow.g, tannin.shallow.b);
}

}  // namespace
}  // namespace toyhost::testing
