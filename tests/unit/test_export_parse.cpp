// Shadertoy JSON exports into ManifestDesc: the API form and the older site form, pass order and
// buffer identity by output id, every supported ctype with its sampler strings, unsupported inputs
// and passes, error messages of broken exports, the real exports of ../shared/corpus/public, and
// the round trip through writeManifestFolder (what `toyhost import` writes) and loadShadertoy.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "DiagnosticText.h"
#include "TestFolder.h"
#include "export/LoadShadertoy.h"
#include "export/ShadertoyExport.h"
#include "graph/PassGraph.h"
#include "manifest/BufferWraps.h"
#include "manifest/ManifestWriter.h"
#include "manifest/StockMedia.h"

using namespace toyhost;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Parsing needs no file on disk; the path only names the export in messages.
const fs::path kExportPath = "/exports/toy.json";
const std::string kLabel = kExportPath.string();

const std::string kLondon = "/media/a/8de3a3924cb95bd0e95a443fff0326c869f9d4979cd1d5b6e94e2a01f5be53e9.jpg";
const std::string kRockTiles = "/media/a/10eb4fe0ac8a7dc348a2cc282ca5df1759ab8bf680117e4047728100969e7b43.jpg";
const std::string kGrayNoise = "/media/a/0c7bf5fe9462d5bffbd11126e82908e39be3ce56220d900f633d58fb432e56f5.png";

ManifestDesc parseOk(const std::string& text, const fs::path& path = kExportPath) {
    Result<ManifestDesc> result = parseShadertoyExport(text, path);
    EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().text());
    return result.ok() ? std::move(result.value()) : ManifestDesc{};
}

std::string parseError(const std::string& text, const fs::path& path = kExportPath) {
    Result<ManifestDesc> result = parseShadertoyExport(text, path);
    EXPECT_FALSE(result.ok()) << "expected an error for:\n" << text;
    return result.ok() ? std::string() : toyhost::testing::plainText(result.error());
}

void expectMentions(const std::string& message, std::initializer_list<std::string> parts) {
    for (const std::string& part : parts)
        EXPECT_NE(message.find(part), std::string::npos) << "message lacks \"" << part << "\":\n" << message;
}

// Every notice as the CLI prints it (without the "toyhost: " prefix).
std::vector<std::string> noticeLines(const ManifestDesc& desc) {
    std::vector<std::string> lines;
    for (const Diagnostic& d : desc.notices) lines.push_back(formatDiagnostic(d));
    return lines;
}

std::vector<PassId> passIds(const ManifestDesc& desc) {
    std::vector<PassId> ids;
    for (const PassDesc& pass : desc.passes) ids.push_back(pass.id);
    return ids;
}

const PassDesc& pass(const ManifestDesc& desc, PassId id) {
    const PassDesc* found = desc.find(id);
    static const PassDesc none{};
    EXPECT_NE(found, nullptr) << passName(id) << " is missing";
    return found ? *found : none;
}

void expectSampler(const SamplerDesc& s, Filter filter, Wrap wrap, bool vflip, const std::string& what) {
    EXPECT_EQ(s.filter, filter) << what << ": filter is " << filterName(s.filter);
    EXPECT_EQ(s.wrap, wrap) << what << ": wrap is " << wrapName(s.wrap);
    EXPECT_EQ(s.vflip, vflip) << what << ": vflip";
}

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// A renderpass as the API writes it; `inputs` is a JSON array text.
std::string apiPass(const std::string& type, const std::string& name, const std::string& outputId,
                    const std::string& code, const std::string& inputs = "[]") {
    json pass = {{"inputs", json::parse(inputs)},
                 {"outputs", outputId.empty() ? json::array() : json::array({{{"id", json::parse(outputId)}, {"channel", 0}}})},
                 {"code", code},
                 {"name", name},
                 {"description", ""},
                 {"type", type}};
    return pass.dump();
}

std::string apiExport(const std::vector<std::string>& passes) {
    std::string list;
    for (const std::string& p : passes) list += (list.empty() ? "" : ",") + p;
    return R"({"Shader": {"ver": "0.1", "info": {"id": "tSt123", "name": "Synthetic", "username": "tester",
               "description": "", "tags": [], "published": 3}, "renderpass": [)" +
           list + "]}}";
}

const std::string kImageCode = "void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n";

// ---------------------------------------------------------------------------------------------
// API form

TEST(ExportParse, ApiPassesInAnyOrderComeOutSortedWithBuffersKnownByOutputId) {
    // Image first, Common in the middle; two buffers whose names disagree with their output ids.
    const std::string text = apiExport({
        apiPass("image", "Image", "37", "// image\n"),
        apiPass("buffer", "Buffer D", "258", "// output 258\n"),
        apiPass("common", "Common", "", "// common\n"),
        apiPass("buffer", "Buffer C", "259", "// output 259\n"),
        apiPass("buffer", "Buffer B", "260", "// output 260\n"),
        apiPass("buffer", "Buffer A", "257", "// output 257\n"),
    });
    const ManifestDesc desc = parseOk(text);
    EXPECT_EQ(passIds(desc), (std::vector<PassId>{PassId::BufferA, PassId::BufferB, PassId::BufferC,
                                                  PassId::BufferD, PassId::Image}));
    EXPECT_EQ(pass(desc, PassId::BufferA).code, "// output 257\n");
    EXPECT_EQ(pass(desc, PassId::BufferB).code, "// output 258\n");
    EXPECT_EQ(pass(desc, PassId::BufferC).code, "// output 259\n");
    EXPECT_EQ(pass(desc, PassId::BufferD).code, "// output 260\n");
    EXPECT_EQ(pass(desc, PassId::Image).code, "// image\n");
    // Each pass keeps its place in the export's list (the buffer wrap quirk follows it).
    EXPECT_EQ(pass(desc, PassId::Image).listedAt, 0);
    EXPECT_EQ(pass(desc, PassId::BufferA).listedAt, 5);
    EXPECT_EQ(pass(desc, PassId::BufferC).listedAt, 3);

    ASSERT_TRUE(desc.commonSource.has_value());
    EXPECT_EQ(*desc.commonSource, kExportPath);
    EXPECT_EQ(desc.commonCode, "// common\n");
    EXPECT_EQ(desc.commonName, kLabel + " [Common]");

    EXPECT_EQ(pass(desc, PassId::BufferB).sourceName, kLabel + " [Buffer B]");
    EXPECT_EQ(pass(desc, PassId::Image).sourceName, kLabel + " [Image]");
    EXPECT_EQ(pass(desc, PassId::BufferD).source, kExportPath);
    EXPECT_EQ(desc.manifestPath, kExportPath);
    EXPECT_EQ(desc.name, "Synthetic (tSt123 by tester)");
    EXPECT_TRUE(desc.notices.empty());
    EXPECT_TRUE(desc.mediaOverrides.empty());
}

TEST(ExportParse, RelativePathIsMadeAbsoluteInNames) {
    const ManifestDesc desc = parseOk(apiExport({apiPass("image", "Image", "37", kImageCode)}), "some/dir/../x.json");
    const fs::path expected = (fs::current_path() / "some/x.json").lexically_normal();
    EXPECT_EQ(desc.manifestPath, expected);
    EXPECT_EQ(pass(desc, PassId::Image).sourceName, expected.string() + " [Image]");
}

