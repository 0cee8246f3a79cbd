// Shadertoy JSON exports through the CLI: the originals run straight from their exports and give
// the same pixels as their manifests; `run export.json` and `run` of the folder `toyhost import`
// wrote give identical frames; the imported pass files are the export's code byte for byte;
// compile errors name the export, the pass and the line in that pass; bad exports are refused
// without writing a manifest.
#include "GlTestSupport.h"

#include <cstring>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "image/ImageWriters.h"
#include "export/ShadertoyExport.h"
#include "image/ImageFile.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const char* kDate = "2024-03-15T12:34:56";

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}


std::vector<std::string> fileNames(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// Decoded PNG pixels of two files are identical (and not empty).
void expectSamePng(const fs::path& expectedPath, const fs::path& actualPath) {
    auto expected = loadImageFile(expectedPath);
    auto actual = loadImageFile(actualPath);
    ASSERT_TRUE(expected.ok()) << expected.error().text();
    ASSERT_TRUE(actual.ok()) << actual.error().text();
    ASSERT_EQ(expected->width, actual->width);
    ASSERT_EQ(expected->height, actual->height);
    ASSERT_FALSE(expected->rgba.empty());
    size_t differing = 0;
    for (size_t i = 0; i < expected->rgba.size(); ++i) differing += expected->rgba[i] != actual->rgba[i];
    EXPECT_EQ(differing, 0u) << expectedPath << " and " << actualPath << " differ in " << differing << " bytes";
}

void expectSameExr(const fs::path& expectedPath, const fs::path& actualPath) {
    auto expected = readExr(expectedPath);
    auto actual = readExr(actualPath);
    ASSERT_TRUE(expected.ok()) << expected.error().text();
    ASSERT_TRUE(actual.ok()) << actual.error().text();
    ASSERT_EQ(expected->width, actual->width);
    ASSERT_EQ(expected->height, actual->height);
    ASSERT_EQ(expected->rgba.size(), actual->rgba.size());
    ASSERT_FALSE(expected->rgba.empty());
    // Bitwise, so NaNs compare too.
    EXPECT_EQ(std::memcmp(expected->rgba.data(), actual->rgba.data(), expected->rgba.size() * sizeof(float)), 0)
        << expectedPath << " and " << actualPath << " differ";
}

// Not a flat image: some pixel differs from the first one.
bool hasDetail(const fs::path& png) {
    auto image = loadImageFile(png);
    if (!image.ok()) return false;
    for (size_t i = 4; i + 3 < image->rgba.size(); i += 4)
        if (std::memcmp(&image->rgba[i], &image->rgba[0], 3) != 0) return true;
    return false;
}

// Every file the two runs wrote has the same decoded content.
void expectSameFrames(const fs::path& expectedDir, const fs::path& actualDir, size_t count) {
    const std::vector<std::string> names = fileNames(expectedDir);
    ASSERT_EQ(names.size(), count) << expectedDir;
    ASSERT_EQ(fileNames(actualDir), names);
    for (const std::string& name : names) {
        SCOPED_TRACE(name);
        if (fs::path(name).extension() == ".exr") expectSameExr(expectedDir / name, actualDir / name);
        else expectSamePng(expectedDir / name, actualDir / name);
    }
}

// The pass file `toyhost import` writes for a renderpass of the export.
std::string importedFileFor(const json& renderpass) {
    const std::string type = renderpass["type"];
    if (type == "common") return "common.glsl";
    if (type == "image") return "image.glsl";
    const int index = bufferIndexFromExportId(renderpass["outputs"][0]["id"]);
    return std::string("buffer_") + static_cast<char>('a' + index) + ".glsl";
}

const json& renderpasses(const json& document) {
    return document.contains("Shader") ? document["Shader"]["renderpass"] : document["renderpass"];
}

fs::path corpusFile(const std::string& id) { return (sharedDir() / "corpus/public" / (id + ".json")).lexically_normal(); }

// ---------------------------------------------------------------------------------------------
// The originals straight from their exports

TEST(ExportRun, OriginalsRunFromTheirExports) {
    TOYHOST_REQUIRE_SHARED("shadertoys/MdXyzX/MdXyzX.json");
    TOYHOST_REQUIRE_SHARED("shadertoys/7tSSDD/7tSSDD.json");
    const fs::path dir = freshOutputDir("export-run/originals");
    for (const char* id : {"MdXyzX", "7tSSDD"}) {
        SCOPED_TRACE(id);
        const fs::path out = dir / (std::string(id) + "_%d.png");
        auto run = runToyhost("run " + quoted(sharedDir() / "shadertoys" / id / (std::string(id) + ".json")) +
                              " --size 64x36 --frames 3 --quiet --date " + kDate + " --out " + quoted(out));
        ASSERT_EQ(run.exitCode, 0) << run.output;
        EXPECT_TRUE(fs::exists(dir / (std::string(id) + "_2.png")));
        EXPECT_TRUE(hasDetail(dir / (std::string(id) + "_2.png"))) << id << " rendered a flat frame";
    }
}

TEST(ExportRun, OceanExportGivesTheManifestsPixels) {
    TOYHOST_REQUIRE_SHARED("shadertoys/MdXyzX/MdXyzX.json");
    const fs::path dir = freshOutputDir("export-run/ocean");
    for (const char* startTime : {"0", "4"}) {
        SCOPED_TRACE(startTime);
        const std::string common = std::string(" --size 160x90 --frames 1 --quiet --start-time ") + startTime + " --out ";
        const fs::path fromExport = dir / (std::string("export_t") + startTime + ".png");
        const fs::path fromManifest = dir / (std::string("manifest_t") + startTime + ".png");
        auto a = runToyhost("run " + quoted(sharedDir() / "shadertoys/MdXyzX/MdXyzX.json") + common + quoted(fromExport));
        ASSERT_EQ(a.exitCode, 0) << a.output;
        auto b = runToyhost("run " + quoted(sourceDir() / "shadertoys/ocean") + common + quoted(fromManifest));
        ASSERT_EQ(b.exitCode, 0) << b.output;
        expectSamePng(fromManifest, fromExport);
        EXPECT_TRUE(hasDetail(fromExport));
    }
}

TEST(ExportRun, MountainsLakesExportGivesTheManifestsPixels) {
    TOYHOST_REQUIRE_SHARED("shadertoys/7tSSDD/7tSSDD.json");
    const fs::path dir = freshOutputDir("export-run/mountains-lakes");
    const std::string common = std::string(" --size 96x54 --frames 4 --quiet --date ") + kDate + " --out ";
    auto a = runToyhost("run " + quoted(sharedDir() / "shadertoys/7tSSDD/7tSSDD.json") + common + quoted(dir / "export/f_%d.png"));
    ASSERT_EQ(a.exitCode, 0) << a.output;
    auto b = runToyhost("run " + quoted(sourceDir() / "shadertoys/mountains-lakes") + common + quoted(dir / "manifest/f_%d.png"));
    ASSERT_EQ(b.exitCode, 0) << b.output;
    expectSameFrames(dir / "manifest", dir / "export", 4);
}

// ---------------------------------------------------------------------------------------------
// run export.json == run of its imported folder

struct ImportCase {
    const char* name;
    const char* sharedPath;  // relative to ../shared
    const char* bufferToDump;
    friend void PrintTo(const ImportCase& c, std::ostream* os) { *os << c.name; }
};

class ExportImportRun : public ::testing::TestWithParam<ImportCase> {};

TEST_P(ExportImportRun, ExportAndImportedFolderGiveIdenticalFrames) {
    const ImportCase& c = GetParam();
    TOYHOST_REQUIRE_SHARED(c.sharedPath);
    const fs::path exportFile = (sharedDir() / c.sharedPath).lexically_normal();
    const fs::path dir = freshOutputDir(std::string("export-run/import-") + c.name);
    const fs::path imported = dir / "imported";

    auto import = runToyhost("import " + quoted(exportFile) + " " + quoted(imported));
    ASSERT_EQ(import.exitCode, 0) << import.output;
    ASSERT_TRUE(fs::exists(imported / "manifest.json")) << import.output;
    EXPECT_NE(import.output.find("imported"), std::string::npos) << import.output;

    // Scripted keys and mouse, so keyboard and iMouse inputs carry something.
    writeFile(dir / "keys.json", R"([{"frame": 2, "type": "down", "key": "R"}, {"frame": 3, "type": "down", "key": "O"},
                                     {"frame": 5, "type": "up", "key": "R"}, {"frame": 6, "type": "up", "key": "O"}])");
    writeFile(dir / "mouse.json", R"([{"frame": 1, "type": "down", "x": 40, "y": 30}, {"frame": 4, "type": "move", "x": 90, "y": 50},
                                      {"frame": 7, "type": "up"}])");
    const std::string options = std::string(" --size 160x90 --frames 10 --quiet --date ") + kDate + " --key-script " +
                                quoted(dir / "keys.json") + " --mouse-script " + quoted(dir / "mouse.json");
    for (const auto& [label, target] : {std::pair{"export", exportFile}, std::pair{"folder", imported}}) {
        auto image = runToyhost("run " + quoted(target) + options + " --out " + quoted(dir / label / "image_%02d.png"));
        ASSERT_EQ(image.exitCode, 0) << label << ": " << image.output;
        auto buffer = runToyhost("run " + quoted(target) + options + " --capture-pass " + c.bufferToDump + " --out " +
                                 quoted(dir / (std::string(label) + "_buffer") / "buffer_%02d.exr"));
        ASSERT_EQ(buffer.exitCode, 0) << label << ": " << buffer.output;
    }
    expectSameFrames(dir / "export", dir / "folder", 10);
    expectSameFrames(dir / "export_buffer", dir / "folder_buffer", 10);
    EXPECT_TRUE(hasDetail(dir / "export" / "image_09.png")) << c.name << " rendered a flat last frame";
}

