// ManifestLoader, success cases: sampler defaults, the two channel forms, path resolution, pass
// order, Common, media overrides, loadManifest on a folder or a file, and the repository's real
// manifests of the original shaders (read from ../shared/shadertoys beside the repo).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "TestFolder.h"
#include "graph/PassGraph.h"
#include "manifest/ManifestLoader.h"

using namespace toyhost;
namespace fs = std::filesystem;

namespace {

// A fresh folder per test (named "toy" inside a unique parent); removed afterwards.
struct ManifestFolder {
    toyhost::testing::TestFolder root;
    fs::path dir = root.path / "toy";
    ManifestFolder() { fs::create_directories(dir); }
    fs::path write(const fs::path& relative, const std::string& text) const {
        return root.write(fs::path("toy") / relative, text);
    }
    ManifestDesc parse(const std::string& json) const {
        Result<ManifestDesc> result = parseManifest(json, dir / "manifest.json");
        EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().text());
        return result.ok() ? std::move(result.value()) : ManifestDesc{};
    }
};

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void expectSampler(const SamplerDesc& s, Filter filter, Wrap wrap, bool vflip, const std::string& what) {
    EXPECT_EQ(s.filter, filter) << what << ": filter is " << filterName(s.filter);
    EXPECT_EQ(s.wrap, wrap) << what << ": wrap is " << wrapName(s.wrap);
    EXPECT_EQ(s.vflip, vflip) << what << ": vflip";
}

std::vector<PassId> passIds(const ManifestDesc& m) {
    std::vector<PassId> ids;
    for (const PassDesc& p : m.passes) ids.push_back(p.id);
    return ids;
}

const std::string kAbstract3 = "/media/a/8979352a182bde7c3c651ba2b2f4e0615de819585cc37b7175bcefbca15a6683.jpg";

}  // namespace

TEST(ManifestLoading, MinimalImageOnly) {
    ManifestFolder f;
    f.write("image.glsl", "// image\nvoid mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n");
    const ManifestDesc m = f.parse(R"({"passes": {"Image": {"source": "image.glsl"}}})");
    ASSERT_EQ(m.passes.size(), 1u);
    EXPECT_EQ(m.passes[0].id, PassId::Image);
    EXPECT_EQ(m.passes[0].source, f.dir / "image.glsl");
    EXPECT_EQ(m.passes[0].code, "// image\nvoid mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n");
    for (const ChannelDesc& c : m.passes[0].channels) EXPECT_EQ(c.kind, ChannelKind::None);
    EXPECT_EQ(m.manifestPath, f.dir / "manifest.json");
    EXPECT_FALSE(m.commonSource.has_value());
    EXPECT_EQ(m.commonCode, "");
    EXPECT_TRUE(m.mediaOverrides.empty());
    EXPECT_EQ(m.name, "toy");  // the folder's name when "name" is absent
    EXPECT_NE(m.find(PassId::Image), nullptr);
    EXPECT_EQ(m.find(PassId::BufferA), nullptr);
    for (int b = 0; b < kBufferCount; ++b) EXPECT_FALSE(m.hasBuffer(b));
}

TEST(ManifestLoading, ExplicitName) {
    ManifestFolder f;
    f.write("image.glsl", "x");
    EXPECT_EQ(f.parse(R"({"name": "My Toy", "passes": {"Image": {"source": "image.glsl"}}})").name, "My Toy");
}

