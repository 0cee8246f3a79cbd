// Every pass type and input kind, rendered on EGL: Cube A's faces against the site's corners and
// GL's cube convention, Cube A feedback, volumes by texelFetch, a video's frame at iTime, a pure
// tone's FFT peak in a music texture, the Sound pass to WAV (rate, length, frequency, the 16-bit
// round trip, samp and time agreeing) and muxed into a video, stand-ins for every stock kind, the
// browser's zero-initialisation, CPU mip chains, the site's sampler quirk and preprocessing as
// browsers do.
#include "GlTestSupport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

#include <nlohmann/json.hpp>

#include "capture/SoundEncoding.h"
#include "core/ChildProcess.h"
#include "capture/WavFile.h"
#include "core/AtomicFile.h"
#include "image/ImageWriters.h"
#include "media/VolumeFile.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

// A manifest folder under the test output: files by name, then the manifest text.
fs::path shadertoyFolder(const std::string& name, const std::vector<std::pair<std::string, std::string>>& files,
                         const std::string& manifest) {
    const fs::path dir = freshOutputDir("every_input/" + name);
    for (const auto& [file, text] : files) writeFile(dir / file, text);
    writeFile(dir / "manifest.json", manifest);
    return dir;
}

class EveryInput : public GlTest {};

std::array<float, 3> normalised(std::array<float, 3> v) {
    const float n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return {v[0] / n, v[1] / n, v[2] / n};
}

// The ray through pixel (x, y) of `face` of an N x N Cube A face, from SEMANTICS' corner table.
std::array<float, 3> siteRay(int face, int x, int y, int n) {
    static const float corners[6][4][3] = {
        {{1, 1, 1}, {1, 1, -1}, {1, -1, -1}, {1, -1, 1}},      {{-1, 1, -1}, {-1, 1, 1}, {-1, -1, 1}, {-1, -1, -1}},
        {{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}},      {{-1, -1, 1}, {1, -1, 1}, {1, -1, -1}, {-1, -1, -1}},
        {{-1, 1, 1}, {1, 1, 1}, {1, -1, 1}, {-1, -1, 1}},      {{1, 1, -1}, {-1, 1, -1}, {-1, -1, -1}, {1, -1, -1}}};
    const float u = (x + 0.5f) / n, v = (y + 0.5f) / n;
    std::array<float, 3> d{};
    for (int k = 0; k < 3; ++k) {
        const float bottom = corners[face][0][k] + (corners[face][1][k] - corners[face][0][k]) * u;
        const float top = corners[face][3][k] + (corners[face][2][k] - corners[face][3][k]) * u;
        d[k] = bottom + (top - bottom) * v;
    }
    return normalised(d);
}

const char* kFaceOfDirection =
    "float faceOf(vec3 d) { vec3 a = abs(d);\n"
    "  if (a.x >= a.y && a.x >= a.z) return d.x > 0.0 ? 0.0 : 1.0;\n"
    "  if (a.y >= a.z) return d.y > 0.0 ? 2.0 : 3.0;\n"
    "  return d.z > 0.0 ? 4.0 : 5.0; }\n";