INSTANTIATE_TEST_SUITE_P(Shaders, ExportImportRun,
                         ::testing::Values(ImportCase{"MountainsLakes", "shadertoys/7tSSDD/7tSSDD.json", "C"},
                                           ImportCase{"WavesKeyboard", "corpus/public/4cdXR8.json", "A"},
                                           ImportCase{"TriplePendulumKeyboard", "corpus/public/lclcz4.json", "A"}),
                         [](const auto& info) { return std::string(info.param.name); });

// The buffer wrap quirk follows the export's listed order, which a manifest cannot hold: Image is
// listed first and Buffer A's repeat input last, so on the site Buffer A wraps with repeat, which
// Image shows by sampling it at -0.5..1.5. Render order (Buffer A, then Image) would end on Image's
// clamp. The imported folder must render what the export renders (it rendered clamp before).
TEST(ExportRun, ImportedFolderKeepsTheWrapOfTheExportsOrder) {
    const fs::path dir = freshOutputDir("export-run/import-wrap-order");
    auto channel = [](int n, const char* wrap) {
        return json{{"id", 257}, {"src", "/media/previz/buffer00.png"}, {"ctype", "buffer"}, {"channel", n},
                    {"sampler", {{"filter", "nearest"}, {"wrap", wrap}, {"vflip", "true"}, {"srgb", "false"},
                                 {"internal", "byte"}}},
                    {"published", 1}};
    };
    auto pass = [](const char* type, const char* name, int output, const char* code, json inputs) {
        return json{{"inputs", inputs}, {"outputs", json::array({{{"id", output}, {"channel", 0}}})}, {"code", code},
                    {"name", name}, {"description", ""}, {"type", type}};
    };
    const json document = {
        {"Shader",
         {{"ver", "0.1"},
          {"info", {{"id", "tWrap1"}, {"name", "Wrap order"}, {"username", "tester"}, {"description", ""},
                    {"tags", json::array()}, {"published", 3}}},
          {"renderpass",
           json::array({pass("image", "Image", 37,
                             "void mainImage(out vec4 c, in vec2 f) {\n"
                             "    c = texture(iChannel0, f / iResolution.xy * 2.0 - 0.5);\n}\n",
                             json::array({channel(0, "clamp")})),
                        pass("buffer", "Buffer A", 257,
                             "void mainImage(out vec4 c, in vec2 f) {\n"
                             "    vec2 uv = f / iResolution.xy;\n"
                             "    c = vec4(uv, step(0.5, fract(uv.x * 4.0)), 1.0);\n}\n",
                             json::array({channel(2, "clamp"), channel(0, "repeat")}))})}}}};
    writeFile(dir / "wrap.json", document.dump(2));
    auto import = runToyhost("import " + quoted(dir / "wrap.json") + " " + quoted(dir / "imported"));
    ASSERT_EQ(import.exitCode, 0) << import.output;
    const std::string options = " --size 64x36 --frames 2 --quiet --date " + std::string(kDate);
    for (const auto& [label, target] : {std::pair{"export", dir / "wrap.json"}, std::pair{"folder", dir / "imported"}}) {
        auto run = runToyhost("run " + quoted(target) + options + " --out " + quoted(dir / label / "f_%d.png"));
        ASSERT_EQ(run.exitCode, 0) << label << ": " << run.output;
    }
    expectSameFrames(dir / "export", dir / "folder", 2);
    // Repeat, not clamp: the left quarter samples Buffer A at u < 0, which repeat wraps to u + 1
    // (red near 1) and clamp would hold at u = 0 (red 0).
    auto frame = loadImageFile(dir / "export" / "f_1.png");
    ASSERT_TRUE(frame.ok()) << frame.error().text();
    const std::uint8_t* leftMiddle = &frame->rgba[4 * (18 * frame->width + 4)];
    EXPECT_GT(leftMiddle[0], 150) << "the export's Buffer A is sampled with clamp: the listed order is lost";
}