TEST(ManifestLoading, SamplerDefaultsPerChannelKind) {
    ManifestFolder f;
    f.write("image.glsl", "x");
    f.write("a.glsl", "a");
    f.write("tex.png", "png bytes");
    const ManifestDesc m = f.parse(R"({"passes": {
        "Buffer A": {"source": "a.glsl"},
        "Image": {"source": "image.glsl", "channels": {
            "iChannel0": {"texture": "tex.png"},
            "iChannel1": {"buffer": "A"},
            "iChannel2": {"keyboard": true},
            "iChannel3": {"media": "Abstract 3"}}}}})");
    const PassDesc* image = m.find(PassId::Image);
    ASSERT_NE(image, nullptr);
    EXPECT_EQ(image->channels[0].kind, ChannelKind::ImageFile);
    EXPECT_EQ(image->channels[0].file, f.dir / "tex.png");
    expectSampler(image->channels[0].sampler, Filter::Mipmap, Wrap::Repeat, true, "texture");
    EXPECT_EQ(image->channels[1].kind, ChannelKind::Buffer);
    EXPECT_EQ(image->channels[1].buffer, 0);
    expectSampler(image->channels[1].sampler, Filter::Linear, Wrap::Clamp, false, "buffer");
    EXPECT_EQ(image->channels[2].kind, ChannelKind::Keyboard);
    expectSampler(image->channels[2].sampler, Filter::Nearest, Wrap::Clamp, false, "keyboard");
    EXPECT_EQ(image->channels[3].kind, ChannelKind::StockMedia);
    EXPECT_EQ(image->channels[3].media, "Abstract 3");  // kept as written
    expectSampler(image->channels[3].sampler, Filter::Mipmap, Wrap::Repeat, true, "stock media");

    // The same defaults from the table the renderer sees.
    expectSampler(defaultSampler(ChannelKind::ImageFile), Filter::Mipmap, Wrap::Repeat, true, "ImageFile");
    expectSampler(defaultSampler(ChannelKind::StockMedia), Filter::Mipmap, Wrap::Repeat, true, "StockMedia");
    expectSampler(defaultSampler(ChannelKind::Buffer), Filter::Linear, Wrap::Clamp, false, "Buffer");
    expectSampler(defaultSampler(ChannelKind::Keyboard), Filter::Nearest, Wrap::Clamp, false, "Keyboard");
}

TEST(ManifestLoading, ExplicitSamplerSettings) {
    ManifestFolder f;
    f.write("image.glsl", "x");
    f.write("a.glsl", "a");
    f.write("tex.png", "png bytes");
    const ManifestDesc m = f.parse(R"({"passes": {
        "Buffer A": {"source": "a.glsl"},
        "Image": {"source": "image.glsl", "channels": [
            {"texture": "tex.png", "filter": "nearest", "wrap": "clamp", "vflip": false},
            {"buffer": "Buffer A", "filter": "mipmap", "wrap": "repeat"},
            {"media": "/media/a/3083c722c0c738cad0f468383167a0d246f91af2bfa373e9c5c094fb8c8413e0.png", "filter": "linear"},
            {"buffer": "A", "filter": "nearest"}]}}})");
    const PassDesc* image = m.find(PassId::Image);
    ASSERT_NE(image, nullptr);
    expectSampler(image->channels[0].sampler, Filter::Nearest, Wrap::Clamp, false, "texture");
    EXPECT_EQ(image->channels[1].buffer, 0);  // "Buffer A" is accepted as well as "A"
    expectSampler(image->channels[1].sampler, Filter::Mipmap, Wrap::Repeat, false, "buffer");
    expectSampler(image->channels[2].sampler, Filter::Linear, Wrap::Repeat, true, "media");
    expectSampler(image->channels[3].sampler, Filter::Nearest, Wrap::Clamp, false, "buffer 2");
}

