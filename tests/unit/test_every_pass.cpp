// Every pass type and input kind in the pure modules: the Cube A and Sound wrappers, the
// sampler types the header declares, the lowp/mediump macros beside a user's own, the WebGL
// zero-initialised `out` of mainImage, Cube A's frame ages and the site's sampler quirks in the
// pass graph, and manifests naming Cube A, Sound, cubemaps, volumes, videos, music, webcam, mic.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "DiagnosticText.h"
#include "ManifestFolder.h"
#include "graph/PassGraph.h"
#include "manifest/ManifestWriter.h"
#include "manifest/StockMedia.h"
#include "shader/ShaderAssembly.h"

using namespace toyhost;
using toyhost::testing::ManifestFolder;
using toyhost::testing::imageWithChannels;

namespace {

std::string assembled(PassId pass, std::string_view code, bool sound = false,
                      std::array<SamplerType, kChannelCount> samplers = {}, const std::string* common = nullptr) {
    ShaderInputs in;
    in.pass = pass;
    in.sound = sound;
    in.code = code;
    in.samplers = samplers;
    in.common = common;
    return assembleFragmentShader(in).text;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

int lineCount(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

}  // namespace

// ---- Shader wrappers ---------------------------------------------------------------------------

TEST(EveryPassAssembly, CubeAWrapperPassesFacePixelApexAndRayThroughTheFaceCorners) {
    const std::string text = assembled(PassId::CubeA, "void mainCubemap(out vec4 c, in vec2 f, in vec3 o, in vec3 d) {}\n");
    EXPECT_TRUE(has(text, "uniform vec4      unViewport;"));
    EXPECT_TRUE(has(text, "uniform vec3      unCorners[5];"));
    EXPECT_TRUE(has(text, "void mainCubemap( out vec4 fragColor, in vec2 fragCoord, in vec3 fragRayOri, in vec3 fragRayDir );"));
    EXPECT_TRUE(has(text, "vec3 ro = unCorners[4];"));
    EXPECT_TRUE(has(text, "vec2 uv = (gl_FragCoord.xy - unViewport.xy)/unViewport.zw;"));
    EXPECT_TRUE(has(text, "vec3 rd = normalize( mix( mix( unCorners[0], unCorners[1], uv.x ), "
                          "mix( unCorners[3], unCorners[2], uv.x ), uv.y ) - ro);"));
    EXPECT_TRUE(has(text, "mainCubemap(color, gl_FragCoord.xy-unViewport.xy, ro, rd);outColor = color;"));
    // The usual uniforms, no Image-only parts, no mainImage.
    EXPECT_TRUE(has(text, "uniform vec3      iResolution;"));
    EXPECT_FALSE(has(text, "st_assert"));
    EXPECT_FALSE(has(text, "mainImage"));
    // mainCubemap's own `out` is zero-initialised like mainImage's.
    EXPECT_TRUE(has(text, "in vec3 d) {c=vec4(0);}"));
}

TEST(EveryPassAssembly, SoundWrapperEncodesTwoSixteenBitSamplesPerPixel) {
    const std::string text = assembled(PassId::Sound, "vec2 mainSound(int s, float t) { return vec2(0.0); }\n", true);
    for (const char* part : {"uniform float     iTimeOffset;", "uniform int       iSampleOffset;",
                             "uniform float     iSampleRate;", "uniform vec4      iDate;",
                             "uniform float     iChannelTime[4];", "uniform vec3      iChannelResolution[4];",
                             "vec2 mainSound( in int samp, float time );",
                             "float t = iTimeOffset + ((gl_FragCoord.x-0.5) + (gl_FragCoord.y-0.5)*512.0)/iSampleRate;",
                             "int   s = iSampleOffset + int(gl_FragCoord.y-0.2)*512 + int(gl_FragCoord.x-0.2);",
                             "vec2 v  = floor((0.5+0.5*y)*65536.0);", "outColor = vec4(vl.x,vh.x,vl.y,vh.y);"})
        EXPECT_TRUE(has(text, part)) << part;
    // The sound header has no iTime, iResolution, iMouse or iFrame.
    for (const char* absent : {"iResolution", "uniform float     iTime;", "iMouse", "iFrame"})
        EXPECT_FALSE(has(text, absent)) << absent;
}

TEST(EveryPassAssembly, ChannelsAreDeclaredWithTheirSamplerTypeInEveryPassKind) {
    const std::array<SamplerType, kChannelCount> samplers{SamplerType::SamplerCube, SamplerType::Sampler3D,
                                                          SamplerType::Sampler2D, SamplerType::SamplerCube};
    for (bool sound : {false, true})
        for (PassId pass : {PassId::BufferA, PassId::CubeA, PassId::Image}) {
            const std::string text = assembled(pass, "\n", sound, samplers);
            EXPECT_TRUE(has(text, "uniform samplerCube iChannel0;")) << passName(pass) << sound;
            EXPECT_TRUE(has(text, "uniform sampler3D iChannel1;")) << passName(pass) << sound;
            EXPECT_TRUE(has(text, "uniform sampler2D iChannel2;")) << passName(pass) << sound;
            EXPECT_TRUE(has(text, "uniform samplerCube iChannel3;")) << passName(pass) << sound;
        }
}

TEST(EveryPassAssembly, LowpAndMediumpAreWrittenHighpWithoutAMacro) {
    // No macro: `#ifdef lowp` is false as in WebGL; the qualifiers in code and in #define bodies
    // compute in 32 bits; the directives that test the name are left alone.
    const std::string code = "#ifdef lowp\n#endif\n#define P mediump\nvoid mainImage(out vec4 c, in vec2 f) { lowp float x = 1.; }\n";
    const std::string plain = assembled(PassId::Image, code);
    EXPECT_FALSE(has(plain, "#define lowp"));
    EXPECT_FALSE(has(plain, "#define mediump"));
    EXPECT_TRUE(has(plain, "#ifdef lowp\n#endif\n#define P highp\nvoid mainImage(out vec4 c, in vec2 f) {c=vec4(0); highp float x = 1.; }"));
    // A user's own macro of that name is left to work as the user wrote it.
    const std::string own = assembled(PassId::Image, "#define lowp\nvoid mainImage(out vec4 c, in vec2 f) { lowp float x; mediump float y; }\n");
    EXPECT_TRUE(has(own, "lowp float x=float(0); highp float y=float(0);"));
    const std::string common = "#define mediump\n";
    EXPECT_TRUE(has(assembled(PassId::BufferA, "void f(){ mediump float y; }\n", false, {}, &common), "mediump float y"));
    // The header keeps its line count either way.
    EXPECT_EQ(lineCount(assembled(PassId::Image, "\n")), lineCount(assembled(PassId::Image, "#define lowp\n")));
}

// ---- Pass graph: Cube A and the sampler quirks -------------------------------------------------

namespace {

ChannelDesc channelOf(ChannelKind kind, int buffer = -1, Filter filter = Filter::Linear, Wrap wrap = Wrap::Clamp) {
    ChannelDesc c;
    c.kind = kind;
    c.buffer = buffer;
    c.sampler = {filter, wrap, false};
    c.samplerType = samplerTypeOf(kind);
    return c;
}

PassDesc passOf(PassId id) {
    PassDesc p;
    p.id = id;
    return p;
}

const PassPlan& planOf(const PassGraph& g, PassId id) {
    for (const PassPlan& p : g.passes)
        if (p.id == id) return p;
    throw std::runtime_error("no such pass");
}

}  // namespace

TEST(EveryPassGraph, CubeARunsAfterTheBuffersAndOnlyImageSeesItsCurrentFaces) {
    ManifestDesc m;
    PassDesc a = passOf(PassId::BufferA), cube = passOf(PassId::CubeA), image = passOf(PassId::Image);
    a.channels[0] = channelOf(ChannelKind::CubeBuffer);
    cube.channels[0] = channelOf(ChannelKind::CubeBuffer);
    cube.channels[1] = channelOf(ChannelKind::Buffer, 0);
    image.channels[0] = channelOf(ChannelKind::CubeBuffer, -1, Filter::Mipmap);
    m.passes = {a, cube, image};
    const PassGraph g = buildPassGraph(m);
    ASSERT_EQ(g.passes.size(), 3u);
    EXPECT_EQ(g.passes[1].id, PassId::CubeA);
    EXPECT_TRUE(g.passes[1].targetCube);
    EXPECT_EQ(g.passes[1].targetBuffer, -1);
    EXPECT_TRUE(g.cubeUsed);
    EXPECT_TRUE(g.cubeMipmapped);
    EXPECT_EQ(planOf(g, PassId::BufferA).channels[0].age, FrameAge::Previous);
    EXPECT_EQ(planOf(g, PassId::CubeA).channels[0].age, FrameAge::Previous);  // itself: last frame
    EXPECT_EQ(planOf(g, PassId::CubeA).channels[1].age, FrameAge::Current);   // Buffer A ran before it
    EXPECT_EQ(planOf(g, PassId::Image).channels[0].age, FrameAge::Current);
}

TEST(EveryPassGraph, TheHighestChannelReadingABufferSetsTheFilterForTheWholePass) {
    ManifestDesc m;
    PassDesc a = passOf(PassId::BufferA), b = passOf(PassId::BufferB), image = passOf(PassId::Image);
    image.channels[0] = channelOf(ChannelKind::Buffer, 0, Filter::Linear);
    image.channels[1] = channelOf(ChannelKind::Buffer, 1, Filter::Linear);
    image.channels[2] = channelOf(ChannelKind::Buffer, 0, Filter::Nearest);
    // Buffer B reads A twice as well, but A's previous frame is another texture than... A ran
    // before B, so both read the current one: the quirk applies there too.
    b.channels[0] = channelOf(ChannelKind::Buffer, 0, Filter::Nearest);
    b.channels[3] = channelOf(ChannelKind::Buffer, 0, Filter::Mipmap);
    // Buffer A reading itself (previous) and B (previous, another texture): no interaction.
    a.channels[0] = channelOf(ChannelKind::Buffer, 0, Filter::Linear);
    a.channels[1] = channelOf(ChannelKind::Buffer, 1, Filter::Nearest);
    m.passes = {a, b, image};
    const PassGraph g = buildPassGraph(m);
    const auto& i = planOf(g, PassId::Image).channels;
    EXPECT_EQ(i[0].sampler.filter, Filter::Nearest);  // channel 2 reads the same texture, later
    EXPECT_EQ(i[1].sampler.filter, Filter::Linear);
    EXPECT_EQ(i[2].sampler.filter, Filter::Nearest);
    EXPECT_EQ(planOf(g, PassId::BufferB).channels[0].sampler.filter, Filter::Mipmap);
    EXPECT_EQ(planOf(g, PassId::BufferA).channels[0].sampler.filter, Filter::Linear);
    EXPECT_EQ(planOf(g, PassId::BufferA).channels[1].sampler.filter, Filter::Nearest);
    // Mipmaps are still built because some channel asked for them.
    EXPECT_TRUE(g.bufferMipmapped[0]);
}

TEST(EveryPassGraph, ABuffersWrapIsTheLastReadingChannelsForTheWholeShader) {
    ManifestDesc m;
    PassDesc a = passOf(PassId::BufferA), image = passOf(PassId::Image);
    a.channels[0] = channelOf(ChannelKind::Buffer, 0, Filter::Linear, Wrap::Repeat);
    image.channels[0] = channelOf(ChannelKind::Buffer, 0, Filter::Linear, Wrap::Clamp);
    image.channels[1] = channelOf(ChannelKind::Keyboard);
    m.passes = {a, image};
    const PassGraph g = buildPassGraph(m);
    EXPECT_EQ(planOf(g, PassId::BufferA).channels[0].sampler.wrap, Wrap::Clamp);
    EXPECT_EQ(planOf(g, PassId::Image).channels[0].sampler.wrap, Wrap::Clamp);
    // Textures other than buffers keep their own settings.
    EXPECT_EQ(planOf(g, PassId::Image).channels[1].sampler.filter, Filter::Linear);
}

// The site creates an export's passes as listed and each pass's inputs as listed; the last
// created channel reading a buffer sets its wrap. Render order would say clamp here (Image's
// channel 0, created last in render order); the export lists Image first and Buffer A's repeat
// input last, so the site shows repeat.
TEST(EveryPassGraph, InAnExportTheWrapFollowsTheListedOrderOfPassesAndInputs) {
    ManifestDesc m;
    PassDesc a = passOf(PassId::BufferA), image = passOf(PassId::Image);
    a.channels[0] = channelOf(ChannelKind::Buffer, 0, Filter::Linear, Wrap::Repeat);
    a.channels[2] = channelOf(ChannelKind::Buffer, 0, Filter::Linear, Wrap::Clamp);
    image.channels[0] = channelOf(ChannelKind::Buffer, 0, Filter::Linear, Wrap::Clamp);
    image.listedAt = 0;
    a.listedAt = 1;
    a.channels[2].listedAt = 0;  // iChannel2 listed before iChannel0
    a.channels[0].listedAt = 1;
    m.passes = {a, image};
    const PassGraph g = buildPassGraph(m);
    EXPECT_EQ(planOf(g, PassId::Image).channels[0].sampler.wrap, Wrap::Repeat);
    EXPECT_EQ(planOf(g, PassId::BufferA).channels[2].sampler.wrap, Wrap::Repeat);
    // Without export places (a manifest): render order, channel order.
    for (PassDesc& p : m.passes) {
        p.listedAt = -1;
        for (ChannelDesc& ch : p.channels) ch.listedAt = -1;
    }
    EXPECT_EQ(planOf(buildPassGraph(m), PassId::Image).channels[0].sampler.wrap, Wrap::Clamp);
}

// ---- Manifests ---------------------------------------------------------------------------------

TEST(EveryPassManifest, CubeAAndSoundPassesWithEveryChannelSource) {
    ManifestFolder f;
    f.write("cube_a.glsl", "void mainCubemap(out vec4 c, in vec2 f, in vec3 o, in vec3 d) { c = vec4(d, 1.0); }\n");
    f.write("sound.glsl", "vec2 mainSound(int s, float t) { return vec2(sin(6.2831*440.0*t)); }\n");
    f.write("sky.png", "x");
    f.write("noise.bin", "x");
    f.write("clip.mp4", "x");
    f.write("song.mp3", "x");
    const Result<ManifestDesc> m = f.parse(R"({"passes": {
        "Cube A": {"source": "cube_a.glsl", "channels": {"iChannel0": {"buffer": "Cube A"}}},
        "Sound": {"source": "sound.glsl", "channels": {"iChannel0": {"volume": "noise.bin"}}},
        "Image": {"source": "image.glsl", "channels": {
            "iChannel0": {"buffer": "Cube A", "filter": "mipmap"},
            "iChannel1": {"cubemap": "sky.png", "vflip": true},
            "iChannel2": {"video": "clip.mp4"},
            "iChannel3": {"music": "song.mp3"}}}}})");
    ASSERT_TRUE(m) << m.error().text();
    ASSERT_EQ(m->passes.size(), 2u);
    EXPECT_EQ(m->passes[0].id, PassId::CubeA);
    EXPECT_EQ(m->passes[1].id, PassId::Image);
    ASSERT_TRUE(m->sound);
    EXPECT_EQ(m->sound->id, PassId::Sound);
    EXPECT_EQ(m->sound->channels[0].kind, ChannelKind::Volume);
    EXPECT_EQ(m->sound->channels[0].samplerType, SamplerType::Sampler3D);
    EXPECT_EQ(m->passes[0].channels[0].kind, ChannelKind::CubeBuffer);
    const auto& i = m->passes[1].channels;
    EXPECT_EQ(i[0].kind, ChannelKind::CubeBuffer);
    EXPECT_EQ(i[0].samplerType, SamplerType::SamplerCube);
    EXPECT_EQ(i[0].sampler.filter, Filter::Mipmap);
    EXPECT_EQ(i[1].kind, ChannelKind::Cubemap);
    EXPECT_EQ(i[1].file, f.dir / "sky.png");
    EXPECT_TRUE(i[1].sampler.vflip);
    EXPECT_EQ(i[1].samplerType, SamplerType::SamplerCube);
    EXPECT_EQ(i[2].kind, ChannelKind::Video);
    EXPECT_EQ(i[2].sampler.filter, Filter::Linear);
    EXPECT_TRUE(i[2].sampler.vflip);
    EXPECT_EQ(i[3].kind, ChannelKind::Music);
}