TEST(ExportParse, NameFallsBackToTheFileStemAndOmitsMissingUser) {
    const std::string pass = apiPass("image", "Image", "37", kImageCode);
    EXPECT_EQ(parseOk(R"({"Shader": {"renderpass": [)" + pass + "]}}", "/x/my_toy.json").name, "my_toy");
    EXPECT_EQ(parseOk(R"({"Shader": {"info": {"id": "abc", "name": "N"}, "renderpass": [)" + pass + "]}}").name,
              "N (abc)");
}

TEST(ExportParse, BufferWithoutOutputIdIsKnownByItsName) {
    const ManifestDesc desc = parseOk(apiExport({apiPass("buffer", "Buffer C", "", "// c\n"),
                                                 apiPass("image", "Image", "37", kImageCode)}));
    EXPECT_EQ(passIds(desc), (std::vector<PassId>{PassId::BufferC, PassId::Image}));
    EXPECT_EQ(pass(desc, PassId::BufferC).code, "// c\n");
}

// ---------------------------------------------------------------------------------------------
// Older site form

const std::string kSitePasses = R"([
  {"inputs": [{"id": "XsXGR8", "filepath": "/media/previz/buffer01.png", "type": "buffer", "channel": 0,
               "sampler": {"filter": "linear", "wrap": "clamp", "vflip": "true", "srgb": "false", "internal": "byte"}},
              {"id": "4dXGRr", "filepath": "/presets/tex00.jpg", "type": "keyboard", "channel": 1,
               "sampler": {"filter": "linear", "wrap": "clamp", "vflip": "true", "srgb": "false", "internal": "byte"}},
              {"id": "XsfGRn", "filepath": ")" + kLondon + R"(", "type": "texture", "channel": 2,
               "sampler": {"filter": "mipmap", "wrap": "repeat", "vflip": "false", "srgb": "false", "internal": "byte"}},
              {"id": "zzzzzz", "filepath": "/media/previz/buffer02.png", "type": "buffer", "channel": 3,
               "sampler": {"filter": "nearest", "wrap": "clamp", "vflip": "true", "srgb": "false", "internal": "byte"}}],
   "outputs": [{"id": "4sXGR8", "channel": 0}], "code": "// site C\n", "name": "Buf C", "description": "", "type": "buffer"},
  {"inputs": [{"id": "4sXGR8", "filepath": "/media/previz/buffer02.png", "type": "buffer", "channel": 0,
               "sampler": {"filter": "linear", "wrap": "clamp", "vflip": "true", "srgb": "false", "internal": "byte"}}],
   "outputs": [{"id": "4dfGRr", "channel": 0}], "code": "// site image\n", "name": "", "description": "", "type": "image"},
  {"inputs": [], "outputs": [{"id": "XdfGR8", "channel": 0}], "code": "// site D\n", "name": "", "description": "", "type": "buffer"},
  {"inputs": [], "outputs": [{"id": "4dXGR8", "channel": 0}], "code": "// site A\n", "name": "", "description": "", "type": "buffer"},
  {"inputs": [], "outputs": [{"id": "XsXGR8", "channel": 0}], "code": "// site B\n", "name": "", "description": "", "type": "buffer"}
])";

void expectSiteDesc(const ManifestDesc& desc) {
    EXPECT_EQ(passIds(desc), (std::vector<PassId>{PassId::BufferA, PassId::BufferB, PassId::BufferC,
                                                  PassId::BufferD, PassId::Image}));
    EXPECT_EQ(pass(desc, PassId::BufferA).code, "// site A\n");
    EXPECT_EQ(pass(desc, PassId::BufferB).code, "// site B\n");
    EXPECT_EQ(pass(desc, PassId::BufferC).code, "// site C\n");
    EXPECT_EQ(pass(desc, PassId::BufferD).code, "// site D\n");
    EXPECT_EQ(pass(desc, PassId::Image).code, "// site image\n");
    EXPECT_FALSE(desc.commonSource.has_value());
    EXPECT_EQ(desc.name, "Site Toy (XsSite by old)");

    const auto& c = pass(desc, PassId::BufferC).channels;
    EXPECT_EQ(c[0].kind, ChannelKind::Buffer);
    EXPECT_EQ(c[0].buffer, 1);
    EXPECT_EQ(c[1].kind, ChannelKind::Keyboard);
    expectSampler(c[1].sampler, Filter::Nearest, Wrap::Clamp, false, "keyboard");
    EXPECT_EQ(c[2].kind, ChannelKind::StockMedia);
    EXPECT_EQ(c[2].media, kLondon);
    expectSampler(c[2].sampler, Filter::Mipmap, Wrap::Repeat, false, "site texture");
    // The id is not a buffer id; the filepath names Buffer C's preview image.
    EXPECT_EQ(c[3].kind, ChannelKind::Buffer);
    EXPECT_EQ(c[3].buffer, 2);
    expectSampler(c[3].sampler, Filter::Nearest, Wrap::Clamp, false, "site buffer by filepath");

    const auto& image = pass(desc, PassId::Image).channels;
    EXPECT_EQ(image[0].kind, ChannelKind::Buffer);
    EXPECT_EQ(image[0].buffer, 2);
    EXPECT_EQ(image[1].kind, ChannelKind::None);
    EXPECT_TRUE(desc.notices.empty());
}

TEST(ExportParse, SiteFormTopLevelWithStringIdsAndTypeFilepath) {
    const std::string text = R"({"ver": "0.1", "info": {"id": "XsSite", "name": "Site Toy", "username": "old"},
                                 "renderpass": )" + kSitePasses + "}";
    expectSiteDesc(parseOk(text));
}

TEST(ExportParse, SiteFormAsOneElementArray) {
    const std::string text = R"([{"ver": "0.1", "info": {"id": "XsSite", "name": "Site Toy", "username": "old"},
                                  "renderpass": )" + kSitePasses + "}]";
    expectSiteDesc(parseOk(text));
}

TEST(ExportParse, ApiFormInsideOneElementArray) {
    const ManifestDesc desc = parseOk("[" + apiExport({apiPass("image", "Image", "37", kImageCode)}) + "]");
    EXPECT_EQ(passIds(desc), std::vector<PassId>{PassId::Image});
}

// ---------------------------------------------------------------------------------------------
// Every ctype the host supports, with the export's sampler strings

std::string input(const std::string& ctype, const std::string& id, const std::string& src, int channel,
                  const std::string& sampler = "") {
    return R"({"id": )" + id + R"(, "src": ")" + src + R"(", "ctype": ")" + ctype + R"(", "channel": )" +
           std::to_string(channel) + (sampler.empty() ? "" : R"(, "sampler": )" + sampler) + R"(, "published": 1})";
}

std::string samplerJson(const std::string& filter, const std::string& wrap, const std::string& vflip,
                        const std::string& extra = R"("srgb": "false", "internal": "byte")") {
    return R"({"filter": ")" + filter + R"(", "wrap": ")" + wrap + R"(", "vflip": )" + vflip + ", " + extra + "}";
}