TEST(ManifestLoading, ArrayAndObjectChannelFormsAreEquivalent) {
    ManifestFolder f;
    f.write("image.glsl", "x");
    f.write("a.glsl", "a");
    f.write("b.glsl", "b");
    const ManifestDesc fromArray = f.parse(R"({"passes": {
        "Buffer A": {"source": "a.glsl"}, "Buffer B": {"source": "b.glsl"},
        "Image": {"source": "image.glsl", "channels": [null, {"buffer": "B", "filter": "nearest"}, null, {"buffer": "A"}]}}})");
    const ManifestDesc fromObject = f.parse(R"({"passes": {
        "Buffer A": {"source": "a.glsl"}, "Buffer B": {"source": "b.glsl"},
        "Image": {"source": "image.glsl", "channels": {"iChannel3": {"buffer": "A"}, "iChannel1": {"buffer": "B", "filter": "nearest"}}}}})");
    for (const ManifestDesc* m : {&fromArray, &fromObject}) {
        const PassDesc* image = m->find(PassId::Image);
        ASSERT_NE(image, nullptr);
        EXPECT_EQ(image->channels[0].kind, ChannelKind::None);
        EXPECT_EQ(image->channels[1].kind, ChannelKind::Buffer);
        EXPECT_EQ(image->channels[1].buffer, 1);
        EXPECT_EQ(image->channels[1].sampler.filter, Filter::Nearest);
        EXPECT_EQ(image->channels[2].kind, ChannelKind::None);
        EXPECT_EQ(image->channels[3].kind, ChannelKind::Buffer);
        EXPECT_EQ(image->channels[3].buffer, 0);
        EXPECT_EQ(image->channels[3].sampler.filter, Filter::Linear);
    }
    // A short array leaves the remaining channels unbound.
    const ManifestDesc shortArray = f.parse(R"({"passes": {"Buffer A": {"source": "a.glsl"},
        "Image": {"source": "image.glsl", "channels": [{"buffer": "A"}]}}})");
    EXPECT_EQ(shortArray.find(PassId::Image)->channels[0].kind, ChannelKind::Buffer);
    for (int c = 1; c < kChannelCount; ++c)
        EXPECT_EQ(shortArray.find(PassId::Image)->channels[c].kind, ChannelKind::None);
}

TEST(ManifestLoading, RelativePathsResolveAgainstTheManifestFolder) {
    ManifestFolder f;
    const fs::path outside = f.dir.parent_path() / "elsewhere";
    f.write("shaders/image.glsl", "image code");
    f.write("../elsewhere/common.glsl", "common code");
    f.write("../elsewhere/buf.glsl", "buffer code");
    f.write("textures/t.png", "png");
    f.write("override.jpg", "jpg");
    const fs::path absoluteBuffer = outside / "buf.glsl";
    const std::string json = R"({"common": "../elsewhere/common.glsl",
        "media": {"Abstract 3": "./override.jpg"},
        "passes": {"Buffer D": {"source": ")" + absoluteBuffer.string() + R"("},
                   "Image": {"source": "shaders/./image.glsl",
                             "channels": [{"texture": "shaders/../textures/t.png"}, {"buffer": "D"}]}}})";
    // Parsing from another working directory must not matter.
    const fs::path cwd = fs::current_path();
    fs::current_path(fs::temp_directory_path());
    const ManifestDesc m = f.parse(json);
    fs::current_path(cwd);
    ASSERT_EQ(m.passes.size(), 2u);
    EXPECT_EQ(m.commonSource, outside / "common.glsl");
    EXPECT_EQ(m.commonCode, "common code");
    EXPECT_EQ(m.passes[0].id, PassId::BufferD);
    EXPECT_EQ(m.passes[0].source, absoluteBuffer);
    EXPECT_EQ(m.passes[0].code, "buffer code");
    EXPECT_EQ(m.passes[1].source, f.dir / "shaders" / "image.glsl");
    EXPECT_EQ(m.passes[1].code, "image code");
    EXPECT_EQ(m.passes[1].channels[0].file, f.dir / "textures" / "t.png");
    ASSERT_EQ(m.mediaOverrides.size(), 1u);
    EXPECT_EQ(m.mediaOverrides.at("Abstract 3"), f.dir / "override.jpg");
}