TEST_F(EveryInput, CubeAFacesCarryTheSitesRaysAndGlSamplesThemBackByDirection) {
    const std::string cube = std::string(kFaceOfDirection) +
                             "void mainCubemap(out vec4 c, in vec2 f, in vec3 o, in vec3 d) { c = vec4(d, faceOf(d)); }\n";
    // Image: pixel i samples the cube in direction i of a fixed list.
    const std::string image =
        "const vec3 dirs[8] = vec3[8](vec3(1,.2,.3), vec3(-1,-.4,.1), vec3(.1,1,-.5), vec3(.3,-1,.2),\n"
        "                             vec3(-.2,.1,1), vec3(.4,.3,-1), vec3(1,1,.99), vec3(-.7,.7,-.7));\n"
        "void mainImage(out vec4 c, in vec2 f) { vec3 d = dirs[int(f.x)]; c = vec4(texture(iChannel0, d).xyz, 1.0); }\n";
    const fs::path dir = shadertoyFolder(
        "cube_rays", {{"cube.glsl", cube}, {"image.glsl", image}},
        R"({"passes": {"Cube A": {"source": "cube.glsl"},
                       "Image": {"source": "image.glsl", "channels": {"iChannel0": {"buffer": "Cube A"}}}}})");
    auto toy = loadSession(context_, dir, 8, 1, true);
    ASSERT_TRUE(toy);
    stepAt(*toy);
    ASSERT_TRUE(playerOf(*toy).hasCube());
    std::vector<float> face;
    int n = 0;
    for (int f = 0; f < 6; ++f) {
        playerOf(*toy).readCubeFace(f, face, n);
        ASSERT_EQ(n, 1024);
        std::vector<std::pair<int, int>> pixels{{0, 0}, {n - 1, 0}, {0, n - 1}, {n - 1, n - 1}, {n / 2, n / 2}, {n / 2 - 1, n / 2 - 1}};
        for (int k = 0; k < 64; ++k) pixels.push_back({(k * 97 + 13) % n, (k * 389 + 7) % n});
        for (auto [x, y] : pixels) {
            const float* p = &face[(static_cast<std::size_t>(y) * n + x) * 4];
            const std::array<float, 3> want = siteRay(f, x, y, n);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(p[c], want[c], 2e-3) << "face " << f << " pixel " << x << "," << y << " component " << c;
            // The shader's own major-axis rule names the face being drawn: the corner table is
            // GL's face orientation.
            EXPECT_EQ(p[3], float(f)) << "face " << f << " pixel " << x << "," << y;
        }
    }
    std::vector<float> image8;
    playerOf(*toy).readRgba32f(PassId::Image, image8);
    const float dirs[8][3] = {{1, .2f, .3f}, {-1, -.4f, .1f}, {.1f, 1, -.5f}, {.3f, -1, .2f},
                              {-.2f, .1f, 1}, {.4f, .3f, -1}, {1, 1, .99f}, {-.7f, .7f, -.7f}};
    for (int i = 0; i < 8; ++i) {
        const std::array<float, 3> want = normalised({dirs[i][0], dirs[i][1], dirs[i][2]});
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(image8[i * 4 + c], want[c], 4e-3) << "direction " << i;
    }
}

TEST_F(EveryInput, CapturingCubeAWritesItsSixFacesSideBySideInGlOrder) {
    const std::string cube = std::string(kFaceOfDirection) +
                             "void mainCubemap(out vec4 c, in vec2 f, in vec3 o, in vec3 d) { c = vec4(d, faceOf(d)); }\n";
    const fs::path dir = shadertoyFolder(
        "cube_capture", {{"cube.glsl", cube}, {"image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n"}},
        R"({"passes": {"Cube A": {"source": "cube.glsl"}, "Image": {"source": "image.glsl"}}})");
    auto run = runToyhost("run '" + dir.string() + "' --size 8x8 --quiet --capture-pass 'Cube A' --out '" +
                          (dir / "faces.exr").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    Result<ImageF32> strip = readExr(dir / "faces.exr");
    ASSERT_TRUE(strip) << strip.error().text();
    ASSERT_EQ(strip->width, 6 * 1024);
    ASSERT_EQ(strip->height, 1024);
    for (int f = 0; f < 6; ++f)
        for (auto [x, y] : {std::pair{0, 0}, std::pair{1023, 0}, std::pair{512, 700}, std::pair{1023, 1023}}) {
            const float* p = &strip->rgba[(static_cast<std::size_t>(y) * strip->width + f * 1024 + x) * 4];
            const std::array<float, 3> want = siteRay(f, x, y, 1024);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], want[c], 2e-3) << "face " << f << " " << x << "," << y;
            EXPECT_EQ(p[3], float(f));
        }
}

TEST_F(EveryInput, CubeAReadsItsPreviousFrameAndImageItsCurrentOne) {
    const std::string cube =
        "void mainCubemap(out vec4 c, in vec2 f, in vec3 o, in vec3 d) { c = texture(iChannel0, d) + vec4(1.0); }\n";
    const std::string image = "void mainImage(out vec4 c, in vec2 f) { c = vec4(texture(iChannel0, vec3(0.3, 1.0, -0.2)).x / 16.0); }\n";
    const fs::path dir = shadertoyFolder(
        "cube_feedback", {{"cube.glsl", cube}, {"image.glsl", image}},
        R"({"passes": {"Cube A": {"source": "cube.glsl", "channels": {"iChannel0": {"buffer": "Cube A", "filter": "nearest"}}},
                       "Image": {"source": "image.glsl", "channels": {"iChannel0": {"buffer": "Cube A"}}}}})");
    auto toy = loadSession(context_, dir, 4, 4, true);
    ASSERT_TRUE(toy);
    std::vector<float> pixels, face;
    int n = 0;
    for (int frame = 0; frame < 5; ++frame) {
        stepAt(*toy);
        playerOf(*toy).readRgba32f(PassId::Image, pixels);
        EXPECT_FLOAT_EQ(pixels[0] * 16.0f, float(frame + 1)) << "Image sees this frame's faces at frame " << frame;
        playerOf(*toy).readCubeFace(frame % 6, face, n);
        EXPECT_FLOAT_EQ(face[(static_cast<std::size_t>(n / 3) * n + n / 5) * 4], float(frame + 1)) << frame;
    }
    // A restart clears the cube like the buffers (frame 0 starts from zero).
    playerOf(*toy).restart();
    stepAt(*toy);
    playerOf(*toy).readRgba32f(PassId::Image, pixels);
    EXPECT_FLOAT_EQ(pixels[0] * 16.0f, 1.0f);
}