TEST(ExportParse, BufferInputsDefaultToLinearClampAndTakeExplicitFilterAndWrap) {
    const std::string inputs = "[" +
        input("buffer", "257", "/media/previz/buffer00.png", 0) + "," +
        input("buffer", "258", "/media/previz/buffer01.png", 1, samplerJson("nearest", "repeat", "\"true\"")) + "," +
        input("buffer", "257", "/media/previz/buffer00.png", 2, samplerJson("mipmap", "clamp", "true")) + "," +
        input("buffer", "258", "/media/previz/buffer01.png", 3, samplerJson("linear", "clamp", "\"false\"")) + "]";
    const ManifestDesc desc = parseOk(apiExport({apiPass("buffer", "Buffer A", "257", "// a\n"),
                                                 apiPass("buffer", "Buffer B", "258", "// b\n"),
                                                 apiPass("image", "Image", "37", kImageCode, inputs)}));
    const auto& c = pass(desc, PassId::Image).channels;
    for (int i = 0; i < 4; ++i) EXPECT_EQ(c[i].kind, ChannelKind::Buffer) << "iChannel" << i;
    EXPECT_EQ(c[0].buffer, 0);
    EXPECT_EQ(c[1].buffer, 1);
    EXPECT_EQ(c[2].buffer, 0);
    EXPECT_EQ(c[3].buffer, 1);
    // vflip means nothing for buffers, whatever the export says.
    expectSampler(c[0].sampler, Filter::Linear, Wrap::Clamp, false, "buffer without sampler");
    expectSampler(c[1].sampler, Filter::Nearest, Wrap::Repeat, false, "buffer nearest/repeat");
    expectSampler(c[2].sampler, Filter::Mipmap, Wrap::Clamp, false, "buffer mipmap");
    expectSampler(c[3].sampler, Filter::Linear, Wrap::Clamp, false, "buffer linear/clamp");
    EXPECT_TRUE(desc.notices.empty());
}

TEST(ExportParse, TextureInputsAreStockMediaWithTheExportSampler) {
    const std::string inputs = "[" +
        input("texture", "5", kLondon, 0, samplerJson("mipmap", "repeat", "\"true\"")) + "," +
        input("texture", "17", kGrayNoise, 1, samplerJson("nearest", "clamp", "\"false\"")) + "," +
        input("texture", "10", kRockTiles, 2,
              samplerJson("linear", "repeat", "false", R"("srgb": "true", "internal": "float")")) + "," +
        input("texture", "5", kLondon, 3, samplerJson("nearest", "repeat", "true")) + "]";
    const ManifestDesc desc = parseOk(apiExport({apiPass("image", "Image", "37", kImageCode, inputs)}));
    const auto& c = pass(desc, PassId::Image).channels;
    for (int i = 0; i < 4; ++i) EXPECT_EQ(c[i].kind, ChannelKind::StockMedia) << "iChannel" << i;
    EXPECT_EQ(c[0].media, kLondon);
    EXPECT_EQ(c[1].media, kGrayNoise);
    EXPECT_EQ(c[2].media, kRockTiles);
    EXPECT_EQ(c[3].media, kLondon);
    expectSampler(c[0].sampler, Filter::Mipmap, Wrap::Repeat, true, "texture mipmap/repeat/\"true\"");
    expectSampler(c[1].sampler, Filter::Nearest, Wrap::Clamp, false, "texture nearest/clamp/\"false\"");
    expectSampler(c[2].sampler, Filter::Linear, Wrap::Repeat, false, "texture linear/repeat/false (JSON)");
    expectSampler(c[3].sampler, Filter::Nearest, Wrap::Repeat, true, "texture nearest/repeat/true (JSON)");
    EXPECT_TRUE(desc.notices.empty());
}

TEST(ExportParse, TextureWithoutSamplerGetsShadertoyDefaults) {
    const std::string inputs = "[" + input("texture", "5", kLondon, 1) + "]";
    const ManifestDesc desc = parseOk(apiExport({apiPass("image", "Image", "37", kImageCode, inputs)}));
    const ChannelDesc& c = pass(desc, PassId::Image).channels[1];
    EXPECT_EQ(c.kind, ChannelKind::StockMedia);
    EXPECT_EQ(c.media, kLondon);
    expectSampler(c.sampler, Filter::Mipmap, Wrap::Repeat, true, "texture without sampler");
}

TEST(ExportParse, KeyboardIsAlwaysNearestClampWhateverTheSamplerSays) {
    const std::string inputs = "[" +
        input("keyboard", "33", "/presets/tex00.jpg", 3, samplerJson("linear", "repeat", "\"true\"")) + "," +
        input("keyboard", "33", "/presets/tex00.jpg", 0, samplerJson("mipmap", "repeat", "true")) + "," +
        input("keyboard", "33", "/presets/tex00.jpg", 1) + "]";
    const ManifestDesc desc = parseOk(apiExport({apiPass("image", "Image", "37", kImageCode, inputs)}));
    const auto& c = pass(desc, PassId::Image).channels;
    for (int i : {0, 1, 3}) {
        EXPECT_EQ(c[i].kind, ChannelKind::Keyboard) << "iChannel" << i;
        expectSampler(c[i].sampler, Filter::Nearest, Wrap::Clamp, false, "keyboard iChannel" + std::to_string(i));
    }
    EXPECT_EQ(c[2].kind, ChannelKind::None);
}

// ---------------------------------------------------------------------------------------------
// Inputs and passes the host cannot provide

TEST(ExportParse, EveryInputKindIsBoundWithItsSamplerTypeAndDefaults) {
    const std::string imageInputs = "[" + input("video", "11", "/media/a/v.webm", 0) + "," +
                                    input("music", "12", "/media/a/m.mp3", 1) + "," +
                                    input("musicstream", "13", "https://soundcloud.com/x", 2) + "," +
                                    input("mic", "32", "/presets/mic.png", 3) + "]";
    const std::string bufferInputs = "[" + input("webcam", "31", "/presets/webcam.png", 0) + "," +
                                     input("cubemap", "22", "/media/a/cube.png", 1) + "," +
                                     input("volume", "39", "/presets/tex3d.bin", 2) + "," +
                                     input("buffer", "257", "/media/previz/buffer00.png", 3) + "]";
    const ManifestDesc desc = parseOk(apiExport({apiPass("image", "Image", "37", kImageCode, imageInputs),
                                                 apiPass("buffer", "Buffer A", "257", "// a\n", bufferInputs)}));
    const auto& i = pass(desc, PassId::Image).channels;
    EXPECT_EQ(i[0].kind, ChannelKind::Video);
    EXPECT_EQ(i[0].media, "/media/a/v.webm");
    EXPECT_EQ(i[1].kind, ChannelKind::Music);
    EXPECT_EQ(i[2].kind, ChannelKind::Music);  // a SoundCloud stream plays as music
    EXPECT_EQ(i[2].media, "https://soundcloud.com/x");
    EXPECT_EQ(i[3].kind, ChannelKind::Mic);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(i[c].samplerType, SamplerType::Sampler2D) << c;
    const auto& a = pass(desc, PassId::BufferA).channels;
    EXPECT_EQ(a[0].kind, ChannelKind::Webcam);
    EXPECT_EQ(a[1].kind, ChannelKind::Cubemap);
    EXPECT_EQ(a[1].samplerType, SamplerType::SamplerCube);
    EXPECT_EQ(a[2].kind, ChannelKind::Volume);
    EXPECT_EQ(a[2].samplerType, SamplerType::Sampler3D);
    EXPECT_EQ(a[3].kind, ChannelKind::Buffer);
    EXPECT_TRUE(desc.notices.empty()) << noticeLines(desc).front();
}

