// What a canvas shows of a shadertoy's problems (core/ProblemDigest.h, issue 43): the first of each
// pass, files relative to the shadertoy's folder, and how many more.
#include <gtest/gtest.h>

#include "core/ProblemDigest.h"

namespace toyhost {
namespace {

Diagnostic problem(std::string pass, std::string file, int line) {
    Diagnostic d;
    d.code = Code::ShaderCompile;
    d.message = "'x' : undeclared identifier";
    d.pass = std::move(pass);
    d.file = std::move(file);
    d.line = line;
    return d;
}

TEST(ProblemDigest, FirstOfEachPassRelativePathsAndTheRestCounted) {
    const std::vector<Diagnostic> problems = {
        problem("Buffer A", "/home/me/toy/buffer_a.glsl", 3), problem("Buffer A", "/home/me/toy/buffer_a.glsl", 7),
        problem("Image", "/home/me/toy/sub/image.glsl", 1),   problem("Buffer A", "/home/me/toy/buffer_a.glsl", 9),
        problem("", "/home/me/toy/manifest.json", 2),         problem("", "/home/me/toy/manifest.json", 4),
        problem("Image", "/elsewhere/common.glsl", 5),        problem("", "code [Image]", 1)};
    const ProblemDigest digest = digestProblems(problems, "/home/me/toy");
    ASSERT_EQ(digest.shown.size(), 4u);
    EXPECT_EQ(digest.more, 4u);
    EXPECT_EQ(digest.shown[0].file, "buffer_a.glsl");
    EXPECT_EQ(digest.shown[0].line, 3);
    EXPECT_EQ(digest.shown[1].file, "sub/image.glsl");
    EXPECT_EQ(digest.shown[2].file, "manifest.json");
    EXPECT_EQ(digest.shown[2].line, 2);
    EXPECT_EQ(digest.shown[3].file, "code [Image]") << "a pseudo-name stays as it is";
    EXPECT_EQ(formatDiagnostic(digest.shown[0]).rfind("buffer_a.glsl:3:", 0), 0u) << formatDiagnostic(digest.shown[0]);
}

TEST(ProblemDigest, AFileOutsideTheFolderKeepsItsPathAndNothingIsLeftOutOfOne) {
    const ProblemDigest digest = digestProblems({problem("Common", "/elsewhere/common.glsl", 5)}, "/home/me/toy");
    ASSERT_EQ(digest.shown.size(), 1u);
    EXPECT_EQ(digest.shown[0].file, "/elsewhere/common.glsl");
    EXPECT_EQ(digest.more, 0u);
    EXPECT_TRUE(digestProblems({}, "/home/me/toy").shown.empty());
}

}  // namespace
}  // namespace toyhost