TEST_F(EveryInput, ACheckpointKeepsCubeAsFacesAndAResumedRunMatchesTheUninterruptedOne) {
    const std::string cube =
        "void mainCubemap(out vec4 c, in vec2 f, in vec3 o, in vec3 d) { c = texture(iChannel0, d) + vec4(d * 0.01, 1.0); }\n";
    const std::string image =
        "void mainImage(out vec4 c, in vec2 f) { vec2 p = f / iResolution.xy * 2.0 - 1.0;\n"
        "  c = vec4(texture(iChannel0, vec3(p, 0.7)).wxy / 16.0, 1.0); }\n";
    const fs::path dir = shadertoyFolder(
        "cube_checkpoint", {{"cube.glsl", cube}, {"image.glsl", image}},
        R"({"passes": {"Cube A": {"source": "cube.glsl", "channels": {"iChannel0": {"buffer": "Cube A"}}},
                       "Image": {"source": "image.glsl", "channels": {"iChannel0": {"buffer": "Cube A"}}}}})");
    const std::string base = "run '" + dir.string() + "' --size 24x16 --quiet ";
    ASSERT_EQ(runToyhost(base + "--frames 8 --out '" + (dir / "full_%d.png").string() + "'").exitCode, 0);
    auto first = runToyhost(base + "--frames 4 --checkpoint '" + (dir / "c.ckpt").string() + "'");
    ASSERT_EQ(first.exitCode, 0) << first.output;
    auto resumed = runToyhost(base + "--frames 8 --resume '" + (dir / "c.ckpt").string() + "' --out '" +
                              (dir / "resumed_%d.png").string() + "'");
    ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
    for (int frame = 4; frame < 8; ++frame) {
        Result<std::string> full = readTextFile(dir / ("full_" + std::to_string(frame) + ".png"));
        Result<std::string> again = readTextFile(dir / ("resumed_" + std::to_string(frame) + ".png"));
        ASSERT_TRUE(full && again) << frame;
        EXPECT_EQ(*full, *again) << "frame " << frame;
    }
    fs::remove(dir / "c.ckpt");  // 200 MB: Cube A's two slots of six 1024x1024 RGBA float faces
}

TEST_F(EveryInput, VolumeVoxelsAreWhereTheBinFileSaysAndTheirSizeIsTheChannelResolution) {
    Volume8 volume{4, 3, 2, 4, false, {}};
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 4; ++x)
                volume.voxels.insert(volume.voxels.end(), {std::uint8_t(x * 60), std::uint8_t(y * 80), std::uint8_t(z * 200), 255});
    const std::vector<std::uint8_t> bytes = encodeVolumeFile(volume);
    const std::string image =
        "void mainImage(out vec4 c, in vec2 f) { ivec2 p = ivec2(f);\n"
        "  if (p.y == 6) { c = vec4(iChannelResolution[0] / 10.0, 1.0); return; }\n"
        "  c = texelFetch(iChannel0, ivec3(p.x, p.y % 3, p.y / 3), 0); }\n";
    const fs::path dir = shadertoyFolder("volume", {{"image.glsl", image}},
                                         R"({"passes": {"Image": {"source": "image.glsl", "channels": {
                                               "iChannel0": {"volume": "v.bin", "filter": "nearest"}}}}})");
    writeFile(dir / "v.bin", std::string(bytes.begin(), bytes.end()));
    auto toy = loadSession(context_, dir, 4, 7, true);
    ASSERT_TRUE(toy);
    stepAt(*toy);
    std::vector<float> pixels;
    playerOf(*toy).readRgba32f(PassId::Image, pixels);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 4; ++x) {
            const float* p = &pixels[(static_cast<std::size_t>(y) * 4 + x) * 4];
            EXPECT_NEAR(p[0] * 255, x * 60, 0.01) << x << "," << y;
            EXPECT_NEAR(p[1] * 255, (y % 3) * 80, 0.01) << x << "," << y;
            EXPECT_NEAR(p[2] * 255, (y / 3) * 200, 0.01) << x << "," << y;
        }
    const float* resolution = &pixels[static_cast<std::size_t>(6) * 4 * 4];
    EXPECT_NEAR(resolution[0] * 10, 4, 1e-5);
    EXPECT_NEAR(resolution[1] * 10, 3, 1e-5);
    EXPECT_NEAR(resolution[2] * 10, 2, 1e-5);
}