TEST(EveryPassManifest, StockCubemapsVolumesVideosAndMusicTakeTheirKindFromTheTable) {
    ManifestFolder f;
    const Result<ManifestDesc> m = f.parse(R"({"passes": {"Image": {"source": "image.glsl", "channels": {
        "iChannel0": {"media": "/media/a/488bd40303a2e2b9a71987e48c66ef41f5e937174bf316d3ed0e86410784b919.jpg"},
        "iChannel1": {"media": "RGBA Noise3D"},
        "iChannel2": {"media": "/media/a/e81e818ac76a8983d746784b423178ee9f6cdcdf7f8e8d719341a6fe2d2ab303.webm"},
        "iChannel3": {"webcam": true}}}}})");
    ASSERT_TRUE(m) << m.error().text();
    const auto& i = m->passes[0].channels;
    EXPECT_EQ(i[0].kind, ChannelKind::Cubemap);
    EXPECT_EQ(i[0].sampler.filter, Filter::Mipmap);
    EXPECT_FALSE(i[0].sampler.vflip);
    EXPECT_EQ(i[1].kind, ChannelKind::Volume);
    EXPECT_EQ(i[1].samplerType, SamplerType::Sampler3D);
    EXPECT_EQ(i[2].kind, ChannelKind::Video);
    EXPECT_EQ(i[3].kind, ChannelKind::Webcam);
    const StockInputInfo* noise = findStockInput("RGBA Noise3D");
    ASSERT_NE(noise, nullptr);
    EXPECT_EQ(noise->form, StockInputForm::Volume);
    EXPECT_EQ(noise->size, 32);
    EXPECT_EQ(noise->channels, 4);
    EXPECT_EQ(findStockInput("/media/a/27012b4eadd0c3ce12498b867058e4f717ce79e10a99568cca461682d84a4b04.bin")->channels, 1);
    EXPECT_EQ(findStockInput("Abstract 1"), nullptr);  // a 2D texture is not a stock input
}