// The keyboard input of the imported folder is live: pressing R (reset the obstacles) changes
// 4cdXR8's Buffer A, in the export and in the imported folder alike.
TEST(ExportRun, KeyboardInputOfAnExportReachesTheShader) {
    TOYHOST_REQUIRE_SHARED("corpus/public/4cdXR8.json");
    const fs::path dir = freshOutputDir("export-run/keyboard");
    writeFile(dir / "keys.json", R"([{"frame": 1, "type": "down", "key": "R"}, {"frame": 3, "type": "up", "key": "R"}])");
    const std::string options = std::string(" --size 160x90 --frames 4 --quiet --capture-every 100 --capture-pass A --date ") + kDate;
    auto pressed = runToyhost("run " + quoted(corpusFile("4cdXR8")) + options + " --key-script " + quoted(dir / "keys.json") +
                              " --out " + quoted(dir / "pressed_%d.exr"));
    ASSERT_EQ(pressed.exitCode, 0) << pressed.output;
    auto idle = runToyhost("run " + quoted(corpusFile("4cdXR8")) + options + " --out " + quoted(dir / "idle_%d.exr"));
    ASSERT_EQ(idle.exitCode, 0) << idle.output;
    auto a = readExr(dir / "pressed_3.exr");
    auto b = readExr(dir / "idle_3.exr");
    ASSERT_TRUE(a.ok() && b.ok());
    ASSERT_EQ(a->rgba.size(), b->rgba.size());
    EXPECT_NE(std::memcmp(a->rgba.data(), b->rgba.data(), a->rgba.size() * sizeof(float)), 0)
        << "pressing R changed nothing in Buffer A: the keyboard channel is not bound";
}