TEST(ExportParse, AnUnknownInputKindIsLeftUnboundWithANoticeNamingPassChannelAndCtype) {
    const std::string inputs = "[" + input("hologram", "11", "/media/a/h.xyz", 2) + "]";
    const ManifestDesc desc = parseOk(apiExport({apiPass("image", "Image", "37", kImageCode, inputs)}));
    EXPECT_EQ(pass(desc, PassId::Image).channels[2].kind, ChannelKind::None);
    const std::vector<std::string> expected = {
        kLabel + ": notice: Image / iChannel2: \"hologram\" inputs are not a Shadertoy input kind; the channel is left "
                 "unbound [export.unsupported-input]"};
    EXPECT_EQ(noticeLines(desc), expected);
}

TEST(ExportParse, SoundPassIsKeptApartFromTheFramePasses) {
    const ManifestDesc desc = parseOk(apiExport({apiPass("sound", "Sound", "", "vec2 mainSound(int s, float t) { return vec2(0); }\n"),
                                                 apiPass("image", "Image", "37", kImageCode)}));
    EXPECT_EQ(passIds(desc), std::vector<PassId>{PassId::Image});
    ASSERT_TRUE(desc.sound.has_value());
    EXPECT_EQ(desc.sound->id, PassId::Sound);
    EXPECT_NE(desc.sound->code.find("mainSound"), std::string::npos);
    EXPECT_EQ(desc.sound->sourceName, kLabel + " [Sound]");
    EXPECT_TRUE(desc.notices.empty());
}

TEST(ExportParse, CubeAPassAndItsReadersByApiAndSiteIds) {
    const std::string inputs = "[" + input("cubemap", "41", "/media/previz/cubemap00.png", 0) + "]";
    const std::string siteInputs = R"([{"id": "4dX3Rr", "type": "cubemap", "filepath": "/media/previz/cubemap00.png", "channel": 1}])";
    const ManifestDesc desc = parseOk(apiExport({apiPass("image", "Image", "37", kImageCode, inputs),
                                                 apiPass("cubemap", "Cube A", "41", "// cube\n", siteInputs)}));
    EXPECT_EQ(passIds(desc), (std::vector<PassId>{PassId::CubeA, PassId::Image}));
    EXPECT_EQ(pass(desc, PassId::Image).channels[0].kind, ChannelKind::CubeBuffer);
    EXPECT_EQ(pass(desc, PassId::Image).channels[0].samplerType, SamplerType::SamplerCube);
    EXPECT_EQ(pass(desc, PassId::CubeA).channels[1].kind, ChannelKind::CubeBuffer);
    EXPECT_EQ(pass(desc, PassId::CubeA).sourceName, kLabel + " [Cube A]");
}

TEST(ExportParse, ReadingACubeAPassTheExportLacksStaysASamplerCubeWithANotice) {
    const std::string inputs = "[" + input("cubemap", "41", "/media/previz/cubemap00.png", 3) + "]";
    const ManifestDesc desc = parseOk(apiExport({apiPass("image", "Image", "37", kImageCode, inputs)}));
    const ChannelDesc& c = pass(desc, PassId::Image).channels[3];
    EXPECT_EQ(c.kind, ChannelKind::None);
    EXPECT_EQ(c.samplerType, SamplerType::SamplerCube);
    ASSERT_EQ(desc.notices.size(), 1u);
    expectMentions(formatDiagnostic(desc.notices[0]), {"Image / iChannel3", "reads Cube A, which the export does not define"});
}

TEST(ExportParse, ReadingABufferTheExportLacksUnbindsTheChannelWithANotice) {
    const std::string inputs = "[" + input("buffer", "257", "/media/previz/buffer00.png", 0) + "," +
                               input("buffer", "258", "/media/previz/buffer01.png", 1) + "]";
    const ManifestDesc desc = parseOk(apiExport({apiPass("image", "Image", "37", kImageCode, inputs),
                                                 apiPass("buffer", "Buffer A", "257", "// a\n", inputs)}));
    for (PassId id : {PassId::BufferA, PassId::Image}) {
        const auto& c = pass(desc, id).channels;
        EXPECT_EQ(c[0].kind, ChannelKind::Buffer) << passName(id);
        EXPECT_EQ(c[0].buffer, 0);
        EXPECT_EQ(c[1].kind, ChannelKind::None) << passName(id);
        EXPECT_EQ(c[1].buffer, -1);
    }
    const std::vector<std::string> expected = {
        kLabel + ": notice: Buffer A / iChannel1: reads Buffer B, which the export does not define; the channel is left unbound [export.missing-buffer]",
        kLabel + ": notice: Image / iChannel1: reads Buffer B, which the export does not define; the channel is left unbound [export.missing-buffer]",
    };
    EXPECT_EQ(noticeLines(desc), expected);
}

// ---------------------------------------------------------------------------------------------
// Broken exports

TEST(ExportParse, InvalidJsonNamesThePath) {
    const std::string message = parseError(R"({"Shader": {"renderpass": [)");
    expectMentions(message, {kLabel + ":1:28: invalid JSON: the text ends too early"});
}

TEST(ExportParse, NotAnExport) {
    for (const char* text : {R"({"foo": 1})", "[]", "42", R"({"passes": {"Image": {"source": "image.glsl"}}})"}) {
        const std::string message = parseError(text);
        expectMentions(message, {kLabel + ": not a Shadertoy export"});
    }
}

// The site's array form holds one shader; an array of several is named as such, shader by shader,
// not reported as "not a Shadertoy export" (or, through loadShadertoy, as a bad manifest).
TEST(ExportParse, SeveralShadersInOneFileAreNamed) {
    const std::string two = R"([{"ver": "0.1", "info": {"id": "aaaaaa", "name": "First"}, "renderpass": []},
                                {"ver": "0.1", "info": {"id": "bbbbbb", "name": "Second"}, "renderpass": []}])";
    const std::string message = parseError(two);
    expectMentions(message, {kLabel + ": the file holds 2 shaders ([0] \"First\" (id aaaaaa), [1] \"Second\" (id bbbbbb))",
                             "toyhost runs one shader per file"});
    EXPECT_EQ(message.find("not a Shadertoy export"), std::string::npos) << message;
    expectMentions(parseError(R"([{"Shader": {"info": {"name": "A"}, "renderpass": []}}, {"Shader": {"renderpass": []}},
                                  {"Shader": {"info": {"id": "ccc"}}}, {"Shader": {}}])"),
                   {"holds 4 shaders ([0] \"A\", [1] a shader without \"info\", [2] id ccc, ...)"});
}

// {"info": {}} is an export without its passes: said in export terms ("renderpass"), once.
TEST(ExportParse, AnExportWithoutRenderpassSaysSo) {
    for (const char* text : {R"({"info": {}})", R"({"ver": "0.1", "info": {"name": "x"}})", R"([{"info": {}}])"}) {
        const std::string message = parseError(text);
        expectMentions(message, {kLabel + ": a broken Shadertoy export: ", "renderpass: is missing"});
    }
    expectMentions(parseError(R"({"Shader": {"renderpass": ""}})"),
                   {"Shader.renderpass: must be an array of passes, not an empty string"});
}

