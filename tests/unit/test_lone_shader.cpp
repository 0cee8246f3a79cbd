// A lone shader file (toyhost run image.glsl): an Image-only shadertoy, with the common.glsl next
// to it as Common, saying so; a folder's manifest.json next to it is pointed out.
#include <gtest/gtest.h>

#include "TestFolder.h"
#include "export/LoadShadertoy.h"
#include "manifest/CodeShadertoy.h"

using namespace toyhost;
namespace fs = std::filesystem;

namespace {

const std::string kImage = "void mainImage(out vec4 c, in vec2 f) { c = vec4(helper()); }\n";

bool mentions(const std::vector<Diagnostic>& notices, const std::string& text) {
    for (const Diagnostic& d : notices)
        if (d.message.find(text) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST(LoneShader, AGlslFileIsAnImageOnlyShadertoy) {
    toyhost::testing::TestFolder folder;
    const fs::path file = folder.write("toy/wave.glsl", kImage);
    Result<ManifestDesc> loaded = loadShadertoy(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().text();
    EXPECT_EQ(loaded->name, "wave");
    ASSERT_EQ(loaded->passes.size(), 1u);
    EXPECT_EQ(loaded->passes[0].id, PassId::Image);
    EXPECT_EQ(loaded->passes[0].code, kImage);
    EXPECT_EQ(loaded->passes[0].sourceName, file.string());
    for (const ChannelDesc& channel : loaded->passes[0].channels) EXPECT_EQ(channel.kind, ChannelKind::None);
    EXPECT_FALSE(loaded->commonSource);
    EXPECT_FALSE(loaded->sound);
    ASSERT_EQ(loaded->notices.size(), 1u);
    EXPECT_EQ(loaded->notices[0].severity, Severity::Notice);
    EXPECT_EQ(loaded->notices[0].code, Code::ManifestLoneShader);
    EXPECT_TRUE(mentions(loaded->notices, "Image-only shadertoy (no channels bound)"));
}

TEST(LoneShader, TheCommonGlslNextToItJoinsAsCommonAndItIsSaid) {
    toyhost::testing::TestFolder folder;
    const fs::path file = folder.write("toy/image.frag", kImage);
    folder.write("toy/common.glsl", "float helper() { return 0.5; }\n");
    Result<ManifestDesc> loaded = loadShadertoy(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().text();
    ASSERT_TRUE(loaded->commonSource);
    EXPECT_EQ(loaded->commonCode, "float helper() { return 0.5; }\n");
    EXPECT_EQ(*loaded->commonSource, folder.path / "toy" / "common.glsl");
    EXPECT_TRUE(mentions(loaded->notices, "common.glsl (next to it) as its Common pass"));
}

TEST(LoneShader, CommonGlslItselfDoesNotJoinItself) {
    toyhost::testing::TestFolder folder;
    const fs::path file = folder.write("toy/common.glsl", kImage);
    Result<ManifestDesc> loaded = loadShadertoy(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().text();
    EXPECT_FALSE(loaded->commonSource);
}

TEST(LoneShader, APassFileOfAManifestFolderPointsToTheFolder) {
    toyhost::testing::TestFolder folder;
    const fs::path file = folder.write("toy/IMAGE.GLSL", kImage);
    folder.write("toy/manifest.json", R"({"passes": {"Image": {"source": "IMAGE.GLSL"}}})");
    Result<ManifestDesc> loaded = loadShadertoy(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().text();
    EXPECT_TRUE(mentions(loaded->notices, "give the folder to run the whole shadertoy"));
}

TEST(LoneShader, AMissingFileIsAnErrorNamingIt) {
    toyhost::testing::TestFolder folder;
    Result<ManifestDesc> loaded = loadShadertoy(folder.path / "nope.glsl");
    ASSERT_FALSE(loaded.ok());
    EXPECT_NE(loaded.error().text().find("nope.glsl"), std::string::npos) << loaded.error().text();
}

TEST(LoneShader, CodeFromElsewhereIsTheSameShadertoy) {
    const ManifestDesc desc = imageOnlyShadertoy("stdin", "/work/stdin", PassCode{kImage, "stdin", "stdin"});
    ASSERT_EQ(desc.passes.size(), 1u);
    EXPECT_EQ(desc.passes[0].sourceName, "stdin");
    EXPECT_EQ(desc.passes[0].code, kImage);
    EXPECT_EQ(desc.manifestPath, fs::path("/work/stdin"));
}

// Once skipped without a word (issue 46): a common.glsl next to the file that is a link to nothing
// was meant as its Common pass; the run then failed on "undeclared" names, far from the cause.
TEST(LoneShader, ACommonGlslThatCannotBeReadIsSaidNotSkipped) {
    toyhost::testing::TestFolder folder;
    const fs::path file = folder.write("toy/image.glsl", kImage);
    fs::create_symlink("gone.glsl", folder.path / "toy/common.glsl");
    Result<ManifestDesc> loaded = loadShadertoy(file);
    ASSERT_FALSE(loaded.ok());
    EXPECT_EQ(loaded.error().first().code, Code::IoNotFound);
    EXPECT_EQ(loaded.error().first().file, (folder.path / "toy/common.glsl").string());
    EXPECT_NE(loaded.error().first().message.find("is a symbolic link to gone.glsl, which does not exist"),
              std::string::npos)
        << loaded.error().text();
    fs::remove(folder.path / "toy/common.glsl");
    fs::create_directory(folder.path / "toy/common.glsl");
    Result<ManifestDesc> folderCommon = loadShadertoy(file);
    ASSERT_FALSE(folderCommon.ok());
    EXPECT_EQ(folderCommon.error().first().code, Code::IoNotAFile);
}