TEST_F(EveryInput, AFloatVolumeKeepsItsValuesOutsideZeroToOne) {
    Volume8 volume{2, 1, 1, 1, true, {}};
    volume.voxels.resize(2 * sizeof(float));
    const float values[2] = {-0.5f, 7.25f};
    std::memcpy(volume.voxels.data(), values, sizeof values);
    const std::vector<std::uint8_t> bytes = encodeVolumeFile(volume);
    const fs::path dir = shadertoyFolder(
        "volume_float", {{"image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec3(f.x, 0, 0), 0).rrrr; }\n"}},
        R"({"passes": {"Image": {"source": "image.glsl", "channels": {"iChannel0": {"volume": "f.bin", "filter": "nearest"}}}}})");
    writeFile(dir / "f.bin", std::string(bytes.begin(), bytes.end()));
    auto toy = loadSession(context_, dir, 2, 1, true);
    ASSERT_TRUE(toy);
    stepAt(*toy);
    std::vector<float> pixels;
    playerOf(*toy).readRgba32f(PassId::Image, pixels);
    EXPECT_EQ(pixels[0], -0.5f);
    EXPECT_EQ(pixels[4], 7.25f);
}

TEST_F(EveryInput, AVideoShowsItsFrameAtITimeAndICannelTimeIsItsLoopingPlaybackTime) {
    if (!findExecutable("ffmpeg")) GTEST_FAIL() << "needs ffmpeg (scripts/install-deps.sh installs it)";
    const fs::path dir = shadertoyFolder(
        "video",
        {{"image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(texture(iChannel0, vec2(0.5)).rg, "
                        "iChannelTime[0] / 10.0, iChannelResolution[0].x / 100.0); }\n"}},
        R"({"passes": {"Image": {"source": "image.glsl", "channels": {"iChannel0": {"video": "clip.mkv", "filter": "nearest"}}}}})");
    // 20 frames at 10 fps, 32x16, frame k a uniform (12k, 255 - 12k, 0), lossless.
    std::string raw;
    for (int k = 0; k < 20; ++k)
        for (int i = 0; i < 32 * 16; ++i) raw += {char(12 * k), char(255 - 12 * k), 0, char(255)};
    writeFile(dir / "clip.rgba", raw);
    const std::string encode = "ffmpeg -v error -y -f rawvideo -pix_fmt rgba -video_size 32x16 -framerate 10 -i '" +
                               (dir / "clip.rgba").string() + "' -c:v ffv1 '" + (dir / "clip.mkv").string() + "'";
    ASSERT_EQ(std::system(encode.c_str()), 0);
    auto toy = loadSession(context_, dir, 2, 2, true);
    ASSERT_TRUE(toy);
    std::vector<float> pixels;
    for (int frame = 0; frame <= 130; ++frame) {
        stepAt(*toy);
        if (frame != 0 && frame != 7 && frame != 59 && frame != 60 && frame != 130) continue;
        playerOf(*toy).readRgba32f(PassId::Image, pixels);
        const double t = frame / 60.0;
        const int videoFrame = static_cast<int>(std::floor(t * 10 + 1e-9)) % 20;
        EXPECT_NEAR(pixels[0] * 255, 12 * videoFrame, 1.01) << "iTime " << t;
        EXPECT_NEAR(pixels[1] * 255, 255 - 12 * videoFrame, 1.01) << "iTime " << t;
        EXPECT_NEAR(pixels[2] * 10, std::fmod(t, 2.0), 2e-3) << "iTime " << t;
    }
}