// What `toyhost run FILE` does with each shape: exports are parsed as exports (one export.shape
// line), anything else as a manifest.
TEST(LoadShadertoy, ExportShapesAreReportedAsExportsNotManifests) {
    toyhost::testing::TestFolder folder;
    for (const char* text : {R"({"info": {}})", R"([{"info": {"name": "A"}, "renderpass": []}, {"info": {"name": "B"}, "renderpass": []}])",
                             R"({"Shader": {"info": {}}})"}) {
        const fs::path file = folder.write("export.json", text);
        Result<ManifestDesc> loaded = loadShadertoy(file);
        ASSERT_FALSE(loaded.ok()) << text;
        ASSERT_EQ(loaded.error().diagnostics.size(), 1u) << text << "\n" << loaded.error().text();
        EXPECT_EQ(loaded.error().first().code, Code::ExportShape) << text << "\n" << loaded.error().text();
    }
    // A manifest that happens to have an "info" field is still a manifest (its unknown field named).
    const fs::path manifest = folder.write("m.json", R"({"info": {}, "passes": {"Image": {"source": "image.glsl"}}})");
    folder.write("image.glsl", "void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n");
    Result<ManifestDesc> loaded = loadShadertoy(manifest);
    ASSERT_FALSE(loaded.ok());
    EXPECT_EQ(loaded.error().first().code, Code::ManifestUnknownField) << loaded.error().text();
}

TEST(ExportParse, NoImagePass) {
    expectMentions(parseError(apiExport({apiPass("buffer", "Buffer A", "257", "// a\n")})),
                   {kLabel + ": the export has no image pass"});
    expectMentions(parseError(R"({"Shader": {"renderpass": []}})"), {kLabel, "no image pass"});
}

TEST(ExportParse, PassWithoutCode) {
    const std::string noCode = R"({"inputs": [], "outputs": [{"id": 257, "channel": 0}], "name": "Buffer A", "type": "buffer"})";
    const std::string nullCode = R"({"inputs": [], "outputs": [], "code": null, "name": "Common", "type": "common"})";
    const std::string message = parseError(apiExport({apiPass("image", "Image", "37", kImageCode), noCode, nullCode}));
    expectMentions(message, {kLabel + ": renderpass[1].code: is missing or not a string",
                             kLabel + ": renderpass[2].code: is missing or not a string"});
}

TEST(ExportParse, TwoImagePasses) {
    const std::string message = parseError(apiExport({apiPass("image", "Image", "37", kImageCode),
                                                      apiPass("image", "Image", "37", kImageCode)}));
    expectMentions(message, {kLabel + ": Image: renderpass[1]: a second Image pass"});
}

TEST(ExportParse, TwoPassesWithTheSameBufferId) {
    const std::string message = parseError(apiExport({apiPass("buffer", "Buffer A", "257", "// a\n"),
                                                      apiPass("buffer", "Buffer B", "257", "// b\n"),
                                                      apiPass("image", "Image", "37", kImageCode)}));
    expectMentions(message, {kLabel + ": Buffer A: renderpass[1]: a second Buffer A pass"});
}

TEST(ExportParse, InputOnChannelSeven) {
    const std::string inputs = "[" + input("buffer", "257", "/media/previz/buffer00.png", 7) + "]";
    const std::string message = parseError(apiExport({apiPass("buffer", "Buffer A", "257", "// a\n"),
                                                      apiPass("image", "Image", "37", kImageCode, inputs)}));
    expectMentions(message, {kLabel + ": Image: renderpass[1].inputs[0].channel: 7 is not 0..3"});
}

TEST(ExportParse, UnknownFilterAndWrapNameBufferAndChannel) {
    const std::string inputs = "[" + input("texture", "5", kLondon, 2, samplerJson("trilinear", "repeat", "\"true\"")) + "," +
                               input("texture", "5", kLondon, 1, samplerJson("linear", "mirror", "\"true\"")) + "]";
    const std::string message = parseError(apiExport({apiPass("image", "Image", "37", kImageCode),
                                                      apiPass("buffer", "Buffer B", "258", "// b\n", inputs)}));
    expectMentions(message, {kLabel + ": Buffer B / iChannel2: renderpass[1].inputs[0].sampler.filter: unknown filter \"trilinear\"",
                             kLabel + ": Buffer B / iChannel1: renderpass[1].inputs[1].sampler.wrap: unknown wrap \"mirror\""});
}

TEST(ExportParse, BufferInputWithUnknownId) {
    const std::string inputs = "[" + input("buffer", "999", "/media/previz/whatever.png", 1) + "]";
    const std::string message = parseError(apiExport({apiPass("image", "Image", "37", kImageCode, inputs)}));
    expectMentions(message, {kLabel + ": Image / iChannel1: renderpass[0].inputs[0].id: buffer input with an unknown id 999"});
}

TEST(ExportParse, ChannelBoundTwice) {
    const std::string inputs = "[" + input("texture", "5", kLondon, 0) + "," + input("keyboard", "33", "/presets/tex00.jpg", 0) + "]";
    const std::string message = parseError(apiExport({apiPass("image", "Image", "37", kImageCode, inputs)}));
    expectMentions(message, {kLabel + ": Image / iChannel0: renderpass[0].inputs[1].channel: iChannel0 is bound twice"});
}

TEST(ExportParse, UnknownPassTypeAndUnidentifiableBuffer) {
    const std::string message = parseError(apiExport({apiPass("image", "Image", "37", kImageCode),
                                                      apiPass("shader", "Weird", "", "// w\n"),
                                                      apiPass("buffer", "Scratch", "37", "// s\n")}));
    expectMentions(message, {kLabel + ": renderpass[1].type: unknown pass type \"shader\"",
                             kLabel + ": renderpass[2].outputs: buffer pass without a Buffer A..D output id"});
}

TEST(ExportParse, EveryProblemIsReportedOnItsOwnLine) {
    const std::string inputs = "[" + input("buffer", "999", "/x.png", 0) + "]";
    const std::string message = parseError(apiExport({apiPass("image", "Image", "37", kImageCode, inputs),
                                                      apiPass("hologram", "Holo", "41", "// c\n")}));
    EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
    expectMentions(message, {"Image / iChannel0", "renderpass[1].type"});
}

// ---------------------------------------------------------------------------------------------
// Ids and document shapes