TEST(ManifestLoading, RelativeManifestPathIsMadeAbsolute) {
    ManifestFolder f;
    f.write("image.glsl", "x");
    const fs::path cwd = fs::current_path();
    fs::current_path(f.dir.parent_path());
    Result<ManifestDesc> m = parseManifest(R"({"passes": {"Image": {"source": "image.glsl"}}})", "toy/manifest.json");
    fs::current_path(cwd);
    ASSERT_TRUE(m.ok()) << m.error().text();
    EXPECT_EQ(m->manifestPath, f.dir / "manifest.json");
    EXPECT_EQ(m->passes[0].source, f.dir / "image.glsl");
    EXPECT_EQ(m->name, "toy");
}

TEST(ManifestLoading, PassesSortedInRenderOrderRegardlessOfJsonOrder) {
    ManifestFolder f;
    for (const char* name : {"a", "b", "c", "d", "image"}) f.write(std::string(name) + ".glsl", name);
    const ManifestDesc m = f.parse(R"({"passes": {
        "Image": {"source": "image.glsl"}, "Buffer D": {"source": "d.glsl"}, "Buffer B": {"source": "b.glsl"},
        "Buffer C": {"source": "c.glsl"}, "Buffer A": {"source": "a.glsl"}}})");
    EXPECT_EQ(passIds(m), (std::vector<PassId>{PassId::BufferA, PassId::BufferB, PassId::BufferC, PassId::BufferD,
                                               PassId::Image}));
    // Each pass kept its own source.
    ASSERT_EQ(m.passes.size(), 5u);
    EXPECT_EQ(m.passes[0].code, "a");
    EXPECT_EQ(m.passes[1].code, "b");
    EXPECT_EQ(m.passes[2].code, "c");
    EXPECT_EQ(m.passes[3].code, "d");
    EXPECT_EQ(m.passes[4].code, "image");

    const ManifestDesc gaps = f.parse(R"({"passes": {"Image": {"source": "image.glsl"}, "Buffer C": {"source": "c.glsl"},
        "Buffer A": {"source": "a.glsl"}}})");
    EXPECT_EQ(passIds(gaps), (std::vector<PassId>{PassId::BufferA, PassId::BufferC, PassId::Image}));
    EXPECT_TRUE(gaps.hasBuffer(0));
    EXPECT_FALSE(gaps.hasBuffer(1));
    EXPECT_TRUE(gaps.hasBuffer(2));
    EXPECT_FALSE(gaps.hasBuffer(3));
}

TEST(ManifestLoading, CommonIsRead) {
    ManifestFolder f;
    f.write("image.glsl", "x");
    f.write("common.glsl", "#define PI 3.14159\nfloat sq(float x) { return x * x; }");
    const ManifestDesc m = f.parse(R"({"common": "common.glsl", "passes": {"Image": {"source": "image.glsl"}}})");
    ASSERT_TRUE(m.commonSource.has_value());
    EXPECT_EQ(*m.commonSource, f.dir / "common.glsl");
    EXPECT_EQ(m.commonCode, "#define PI 3.14159\nfloat sq(float x) { return x * x; }");
}

TEST(ManifestLoading, MediaOverridesForStockAndOwnIds) {
    ManifestFolder f;
    f.write("image.glsl", "x");
    f.write("abstract.jpg", "jpg");
    f.write("mine.png", "png");
    const ManifestDesc m = f.parse(R"({"media": {")" + kAbstract3 + R"(": "abstract.jpg", "my-noise": "mine.png"},
        "passes": {"Image": {"source": "image.glsl", "channels": [{"media": ")" + kAbstract3 + R"("}, {"media": "my-noise"}]}}})");
    ASSERT_EQ(m.mediaOverrides.size(), 2u);
    EXPECT_EQ(m.mediaOverrides.at(kAbstract3), f.dir / "abstract.jpg");
    EXPECT_EQ(m.mediaOverrides.at("my-noise"), f.dir / "mine.png");
    const PassDesc* image = m.find(PassId::Image);
    EXPECT_EQ(image->channels[0].kind, ChannelKind::StockMedia);
    EXPECT_EQ(image->channels[0].media, kAbstract3);
    EXPECT_EQ(image->channels[1].kind, ChannelKind::StockMedia);
    EXPECT_EQ(image->channels[1].media, "my-noise");
    expectSampler(image->channels[1].sampler, Filter::Mipmap, Wrap::Repeat, true, "own media id");
    // A stock id may be overridden without any channel using it.
    f.parse(R"({"media": {"Abstract 3": "abstract.jpg"}, "passes": {"Image": {"source": "image.glsl"}}})");
}