TEST_F(EveryInput, APureToneInAMusicChannelPeaksInItsBinOfRowZero) {
    const int rate = 44100;
    std::vector<float> stereo;
    for (int i = 0; i < rate * 2; ++i) {
        // -26 dBFS: loud enough to stand out, quiet enough not to saturate the -30 dB top.
        const float v = static_cast<float>(0.05 * std::sin(2.0 * M_PI * 1000.0 * i / rate));
        stereo.push_back(v);
        stereo.push_back(v);
    }
    const fs::path dir = shadertoyFolder(
        "music", {{"image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(texelFetch(iChannel0, ivec2(f), 0).x, "
                                 "iChannelTime[0], iChannelResolution[0].xy / 1000.0); }\n"}},
        R"({"passes": {"Image": {"source": "image.glsl", "channels": {"iChannel0": {"music": "tone.wav"}}}}})");
    ASSERT_TRUE(writeWav16(dir / "tone.wav", stereo, rate));
    auto toy = loadSession(context_, dir, 512, 2, true);
    ASSERT_TRUE(toy);
    for (int frame = 0; frame < 31; ++frame) stepAt(*toy);  // iTime 0.5: the window is full
    std::vector<float> pixels;
    playerOf(*toy).readRgba32f(PassId::Image, pixels);
    std::vector<float> row0(512), row1(512);
    for (int x = 0; x < 512; ++x) {
        row0[x] = pixels[static_cast<std::size_t>(x) * 4];
        row1[x] = pixels[(512 + static_cast<std::size_t>(x)) * 4];
    }
    const int peak = static_cast<int>(std::max_element(row0.begin(), row0.end()) - row0.begin());
    // 1000 Hz with a 2048-point FFT at 44100 Hz: bin 1000 * 2048 / 44100 = 46.4.
    EXPECT_EQ(peak, 46) << row0[44] * 255 << " " << row0[45] * 255 << " " << row0[46] * 255 << " " << row0[47] * 255 << " " << row0[48] * 255;
    EXPECT_GT(row0[46], 0.5f);
    EXPECT_LT(row0[46], 1.0f);
    EXPECT_LT(row0[36], row0[46] - 0.2f);
    EXPECT_LT(row0[56], row0[46] - 0.2f);
    EXPECT_LT(row0[300], 0.1f);
    // The waveform row swings about 128 by the tone's amplitude (0.05: 6.4 levels): the stereo
    // file is mixed down to mono as WebAudio does, (left + right) / 2.
    const auto [low, high] = std::minmax_element(row1.begin(), row1.end());
    EXPECT_NEAR(*low * 255, 121, 1);
    EXPECT_NEAR(*high * 255, 134, 1);
    EXPECT_NEAR(pixels[1], 30.0 / 60.0, 1e-4);  // iChannelTime: the playback time
    EXPECT_NEAR(pixels[2] * 1000, 512, 1e-3);  // iChannelResolution.x
}

// The 16-bit little-endian samples of a canonical 44-byte-header WAV.
struct Wav {
    int rate = 0, channels = 0;
    std::vector<std::int16_t> samples;
};
Wav readWav(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    Wav wav;
    if (bytes.size() < 44 || bytes.compare(0, 4, "RIFF") != 0 || bytes.compare(8, 4, "WAVE") != 0) return wav;
    auto u16 = [&](std::size_t at) { return int(std::uint8_t(bytes[at])) | int(std::uint8_t(bytes[at + 1])) << 8; };
    wav.channels = u16(22);
    wav.rate = u16(24) | u16(26) << 16;
    for (std::size_t at = 44; at + 1 < bytes.size(); at += 2) wav.samples.push_back(static_cast<std::int16_t>(u16(at)));
    return wav;
}

int zeroCrossings(const Wav& wav, int channel) {
    int count = 0;
    for (std::size_t i = channel + 2; i < wav.samples.size(); i += 2)
        count += (wav.samples[i - 2] < 0) != (wav.samples[i] < 0);
    return count;
}