// ---------------------------------------------------------------------------------------------
// The imported pass files are the export's code, byte for byte

void expectImportedFilesMatchExport(const fs::path& exportFile, const fs::path& imported) {
    const json document = json::parse(readFile(exportFile));
    std::vector<std::string> expectedNames = {"manifest.json"};
    for (const json& rp : renderpasses(document)) {
        const std::string name = importedFileFor(rp);
        expectedNames.push_back(name);
        EXPECT_EQ(readFile(imported / name), rp["code"].get<std::string>()) << exportFile << ": " << name;
    }
    std::sort(expectedNames.begin(), expectedNames.end());
    EXPECT_EQ(fileNames(imported), expectedNames);
}

TEST(ExportImportFiles, MountainsLakesPassFilesAreTheExportsAndTheOriginalsCode) {
    TOYHOST_REQUIRE_SHARED("shadertoys/7tSSDD/7tSSDD.json");
    const fs::path dir = freshOutputDir("export-run/import-files-7tSSDD");
    const fs::path exportFile = sharedDir() / "shadertoys/7tSSDD/7tSSDD.json";
    auto import = runToyhost("import " + quoted(exportFile) + " " + quoted(dir / "toy"));
    ASSERT_EQ(import.exitCode, 0) << import.output;
    EXPECT_NE(import.output.find("(5 passes + Common)"), std::string::npos) << import.output;
    expectImportedFilesMatchExport(exportFile, dir / "toy");
    const std::map<std::string, std::string> originals = {
        {"common.glsl", "common.glsl"},     {"buffer_a.glsl", "bufferA.glsl"}, {"buffer_b.glsl", "bufferB.glsl"},
        {"buffer_c.glsl", "bufferC.glsl"}, {"buffer_d.glsl", "bufferD.glsl"}, {"image.glsl", "image.glsl"}};
    for (const auto& [imported, original] : originals) {
        const std::string originalText = readFile(sharedDir() / "shadertoys/7tSSDD" / original);
        ASSERT_FALSE(originalText.empty()) << original;
        EXPECT_EQ(readFile(dir / "toy" / imported), originalText) << imported << " vs " << original;
    }
    // The manifest binds what the export binds.
    const json manifest = json::parse(readFile(dir / "toy" / "manifest.json"));
    EXPECT_EQ(manifest["common"], "common.glsl");
    EXPECT_EQ(manifest["passes"]["Buffer A"]["channels"]["iChannel0"]["buffer"], "C");
    EXPECT_EQ(manifest["passes"]["Buffer A"]["channels"]["iChannel1"]["buffer"], "D");
    // The export's /media/a/8979352a...jpg, written by the site's name.
    EXPECT_EQ(manifest["passes"]["Image"]["channels"]["iChannel1"]["media"], "Abstract 3");
    EXPECT_EQ(manifest["passes"]["Image"]["channels"]["iChannel1"]["filter"], "mipmap");
    EXPECT_EQ(manifest["passes"]["Image"]["channels"]["iChannel1"]["vflip"], true);
}