TEST(ManifestLoading, LoadManifestFromFolderAndFromFile) {
    ManifestFolder f;
    f.write("image.glsl", "image code");
    f.write("a.glsl", "buffer code");
    const std::string json = R"({"passes": {"Buffer A": {"source": "a.glsl", "channels": [{"buffer": "A"}]},
                                            "Image": {"source": "image.glsl", "channels": [{"buffer": "A"}]}}})";
    const fs::path manifest = f.write("manifest.json", json);
    f.write("other.json", R"({"name": "other", "passes": {"Image": {"source": "image.glsl"}}})");

    for (const fs::path& target : {f.dir, manifest}) {
        Result<ManifestDesc> m = loadManifest(target);
        ASSERT_TRUE(m.ok()) << target << ": " << m.error().text();
        EXPECT_EQ(m->name, "toy");
        EXPECT_EQ(m->manifestPath, manifest);
        EXPECT_EQ(passIds(*m), (std::vector<PassId>{PassId::BufferA, PassId::Image}));
        EXPECT_EQ(m->passes[0].code, "buffer code");
        EXPECT_EQ(m->passes[1].code, "image code");
    }
    // A manifest file with another name is loaded as given.
    Result<ManifestDesc> other = loadManifest(f.dir / "other.json");
    ASSERT_TRUE(other.ok()) << other.error().text();
    EXPECT_EQ(other->name, "other");
    EXPECT_EQ(other->manifestPath, f.dir / "other.json");
}

// ---- The repository's manifests ----------------------------------------------------------------

namespace {
const fs::path kRepo = TOYHOST_SOURCE_DIR;
const fs::path kShared = kRepo / ".." / "shared" / "shadertoys";
}  // namespace

TEST(ManifestLoading, RepositoryOceanManifest) {
    if (!fs::is_directory(kShared / "MdXyzX"))
        GTEST_SKIP() << "the original shaders are not beside the repo (" << kShared << " missing)";
    Result<ManifestDesc> m = loadManifest(kRepo / "shadertoys" / "ocean");
    ASSERT_TRUE(m.ok()) << m.error().text();
    EXPECT_EQ(m->name, "Very fast procedural ocean (afl_ext, MdXyzX)");
    EXPECT_FALSE(m->commonSource.has_value());
    ASSERT_EQ(m->passes.size(), 1u);
    EXPECT_EQ(m->passes[0].id, PassId::Image);
    EXPECT_EQ(m->passes[0].source, (kShared / "MdXyzX" / "image.glsl").lexically_normal());
    EXPECT_EQ(m->passes[0].code, readFile(kShared / "MdXyzX" / "image.glsl"));
    EXPECT_NE(m->passes[0].code.find("mainImage"), std::string::npos);
    for (const ChannelDesc& c : m->passes[0].channels) EXPECT_EQ(c.kind, ChannelKind::None);
}

