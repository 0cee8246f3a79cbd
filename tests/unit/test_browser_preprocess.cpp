// BrowserPreprocess: the GCC-cpp fallback refuses what GLSL ES's preprocessor refuses (browsers and
// Mesa alike; webref probes cp_pp_paste, cp_pp_if_undef, cp_pp_redef, cp_pp_gl_prefix) and still
// accepts what they accept (cp_pp_redef_same, a definition per #if branch, an apostrophe in a
// skipped group). Needs Debian's cpp.
#include <gtest/gtest.h>

#include <string>

#include "shader/BrowserPreprocess.h"

using namespace toyhost;

namespace {

Result<std::string> expand(const std::string& body) { return preprocessLikeBrowsers("#version 300 es\n" + body); }

}  // namespace

TEST(BrowserPreprocess, RefusesTokenPasting) {
    EXPECT_FALSE(expand("#define CAT(a, b) a##b\nconst float v12 = 0.3;\nfloat f() { return CAT(v, 12); }\n").ok());
}

TEST(BrowserPreprocess, RefusesAnUndefinedNameInAnEvaluatedIf) {
    EXPECT_FALSE(expand("#if UNDEFINED_THING\nconst float X = 0.9;\n#else\nconst float X = 0.3;\n#endif\n").ok());
    EXPECT_FALSE(expand("#ifdef GL_ES\n#elif OTHER\n#endif\n#if 1\n#elif NOPE\n#endif\n#if MISSING\n#endif\n").ok());
}

TEST(BrowserPreprocess, RefusesARedefinitionWithAnotherBody) {
    EXPECT_FALSE(expand("#define PI 3.14\n#define PI 3.14159\nfloat f() { return PI; }\n").ok());
}

TEST(BrowserPreprocess, RefusesTheReservedGlPrefix) {
    EXPECT_FALSE(expand("#define GL_MINE 0.3\nfloat f() { return GL_MINE; }\n").ok());
    EXPECT_FALSE(expand("#undef GL_ES\n").ok());
}

TEST(BrowserPreprocess, AcceptsWhatBrowsersAccept) {
    const Result<std::string> out = expand(
        "#define PI 3.14\n#define PI 3.14\n"                                 // the same body again
        "#ifdef GL_ES\n#define Q 1.0\n#else\n#define Q 2.0\n#endif\n"        // one definition per branch
        "#if 0\nit's skipped\n#if NOT_EVALUATED\n#endif\n#endif\n"           // skipped groups
        "#if defined(NOPE) && NOPE\n#endif\n"                                // short-circuited
        "#define F(a) (-a)\nfloat f() { return F(-.5) * PI * Q; } // don't\n");
    ASSERT_TRUE(out.ok()) << out.error().text();
    EXPECT_NE(out->find("- -.5"), std::string::npos) << *out;
}

// Issue 42: `#elseif` (a typo of `#elif`) in a skipped group is ignored by browsers (only conditional
// directives are read there) and stopped Mesa's preprocessor; written as `#error`, it is ignored
// in a skipped group and refuses the shader elsewhere, as in the browser. Lines stay where they were.
TEST(BrowserPreprocess, UnknownDirectivesBecomeErrors) {
    EXPECT_EQ(neutraliseUnknownDirectives("#if 0\n#elseif 1\n  # foo x\n#else\n#endif\n"),
              "#if 0\n#error invalid directive elseif 1\n  # error invalid directive foo x\n#else\n#endif\n");
    const std::string known = "#version 300 es\n#define A 1\n#undef A\n#ifdef A\n#elif 1\n#endif\n#pragma x\n#line 3\n#\n"
                              "/*\n#notadirective\n*/ float x; // #nor\n";
    EXPECT_EQ(neutraliseUnknownDirectives(known), known);
}