TEST(EveryPassManifest, ReadingCubeAWithoutTheCubeAPassIsAnErrorNamingTheChannel) {
    ManifestFolder f;
    const Result<ManifestDesc> m = f.parse(imageWithChannels(R"({"iChannel2": {"buffer": "Cube A"}})"));
    ASSERT_FALSE(m);
    EXPECT_EQ(toyhost::testing::plainText(m.error()), f.line(R"(passes."Image".channels.iChannel2)", "reads Cube A, which this manifest does not define"));
}

TEST(EveryPassManifest, MediaFilesMustExistAndDevicesMustBeTrue) {
    ManifestFolder f;
    const Result<ManifestDesc> m = f.parse(imageWithChannels(R"({"iChannel0": {"video": "missing.mp4"},
                                                                  "iChannel1": {"mic": "yes"}})"));
    ASSERT_FALSE(m);
    const std::string text = m.error().text();
    EXPECT_TRUE(has(text, "iChannel0: video " + (f.dir / "missing.mp4").string())) << text;
    EXPECT_TRUE(has(text, R"(iChannel1: "mic" must be true)")) << text;
    const Result<ManifestDesc> vflip = f.parse(imageWithChannels(R"({"iChannel0": {"webcam": true, "vflip": false},
                                                                      "iChannel1": {"mic": true, "vflip": true}})"));
    ASSERT_FALSE(vflip);
    EXPECT_EQ(toyhost::testing::plainText(vflip.error()), f.line(R"(passes."Image".channels.iChannel1)",
                                           R"("vflip" applies only to image textures, cubemaps and videos, not mic channels)"));
}