TEST(ManifestLoading, RepositoryMountainsLakesManifestHas7tSSDDWiring) {
    if (!fs::is_directory(kShared / "7tSSDD"))
        GTEST_SKIP() << "the original shaders are not beside the repo (" << kShared << " missing)";
    Result<ManifestDesc> m = loadManifest(kRepo / "shadertoys" / "mountains-lakes");
    ASSERT_TRUE(m.ok()) << m.error().text();
    const fs::path src = (kShared / "7tSSDD").lexically_normal();
    EXPECT_EQ(m->name, "Mountains & Lakes (xjorma, 7tSSDD)");
    ASSERT_TRUE(m->commonSource.has_value());
    EXPECT_EQ(*m->commonSource, src / "common.glsl");
    EXPECT_EQ(m->commonCode, readFile(src / "common.glsl"));
    ASSERT_EQ(passIds(*m), (std::vector<PassId>{PassId::BufferA, PassId::BufferB, PassId::BufferC, PassId::BufferD,
                                                PassId::Image}));
    const char* files[] = {"bufferA.glsl", "bufferB.glsl", "bufferC.glsl", "bufferD.glsl", "image.glsl"};
    for (int i = 0; i < 5; ++i) {
        EXPECT_EQ(m->passes[i].source, src / files[i]);
        EXPECT_EQ(m->passes[i].code, readFile(src / files[i])) << files[i];
    }

    // README table: pass -> (iChannel0, iChannel1) buffers; every buffer input is linear/clamp.
    struct Wire {
        PassId pass;
        int ch0, ch1;  // buffer index, -1 for the stock texture
    };
    const Wire wiring[] = {{PassId::BufferA, 2, 3}, {PassId::BufferB, 0, 3}, {PassId::BufferC, 0, 1},
                           {PassId::BufferD, 2, 1}, {PassId::Image, 2, -1}};
    for (const Wire& w : wiring) {
        const PassDesc* pass = m->find(w.pass);
        ASSERT_NE(pass, nullptr) << passName(w.pass);
        for (int c = 0; c < 2; ++c) {
            const int buffer = c == 0 ? w.ch0 : w.ch1;
            const ChannelDesc& ch = pass->channels[c];
            const std::string what = std::string(passName(w.pass)) + " iChannel" + std::to_string(c);
            if (buffer < 0) continue;
            EXPECT_EQ(ch.kind, ChannelKind::Buffer) << what;
            EXPECT_EQ(ch.buffer, buffer) << what;
            expectSampler(ch.sampler, Filter::Linear, Wrap::Clamp, false, what);
        }
        EXPECT_EQ(pass->channels[2].kind, ChannelKind::None);
        EXPECT_EQ(pass->channels[3].kind, ChannelKind::None);
    }
    const ChannelDesc& abstract3 = m->find(PassId::Image)->channels[1];
    EXPECT_EQ(abstract3.kind, ChannelKind::StockMedia);
    EXPECT_EQ(abstract3.media, kAbstract3);
    expectSampler(abstract3.sampler, Filter::Mipmap, Wrap::Repeat, true, "Image iChannel1");

    // And the ages the README gives ("this frame" / "previous frame").
    const PassGraph graph = buildPassGraph(*m);
    const FrameAge P = FrameAge::Previous, C = FrameAge::Current;
    const FrameAge ages[5][2] = {{P, P}, {C, P}, {C, C}, {C, C}, {C, C}};
    ASSERT_EQ(graph.passes.size(), 5u);
    for (int p = 0; p < 5; ++p)
        for (int c = 0; c < 2; ++c) {
            if (p == 4 && c == 1) continue;
            EXPECT_EQ(graph.passes[p].channels[c].age, ages[p][c]) << passName(graph.passes[p].id) << " iChannel" << c;
        }
    EXPECT_EQ(graph.bufferMipmapped, (std::array<bool, 4>{false, false, false, false}));
}

TEST(ManifestLoading, RepositoryProbeManifests) {
    for (const char* name : {"pingpong-probe", "uniform-probe"}) {
        Result<ManifestDesc> m = loadManifest(kRepo / "shadertoys" / name);
        ASSERT_TRUE(m.ok()) << name << ": " << m.error().text();
        EXPECT_EQ(m->name, name);
    }
}