TEST(ExportIds, BufferIndexFromExportId) {
    EXPECT_EQ(bufferIndexFromExportId(json(257)), 0);
    EXPECT_EQ(bufferIndexFromExportId(json(258)), 1);
    EXPECT_EQ(bufferIndexFromExportId(json(259)), 2);
    EXPECT_EQ(bufferIndexFromExportId(json(260)), 3);
    EXPECT_EQ(bufferIndexFromExportId(json("257")), 0);
    EXPECT_EQ(bufferIndexFromExportId(json("258")), 1);
    EXPECT_EQ(bufferIndexFromExportId(json("259")), 2);
    EXPECT_EQ(bufferIndexFromExportId(json("260")), 3);
    EXPECT_EQ(bufferIndexFromExportId(json("4dXGR8")), 0);
    EXPECT_EQ(bufferIndexFromExportId(json("XsXGR8")), 1);
    EXPECT_EQ(bufferIndexFromExportId(json("4sXGR8")), 2);
    EXPECT_EQ(bufferIndexFromExportId(json("XdfGR8")), 3);
    EXPECT_EQ(bufferIndexFromExportId(json(37)), -1);   // Image output
    EXPECT_EQ(bufferIndexFromExportId(json(33)), -1);   // keyboard
    EXPECT_EQ(bufferIndexFromExportId(json(256)), -1);
    EXPECT_EQ(bufferIndexFromExportId(json(261)), -1);
    EXPECT_EQ(bufferIndexFromExportId(json(-257)), -1);
    EXPECT_EQ(bufferIndexFromExportId(json("foo")), -1);
    EXPECT_EQ(bufferIndexFromExportId(json("4dX3Rr")), -1);  // Cube A
    EXPECT_EQ(bufferIndexFromExportId(json("4dXGRr")), -1);  // keyboard (site form)
    EXPECT_EQ(bufferIndexFromExportId(json("4dxgr8")), -1);  // ids are case-sensitive
    EXPECT_EQ(bufferIndexFromExportId(json("2570")), -1);
    EXPECT_EQ(bufferIndexFromExportId(json()), -1);
    EXPECT_EQ(bufferIndexFromExportId(json::array({257})), -1);
}

TEST(ExportIds, IsShadertoyExport) {
    for (const char* yes : {R"({"Shader": {"renderpass": []}})",
                            R"({"Shader": {"info": {}, "renderpass": [{"type": "image"}]}})",
                            R"({"ver": "0.1", "info": {}, "renderpass": []})",
                            R"([{"ver": "0.1", "info": {}, "renderpass": []}])",
                            R"([{"Shader": {"renderpass": []}}])",
                            // Broken exports are still exports: their problems are reported in
                            // export terms (renderpass: must be an array), not as a bad manifest.
                            R"({"Shader": {}})", R"({"Shader": {"renderpass": {}}})", R"({"Shader": []})",
                            R"({"renderpass": "image"})", R"({"info": {}})", R"({"ver": "0.1"})",
                            // Several shaders: an export toyhost refuses, naming them.
                            R"([{"renderpass": []}, {"renderpass": []}])", R"([{"info": {}}, {"Shader": {}}])"})
        EXPECT_TRUE(isShadertoyExport(json::parse(yes))) << yes;
    for (const char* no : {R"({"foo": 1})", "[]", R"([{"renderpass": []}, 5])", R"([[{"renderpass": []}]])", "42",
                           "null", R"("renderpass")",
                           R"({"name": "m", "passes": {"Image": {"source": "image.glsl"}}})",
                           R"({"info": {}, "passes": {"Image": {"source": "image.glsl"}}})"})
        EXPECT_FALSE(isShadertoyExport(json::parse(no))) << no;
}

// ---------------------------------------------------------------------------------------------
// The public corpus: real API exports

fs::path corpusDir() { return (fs::path(TOYHOST_SOURCE_DIR) / ".." / "shared" / "corpus" / "public").lexically_normal(); }

std::vector<fs::path> corpusFiles() {
    std::vector<fs::path> files;
    std::error_code ec;
    if (!fs::is_directory(corpusDir(), ec)) return files;
    for (const auto& entry : fs::directory_iterator(corpusDir()))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

TEST(ExportCorpus, EveryPublicExportParsesWithItsPassesAndInputs) {
    const std::vector<fs::path> files = corpusFiles();
    if (files.empty()) GTEST_SKIP() << "needs ../shared/corpus/public beside the repository";
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.filename().string());
        const std::string text = readFile(file);
        const json document = json::parse(text);
        ASSERT_TRUE(isShadertoyExport(document));
        Result<ManifestDesc> parsed = parseShadertoyExport(text, file);
        ASSERT_TRUE(parsed.ok()) << parsed.error().text();
        const ManifestDesc& desc = *parsed;
        ASSERT_NE(desc.find(PassId::Image), nullptr);
        EXPECT_EQ(desc.passes.back().id, PassId::Image);
        for (size_t i = 1; i < desc.passes.size(); ++i) EXPECT_LT(desc.passes[i - 1].id, desc.passes[i].id);

        const json& shader = document.contains("Shader") ? document["Shader"] : document;
        int bufferPasses = 0;
        std::set<int> definedBuffers;
        for (const json& rp : shader["renderpass"])
            if (rp["type"] == "buffer") definedBuffers.insert(bufferIndexFromExportId(rp["outputs"][0]["id"]));
        size_t expectedNotices = 0;
        for (const json& rp : shader["renderpass"]) {
            const std::string type = rp["type"];
            PassId id = PassId::Image;
            if (type == "common") {
                EXPECT_EQ(desc.commonCode, rp["code"].get<std::string>());
                EXPECT_EQ(desc.commonName, file.string() + " [Common]");
                continue;
            }
            if (type == "buffer") {
                ++bufferPasses;
                const int index = bufferIndexFromExportId(rp["outputs"][0]["id"]);
                ASSERT_GE(index, 0) << rp["outputs"].dump();
                id = bufferPass(index);
                ASSERT_TRUE(desc.hasBuffer(index)) << passName(id);
            }
            const PassDesc& p = pass(desc, id);
            EXPECT_EQ(p.code, rp["code"].get<std::string>()) << passName(id);
            EXPECT_EQ(p.sourceName, file.string() + " [" + passName(id) + "]");
            std::set<int> boundChannels;
            for (const json& in : rp["inputs"]) {
                const int c = in["channel"];
                boundChannels.insert(c);
                const std::string ctype = in["ctype"];
                const ChannelDesc& channel = p.channels[c];
                const std::string where = std::string(passName(id)) + " / iChannel" + std::to_string(c);
                if (ctype == "keyboard") {
                    EXPECT_EQ(channel.kind, ChannelKind::Keyboard) << where;
                    expectSampler(channel.sampler, Filter::Nearest, Wrap::Clamp, false, where);
                } else if (ctype == "texture") {
                    EXPECT_EQ(channel.kind, ChannelKind::StockMedia) << where;
                    EXPECT_EQ(channel.media, in["src"].get<std::string>()) << where;
                    EXPECT_EQ(filterName(channel.sampler.filter), in["sampler"]["filter"].get<std::string>()) << where;
                    EXPECT_EQ(wrapName(channel.sampler.wrap), in["sampler"]["wrap"].get<std::string>()) << where;
                    EXPECT_EQ(channel.sampler.vflip, in["sampler"]["vflip"] == "true") << where;
                } else if (ctype == "buffer") {
                    const int buffer = bufferIndexFromExportId(in["id"]);
                    if (definedBuffers.count(buffer)) {
                        EXPECT_EQ(channel.kind, ChannelKind::Buffer) << where;
                        EXPECT_EQ(channel.buffer, buffer) << where;
                        EXPECT_EQ(filterName(channel.sampler.filter), in["sampler"]["filter"].get<std::string>()) << where;
                        EXPECT_EQ(wrapName(channel.sampler.wrap), in["sampler"]["wrap"].get<std::string>()) << where;
                    } else {
                        EXPECT_EQ(channel.kind, ChannelKind::None) << where;
                        ++expectedNotices;
                    }
                } else {
                    ADD_FAILURE() << where << ": the corpus should hold no " << ctype << " inputs";
                }
            }
            for (int c = 0; c < kChannelCount; ++c)
                if (!boundChannels.count(c)) EXPECT_EQ(p.channels[c].kind, ChannelKind::None) << passName(id) << " " << c;
        }
        EXPECT_EQ(static_cast<int>(desc.passes.size()), bufferPasses + 1);
        EXPECT_EQ(desc.notices.size(), expectedNotices);

        // loadShadertoy recognises the file as an export and gives the same description.
        Result<ManifestDesc> loaded = loadShadertoy(file);
        ASSERT_TRUE(loaded.ok()) << loaded.error().text();
        EXPECT_EQ(passIds(*loaded), passIds(desc));
        EXPECT_EQ(loaded->name, desc.name);
    }
}