TEST(ExportImportFiles, EveryPublicExportImportsByteForByte) {
    TOYHOST_REQUIRE_SHARED("corpus/public/4cdXR8.json");
    const fs::path dir = freshOutputDir("export-run/import-files-corpus");
    int count = 0;
    for (const auto& entry : fs::directory_iterator(sharedDir() / "corpus/public")) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().filename().string());
        const fs::path target = dir / entry.path().stem();
        auto import = runToyhost("import " + quoted(entry.path()) + " " + quoted(target));
        ASSERT_EQ(import.exitCode, 0) << import.output;
        expectImportedFilesMatchExport(entry.path(), target);
        ++count;
    }
    EXPECT_GE(count, 40);
}

TEST(ExportImportFiles, RefusesToOverwriteWithoutForce) {
    TOYHOST_REQUIRE_SHARED("corpus/public/lclcz4.json");
    const fs::path dir = freshOutputDir("export-run/import-force");
    const fs::path target = dir / "toy";
    ASSERT_EQ(runToyhost("import " + quoted(corpusFile("lclcz4")) + " " + quoted(target)).exitCode, 0);
    writeFile(target / "image.glsl", "// edited by hand\n");
    auto again = runToyhost("import " + quoted(corpusFile("lclcz4")) + " " + quoted(target));
    EXPECT_NE(again.exitCode, 0) << again.output;
    EXPECT_NE(again.output.find((target / "manifest.json").string() + ": error: already exists"), std::string::npos) << again.output;
    EXPECT_NE(again.output.find("--force"), std::string::npos) << again.output;
    EXPECT_EQ(readFile(target / "image.glsl"), "// edited by hand\n");
    auto forced = runToyhost("import " + quoted(corpusFile("lclcz4")) + " " + quoted(target) + " --force");
    EXPECT_EQ(forced.exitCode, 0) << forced.output;
    EXPECT_NE(readFile(target / "image.glsl"), "// edited by hand\n");
    expectImportedFilesMatchExport(corpusFile("lclcz4"), target);
}

// ---------------------------------------------------------------------------------------------
// Compile errors in a multi-pass export name the export, the pass and the line in that pass

