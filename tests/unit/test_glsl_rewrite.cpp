// GlslRewrite: zero-initialisation of locals at every declaration and of `out` parameters at every
// call (WebGL's semantics), the renaming of words Mesa reserves, and what the rewrite must leave
// alone (const, globals, for headers, struct declarations, precision statements, macros). Pure.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "shader/GlslRewrite.h"

using namespace toyhost;

namespace {

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

TEST(GlslRewrite, LocalsWithoutInitialiserGetZero) {
    EXPECT_EQ(rewriteLikeWebGL("float f(float x){ float t; t += x; return t; }"),
              "float f(float x){ float t=float(0); t += x; return t; }");
    EXPECT_EQ(rewriteLikeWebGL("void f(){ highp vec3 a; mat3 m; ivec2 i; bool b; uvec4 u; }"),
              "void f(){ highp vec3 a=vec3(0); mat3 m=mat3(0); ivec2 i=ivec2(0); bool b=bool(0); uvec4 u=uvec4(0); }");
}

TEST(GlslRewrite, MultipleDeclaratorsOnlyThoseWithoutInitialiser) {
    EXPECT_EQ(rewriteLikeWebGL("void f(){ float a, b = 1., c; }"), "void f(){ float a=float(0), b = 1., c=float(0); }");
    EXPECT_EQ(rewriteLikeWebGL("void f(){ vec2 a = vec2(1., g(2., 3.)), b; }"),
              "void f(){ vec2 a = vec2(1., g(2., 3.)), b=vec2(0); }");
}

TEST(GlslRewrite, ArraysAreZeroedElementByElementAfterTheirDeclaration) {
    EXPECT_EQ(rewriteLikeWebGL("void f(){ float a[3]; }"),
              "void f(){ float a[3];for(int toyhost_i=0;toyhost_i<a.length();++toyhost_i)a[toyhost_i]=float(0); }");
    EXPECT_EQ(rewriteLikeWebGL("void f(){ vec2[2] a, b = vec2[2](vec2(1), vec2(2)); }"),
              "void f(){ vec2[2] a, b = vec2[2](vec2(1), vec2(2));"
              "for(int toyhost_i=0;toyhost_i<a.length();++toyhost_i)a[toyhost_i]=vec2(0); }");
}

TEST(GlslRewrite, StructsGetAZeroFunctionDefinedAfterTheirDeclaration) {
    const std::string code = "struct L { vec3 e; float k; };\nvoid g(){ L l; }";
    EXPECT_EQ(rewriteLikeWebGL(code), "struct L { vec3 e; float k; }; L toyhost_zL(){L z;z.e=vec3(0);z.k=float(0);return z;}\n"
                                      "void g(){ L l=toyhost_zL(); }");
    // Members are not locals; arrays and structs inside; a struct declared with a variable too.
    EXPECT_EQ(rewriteLikeWebGL("struct S { highp float a, b[2]; } s;\nstruct T { S s; };"),
              "struct S { highp float a, b[2]; } s; S toyhost_zS(){S z;z.a=float(0);"
              "for(int toyhost_i=0;toyhost_i<z.b.length();++toyhost_i)z.b[toyhost_i]=float(0);return z;}\n"
              "struct T { S s; }; T toyhost_zT(){T z;z.s=toyhost_zS();return z;}");
    // A member of a type it does not know: the struct stays unknown.
    const std::string unknown = "struct U { Thing t; };\nvoid g(){ U u; }";
    EXPECT_EQ(rewriteLikeWebGL(unknown), unknown);
}

TEST(GlslRewrite, OutParametersAreZeroedAtEveryCall) {
    EXPECT_EQ(rewriteLikeWebGL("void g(out float x, float y) { if (y < 0.) x = 1.; }"),
              "void g(out float x, float y) {x=float(0); if (y < 0.) x = 1.; }");
    EXPECT_EQ(rewriteLikeWebGL("struct L { float k; };\nvoid s(vec2 p, out L l, out highp vec3 c, out float a[2]) {}"),
              "struct L { float k; }; L toyhost_zL(){L z;z.k=float(0);return z;}\n"
              "void s(vec2 p, out L l, out highp vec3 c, out float a[2]) {l=toyhost_zL();c=vec3(0);for(int toyhost_i=0;toyhost_i<a.length();++toyhost_i)a[toyhost_i]=float(0);}");
    // mainImage's output, on the line of its brace; inout and in are the caller's.
    EXPECT_EQ(rewriteLikeWebGL("void mainImage( out vec4 O, in vec2 U )\n{\n  O.x = 1.;\n}"),
              "void mainImage( out vec4 O, in vec2 U )\n{O=vec4(0);\n  O.x = 1.;\n}");
    const std::string inout = "void f(inout vec4 c, vec2 p) {}\nvoid f(out vec4 c);";
    EXPECT_EQ(rewriteLikeWebGL(inout), inout);
}

TEST(GlslRewrite, GlobalsAreZeroInlineOrWhenTheEntryFunctionStarts) {
    // A global's initialiser must be constant: scalars, vectors and matrices inline; arrays and
    // structs in mainImage (mainCubemap, mainSound), as WebGL initialises globals once per pixel.
    EXPECT_EQ(rewriteLikeWebGL("struct S { float a; };\nvec3 g, h = vec3(1); S s; float a[2];\n"
                               "void mainImage(out vec4 o, vec2 f) {}"),
              "struct S { float a; }; S toyhost_zS(){S z;z.a=float(0);return z;}\nvec3 g=vec3(0), h = vec3(1); S s; float a[2];\n"
              "void mainImage(out vec4 o, vec2 f) {o=vec4(0);s=toyhost_zS();"
              "for(int toyhost_i=0;toyhost_i<a.length();++toyhost_i)a[toyhost_i]=float(0);}");
    EXPECT_EQ(rewriteLikeWebGL("float f(){ return 1.; }\nfloat g;"), "float f(){ return 1.; }\nfloat g=float(0);");
}

TEST(GlslRewrite, LeavesAloneWhatIsNotALocalWithoutInitialiser) {
    for (const std::string code : {
             "const float k = 1.;\nuniform float u;\nin vec2 p;\nout vec4 o;\nfloat f(float x);\nlayout(location = 0) out vec4 c;\n",
             "void f(){ const float k = 2.; for (int i = 0; i < 3; i++) {} for (float a[2]; ;) {} x = 1.; return; }",
             "void f(){ precision highp float; vec3(1.); a.b = c; y++; }",
             "void f(){ float x = 1.; if (x > 0.) { x = 2.; } else { x = c ? a : b; } }",
             "void f(){ Unknown u; }",   // a type it does not know
             "void f(){ switch (i) { case 0: x = 1.; break; default: break; } }",
         })
        EXPECT_EQ(rewriteLikeWebGL(code), code) << code;
}

TEST(GlslRewrite, ObjectMacrosNamingATypeAreFollowed) {
    EXPECT_EQ(rewriteLikeWebGL("#define V3 vec3\nvoid f(){ V3 p; }"), "#define V3 vec3\nvoid f(){ V3 p=vec3(0); }");
    // A function-like macro is not a type.
    const std::string fn = "#define V(x) vec3\nvoid f(){ V p; }";
    EXPECT_EQ(rewriteLikeWebGL(fn), fn);
}

// Issue 42: the browser zeroes what it sees after preprocessing, so a local declared by a macro is
// zeroed too: right after the statement that declares it (the macro's text is left as it is).
TEST(GlslRewrite, LocalsDeclaredByAMacroGetZero) {
    EXPECT_EQ(rewriteLikeWebGL("#define DECL float q;\nvoid f(){ DECL q += 1.; }"),
              "#define DECL float q;\nvoid f(){ DECL q=float(0); q += 1.; }");
    EXPECT_EQ(rewriteLikeWebGL("#define LOCAL(t, n) t n\n#define V3 vec3\nvoid f(){ LOCAL(V3, p), k[2]; LOCAL(float, s) = 1.; }"),
              "#define LOCAL(t, n) t n\n#define V3 vec3\nvoid f(){ LOCAL(V3, p), k[2]; p=vec3(0);"
              "for(int toyhost_i=0;toyhost_i<k.length();++toyhost_i)k[toyhost_i]=vec3(0); LOCAL(float, s) = 1.; }");
    // Not a declaration (a statement, a call), a global, a for-init: left as they are.
    for (const std::string code : {"#define ADD(x) x += 1.\nvoid f(){ float a = 0.; ADD(a); }",
                                   "#define G float g;\nG\nvoid f(){ }",
                                   "#define T(n) float n\nvoid f(){ for (T(i); i < 1.; i += 1.) {} }",
                                   "#define OPEN float a; float\nvoid f(){ OPEN b; }"})
        EXPECT_EQ(rewriteLikeWebGL(code), code) << code;
}

TEST(GlslRewrite, UnbalancedBracesOutsideDirectivesOnlyRename) {
    const std::string code = "#ifdef A\nvoid f(int a) {\n#else\nvoid f() {\n#endif\n float t; }";
    EXPECT_EQ(rewriteLikeWebGL(code), code);
}

TEST(GlslRewrite, CommentsAndDirectivesAreSkipped) {
    const std::string code = "void f(){ // float c;\n /* float d; */ float e; }\n#define X float z;\n";
    EXPECT_EQ(rewriteLikeWebGL(code), "void f(){ // float c;\n /* float d; */ float e=float(0); }\n#define X float z;\n");
}

TEST(GlslRewrite, LinesStayWhereTheyWere) {
    const std::string code = "struct S { float a; };\nvoid f(out S s,\n out float b)\n{\n float t;\n vec2 q[2];\n}\n";
    EXPECT_EQ(lines(rewriteLikeWebGL(code)), lines(code));
}

TEST(GlslRewrite, WordsMesaReservesAreRenamedEverywhere) {
    EXPECT_EQ(rewriteLikeWebGL("#define P packed\nfloat f(){ float packed = 1.; return packed * P; }"),
              "#define P toyhost_packed\nfloat f(){ float toyhost_packed = 1.; return toyhost_packed * P; }");
    EXPECT_EQ(webglOnlyIdentifierRename("packedx"), "");
    EXPECT_EQ(webglOnlyIdentifierRename("dmat3x2"), "toyhost_dmat3x2");
    EXPECT_EQ(webglOnlyIdentifierRename("dvec2"), "");  // refused by browsers too
}

// Mesa's asin and acos are off by up to 4e-4 rad; the rewrite calls the header's precise versions
// (shader/ShaderAssembly.cpp), in code and in macro bodies alike.
TEST(GlslRewrite, AsinAndAcosCallThePreciseVersions) {
    GlslRewriteOptions options;
    options.zeroInit = options.rename = options.clampIndices = false;
    EXPECT_EQ(rewriteLikeWebGL("#define LAT(p) asin(p.y)\nfloat f(vec2 p){ return acos(p.x) + LAT(p) + asinh(p.x); }", options),
              "#define LAT(p) toyhost_asin(p.y)\nfloat f(vec2 p){ return toyhost_acos(p.x) + LAT(p) + asinh(p.x); }");
    options.preciseInverseTrig = false;
    EXPECT_EQ(rewriteLikeWebGL("float f(float x){ return asin(x); }", options), "float f(float x){ return asin(x); }");
}

// Issue 42: the browser zeroes a for-init declaration at every execution of the loop (a
// `for (float t; ...)` in a function called 3 times runs 6 times; with Mesa alone, 2) and a struct
// defined in a function body (no function can be defined there: its constructor with zero members).
TEST(GlslRewrite, ForInitsAndLocalStructsGetZero) {
    EXPECT_EQ(rewriteLikeWebGL("void f(){ for (float t; t < 1.; t += .5) {} }"),
              "void f(){ for (float t=float(0); t < 1.; t += .5) {} }");
    EXPECT_EQ(rewriteLikeWebGL("void f(){ struct L { float a; vec2 b, c; }; L l; l.a += 1.; }"),
              "void f(){ struct L { float a; vec2 b, c; }; L l=L(float(0),vec2(0),vec2(0)); l.a += 1.; }");
    // An array member: no constructor is written, the driver's zero stands.
    const std::string array = "void f(){ struct A { float a[2]; }; A x; }";
    EXPECT_EQ(rewriteLikeWebGL(array), array);
}

// Issue 42: where GLSL requires a constant expression the precise asin/acos (user functions) cannot
// be called: a float literal's is written as ANGLE folds it (acosf), any other is left to the driver.
TEST(GlslRewrite, AsinAndAcosInConstantExpressionsStayConstant) {
    GlslRewriteOptions options;
    options.zeroInit = options.rename = options.clampIndices = options.foldIntegerConstants = false;
    EXPECT_EQ(rewriteLikeWebGL("const float PI = acos(-1.0);", options), "const float PI = 3.14159274;");
    EXPECT_EQ(rewriteLikeWebGL("#define H asin(1.)\nfloat x = asin(-0.5) + acos(1.0);", options),
              "#define H 1.57079637\nfloat x = (-0.52359879) + 0.0;");
    EXPECT_EQ(rewriteLikeWebGL("const float K = asin(sin(.5));\nfloat g = acos(cos(1.));\nfloat a[int(acos(cos(3.)))];\n"
                               "void f(float x){ const float c = 2.0 * acos(cos(x0)), d = asin(x0); float y = asin(x);"
                               " float b[int(asin(sin(2.)))]; b[int(asin(x))] = 1.; }",
                               options),
              "const float K = asin(sin(.5));\nfloat g = acos(cos(1.));\nfloat a[int(acos(cos(3.)))];\n"
              "void f(float x){ const float c = 2.0 * acos(cos(x0)), d = asin(x0); float y = toyhost_asin(x);"
              " float b[int(asin(sin(2.)))]; b[int(toyhost_asin(x))] = 1.; }");
    // Out of [-1, 1], or an int (no implicit conversion in GLSL ES): left to the driver.
    EXPECT_EQ(rewriteLikeWebGL("void f(){ float a = asin(2.0) + acos(1); }", options),
              "void f(){ float a = toyhost_asin(2.0) + toyhost_acos(1); }");
}

// The names of the rules a driver's refusal can turn off, and the test hook that makes one fail.
TEST(GlslRewrite, APlantedFailureIsWrittenOnlyWhenItsRuleIsOn) {
    GlslRewriteOptions options;
    options.plantedFailure = RewriteRule::ClampIndices;
    EXPECT_EQ(rewriteLikeWebGL("float x;\n", options), "float x=float(0);\nfloat toyhost_planted = toyhost_planted_failure_of_clampIndices;");
    ruleSwitch(options, RewriteRule::ClampIndices) = false;
    EXPECT_EQ(rewriteLikeWebGL("float x;\n", options), "float x=float(0);\n");
    for (RewriteRule rule : kRewriteRules) EXPECT_STRNE(rewriteRuleName(rule), "");
}