// ---------------------------------------------------------------------------------------------
// writeManifestFolder (toyhost import) and back through loadShadertoy

using TempFolder = toyhost::testing::TestFolder;

// `a` an export, `b` the folder it was imported to. A buffer channel's wrap in `b` is the one the
// site samples with in `a` (decided by the export's listed order, manifest/BufferWraps.h).
void expectSameChannels(const ManifestDesc& a, const ManifestDesc& b) {
    ASSERT_EQ(passIds(a), passIds(b));
    const BufferWraps wraps = siteBufferWraps(a);
    for (size_t i = 0; i < a.passes.size(); ++i) {
        const PassDesc& pa = a.passes[i];
        const PassDesc& pb = b.passes[i];
        EXPECT_EQ(pa.code, pb.code) << passName(pa.id) << ": code differs";
        for (int c = 0; c < kChannelCount; ++c) {
            const std::string where = std::string(passName(pa.id)) + " / iChannel" + std::to_string(c);
            const ChannelDesc& ca = pa.channels[c];
            const ChannelDesc& cb = pb.channels[c];
            EXPECT_EQ(ca.kind, cb.kind) << where;
            EXPECT_EQ(ca.buffer, cb.buffer) << where;
            // import writes a known stock texture by its site name ("London"): the same texture.
            if (const StockMediaInfo* stock = findStockMedia(ca.media)) EXPECT_EQ(findStockMedia(cb.media), stock) << where;
            else EXPECT_EQ(ca.media, cb.media) << where;
            EXPECT_EQ(ca.file, cb.file) << where;
            expectSampler(cb.sampler, ca.sampler.filter, wrapSampled(wraps, ca), ca.sampler.vflip, where);
        }
    }
    EXPECT_EQ(a.commonSource.has_value(), b.commonSource.has_value());
    EXPECT_EQ(a.commonCode, b.commonCode);
    EXPECT_EQ(a.mediaOverrides, b.mediaOverrides);
}

// Common with CRLF line endings and non-ASCII UTF-8 in a comment; buffers A and C (no B), every
// supported input kind with non-default samplers.
std::string roundTripExport() {
    const std::string common = "// Gr\xc3\xbc\xc3\x9f" "e \xe2\x86\x93 \xe6\xb3\xa2 \xf0\x9f\x8c\x8a\r\n"
                               "float helper() {\r\n    return 1.0;\r\n}\r\n";
    const std::string bufferA = "// \xc2\xa9 A\nvoid mainImage(out vec4 c, in vec2 p) {\n\tc = vec4(helper());\n}";  // no final newline
    const std::string bufferC = "void mainImage(out vec4 c, in vec2 p) { c = texture(iChannel0, p); }\r\n\r\n";
    const std::string aInputs = "[" +
                                input("buffer", "257", "/media/previz/buffer00.png", 0, samplerJson("nearest", "repeat", "\"true\"")) + "," +
                                input("keyboard", "33", "/presets/tex00.jpg", 3, samplerJson("linear", "clamp", "\"true\"")) + "]";
    const std::string cInputs = "[" +
                                input("buffer", "257", "/media/previz/buffer00.png", 0, samplerJson("mipmap", "clamp", "\"false\"")) + "," +
                                input("texture", "5", kLondon, 2, samplerJson("nearest", "clamp", "\"false\"")) + "]";
    const std::string imageInputs = "[" + input("buffer", "259", "/media/previz/buffer02.png", 1) + "," +
                                    input("texture", "17", kGrayNoise, 0, samplerJson("mipmap", "repeat", "\"true\"")) + "," +
                                    input("texture", "10", kRockTiles, 3, samplerJson("linear", "repeat", "\"false\"")) + "]";
    return apiExport({apiPass("image", "Image", "37", kImageCode, imageInputs), apiPass("common", "Common", "", common),
                      apiPass("buffer", "Buffer C", "259", bufferC, cInputs), apiPass("buffer", "Buffer A", "257", bufferA, aInputs)});
}

TEST(ExportImport, PassFileNames) {
    EXPECT_EQ(passFileName(PassId::BufferA), "buffer_a.glsl");
    EXPECT_EQ(passFileName(PassId::BufferB), "buffer_b.glsl");
    EXPECT_EQ(passFileName(PassId::BufferC), "buffer_c.glsl");
    EXPECT_EQ(passFileName(PassId::BufferD), "buffer_d.glsl");
    EXPECT_EQ(passFileName(PassId::Image), "image.glsl");
}

TEST(ExportImport, WrittenFolderLoadsBackIdentically) {
    TempFolder temp;
    const ManifestDesc exported = parseOk(roundTripExport());
    ASSERT_EQ(passIds(exported), (std::vector<PassId>{PassId::BufferA, PassId::BufferC, PassId::Image}));
    Status written = writeManifestFolder(exported, temp.path / "toy", false);
    ASSERT_TRUE(written.ok()) << written.error().text();

    // The pass files hold the code byte for byte (CRLF and UTF-8 untouched).
    EXPECT_EQ(readFile(temp.path / "toy" / "common.glsl"), exported.commonCode);
    EXPECT_EQ(readFile(temp.path / "toy" / "buffer_a.glsl"), pass(exported, PassId::BufferA).code);
    EXPECT_EQ(readFile(temp.path / "toy" / "buffer_c.glsl"), pass(exported, PassId::BufferC).code);
    EXPECT_EQ(readFile(temp.path / "toy" / "image.glsl"), kImageCode);
    EXPECT_FALSE(fs::exists(temp.path / "toy" / "buffer_b.glsl"));
    EXPECT_NE(exported.commonCode.find("\r\n"), std::string::npos);

    Result<ManifestDesc> loaded = loadShadertoy(temp.path / "toy");
    ASSERT_TRUE(loaded.ok()) << loaded.error().text();
    expectSameChannels(exported, *loaded);
    EXPECT_EQ(loaded->name, "Synthetic (tSt123 by tester)");
    EXPECT_EQ(loaded->commonCode, exported.commonCode);
    EXPECT_EQ(loaded->manifestPath, temp.path / "toy" / "manifest.json");
    EXPECT_EQ(pass(*loaded, PassId::BufferC).source, temp.path / "toy" / "buffer_c.glsl");
    EXPECT_TRUE(loaded->notices.empty());

    // Spot checks against the export itself, so a symmetric mistake cannot hide.
    const auto& a = pass(*loaded, PassId::BufferA).channels;
    EXPECT_EQ(a[3].kind, ChannelKind::Keyboard);
    expectSampler(a[0].sampler, Filter::Nearest, Wrap::Repeat, false, "Buffer A / iChannel0");
    const auto& c = pass(*loaded, PassId::BufferC).channels;
    EXPECT_EQ(c[2].media, "London");  // the site's name, which the loader accepts
    EXPECT_EQ(findStockMedia(c[2].media), findStockMedia(kLondon));
    // The export says clamp, but the site samples Buffer A with repeat: Buffer A's own iChannel0
    // (repeat) is its last created reader, Buffer A being listed after Buffer C.
    expectSampler(c[0].sampler, Filter::Mipmap, Wrap::Repeat, false, "Buffer C / iChannel0");
    expectSampler(c[2].sampler, Filter::Nearest, Wrap::Clamp, false, "Buffer C / iChannel2");
    const auto& image = pass(*loaded, PassId::Image).channels;
    EXPECT_EQ(image[1].buffer, 2);
    expectSampler(image[0].sampler, Filter::Mipmap, Wrap::Repeat, true, "Image / iChannel0");
    expectSampler(image[3].sampler, Filter::Linear, Wrap::Repeat, false, "Image / iChannel3");
    EXPECT_EQ(image[2].kind, ChannelKind::None);
}