json syntheticExport() {
    return json::parse(R"({"Shader": {"ver": "0.1", "info": {"id": "errTst", "name": "Errors", "username": "tests"},
      "renderpass": [
        {"inputs": [{"id": 258, "src": "/media/previz/buffer01.png", "ctype": "buffer", "channel": 0,
                     "sampler": {"filter": "linear", "wrap": "clamp", "vflip": "true", "srgb": "false", "internal": "byte"}}],
         "outputs": [{"id": 37, "channel": 0}], "name": "Image", "description": "", "type": "image",
         "code": "void mainImage(out vec4 c, in vec2 p) {\n    c = texture(iChannel0, p / iResolution.xy);\n}\n"},
        {"inputs": [], "outputs": [], "name": "Common", "description": "", "type": "common",
         "code": "float helper() {\n    return 0.5;\n}\n"},
        {"inputs": [{"id": 257, "src": "/media/previz/buffer00.png", "ctype": "buffer", "channel": 0,
                     "sampler": {"filter": "linear", "wrap": "clamp", "vflip": "true", "srgb": "false", "internal": "byte"}}],
         "outputs": [{"id": 258, "channel": 0}], "name": "Buffer B", "description": "", "type": "buffer",
         "code": "void mainImage(out vec4 c, in vec2 p) {\n    float x = helper();\n    c = vec4(x, texture(iChannel0, p).y, 0.0, 1.0);\n}\n"
        },
        {"inputs": [], "outputs": [{"id": 257, "channel": 0}], "name": "Buffer A", "description": "", "type": "buffer",
         "code": "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(helper());\n}\n"}
      ]}})");
}

json& passNamed(json& document, const std::string& name) {
    for (json& rp : document["Shader"]["renderpass"])
        if (rp["name"] == name) return rp;
    throw std::runtime_error("no pass " + name);
}

CommandResult runExport(const fs::path& file, const fs::path& out) {
    return runToyhost("run " + quoted(file) + " --size 32x16 --frames 2 --quiet --out " + quoted(out / "f_%d.png"));
}

TEST(ExportCompileErrors, SyntheticExportRuns) {
    const fs::path dir = freshOutputDir("export-run/compile-ok");
    writeFile(dir / "toy.json", syntheticExport().dump(2));
    auto run = runExport(dir / "toy.json", dir / "out");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    // Image shows Buffer B, which is (helper(), Buffer A's green, 0, 1) = (0.5, 0.5, 0, 1).
    auto image = loadImageFile(dir / "out" / "f_1.png");
    ASSERT_TRUE(image.ok()) << image.error().text();
    EXPECT_NEAR(image->rgba[0], 128, 1);
    EXPECT_NEAR(image->rgba[1], 128, 1);
    EXPECT_EQ(image->rgba[2], 0);
    EXPECT_EQ(image->rgba[3], 255);
}

