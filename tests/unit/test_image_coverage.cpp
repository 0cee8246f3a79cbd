// ImageCoverage: an Image (or its Common) with the word `discard` may leave pixels as the previous
// frame drew them, so it is drawn on every frame; a comment or a buffer's discard does not count.
#include <gtest/gtest.h>

#include "shader/ImageCoverage.h"

using namespace toyhost;

namespace {

ManifestDesc withImage(const std::string& image, const std::string& buffer = "", const std::string& common = "") {
    ManifestDesc m;
    PassDesc a, i;
    a.id = PassId::BufferA;
    a.code = buffer;
    i.id = PassId::Image;
    i.code = image;
    m.passes = {a, i};
    if (!common.empty()) {
        m.commonSource = "common.glsl";
        m.commonCode = common;
    }
    return m;
}

}  // namespace

TEST(ImageCoverage, OnlyADiscardInImageOrCommonCounts) {
    const std::string writes = "void mainImage(out vec4 o, in vec2 f) { o = vec4(1.0); }";
    EXPECT_FALSE(imageMayKeepPixels(withImage(writes)));
    EXPECT_FALSE(imageMayKeepPixels(withImage(writes + " // never discard here\n/* discard */")));
    EXPECT_FALSE(imageMayKeepPixels(withImage(writes, "void mainImage(out vec4 o, in vec2 f) { discard; }")));
    EXPECT_TRUE(imageMayKeepPixels(withImage("void mainImage(out vec4 o, in vec2 f) { if (f.x < 4.0) discard; }")));
    EXPECT_TRUE(imageMayKeepPixels(withImage(writes, "", "#define CUT discard\n")));
}