// The buffer wrap quirk follows an export's listed order, which a manifest cannot hold: Image is
// listed first and Buffer A's repeat input last, so the site samples Buffer A with repeat
// everywhere, while render order (A, then Image) ends on Image's clamp. The imported folder must
// sample as the export does (it sampled with clamp before).
TEST(ExportImport, TheImportedFolderKeepsTheWrapTheExportsOrderGives) {
    const std::string aInputs = "[" +
        input("buffer", "257", "/media/previz/buffer00.png", 2, samplerJson("linear", "clamp", "\"false\"")) + "," +
        input("buffer", "257", "/media/previz/buffer00.png", 0, samplerJson("linear", "repeat", "\"false\"")) + "]";
    const std::string imageInputs = "[" + input("buffer", "257", "/media/previz/buffer00.png", 0,
                                                samplerJson("linear", "clamp", "\"false\"")) + "]";
    const ManifestDesc exported = parseOk(apiExport({apiPass("image", "Image", "37", kImageCode, imageInputs),
                                                     apiPass("buffer", "Buffer A", "257", "// a\n", aInputs)}));
    const PassGraph fromExport = buildPassGraph(exported);
    ASSERT_EQ(fromExport.passes.back().id, PassId::Image);
    EXPECT_EQ(fromExport.passes.back().channels[0].sampler.wrap, Wrap::Repeat);

    TempFolder temp;
    ASSERT_TRUE(writeManifestFolder(exported, temp.path / "toy", false).ok());
    Result<ManifestDesc> imported = loadShadertoy(temp.path / "toy");
    ASSERT_TRUE(imported.ok()) << imported.error().text();
    const PassGraph fromFolder = buildPassGraph(*imported);
    ASSERT_EQ(fromFolder.passes.size(), fromExport.passes.size());
    for (size_t i = 0; i < fromExport.passes.size(); ++i)
        for (int c = 0; c < kChannelCount; ++c)
            EXPECT_EQ(fromFolder.passes[i].channels[c].sampler.wrap, fromExport.passes[i].channels[c].sampler.wrap)
                << passName(fromExport.passes[i].id) << " / iChannel" << c;
    // What the manifest says is what the shader samples with.
    const json manifest = json::parse(readFile(temp.path / "toy" / "manifest.json"));
    EXPECT_EQ(manifest["passes"]["Image"]["channels"]["iChannel0"]["wrap"], "repeat");
    EXPECT_EQ(manifest["passes"]["Buffer A"]["channels"]["iChannel2"]["wrap"], "repeat");
}

TEST(ExportImport, ManifestJsonIsValidAndNamesThePassFiles) {
    const ManifestDesc exported = parseOk(roundTripExport());
    const json manifest = json::parse(manifestJson(exported));
    EXPECT_EQ(manifest["name"], "Synthetic (tSt123 by tester)");
    EXPECT_EQ(manifest["common"], "common.glsl");
    EXPECT_EQ(manifest["passes"]["Buffer A"]["source"], "buffer_a.glsl");
    EXPECT_EQ(manifest["passes"]["Buffer C"]["source"], "buffer_c.glsl");
    EXPECT_EQ(manifest["passes"]["Image"]["source"], "image.glsl");
    EXPECT_FALSE(manifest["passes"].contains("Buffer B"));
    EXPECT_EQ(manifest["passes"]["Buffer A"]["channels"]["iChannel3"], json::parse(R"({"keyboard": true})"));
    EXPECT_EQ(manifest["passes"]["Image"]["channels"]["iChannel1"],
              json::parse(R"({"buffer": "C", "filter": "linear", "wrap": "clamp"})"));
    EXPECT_FALSE(manifest["passes"]["Image"]["channels"].contains("iChannel2"));
}

TEST(ExportImport, RefusesToOverwriteAnExistingManifestUnlessAsked) {
    TempFolder temp;
    const fs::path dir = temp.path / "toy";
    ManifestDesc exported = parseOk(roundTripExport());
    ASSERT_TRUE(writeManifestFolder(exported, dir, false).ok());
    const std::string firstManifest = readFile(dir / "manifest.json");

    ManifestDesc changed = exported;
    for (PassDesc& p : changed.passes) p.code = "// changed " + std::string(passName(p.id)) + "\n";
    changed.name = "Changed";
    Status refused = writeManifestFolder(changed, dir, false);
    ASSERT_FALSE(refused.ok());
    expectMentions(refused.error().text(), {(dir / "manifest.json").string(), "already exists"});
    // Nothing was touched.
    EXPECT_EQ(readFile(dir / "manifest.json"), firstManifest);
    EXPECT_EQ(readFile(dir / "image.glsl"), kImageCode);
    EXPECT_EQ(readFile(dir / "buffer_a.glsl"), pass(exported, PassId::BufferA).code);

    Status forced = writeManifestFolder(changed, dir, true);
    ASSERT_TRUE(forced.ok()) << forced.error().text();
    EXPECT_EQ(readFile(dir / "image.glsl"), "// changed Image\n");
    Result<ManifestDesc> loaded = loadShadertoy(dir);
    ASSERT_TRUE(loaded.ok()) << loaded.error().text();
    EXPECT_EQ(loaded->name, "Changed");
    EXPECT_EQ(pass(*loaded, PassId::BufferA).code, "// changed Buffer A\n");

    // No temporary files are left beside the written ones.
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
    EXPECT_EQ(names, (std::set<std::string>{"manifest.json", "common.glsl", "buffer_a.glsl", "buffer_c.glsl", "image.glsl"}));
}

TEST(ExportImport, EveryPublicExportRoundTripsThroughAFolder) {
    const std::vector<fs::path> files = corpusFiles();
    if (files.empty()) GTEST_SKIP() << "needs ../shared/corpus/public beside the repository";
    TempFolder temp;
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.filename().string());
        Result<ManifestDesc> exported = parseShadertoyExport(readFile(file), file);
        ASSERT_TRUE(exported.ok()) << exported.error().text();
        const fs::path dir = temp.path / file.stem();
        Status written = writeManifestFolder(*exported, dir, false);
        ASSERT_TRUE(written.ok()) << written.error().text();
        Result<ManifestDesc> loaded = loadShadertoy(dir);
        ASSERT_TRUE(loaded.ok()) << loaded.error().text();
        expectSameChannels(*exported, *loaded);
        EXPECT_EQ(loaded->name, exported->name);
    }
}

}  // namespace