TEST(ExportCompileErrors, ErrorInBufferBNamesThePassAndItsLine) {
    const fs::path dir = freshOutputDir("export-run/compile-buffer-b");
    json document = syntheticExport();
    std::string& code = passNamed(document, "Buffer B")["code"].get_ref<std::string&>();
    code.replace(code.find("0.0, 1.0"), 3, "undeclaredThing");  // line 3 of Buffer B
    writeFile(dir / "toy.json", document.dump(2));
    auto run = runExport(dir / "toy.json", dir / "out");
    EXPECT_NE(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find((dir / "toy.json").string() + " [Buffer B]:3:"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("Buffer B"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("undeclaredThing"), std::string::npos) << run.output;
    EXPECT_TRUE(!fs::exists(dir / "out") || fs::is_empty(dir / "out")) << "frames were written";
}

TEST(ExportCompileErrors, ErrorInCommonNamesCommonAndItsLine) {
    const fs::path dir = freshOutputDir("export-run/compile-common");
    json document = syntheticExport();
    std::string& code = passNamed(document, "Common")["code"].get_ref<std::string&>();
    code.replace(code.find("0.5"), 3, "missingValue");  // line 2 of Common
    writeFile(dir / "toy.json", document.dump(2));
    auto run = runExport(dir / "toy.json", dir / "out");
    EXPECT_NE(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find((dir / "toy.json").string() + " [Common]:2:"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("missingValue"), std::string::npos) << run.output;
    EXPECT_TRUE(!fs::exists(dir / "out") || fs::is_empty(dir / "out")) << "frames were written";
}

TEST(ExportCompileErrors, ErrorInImportedFolderNamesThePassFileAndLine) {
    const fs::path dir = freshOutputDir("export-run/compile-imported");
    json document = syntheticExport();
    std::string& code = passNamed(document, "Buffer B")["code"].get_ref<std::string&>();
    code.replace(code.find("0.0, 1.0"), 3, "undeclaredThing");
    writeFile(dir / "toy.json", document.dump(2));
    auto import = runToyhost("import " + quoted(dir / "toy.json") + " " + quoted(dir / "toy"));
    ASSERT_EQ(import.exitCode, 0) << import.output;  // import does not compile
    auto run = runExport(dir / "toy", dir / "out");
    EXPECT_NE(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find((dir / "toy" / "buffer_b.glsl").string() + ":3:"), std::string::npos) << run.output;
}

// ---------------------------------------------------------------------------------------------
// Bad exports are refused by import, with the file named and no manifest written

struct BadExport {
    const char* name;
    std::string text;
    std::vector<std::string> mentions;
};

TEST(ExportImportErrors, BadExportsAreRefusedWithoutAManifest) {
    const fs::path dir = freshOutputDir("export-run/import-bad");
    json noImage = syntheticExport();
    auto& passes = noImage["Shader"]["renderpass"];
    passes.erase(passes.begin());
    json unknownPass = syntheticExport();
    unknownPass["Shader"]["renderpass"].push_back(
        json::parse(R"({"inputs": [], "outputs": [{"id": 41, "channel": 0}], "name": "Holo", "type": "hologram",
                        "code": "// c\n"})"));
    json unknownBuffer = syntheticExport();
    passNamed(unknownBuffer, "Image")["inputs"][0]["id"] = 999;
    passNamed(unknownBuffer, "Image")["inputs"][0]["src"] = "/media/previz/nothing.png";

    const std::vector<BadExport> cases = {
        {"invalid_json", R"({"Shader": {"renderpass": [)", {":1:28: error: invalid JSON: the text ends too early"}},
        {"no_image", noImage.dump(), {"no image pass"}},
        {"unknown_pass", unknownPass.dump(), {"renderpass[4].type", "unknown pass type \"hologram\""}},
        {"unknown_buffer", unknownBuffer.dump(), {"Image / iChannel0", "unknown id 999"}},
        {"not_an_export", R"({"foo": 1})", {}},
    };
    for (const BadExport& c : cases) {
        SCOPED_TRACE(c.name);
        const fs::path file = dir / (std::string(c.name) + ".json");
        const fs::path target = dir / c.name;
        writeFile(file, c.text);
        auto import = runToyhost("import " + quoted(file) + " " + quoted(target));
        EXPECT_NE(import.exitCode, 0) << import.output;
        // The file named first (a syntax error adds its line and column: "FILE:1:28: ").
        EXPECT_NE(import.output.find("toyhost: " + file.string() + ":"), std::string::npos) << import.output;
        for (const std::string& text : c.mentions)
            EXPECT_NE(import.output.find(text), std::string::npos) << "message lacks \"" << text << "\":\n" << import.output;
        EXPECT_FALSE(fs::exists(target / "manifest.json"));
        EXPECT_TRUE(!fs::exists(target) || fs::is_empty(target)) << "files were written into " << target;
    }
}

TEST(ExportImportErrors, AMediaInputIsImportedAndRunsOnAStandInWithANotice) {
    const fs::path dir = freshOutputDir("export-run/import-notice");
    json document = syntheticExport();
    passNamed(document, "Buffer A")["inputs"].push_back(json::parse(
        R"({"id": 11, "src": "/media/a/video.webm", "ctype": "video", "channel": 2,
            "sampler": {"filter": "linear", "wrap": "clamp", "vflip": "true"}})"));
    writeFile(dir / "toy.json", document.dump(2));
    auto import = runToyhost("import " + quoted(dir / "toy.json") + " " + quoted(dir / "toy"));
    ASSERT_EQ(import.exitCode, 0) << import.output;
    const json manifest = json::parse(readFile(dir / "toy" / "manifest.json"));
    // An id the stock table does not know keeps its kind in the manifest.
    EXPECT_EQ(manifest["passes"]["Buffer A"]["channels"]["iChannel2"]["media"], "/media/a/video.webm") << manifest.dump();
    EXPECT_EQ(manifest["passes"]["Buffer A"]["channels"]["iChannel2"]["kind"], "video") << manifest.dump();
    auto run = runToyhost("run " + quoted(dir / "toy") + " --size 32x16 --frames 2 --out " + quoted(dir / "out" / "f_%d.png"));
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("Buffer A / iChannel2: video '/media/a/video.webm'"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("ATTENTION"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace toyhost::testing