TEST(EveryPassManifest, AnImportedManifestOfEveryKindReadsBackTheSame) {
    ManifestFolder f;
    f.write("cube_a.glsl", "void mainCubemap(out vec4 c, in vec2 f, in vec3 o, in vec3 d) { c = vec4(d, 1.0); }\n");
    f.write("sound.glsl", "vec2 mainSound(int s, float t) { return vec2(0.0); }\n");
    f.write("clip.mp4", "x");
    const Result<ManifestDesc> first = f.parse(R"({"passes": {
        "Cube A": {"source": "cube_a.glsl", "channels": {"iChannel0": {"buffer": "Cube A"}}},
        "Sound": {"source": "sound.glsl"},
        "Image": {"source": "image.glsl", "channels": {
            "iChannel0": {"media": "Forest Blurred"},
            "iChannel1": {"video": "clip.mp4", "filter": "nearest"},
            "iChannel2": {"media": "/media/a/newvideo.webm", "kind": "video"},
            "iChannel3": {"mic": true}}}}})");
    ASSERT_TRUE(first) << first.error().text();
    const std::string written = manifestJson(*first);
    const Result<ManifestDesc> second = f.parse(written);
    ASSERT_TRUE(second) << second.error().text() << "\n" << written;
    ASSERT_TRUE(second->sound);
    ASSERT_EQ(second->passes.size(), first->passes.size());
    for (std::size_t p = 0; p < first->passes.size(); ++p)
        for (int c = 0; c < kChannelCount; ++c) {
            const ChannelDesc& a = first->passes[p].channels[c];
            const ChannelDesc& b = second->passes[p].channels[c];
            EXPECT_EQ(a.kind, b.kind) << p << "/" << c << "\n" << written;
            EXPECT_EQ(a.samplerType, b.samplerType) << p << "/" << c;
            EXPECT_EQ(a.file, b.file) << p << "/" << c;
            EXPECT_EQ(a.sampler.filter, b.sampler.filter) << p << "/" << c;
            EXPECT_EQ(a.sampler.vflip, b.sampler.vflip) << p << "/" << c;
        }
    EXPECT_EQ(second->passes.back().channels[2].kind, ChannelKind::Video);
    EXPECT_EQ(second->passes.back().channels[0].kind, ChannelKind::Cubemap);
}

TEST(EveryPassManifest, KindGoesWithMediaOnlyAndNamesAKnownKind) {
    ManifestFolder f;
    const Result<ManifestDesc> bad = f.parse(imageWithChannels(R"({"iChannel0": {"media": "/media/a/x.bin", "kind": "volum"},
                                                                   "iChannel1": {"buffer": "A", "kind": "video"}})"));
    ASSERT_FALSE(bad);
    const std::string text = toyhost::testing::plainText(bad.error());
    EXPECT_TRUE(has(text, R"(kind "volum" (did you mean "volume"?) is not one of texture, cubemap, volume, video, music)")) << text;
    EXPECT_TRUE(has(text, R"(iChannel1: "kind" goes with "media" only)")) << text;
}