TEST_F(EveryInput, TheSoundPassBecomesAWavOfTheRightRateLengthAndFrequencies) {
    const fs::path dir = shadertoyFolder(
        "sound_sine",
        {{"image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.0); }\n"},
         {"sound.glsl", "vec2 mainSound(int samp, float time) { return vec2(0.5 * sin(6.2831853 * 440.0 * time),\n"
                        "  0.25 * sin(6.2831853 * 880.0 * time)); }\n"}},
        R"({"passes": {"Image": {"source": "image.glsl"}, "Sound": {"source": "sound.glsl"}}})");
    auto run = runToyhost("sound '" + dir.string() + "' --seconds 2 --out '" + (dir / "out.wav").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const Wav wav = readWav(dir / "out.wav");
    EXPECT_EQ(wav.rate, 44100);
    EXPECT_EQ(wav.channels, 2);
    EXPECT_EQ(wav.samples.size(), 2u * 88200u);
    EXPECT_NEAR(zeroCrossings(wav, 0), 2 * 440 * 2, 2);
    EXPECT_NEAR(zeroCrossings(wav, 1), 2 * 880 * 2, 2);
    const auto peak = *std::max_element(wav.samples.begin(), wav.samples.end());
    EXPECT_NEAR(peak / 32767.0, 0.5, 0.01);

    // Muxed into a video as its sound track.
    auto video = runToyhost("run '" + dir.string() + "' --size 32x18 --frames 30 --quiet --out '" +
                            (dir / "movie.mp4").string() + "'");
    ASSERT_EQ(video.exitCode, 0) << video.output;
    const auto probe = runCommand("ffprobe", "-v error -show_entries stream=codec_type -of csv=p=0 '" +
                                                 (dir / "movie.mp4").string() + "'");
    EXPECT_NE(probe.output.find("audio"), std::string::npos) << probe.output;
}

TEST_F(EveryInput, SoundSamplesDecodeAsTheSitesSixteenBitCodesAndSampAgreesWithTime) {
    const fs::path dir = shadertoyFolder(
        "sound_codes",
        {{"image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.0); }\n"},
         {"sound.glsl", "vec2 mainSound(int samp, float time) {\n"
                        "  if (samp < 1000) return vec2(0.5, -0.25);\n"
                        "  return vec2(1000.0 * (float(samp) / iSampleRate - time), 0.0); }\n"}},
        R"({"passes": {"Image": {"source": "image.glsl"}, "Sound": {"source": "sound.glsl"}}})");
    auto run = runToyhost("sound '" + dir.string() + "' --seconds 7 --out '" + (dir / "out.wav").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const Wav wav = readWav(dir / "out.wav");
    ASSERT_EQ(wav.samples.size(), 2u * 7u * 44100u);
    // What the site plays for 0.5 and -0.25, through its bytes, as 16-bit PCM.
    auto pcm = [](float x) {
        const SoundBytes b = soundBytes(x);
        return static_cast<std::int16_t>(std::lround(decodeSoundSample(b.lo, b.hi) * 32767.0));
    };
    EXPECT_EQ(wav.samples[0], pcm(0.5f));
    EXPECT_EQ(wav.samples[1], pcm(-0.25f));
    EXPECT_EQ(wav.samples[2 * 999], pcm(0.5f));
    // samp / iSampleRate and time agree to float rounding over 7 s (several 512x512 blocks).
    for (std::size_t i = 2 * 1000; i < wav.samples.size(); i += 2)
        ASSERT_LE(std::abs(wav.samples[i]), 40) << "sample " << i / 2;
}

TEST_F(EveryInput, AnExportWithEveryStockKindRunsOnStandInsWithANoticeEach) {
    const fs::path dir = freshOutputDir("every_input/stand_ins");
    auto in = [](const char* ctype, const char* src, int channel) {
        return std::string(R"({"id": "1", "src": ")") + src + R"(", "ctype": ")" + ctype + R"(", "channel": )" +
               std::to_string(channel) + R"(, "sampler": {"filter": "linear", "wrap": "clamp", "vflip": "true"}})";
    };
    const std::string image =
        "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, vec3(1.0, 0.2, 0.1)) + texture(iChannel1, vec3(0.5))"
        " + texture(iChannel2, f / iResolution.xy) + texture(iChannel3, vec2(0.1, 0.0)); }\n";
    const std::string buffer =
        "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, vec2(0.3)) + texture(iChannel1, vec2(0.2)) + "
        "texture(iChannel2, vec3(0.0, -1.0, 0.0)); }\n";
    const std::string exportJson =
        R"({"Shader": {"info": {"id": "standin", "name": "stand-ins"}, "renderpass": [)"
        R"({"type": "image", "name": "Image", "code": )" + nlohmann::json(image).dump() + R"(, "outputs": [{"id": 37}], "inputs": [)" +
        in("cubemap", "/media/a/94284d43be78f00eb6b298e6d78656a1b34e2b91b34940d02f1ca8b22310e8a0.png", 0) + "," +
        in("volume", "/media/a/27012b4eadd0c3ce12498b867058e4f717ce79e10a99568cca461682d84a4b04.bin", 1) + "," +
        in("video", "/media/a/e81e818ac76a8983d746784b423178ee9f6cdcdf7f8e8d719341a6fe2d2ab303.webm", 2) + "," +
        in("musicstream", "https://soundcloud.com/someone/some-track", 3) + R"(]},)"
        R"({"type": "buffer", "name": "Buffer A", "code": )" + nlohmann::json(buffer).dump() + R"(, "outputs": [{"id": 257}], "inputs": [)" +
        in("mic", "/presets/mic.png", 0) + "," + in("webcam", "/presets/webcam.png", 1) + "," +
        R"({"id": 41, "src": "/media/previz/cubemap00.png", "ctype": "cubemap", "channel": 2}]}]}})";
    writeFile(dir / "standin.json", exportJson);
    auto run = runToyhost("run '" + (dir / "standin.json").string() + "' --size 32x18 --frames 3 --out '" +
                          (dir / "f%d.png").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    for (const char* expected : {"stock cubemap 'Forest'", "stock volume 'Grey Noise3D'", "video 'Video e81e81'",
                                 "music stream", "no microphone given", "no webcam given",
                                 "reads Cube A, which the export does not define"})
        EXPECT_NE(run.output.find(expected), std::string::npos) << expected << "\n" << run.output;
    EXPECT_TRUE(fs::exists(dir / "f2.png"));
}

TEST_F(EveryInput, UninitialisedVariablesAndAnUnwrittenOutputAreZeroAsInWebGl) {
    const std::string image =
        "float g[4];\n"
        "float h;\n"
        "void mainImage(out vec4 c, in vec2 f) {\n"
        "  float x; vec3 v;\n"
        "  if (f.x < 1.0) { c = vec4(x, v.y, g[1], h + 1.0); return; }\n"
        "}\n";
    const fs::path dir = shadertoyFolder("zero_init", {{"image.glsl", image}},
                                         R"({"passes": {"Image": {"source": "image.glsl"}}})");
    for (int run = 0; run < 2; ++run) {
        auto toy = loadSession(context_, dir, 2, 1, true);
        ASSERT_TRUE(toy);
        stepAt(*toy);
        std::vector<float> pixels;
        playerOf(*toy).readRgba32f(PassId::Image, pixels);
        // Pixel 0: the uninitialised values (alpha forced to 1 by Image); pixel 1: mainImage never
        // wrote its out, which WebGL zero-initialises (black).
        EXPECT_EQ(std::vector<float>(pixels.begin(), pixels.begin() + 3), (std::vector<float>{0, 0, 0}));
        EXPECT_EQ(std::vector<float>(pixels.begin() + 4, pixels.begin() + 7), (std::vector<float>{0, 0, 0}));
    }
}

TEST_F(EveryInput, MipmapsOfAnImageAreExactBoxAverages) {
    const int side = 64;
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(side) * side * 4);
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = ((i / 4) + (i / 4 / side)) % 2 ? 127 : 129;
    const fs::path dir = shadertoyFolder(
        "mips", {{"image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = textureLod(iChannel0, vec2(0.5), f.x < 1.0 ? 6.0 : 3.0); }\n"}},
        R"({"passes": {"Image": {"source": "image.glsl", "channels": {"iChannel0": {"texture": "grey.png", "filter": "mipmap"}}}}})");
    ASSERT_TRUE(writePng(dir / "grey.png", side, side, rgba));
    auto toy = loadSession(context_, dir, 2, 1, true);
    ASSERT_TRUE(toy);
    stepAt(*toy);
    std::vector<float> pixels;
    playerOf(*toy).readRgba32f(PassId::Image, pixels);
    EXPECT_NEAR(pixels[0] * 255, 128, 0.01) << "1x1 level";
    EXPECT_NEAR(pixels[4] * 255, 128, 0.01) << "8x8 level";
}

TEST_F(EveryInput, TwoChannelsReadingOneBufferShareTheHigherChannelsFilter) {
    // Buffer A: left half 0, right half 1. Image samples exactly between the two middle texels
    // through channel 0 (linear) while channel 1 reads the same buffer with nearest: on the site
    // the texture's filter is channel 1's for both.
    const std::string half = "void mainImage(out vec4 c, in vec2 f) { c = vec4(f.x < iResolution.x * 0.5 ? 0.0 : 1.0); }\n";
    const fs::path dir = shadertoyFolder(
        "sampler_quirk",
        {{"a.glsl", half}, {"b.glsl", half},
         {"image.glsl", "void mainImage(out vec4 c, in vec2 f) { vec2 uv = vec2(0.5, 0.5);\n"
                        "  c = vec4(texture(iChannel0, uv).x, texture(iChannel1, uv).x, texture(iChannel2, uv).x, 1.0); }\n"}},
        R"({"passes": {"Buffer A": {"source": "a.glsl"}, "Buffer B": {"source": "b.glsl"},
                       "Image": {"source": "image.glsl", "channels": {
                          "iChannel0": {"buffer": "A", "filter": "linear"},
                          "iChannel1": {"buffer": "A", "filter": "nearest"},
                          "iChannel2": {"buffer": "B", "filter": "linear"}}}}})");
    auto toy = loadSession(context_, dir, 8, 2, true);
    ASSERT_TRUE(toy);
    stepAt(*toy);
    std::vector<float> pixels;
    playerOf(*toy).readRgba32f(PassId::Image, pixels);
    EXPECT_TRUE(pixels[0] == 0.0f || pixels[0] == 1.0f) << "channel 0 sampled with nearest: " << pixels[0];
    EXPECT_EQ(pixels[0], pixels[1]);
    EXPECT_NEAR(pixels[2], 0.5f, 1e-3) << "Buffer B alone keeps its linear filter";
}

TEST_F(EveryInput, ShadersMesasPreprocessorRefusesCompileAsInBrowsers) {
    const fs::path negate = shadertoyFolder(
        "preprocess_negate",
        {{"image.glsl", "#define NEG(x) -x\nvoid mainImage(out vec4 c, in vec2 f) {\n"
                        "  float k = NEG(-.7071);\n  c = vec4(k, 0.0, 0.0, 1.0); }\n"}},
        R"({"passes": {"Image": {"source": "image.glsl"}}})");
    const fs::path directive = shadertoyFolder(
        "preprocess_if_in_arguments",
        {{"image.glsl", "#define PICK(a, b) (a)\nvoid mainImage(out vec4 c, in vec2 f) {\n  float k = PICK(\n"
                        "#if 1\n    0.5\n#else\n    0.25\n#endif\n    , 1.0);\n  c = vec4(k, 0.0, 0.0, 1.0); }\n"}},
        R"({"passes": {"Image": {"source": "image.glsl"}}})");
    std::vector<float> pixels;
    for (auto [dir, want] : {std::pair{negate, 0.7071f}, std::pair{directive, 0.5f}}) {
        auto toy = loadSession(context_, dir, 1, 1, true);
        ASSERT_TRUE(toy) << dir;
        stepAt(*toy);
        playerOf(*toy).readRgba32f(PassId::Image, pixels);
        EXPECT_NEAR(pixels[0], want, 1e-6) << dir;
    }
    // A real error still names the user's line after the preprocessed retry fails too.
    const fs::path broken = shadertoyFolder(
        "preprocess_broken",
        {{"image.glsl", "#define NEG(x) -x\nvoid mainImage(out vec4 c, in vec2 f) {\n  float k = NEG(-.7071);\n"
                        "  c = vec4(k) + undefinedThing; }\n"}},
        R"({"passes": {"Image": {"source": "image.glsl"}}})");
    auto run = runToyhost("run '" + broken.string() + "' --size 4x4");
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.output.find("image.glsl:4:"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("undefinedThing"), std::string::npos) << run.output;
}

// The browser-style expansion runs GCC's cpp, a child process: it is prepared with the plan, off
// the GL thread, so that creating the player (on the GL thread) only compiles. With no cpp to be
// found once the plan is made, the shader Mesa refuses still compiles from the plan's text.
TEST_F(EveryInput, TheBrowserExpansionIsInThePlanBeforeGl) {
    const fs::path dir = shadertoyFolder(
        "preprocess_planned",
        {{"image.glsl", "#define NEG(x) -x\nvoid mainImage(out vec4 c, in vec2 f) {\n"
                        "  float k = NEG(-.7071);\n  c = vec4(k, 0.0, 0.0, 1.0); }\n"}},
        R"({"passes": {"Image": {"source": "image.glsl"}}})");
    auto manifest = loadShadertoy(dir);
    ASSERT_TRUE(manifest) << manifest.error().text();
    auto plan = planPlayer(std::move(*manifest), MediaOptions{});
    ASSERT_TRUE(plan) << plan.error().text();
    ASSERT_EQ(plan->sources.size(), 1u);
    ASSERT_TRUE(plan->sources[0].browserText) << "the expansion is made while planning";

    const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
    ::setenv("PATH", "", 1);  // no cpp from here on
    PlayerDesc desc;
    desc.width = 1;
    desc.height = 1;
    desc.floatImage = true;
    auto player = Player::create(context_, std::move(*plan), desc);
    ::setenv("PATH", path.c_str(), 1);
    ASSERT_TRUE(player) << player.error().text();
    (*player)->step(fixedStep(0));
    std::vector<float> pixels;
    (*player)->readRgba32f(PassId::Image, pixels);
    EXPECT_NEAR(pixels[0], 0.7071f, 1e-6);
    ASSERT_EQ((*player)->compileNotices().size(), 1u);
    EXPECT_EQ((*player)->compileNotices()[0].code, Code::ShaderPreprocessed);
}

TEST_F(EveryInput, AUsersOwnLowpMacroCompiles) {
    const fs::path dir = shadertoyFolder(
        "lowp_macro",
        {{"image.glsl", "#define lowp\n#define mediump\nvoid mainImage(out vec4 c, in vec2 f) { lowp float x = 0.25; "
                        "mediump vec2 y = vec2(0.5); c = vec4(x, y, 1.0); }\n"}},
        R"({"passes": {"Image": {"source": "image.glsl"}}})");
    auto toy = loadSession(context_, dir, 1, 1, true);
    ASSERT_TRUE(toy);
    stepAt(*toy);
    std::vector<float> pixels;
    playerOf(*toy).readRgba32f(PassId::Image, pixels);
    EXPECT_EQ(std::vector<float>(pixels.begin(), pixels.begin() + 3), (std::vector<float>{0.25f, 0.5f, 0.5f}));
}

}  // namespace
}  // namespace toyhost::testing
